// The mapping warps (POV-Ray 3.7's Parse_Warp: planar, cylindrical,
// spherical, toroidal, cubic): a point turned into the coordinates of a
// surface around the origin, each in its own file (planar_warp.hpp, ...).
// This file holds what they share: their record, and the turn that an
// orientation other than +z gives their result.
#pragma once

#include <cmath>

#include <glm/vec3.hpp>

#include "runtime/time/time_function.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime::pattern {

enum class MappingShape { Planar, Cylindrical, Spherical, Toroidal, Cubic };

// As the scene wrote it: the numbers each shape reads (planar: its normal
// as the orientation and its distance; toroidal: major_radius too; cubic:
// none).
struct MappingWarp {
    MappingShape shape = MappingShape::Planar;
    Vector3Function orientation{{0.0, 0.0, 1.0}};
    TimeFunction dist_exp = 0.0;
    TimeFunction major_radius = 1.0;
    TimeFunction distance = 0.0;

    bool depends_on_time() const {
        return orientation.depends_on_time() || dist_exp.depends_on_time() ||
               major_radius.depends_on_time() || distance.depends_on_time();
    }
};

// At one instant: the orientation made unit as POV-Ray's VNormalizeEq does
// (times the inverse of its length), when the parser reads it.
struct MappingAt {
    MappingShape shape = MappingShape::Planar;
    glm::dvec3 orientation{0.0, 0.0, 1.0};
    double dist_exp = 0.0, major_radius = 1.0, distance = 0.0;
};

inline glm::dvec3 unit_orientation(const glm::dvec3& v) {
    const double k = 1.0 / std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return {v.x * k, v.y * k, v.z * k};
}

// The mapped coordinates (x, y, z) turned for the orientation: unchanged
// for exactly +z, else POV-Ray's sum (the same lines in each of
// warp_planar, warp_cylindrical, warp_spherical and warp_toroidal).
inline glm::dvec3 oriented(const glm::dvec3& o, double x, double y, double z) {
    if (o.x == 0.0 && o.y == 0.0 && o.z == 1.0) return {x, y, z};
    return {(o.x * z) + (o.y * x) + (o.z * x), (o.x * y) + (o.y * -z) + (o.z * y),
            (o.x * -x) + (o.y * y) + (o.z * z)};
}

// The angle of (x, z) around y from +x, as a fraction of a turn in [0, 1)
// (the same lines in warp_cylindrical and warp_spherical); len > 0.
inline double turn_fraction(double x, double z, double len) {
    constexpr double kPi = 3.1415926535897932384626;
    double theta;
    if (z == 0.0)
        theta = x > 0 ? 0.0 : kPi;
    else {
        theta = std::acos(x / len);
        if (z < 0.0) theta = 2.0 * kPi - theta;
    }
    return theta / (2.0 * kPi);
}

}  // namespace hexant::runtime::pattern
