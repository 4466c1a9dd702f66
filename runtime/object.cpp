#include "runtime/object.hpp"

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

struct ShapeVaries {
    bool operator()(const Sphere& s) const { return varies(s.center) || varies(s.radius); }
    bool operator()(const Box& b) const { return varies(b.corner1) || varies(b.corner2); }
    bool operator()(const Plane& p) const { return varies(p.normal) || varies(p.distance); }
    bool operator()(const Polygon& p) const {
        for (const auto& q : p.points)
            if (varies(q)) return true;
        return false;
    }
    bool operator()(const Triangle& t) const {
        for (const auto& q : t.points)
            if (varies(q)) return true;
        return false;
    }
    bool operator()(const SmoothTriangle& t) const {
        for (int i = 0; i < 3; ++i)
            if (varies(t.points[i]) || varies(t.normals[i])) return true;
        return false;
    }
    bool operator()(const Disc& d) const {
        return varies(d.center) || varies(d.normal) || varies(d.radius) || varies(d.hole_radius);
    }
    bool operator()(const Cylinder& c) const { return varies(c.base) || varies(c.cap) || varies(c.radius); }
    bool operator()(const Cone& c) const {
        return varies(c.base) || varies(c.cap) || varies(c.base_radius) || varies(c.cap_radius);
    }
    bool operator()(const Torus& t) const { return varies(t.major_radius) || varies(t.minor_radius); }
    bool operator()(const Prism& p) const {
        if (varies(p.height1) || varies(p.height2)) return true;
        for (const auto& q : p.points)
            if (q.depends_on_time()) return true;
        return false;
    }
    bool operator()(const Csg& c) const {
        for (const auto& child : c.children)
            if (child->depends_on_time()) return true;
        return false;
    }
};

}  // namespace

bool ObjectRecord::shape_depends_on_time() const { return std::visit(ShapeVaries{}, shape); }

bool ObjectRecord::texture_depends_on_time() const {
    if (!texture) return false;
    for (const auto& c : texture->pigment.colours)
        if (c.depends_on_time()) return true;
    const Finish& f = texture->finish;
    return varies(f.ambient) || varies(f.diffuse) || varies(f.brilliance) || varies(f.phong) ||
           varies(f.phong_size) || varies(f.specular) || varies(f.roughness) ||
           f.reflection.depends_on_time() || texture->transform.depends_on_time() ||
           texture->pigment.transform.depends_on_time();
}

bool ObjectRecord::depends_on_time() const {
    return shape_depends_on_time() || transform.depends_on_time() || texture_depends_on_time() ||
           (interior && varies(interior->ior));
}

}  // namespace hexant::runtime
