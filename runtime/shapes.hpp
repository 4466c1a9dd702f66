// The geometric primitives a scene may hold, as plain records in object
// space, with POV-Ray's parameters and defaults. Each parameter may be a
// function of time. The tracer's intelligent objects are built from these.
#pragma once

#include <memory>
#include <variant>
#include <vector>

#include "runtime/vector_function.hpp"

namespace hexant::runtime {

struct ObjectRecord;
using ObjectPtr = std::shared_ptr<const ObjectRecord>;

struct Sphere {
    Vector3Function center;
    TimeFunction radius;
};

struct Box {
    Vector3Function corner1, corner2;
};

// All points p with dot(p, normal) = distance; the solid is the side the
// normal points away from.
struct Plane {
    Vector3Function normal;
    TimeFunction distance;
};

// POV-Ray's polygon: one or more closed outlines in a common plane.
struct Polygon {
    std::vector<Vector3Function> points;
};

struct Triangle {
    std::array<Vector3Function, 3> points;
};

struct SmoothTriangle {
    std::array<Vector3Function, 3> points;
    std::array<Vector3Function, 3> normals;
};

struct Disc {
    Vector3Function center, normal;
    TimeFunction radius;
    TimeFunction hole_radius = 0.0;
};

struct Cylinder {
    Vector3Function base, cap;
    TimeFunction radius;
    bool open = false;
};

struct Cone {
    Vector3Function base;
    TimeFunction base_radius;
    Vector3Function cap;
    TimeFunction cap_radius;
    bool open = false;
};

// In the x-z plane about the y axis.
struct Torus {
    TimeFunction major_radius, minor_radius;
};

// linear_sweep, linear_spline: the outline in x-z, swept along y.
struct Prism {
    TimeFunction height1, height2;
    std::vector<Vector2Function> points;
    bool open = false;
};

struct Csg {
    enum class Kind { Union, Merge, Intersection, Difference };
    Kind kind = Kind::Union;
    std::vector<ObjectPtr> children;
};

using Shape = std::variant<Sphere, Box, Plane, Polygon, Triangle, SmoothTriangle, Disc, Cylinder,
                           Cone, Torus, Prism, Csg>;

const char* shape_name(const Shape& shape);

}  // namespace hexant::runtime
