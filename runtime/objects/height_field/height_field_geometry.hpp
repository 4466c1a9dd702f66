// POV-Ray 3.7's height_field in object space (hfield.cpp): the grid of
// HeightFieldData, vertex (x, z) at <x / (width - 1), height / 65536,
// z / (depth - 1)>, each cell split as POV-Ray splits it into the lower
// triangle (x, z), (x + 1, z), (x, z + 1) and the upper one (x + 1, z + 1),
// (x, z + 1), (x + 1, z). POV-Ray finds hits only inside its bounding box,
// whose bottom is `floor` (Parse_HField and Compute_HField: bounding_corner1
// y = max(least height, 65536 water_level) - 0.001, in height units):
// the parts of the surface below it are cut away, and nothing closes the
// cut.
//
// Hits: part 0 for a lower triangle, 1 for an upper one; normal: the
// triangle's, upward (POV-Ray's N = <y1 - y2, 1, y1 - y3> in grid units,
// taken to object space); shading_normal: with `smooth`, POV-Ray's blend of
// the four corner normals of the cell under the point (HField::Normal:
// bilinear in the point's x and z within the cell, each corner normal the
// quantized smooth_height_field one, taken to object space and normalized;
// the blend normalized), else the normal. uv = (x, z) of the point (POV-Ray
// 3.7 gives a height field no uv mapping). inside: POV-Ray's HField::Inside
// (below the triangle's plane over the grid, heights raised to the floor;
// everything below the floor within the grid; nothing above the box).
//
// Accuracy: each triangle is intersect_barycentric's watertight test, its
// vertices computed by one formula wherever they are shared, so rays do not
// slip between cells; the hierarchy's boxes are tested with pbrt-v4's
// conservative slab test.
#pragma once

#include <memory>
#include <optional>

#include "runtime/geometry/ray3.hpp"
#include "runtime/objects/height_field/height_field_data.hpp"

namespace hexant::runtime::geometry {

struct HeightFieldGeometry {
    std::shared_ptr<const objects::HeightFieldData> data;
    double floor = 0.0;  // object-space y below which the surface is cut away
    bool smooth = false;
};

// POV-Ray's bottom of the field for a water level (the scene's value,
// 0..1): (max(least height, 65536 water_level) - 0.001) / 65536.
double height_field_floor(const objects::HeightFieldData& data, double water_level);

std::optional<SurfaceHit> intersect(const HeightFieldGeometry& field, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const HeightFieldGeometry& field, glm::dvec3 p);
Box3 object_bounds(const HeightFieldGeometry& field);
bool surface_may_meet(const HeightFieldGeometry& field, const Box3& box);

// The shading normal `smooth` gives at an object-space point (exposed for
// tests). POV-Ray's HField::Normal takes each corner's normal to the world
// and normalizes it there before it blends the four: with
// `normal_to_world` (the inverse transpose of the map to the world at the
// hit), each corner is weighted so, by 1 / its length in the world, and
// the result, taken to the world, is POV-Ray's direction; without it, the
// corners are normalized in object space (a map that scales all axes
// alike gives the same).
glm::dvec3 height_field_smooth_normal(const objects::HeightFieldData& data, const glm::dvec3& point,
                                      const glm::dmat3* normal_to_world = nullptr);

}  // namespace hexant::runtime::geometry
