#include "runtime/object.hpp"

#include <string>
#include <vector>

namespace hexant::runtime {

const char* shape_name(const Shape& shape) {
    static const char* names[] = {"sphere",   "box",  "plane",    "polygon", "triangle",
                                  "smooth_triangle",  "disc",     "cylinder", "cone",
                                  "torus",    "prism", "csg"};
    if (const auto* csg = std::get_if<Csg>(&shape)) {
        static const char* kinds[] = {"union", "merge", "intersection", "difference"};
        return kinds[static_cast<int>(csg->kind)];
    }
    return names[shape.index()];
}

namespace {

bool varies(const TimeFunction& f) { return f.depends_on_time(); }
bool varies(const Vector3Function& v) { return v.depends_on_time(); }
bool varies(const Vector2Function& v) { return v.depends_on_time(); }
template <typename T, std::size_t N>
bool varies(const std::array<T, N>& items) {
    for (const auto& item : items)
        if (varies(item)) return true;
    return false;
}
template <typename T>
bool varies(const std::vector<T>& items) {
    for (const auto& item : items)
        if (varies(item)) return true;
    return false;
}

// The names of a shape's parameters that depend on time.
struct TimedParameters {
    std::vector<std::string> names;
    void check(bool timed, const char* name) {
        if (timed) names.emplace_back(name);
    }
    void operator()(const Sphere& s) { check(varies(s.center), "center"); check(varies(s.radius), "radius"); }
    void operator()(const Box& b) { check(varies(b.corner1), "corner1"); check(varies(b.corner2), "corner2"); }
    void operator()(const Plane& p) { check(varies(p.normal), "normal"); check(varies(p.distance), "distance"); }
    void operator()(const Polygon& p) { check(varies(p.points), "points"); }
    void operator()(const Triangle& t) { check(varies(t.points), "points"); }
    void operator()(const SmoothTriangle& t) {
        check(varies(t.points), "points");
        check(varies(t.normals), "normals");
    }
    void operator()(const Disc& d) {
        check(varies(d.center), "center");
        check(varies(d.normal), "normal");
        check(varies(d.radius), "radius");
        check(varies(d.hole_radius), "hole_radius");
    }
    void operator()(const Cylinder& c) {
        check(varies(c.base), "base");
        check(varies(c.cap), "cap");
        check(varies(c.radius), "radius");
    }
    void operator()(const Cone& c) {
        check(varies(c.base), "base");
        check(varies(c.base_radius), "base_radius");
        check(varies(c.cap), "cap");
        check(varies(c.cap_radius), "cap_radius");
    }
    void operator()(const Torus& t) {
        check(varies(t.major_radius), "major_radius");
        check(varies(t.minor_radius), "minor_radius");
    }
    void operator()(const Prism& p) {
        check(varies(p.height1), "height1");
        check(varies(p.height2), "height2");
        check(varies(p.points), "points");
    }
    void operator()(const Csg& c) {
        for (const auto& child : c.children)
            if (child->depends_on_time()) {
                names.emplace_back("children");
                return;
            }
    }
};

}  // namespace

std::vector<std::string> ObjectRecord::timed_parameters() const {
    TimedParameters timed;
    std::visit(timed, shape);
    return timed.names;
}

bool ObjectRecord::shape_depends_on_time() const { return !timed_parameters().empty(); }

bool ObjectRecord::texture_depends_on_time() const { return texture && texture->depends_on_time(); }

bool ObjectRecord::depends_on_time() const {
    return !lifetime.is_always() || shape_depends_on_time() || transform.depends_on_time() ||
           texture_depends_on_time() || (interior && varies(interior->ior));
}

}  // namespace hexant::runtime
