// Shared helpers of the intelligent-object tests: scenes parsed from SDL
// text, and an independent reference for where an object's surface is.
//
// The reference never calls the code under test. It evaluates the record's
// time functions with TimeFunction itself (the tree, not the tape), samples
// each shape kind's surface from its own parametrisation, and maps to the
// world step by step: TransformStep::matrix_at for the affine steps, and
// Barr's deformations written geometrically (Rodrigues' rotation for twist,
// the circle of radius 1/k for bend), not in the frame-and-series form of
// runtime/motion/deformation.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "language/interpreter.hpp"
#include "runtime/objects/intelligent_object.hpp"
#include "runtime/objects/object.hpp"
#include "runtime/objects/object_factory.hpp"
#include "runtime/scene/scene.hpp"
#include "runtime/time/user_function.hpp"

namespace object_test {

namespace rt = hexant::runtime;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegree = kPi / 180.0;

class Random {
  public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}
    double uniform(double lo = 0.0, double hi = 1.0) {
        return std::uniform_real_distribution<double>(lo, hi)(engine_);
    }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
    glm::dvec3 unit_vector() {
        const double z = uniform(-1.0, 1.0), phi = uniform(0.0, 2.0 * kPi);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }

  private:
    std::mt19937_64 engine_;
};

// A scene and its objects. The animation has two frames, so that `clock`
// stays a function of time (a single frame fixes it at 0).
struct Parsed {
    rt::SceneDescription scene;
    std::vector<rt::IntelligentObjectPtr> objects;
};

#ifndef HEXANT_SOURCE_DIR
#define HEXANT_SOURCE_DIR "."
#endif

inline Parsed parse(const std::string& sdl) {
    hexant::language::ParseOptions options;
    // Where the height field's image (bump.png) is.
    options.include_paths.push_back(HEXANT_SOURCE_DIR "/tests/tracer/pov_reference/shapes");
    options.animation.initial_frame = 1;
    options.animation.final_frame = 2;
    Parsed parsed{hexant::language::parse_scene_text(sdl, "object-test.pov", options), {}};
    for (const auto& record : parsed.scene.objects)
        parsed.objects.push_back(
            rt::make_intelligent_object(*record, parsed.scene.default_texture));
    return parsed;
}

inline glm::dvec3 vec(const rt::Vector3Function& f, double t) {
    return f(t);
}

// An orthonormal pair perpendicular to a unit vector.
inline void perpendicular_pair(const glm::dvec3& n, glm::dvec3& u, glm::dvec3& v) {
    const glm::dvec3 helper = std::fabs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    u = glm::normalize(glm::cross(n, helper));
    v = glm::cross(n, u);
}

// A point of a convex outline's inside: a random point of a random fan
// triangle (the test scenes' polygons and prisms are convex).
inline glm::dvec3 in_convex_fan(const std::vector<glm::dvec3>& outline, Random& random) {
    const std::size_t n = outline.size();
    const std::size_t i = 1 + static_cast<std::size_t>(random.integer(0, static_cast<int>(n) - 3));
    double a = random.uniform(), b = random.uniform();
    if (a + b > 1.0) {
        a = 1.0 - a;
        b = 1.0 - b;
    }
    return outline[0] + a * (outline[i] - outline[0]) + b * (outline[i + 1] - outline[0]);
}

// A random point of the shape's surface at time t, in object space.
inline glm::dvec3 sample_object_surface(const rt::Shape& shape, double t, Random& random) {
    if (const auto* s = std::get_if<rt::Sphere>(&shape))
        return vec(s->center, t) + s->radius(t) * random.unit_vector();
    if (const auto* b = std::get_if<rt::Box>(&shape)) {
        const glm::dvec3 c1 = vec(b->corner1, t), c2 = vec(b->corner2, t);
        const glm::dvec3 lo = glm::min(c1, c2), hi = glm::max(c1, c2);
        // (Braces: the draws in the order written, whatever the compiler.)
        glm::dvec3 p{random.uniform(lo.x, hi.x), random.uniform(lo.y, hi.y),
                     random.uniform(lo.z, hi.z)};
        const int face = random.integer(0, 5);
        p[face % 3] = face < 3 ? lo[face % 3] : hi[face % 3];
        return p;
    }
    if (const auto* p = std::get_if<rt::Polygon>(&shape)) {
        std::vector<glm::dvec3> outline;
        for (std::size_t i = 0; i + 1 < p->points.size(); ++i)
            outline.push_back(vec(p->points[i], t));
        return in_convex_fan(outline, random);
    }
    const auto barycentric = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
        double u = random.uniform(), v = random.uniform();
        if (u + v > 1.0) {
            u = 1.0 - u;
            v = 1.0 - v;
        }
        return a + u * (b - a) + v * (c - a);
    };
    if (const auto* tr = std::get_if<rt::Triangle>(&shape))
        return barycentric(vec(tr->points[0], t), vec(tr->points[1], t), vec(tr->points[2], t));
    if (const auto* tr = std::get_if<rt::SmoothTriangle>(&shape))
        return barycentric(vec(tr->points[0], t), vec(tr->points[1], t), vec(tr->points[2], t));
    if (const auto* patch = std::get_if<rt::BicubicPatch>(&shape)) {
        // With no flatness test POV-Ray's pieces are the cells of the
        // 2^u_steps by 2^v_steps grid of (u, v), each the two triangles of
        // its corners on the patch (bezier.cpp); the corners here from the
        // Bernstein form, not by halving.
        if (patch->flatness > 0.0)
            throw std::logic_error("sample_object_surface: a bicubic_patch with a flatness");
        const auto point = [&](double u, double v) {
            const double bu[4] = {(1 - u) * (1 - u) * (1 - u), 3 * u * (1 - u) * (1 - u),
                                  3 * u * u * (1 - u), u * u * u};
            const double bv[4] = {(1 - v) * (1 - v) * (1 - v), 3 * v * (1 - v) * (1 - v),
                                  3 * v * v * (1 - v), v * v * v};
            glm::dvec3 p(0.0);
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) p += bu[i] * bv[j] * vec(patch->points[4 * i + j], t);
            return p;
        };
        const int nu = 1 << patch->u_steps, nv = 1 << patch->v_steps;
        const int i = random.integer(0, nu - 1), j = random.integer(0, nv - 1);
        const double u0 = double(i) / nu, u1 = double(i + 1) / nu;
        const double v0 = double(j) / nv, v1 = double(j + 1) / nv;
        const glm::dvec3 c00 = point(u0, v0), c11 = point(u1, v1);
        return random.integer(0, 1) ? barycentric(c00, point(u0, v1), c11)
                                    : barycentric(c00, c11, point(u1, v0));
    }
    if (const auto* d = std::get_if<rt::Disc>(&shape)) {
        glm::dvec3 u, v;
        perpendicular_pair(glm::normalize(vec(d->normal, t)), u, v);
        const double r0 = d->hole_radius(t), r1 = d->radius(t);
        const double r = std::sqrt(random.uniform(r0 * r0, r1 * r1));
        const double phi = random.uniform(0.0, 2.0 * kPi);
        return vec(d->center, t) + r * (std::cos(phi) * u + std::sin(phi) * v);
    }
    // Cylinder and cone: a side point or a cap point.
    const auto round_solid = [&](const glm::dvec3& base, double r_base, const glm::dvec3& cap,
                                 double r_cap, bool open) {
        const glm::dvec3 axis = cap - base;
        glm::dvec3 u, v;
        perpendicular_pair(glm::normalize(axis), u, v);
        const double phi = random.uniform(0.0, 2.0 * kPi);
        const glm::dvec3 around = std::cos(phi) * u + std::sin(phi) * v;
        const int part = open ? 0 : random.integer(0, 2);
        if (part == 0) {
            const double h = random.uniform();
            return base + h * axis + (r_base + h * (r_cap - r_base)) * around;
        }
        const double r = (part == 1 ? r_base : r_cap) * std::sqrt(random.uniform());
        return (part == 1 ? base : cap) + r * around;
    };
    if (const auto* c = std::get_if<rt::Cylinder>(&shape))
        return round_solid(vec(c->base, t), c->radius(t), vec(c->cap, t), c->radius(t), c->open);
    if (const auto* c = std::get_if<rt::Cone>(&shape))
        return round_solid(vec(c->base, t), c->base_radius(t), vec(c->cap, t), c->cap_radius(t),
                           c->open);
    if (const auto* tor = std::get_if<rt::Torus>(&shape)) {
        const double major = tor->major_radius(t), minor = tor->minor_radius(t);
        const double phi = random.uniform(0.0, 2.0 * kPi), theta = random.uniform(0.0, 2.0 * kPi);
        const double ring = major + minor * std::cos(theta);
        return {ring * std::cos(phi), minor * std::sin(theta), ring * std::sin(phi)};
    }
    if (const auto* pr = std::get_if<rt::Prism>(&shape)) {
        const double h1 = pr->height1(t), h2 = pr->height2(t);
        std::vector<glm::dvec3> outline;
        for (const auto& q : pr->points) outline.push_back({q.c[0](t), 0.0, q.c[1](t)});
        if (glm::length(outline.front() - outline.back()) == 0.0) outline.pop_back();
        const int part = pr->open ? 0 : random.integer(0, 2);
        if (part == 0) {
            const std::size_t i =
                static_cast<std::size_t>(random.integer(0, int(outline.size()) - 1));
            const glm::dvec3 a = outline[i], b = outline[(i + 1) % outline.size()];
            glm::dvec3 p = a + random.uniform() * (b - a);
            p.y = random.uniform(std::min(h1, h2), std::max(h1, h2));
            return p;
        }
        glm::dvec3 p = in_convex_fan(outline, random);
        p.y = part == 1 ? h1 : h2;
        return p;
    }
    if (const auto* tx = std::get_if<rt::Text>(&shape)) {
        // A glyph with an outline; then a point of a side wall (a point of
        // a segment, at any depth) or of a cap (a point of the glyph's box
        // that the even-odd rule puts inside, by rejection).
        std::vector<const rt::geometry::TextGlyph*> glyphs;
        for (const auto& g : tx->glyphs)
            if (!g.segments.empty()) glyphs.push_back(&g);
        if (glyphs.empty())
            throw std::logic_error("sample_object_surface: a text without outlines");
        const rt::geometry::TextGlyph& g = *glyphs[random.integer(0, int(glyphs.size()) - 1)];
        const double depth = tx->thickness(t);
        const int part = random.integer(0, 2);
        if (part == 0) {
            const auto& seg = g.segments[random.integer(0, int(g.segments.size()) - 1)];
            const double u = random.uniform();
            const glm::dvec2 q = seg.quadratic ? (1 - u) * (1 - u) * seg.p0 +
                                                     2 * u * (1 - u) * seg.control + u * u * seg.p2
                                               : seg.p0 + u * (seg.p2 - seg.p0);
            return {q.x, q.y, random.uniform(std::min(0.0, depth), std::max(0.0, depth))};
        }
        for (int tries = 0; tries < 100000; ++tries) {
            const glm::dvec2 q{random.uniform(g.lo.x, g.hi.x), random.uniform(g.lo.y, g.hi.y)};
            if (rt::geometry::inside_outline(g, q)) return {q.x, q.y, part == 1 ? 0.0 : depth};
        }
        throw std::logic_error("sample_object_surface: no point inside a glyph");
    }
    if (const auto* mesh = std::get_if<rt::Mesh>(&shape)) {
        // A random face, a random point of it.
        const auto& m = *mesh->data;
        const auto& f =
            m.faces[static_cast<std::size_t>(random.integer(0, int(m.faces.size()) - 1))];
        double u = random.uniform(), v = random.uniform();
        if (u + v > 1.0) {
            u = 1.0 - u;
            v = 1.0 - v;
        }
        const glm::dvec3 a = m.vertices[f.vertex[0]], b = m.vertices[f.vertex[1]],
                         c = m.vertices[f.vertex[2]];
        return a + u * (b - a) + v * (c - a);
    }
    const auto points_at = [&](const std::vector<rt::Vector2Function>& points) {
        std::vector<glm::dvec2> out;
        for (const auto& q : points) out.emplace_back(q.c[0](t), q.c[1](t));
        return out;
    };
    if (const auto* lathe = std::get_if<rt::Lathe>(&shape)) {
        // A point of a segment's profile, turned about y.
        const auto g = rt::geometry::make_lathe(lathe->spline, points_at(lathe->points));
        const auto& seg =
            g.segments[static_cast<std::size_t>(random.integer(0, int(g.segments.size()) - 1))];
        const glm::dvec2 q = seg.at(random.uniform());
        const double phi = random.uniform(0.0, 2.0 * kPi), r = std::fabs(q.x);
        return {r * std::cos(phi), q.y, r * std::sin(phi)};
    }
    if (const auto* sor = std::get_if<rt::Sor>(&shape)) {
        // A point of the side (the radius from r^2(y)), or of a cap.
        const auto g = rt::geometry::make_sor(points_at(sor->points), sor->open);
        const double phi = random.uniform(0.0, 2.0 * kPi);
        const int part = sor->open ? 0 : random.integer(0, 2);
        if (part == 0) {
            const auto& seg =
                g.segments[static_cast<std::size_t>(random.integer(0, int(g.segments.size()) - 1))];
            const double y = random.uniform(seg.y_lo, seg.y_hi);
            const double r = std::sqrt(std::max(0.0, seg.r2(y)));
            return {r * std::cos(phi), y, r * std::sin(phi)};
        }
        const double r2 = part == 1 ? g.base_radius_squared : g.cap_radius_squared;
        const double r = std::sqrt(std::max(0.0, r2) * random.uniform());
        return {r * std::cos(phi), part == 1 ? g.height1 : g.height2, r * std::sin(phi)};
    }
    if (const auto* se = std::get_if<rt::Superellipsoid>(&shape)) {
        // F + 1 is positively homogeneous of degree 1: d / (F(d) + 1) is on
        // the surface for any direction d.
        const auto g = rt::geometry::make_superellipsoid(se->e(t), se->n(t));
        const glm::dvec3 d = random.unit_vector();
        return d / (rt::geometry::superellipsoid_function(g, d) + 1.0);
    }
    if (const auto* hf = std::get_if<rt::HeightField>(&shape)) {
        // A random cell's lower or upper triangle, a random point of it;
        // points below the floor (the water level) are cut away: again.
        const auto& data = *hf->data;
        const double floor = rt::geometry::height_field_floor(data, hf->water_level(t));
        for (int tries = 0; tries < 100000; ++tries) {
            const int x = random.integer(0, data.width() - 2),
                      z = random.integer(0, data.depth() - 2);
            double u = random.uniform(), v = random.uniform();
            if (u + v > 1.0) {
                u = 1.0 - u;
                v = 1.0 - v;
            }
            const bool upper = random.integer(0, 1) == 1;
            const glm::dvec3 a = upper ? data.vertex(x + 1, z + 1) : data.vertex(x, z);
            const glm::dvec3 b = upper ? data.vertex(x, z + 1) : data.vertex(x + 1, z);
            const glm::dvec3 c = upper ? data.vertex(x + 1, z) : data.vertex(x, z + 1);
            const glm::dvec3 p = a + u * (b - a) + v * (c - a);
            if (p.y >= floor) return p;
        }
        throw std::logic_error("sample_object_surface: a height field under its water");
    }
    if (const auto* blob = std::get_if<rt::Blob>(&shape)) {
        // From a point of a component's centre (or segment) where the field
        // is above the threshold, outward in a random direction to beyond
        // every reach (field 0): bisection on the field between them ends
        // on the surface.
        rt::geometry::BlobGeometry g;
        g.threshold = blob->threshold(t);
        for (std::size_t i = 0; i < blob->kinds.size(); ++i) {
            rt::geometry::BlobComponent c{blob->kinds[i], blob->a[i](t), blob->b[i](t),
                                          blob->radii[i](t), blob->strengths[i](t)};
            // A component's own transforms, by the record's reference
            // matrix (not the compiled motion under test).
            if (!blob->transforms[i].empty()) {
                c.transformed = true;
                c.to_blob = blob->transforms[i].matrix_at(t);
                c.to_component = glm::inverse(c.to_blob);
            }
            g.components.push_back(c);
        }
        const auto box = rt::geometry::object_bounds(g);
        const double span = glm::length(box.hi - box.lo);
        for (int tries = 0; tries < 100000; ++tries) {
            const auto& c = g.components[static_cast<std::size_t>(
                random.integer(0, int(g.components.size()) - 1))];
            glm::dvec3 in = c.a + random.uniform() * (c.b - c.a);
            if (c.transformed) in = glm::dvec3(c.to_blob * glm::dvec4(in, 1.0));
            if (!(rt::geometry::blob_field(g, in) > g.threshold)) continue;
            glm::dvec3 out = in + 2.0 * span * random.unit_vector();
            for (int k = 0; k < 200; ++k) {
                const glm::dvec3 mid = 0.5 * (in + out);
                if (mid == in || mid == out) break;
                (rt::geometry::blob_field(g, mid) > g.threshold ? in : out) = mid;
            }
            return in;
        }
        throw std::logic_error("sample_object_surface: a blob without a surface");
    }
    if (const auto* iso = std::get_if<rt::Isosurface>(&shape)) {
        // The solid is the container where F - T <= 0; from a point of it,
        // outward to beyond the container: bisection on membership ends on
        // its boundary (F = T, or a wall). The bisection's some sixty
        // membership tests read F from its tape's point evaluation (what is
        // under test is the tape's interval bound): folding the body for
        // each point took five minutes of the suite. At the end point the
        // tape's value must equal the body folded with the point's
        // coordinates bit for bit, so a wrong tape cannot hide here.
        static thread_local std::optional<rt::TimeFunction> compiled_body;
        static thread_local rt::SpaceFunction tape;
        const rt::TimeFunction& body = *iso->function;
        if (!compiled_body || body.is_constant() || compiled_body->node() != body.node()) {
            // The cached copy holds its node, so the address is not reused.
            compiled_body = body;
            tape = rt::SpaceFunction(body);
        }
        const auto folded = [&](const glm::dvec3& p) {
            return rt::substitute_arguments(*iso->function, {p.x, p.y, p.z})(t);
        };
        const double threshold = iso->threshold(t);
        const glm::dvec3 c1 = iso->corner1(t), c2 = iso->corner2(t), centre = iso->center(t);
        const double radius = iso->radius(t);
        const auto in_solid = [&](const glm::dvec3& p) {
            if (iso->sphere_container ? glm::length(p - centre) > radius
                                      : glm::any(glm::lessThan(p, glm::min(c1, c2))) ||
                                            glm::any(glm::greaterThan(p, glm::max(c1, c2))))
                return false;
            return tape.at(p, t) - threshold <= 0.0;
        };
        const glm::dvec3 lo = iso->sphere_container ? centre - radius : glm::min(c1, c2);
        const glm::dvec3 hi = iso->sphere_container ? centre + radius : glm::max(c1, c2);
        const double span = glm::length(hi - lo);
        for (int tries = 0; tries < 100000; ++tries) {
            glm::dvec3 in{random.uniform(lo.x, hi.x), random.uniform(lo.y, hi.y),
                          random.uniform(lo.z, hi.z)};
            if (!in_solid(in)) continue;
            glm::dvec3 out = in + 2.0 * span * random.unit_vector();
            for (int k = 0; k < 200; ++k) {
                const glm::dvec3 mid = 0.5 * (in + out);
                if (mid == in || mid == out) break;
                (in_solid(mid) ? in : out) = mid;
            }
            if (tape.at(in, t) != folded(in))
                throw std::logic_error(
                    "sample_object_surface: an isosurface's tape is not its body");
            return in;
        }
        throw std::logic_error("sample_object_surface: an isosurface without a solid");
    }
    if (const auto* sweep = std::get_if<rt::SphereSweep>(&shape)) {
        // A point of one of the swept spheres: on the surface or inside the
        // solid, so a ray through it meets the surface at or before it.
        std::vector<glm::dvec3> centres;
        std::vector<double> radii;
        for (std::size_t i = 0; i < sweep->centres.size(); ++i) {
            centres.push_back(sweep->centres[i](t));
            radii.push_back(sweep->radii[i](t));
        }
        const auto g = rt::geometry::make_sphere_sweep(sweep->spline, centres, radii);
        const auto& seg =
            g.segments[static_cast<std::size_t>(random.integer(0, int(g.segments.size()) - 1))];
        const glm::dvec4 c = seg.at(random.uniform());
        return g.origin + g.scale * (glm::dvec3(c) + std::fabs(c.w) * random.unit_vector());
    }
    if (const auto* julia = std::get_if<rt::JuliaFractal>(&shape)) {
        // The quaternion z^2 + c (the kind scenes' algebra), iterated here
        // from the Julia set's definition: a point is inside while |q|^2
        // stays within R^2 + 1e-7, R = min(2, 1 + |c| + 1e-7), for
        // max_iteration steps. From an inside point outward past the ball:
        // bisection on membership ends on the set's boundary.
        if (julia->algebra != rt::geometry::JuliaAlgebra::quaternion ||
            julia->function != rt::geometry::JuliaFunction::sqr)
            throw std::logic_error("sample_object_surface: a julia_fractal other than z^2 + c");
        double c[4], n[4], norm2 = 0.0, c2 = 0.0;
        for (int i = 0; i < 4; ++i) {
            c[i] = julia->parameter[i](t);
            n[i] = julia->slice[i](t);
            norm2 += n[i] * n[i];
            c2 += c[i] * c[i];
        }
        for (double& v : n) v /= std::sqrt(norm2);
        const double distance = julia->slice_distance(t);
        const double r = std::min(2.0, 1.0 + std::sqrt(c2) + 1e-7);
        const double exit = r * r + 1e-7;
        const auto in_set = [&](const glm::dvec3& p) {
            double q[4] = {p.x, p.y, p.z, (distance - n[0] * p.x - n[1] * p.y - n[2] * p.z) / n[3]};
            for (int i = 0; i < julia->iterations; ++i) {
                const double v2 = q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
                if (q[0] * q[0] + v2 > exit) return false;
                const double x = q[0];
                q[0] = x * x - v2 + c[0];
                for (int k = 1; k < 4; ++k) q[k] = 2.0 * x * q[k] + c[k];
            }
            return true;
        };
        for (int tries = 0; tries < 1000000; ++tries) {
            glm::dvec3 in{random.uniform(-r, r), random.uniform(-r, r), random.uniform(-r, r)};
            if (!in_set(in)) continue;
            glm::dvec3 out = in + 5.0 * r * random.unit_vector();
            for (int k = 0; k < 200; ++k) {
                const glm::dvec3 mid = 0.5 * (in + out);
                if (mid == in || mid == out) break;
                (in_set(mid) ? in : out) = mid;
            }
            return in;
        }
        throw std::logic_error("sample_object_surface: a julia_fractal without a set");
    }
    throw std::logic_error("sample_object_surface: a shape kind without a sampler");
}

// The deformation's spine: the unit part of +y perpendicular to the axis, or
// of +z when the axis is within 1e-3 of +-y (hexant's documented rule).
inline glm::dvec3 spine_of(const glm::dvec3& axis) {
    const glm::dvec3 reference =
        axis.x * axis.x + axis.z * axis.z >= 1e-6 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    return glm::normalize(reference - glm::dot(reference, axis) * axis);
}

// Rodrigues' rotation of p about the unit axis by angle (radians).
inline glm::dvec3 rotate_about(const glm::dvec3& p, const glm::dvec3& axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return p * c + glm::cross(axis, p) * s + axis * glm::dot(axis, p) * (1.0 - c);
}

// One deformation step, forward or undone, from its geometric definition.
inline glm::dvec3 reference_deform(rt::TransformKind kind, const glm::dvec3& axis_direction,
                                   double amount, const glm::dvec3& p, bool inverse) {
    const glm::dvec3 axis = glm::normalize(axis_direction);
    const double a = glm::dot(p, axis);
    switch (kind) {
        case rt::TransformKind::Twist:
            return rotate_about(p, axis, (inverse ? -1.0 : 1.0) * amount * kDegree * a);
        case rt::TransformKind::Taper: {
            const glm::dvec3 along = a * axis, across = p - along;
            const double f = 1.0 + amount * a;
            return along + (inverse ? across / f : across * f);
        }
        default: {  // bend: the axis becomes an arc of radius 1/k about a centre on the spine
            const double k = amount * kDegree;
            if (k == 0.0) return p;
            const glm::dvec3 spine = spine_of(axis), cross = glm::cross(axis, spine);
            const double s = glm::dot(p, spine), c = glm::dot(p, cross);
            const double radius = 1.0 / k;
            double a2, s2;
            if (!inverse) {
                const double theta = k * a;
                a2 = (radius - s) * std::sin(theta);
                s2 = radius - (radius - s) * std::cos(theta);
            } else {
                // a' = D sin(k a), R - s' = D cos(k a), D = R - s of the sign of R.
                const double sign = radius > 0.0 ? 1.0 : -1.0;
                const double d = sign * std::hypot(a, radius - s);
                const double theta = std::atan2(sign * a, sign * (radius - s));
                a2 = theta / k;
                s2 = radius - d;
            }
            return a2 * axis + s2 * spine + c * cross;
        }
    }
}

// The record's object-to-world map at t, step by step.
inline glm::dvec3 reference_to_world(const rt::Transform& transform, glm::dvec3 p, double t) {
    for (const auto& step : transform.steps()) {
        if (step.is_deformation())
            p = reference_deform(step.kind, step.vector(t), step.amount(t), p, step.inverse);
        else
            p = glm::dvec3(step.matrix_at(t) * glm::dvec4(p, 1.0));
    }
    return p;
}

inline glm::dvec3 reference_to_object(const rt::Transform& transform, glm::dvec3 p, double t) {
    const auto& steps = transform.steps();
    for (auto it = steps.rbegin(); it != steps.rend(); ++it) {
        if (it->is_deformation())
            p = reference_deform(it->kind, it->vector(t), it->amount(t), p, !it->inverse);
        else
            p = glm::dvec3(glm::inverse(it->matrix_at(t)) * glm::dvec4(p, 1.0));
    }
    return p;
}

// A random surface event of a top-level record at time t.
inline rt::Event sample_surface_event(const rt::ObjectRecord& record, double t, Random& random) {
    const glm::dvec3 p = sample_object_surface(record.shape, t, random);
    return rt::Event(reference_to_world(record.transform, p, t), t);
}

// The motions every object kind is tried with: static, moving and deformed.
struct Variant {
    const char* name;
    std::string transform;  // written inside the object after its parameters
    bool moving_parameters = false;
};

inline const std::vector<Variant>& variants() {
    static const std::vector<Variant> list = {
        {"static", "rotate <20, 30, 40> scale <1, 2, 1.5> translate <1, -2, 3>"},
        {"translation", "translate <4 * clock, -3 * clock * clock, 2 * sin(5 * clock)>"},
        {"fast rotation", "translate <2, 0, 0> rotate <0, 3600 * clock, 0> rotate <15, 0, 0>"},
        {"spline path", "translate Path(clock)"},
        {"moving parameters", "rotate <0, 0, 30>", true},
        {"twist", "twist <0, 1, 0.2>, 720 * clock - 180 translate <clock, 0, 0>"},
        {"taper", "taper <0.3, 1, 0>, 0.8 * clock - 0.4 rotate <0, 90 * clock, 0>"},
        {"bend", "bend <0, 1, 0>, 60 * clock translate <0, 0, clock>"},
        {"stiff twist", "twist <0.1, 1, 0>, 10800 translate <0, clock, 0>"},
    };
    return list;
}

inline const char* kPath =
    "#declare Path = spline { cubic_spline -0.5, <0, 0, 0> 0, <1, 0, 0> 0.3, <1, 2, 0> "
    "0.6, <-1, 1, 1> 1, <0, 0, 3> 1.5, <0, 0, 0> }\n";

// Each bounded kind's parameters in its own space (size about 1), fixed and
// with parameters that move. The polygons and prisms are convex, as the
// sampler requires.
struct KindScene {
    std::string keyword, fixed, moving;
};

inline const std::vector<KindScene>& kind_scenes() {
    static const std::vector<KindScene> list = {
        {"sphere", "<0.2, 0.1, 0>, 0.8", "<0.3 * sin(6 * clock), 0, 0>, 0.5 + 0.3 * clock"},
        {"box", "<-0.5, -0.7, -0.4>, <0.6, 0.5, 0.3>",
         "<-0.5, -0.7, -0.4>, <0.6 + clock, 0.5, 0.3 - 0.5 * clock>"},
        {"polygon",
         "5, <-0.5, -0.5, 0>, <0.5, -0.5, 0>, <0.6, 0.4, 0>, <-0.4, 0.5, 0>, <-0.5, -0.5, 0>",
         "5, <-0.5, -0.5, 0>, <0.5, -0.5, 0>, <0.6 + clock, 0.4, 0>, <-0.4, 0.5, 0>, <-0.5, -0.5, "
         "0>"},
        {"triangle", "<-0.5, 0, 0>, <0.5, 0.1, 0>, <0, 0.7, 0.3>",
         "<-0.5, 0, 0>, <0.5, 0.1, clock>, <0, 0.7 - clock, 0.3>"},
        {"smooth_triangle",
         "<-0.5, 0, 0>, <0, 0, 1>, <0.5, 0.1, 0>, <0.1, 0, 1>, <0, 0.7, 0.3>, <0, 0.2, 1>",
         "<-0.5, 0, 0>, <0, 0, 1>, <0.5, 0.1, clock>, <0.1, 0, 1>, <0, 0.7, 0.3>, <0, 0.2, 1>"},
        {"disc", "<0, 0, 0>, <0.3, 1, 0.2>, 0.8, 0.2",
         "<0, clock, 0>, <0.3, 1, 0.2 + clock>, 0.8 - 0.3 * clock, 0.2"},
        {"cylinder", "<0, -0.5, 0>, <0.2, 0.6, 0.1>, 0.3",
         "<0, -0.5, 0>, <0.2, 0.6 + clock, 0.1>, 0.3 + 0.2 * clock"},
        {"cone", "<0, -0.5, 0>, 0.5, <0, 0.6, 0.2>, 0.1",
         "<0, -0.5, 0>, 0.5 - 0.2 * clock, <0, 0.6, 0.2 + clock>, 0.1"},
        {"torus", "0.7, 0.2", "0.7 - 0.3 * clock, 0.2 + 0.1 * clock"},
        {"prism",
         "linear_sweep linear_spline -0.5, 0.5, 5, <-0.5, -0.5>, <0.5, -0.5>, <0.6, 0.4>, <-0.4, "
         "0.5>, <-0.5, -0.5>",
         "linear_sweep linear_spline -0.5, 0.5 + clock, 5, <-0.5, -0.5>, <0.5, -0.5>, <0.6, 0.4 + "
         "clock>, <-0.4, 0.5>, <-0.5, -0.5>"},
        // Two glyphs of POV-Ray's timrom.ttf (Debian's fonts-povray), one
        // with a hole; the thickness moves.
        {"text", "ttf \"timrom.ttf\" \"Ag\", 0.5, 0",
         "ttf \"timrom.ttf\" \"Ag\", 0.3 + 0.4 * clock, 0"},
        {"lathe",
         "cubic_spline 6, <0, -0.6>, <0.5, -0.5>, <0.7, 0>, <0.4, 0.4>, <0.5, 0.7>, <0, 0.9>",
         "cubic_spline 6, <0, -0.6>, <0.5, -0.5>, <0.7 - 0.3 * clock, 0>, <0.4, 0.4>, <0.5, 0.7 + "
         "clock>, <0, 0.9>"},
        {"sor", "6, <0.3, -0.7>, <0.4, -0.5>, <0.6, -0.1>, <0.3, 0.3>, <0.5, 0.6>, <0.6, 0.8>",
         "6, <0.3, -0.7>, <0.4, -0.5>, <0.6, -0.1>, <0.3 + 0.2 * clock, 0.3>, <0.5, 0.6>, <0.6, "
         "0.8>"},
        // A closed mesh of five faces, one smooth, with an inside; its
        // triangles cannot move, so its moving case moves it whole.
        {"mesh",
         "triangle { <-0.5, -0.4, -0.4>, <0.6, -0.5, -0.3>, <0, 0.7, 0> } "
         "triangle { <0.6, -0.5, -0.3>, <0.1, -0.3, 0.6>, <0, 0.7, 0> } "
         "smooth_triangle { <0.1, -0.3, 0.6>, <0, 0.2, 1>, <-0.5, -0.4, -0.4>, <-1, 0.2, 0>, <0, "
         "0.7, 0>, <0, 1, 0> } "
         "triangle { <-0.5, -0.4, -0.4>, <0.1, -0.3, 0.6>, <0.6, -0.5, -0.3> } "
         "triangle { <-0.5, -0.4, -0.4>, <0.6, -0.5, -0.3>, <0.2, -0.45, -0.35> } inside_vector "
         "<0.1, 1, 0.2>",
         "triangle { <-0.5, -0.4, -0.4>, <0.6, -0.5, -0.3>, <0, 0.7, 0> } "
         "triangle { <0.6, -0.5, -0.3>, <0.1, -0.3, 0.6>, <0, 0.7, 0> } "
         "smooth_triangle { <0.1, -0.3, 0.6>, <0, 0.2, 1>, <-0.5, -0.4, -0.4>, <-1, 0.2, 0>, <0, "
         "0.7, 0>, <0, 1, 0> } "
         "triangle { <-0.5, -0.4, -0.4>, <0.1, -0.3, 0.6>, <0.6, -0.5, -0.3> } "
         "triangle { <-0.5, -0.4, -0.4>, <0.6, -0.5, -0.3>, <0.2, -0.45, -0.35> } inside_vector "
         "<0.1, 1, 0.2> "
         "translate <0.5 * clock, 0, -0.3 * clock>"},
        // Two spheres and a cylinder merged, and components with transforms
        // of their own (a stretched, turned sphere; a sheared cylinder);
        // moving: one sphere moves through the others, a strength and the
        // threshold change, a stretched sphere turns a whole turn and slides.
        {"blob",
         "threshold 0.6 sphere { <-0.4, 0, 0>, 0.8, 1 } sphere { <0.4, 0.1, 0>, 0.8, 1 } "
         "cylinder { <0, -0.5, 0>, <0, 0.5, 0.2>, 0.4, 1 } "
         "sphere { 0, 0.5, 1 scale <1.4, 0.6, 0.8> rotate z * 30 translate <0.2, 0.5, 0.1> } "
         "cylinder { <-0.3, 0, 0>, <0.3, 0, 0>, 0.3, 1 matrix <1, 0.5, 0, 0, 2, 0, 0, 0, 1, 0, "
         "-0.4, 0> }",
         "threshold 0.5 + 0.2 * clock sphere { <-0.9 + 0.8 * clock, 0, 0>, 0.8, 1 } "
         "sphere { <0.4, 0.1, 0>, 0.8, 1 - 0.5 * clock } cylinder { <0, -0.5, 0>, <0, 0.5, 0.2>, "
         "0.4, 1 } sphere { 0, 0.5, 1 scale <1.4, 0.6, 0.8> rotate z * 360 * clock "
         "translate <0.3 * clock, 0.5, 0.1> }"},
        // A b_spline sweep of five spheres; its middle one moves and swells.
        {"sphere_sweep",
         "b_spline 5, <-0.8, 0, 0>, 0.2, <-0.4, 0.4, 0>, 0.3, <0, 0, 0.2>, 0.35, <0.4, 0.3, 0>, "
         "0.25, <0.8, 0, 0>, 0.2",
         "b_spline 5, <-0.8, 0, 0>, 0.2, <-0.4, 0.4, 0>, 0.3, <0, 0.6 * clock, 0.2>, 0.25 + 0.2 * "
         "clock, "
         "<0.4, 0.3, 0>, 0.25, <0.8, 0, 0>, 0.2"},
        {"superellipsoid", "<0.4, 1.5>", "<0.3 + 0.8 * clock, 1.2 - 0.9 * clock>"},
        // A wavy ellipsoid cut by its box (closed: the walls are surface);
        // moving: a sphere that swells with clock, a threshold that moves,
        // in a sphere container.
        {"isosurface",
         "function { x * x + 1.5 * y * y + z * z + 0.1 * sin(6 * x) } threshold 0.6 "
         "contained_by { box { <-1, -0.5, -1>, <1, 0.5, 0.7> } }",
         "function { x * x + y * y + z * z - 0.2 - 0.5 * clock } threshold 0.1 * clock "
         "contained_by { sphere { <0.1, 0, 0>, 0.9 } }"},
        // fractal1.pov's first quaternion z^2 + c; moving: its parameter
        // and the slice's distance move with clock.
        {"julia_fractal",
         "<-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15",
         "<-0.03, 0.5 - 0.3 * clock, -0.2, -0.5> quaternion max_iteration 6 precision 15 "
         "slice <0, 0, 0, 1>, 0.2 * clock"},
        // A wavy patch cut into 4 x 8 pieces (no flatness test: the
        // sampler's grid); moving: two points move, the type-0 subdivision
        // made for each ray.
        {"bicubic_patch",
         "type 1 u_steps 2 v_steps 3 <-0.6, 0, -0.6>, <-0.2, 0.3, -0.6>, <0.2, -0.2, -0.6>, "
         "<0.6, 0.1, -0.6>, <-0.6, 0.2, -0.2>, <-0.2, -0.4, -0.2>, <0.2, 0.5, -0.2>, "
         "<0.6, 0, -0.2>, <-0.6, -0.1, 0.2>, <-0.2, 0.4, 0.2>, <0.2, -0.3, 0.2>, "
         "<0.6, 0.2, 0.2>, <-0.6, 0.1, 0.6>, <-0.2, 0, 0.6>, <0.2, 0.2, 0.6>, <0.6, -0.1, 0.6>",
         "type 0 u_steps 3 v_steps 2 <-0.6, 0, -0.6>, <-0.2, 0.3, -0.6>, <0.2, -0.2, -0.6>, "
         "<0.6, 0.1, -0.6 + 0.3 * clock>, <-0.6, 0.2, -0.2>, <-0.2, -0.4 + 0.8 * clock, -0.2>, "
         "<0.2, 0.5, -0.2>, <0.6, 0, -0.2>, <-0.6, -0.1, 0.2>, <-0.2, 0.4, 0.2>, "
         "<0.2, -0.3, 0.2>, <0.6, 0.2, 0.2>, <-0.6, 0.1, 0.6>, <-0.2, 0, 0.6>, <0.2, 0.2, 0.6>, "
         "<0.6, -0.1, 0.6>"},
        // The height_field still's 32 x 32 bump (on parse()'s include
        // path); the water level rises through it.
        {"height_field", "png \"bump.png\" smooth", "png \"bump.png\" water_level 0.6 * clock"},
    };
    return list;
}

inline const KindScene& kind_scene(const std::string& keyword) {
    for (const auto& k : kind_scenes())
        if (k.keyword == keyword) return k;
    throw std::logic_error("no test scene for " + keyword);
}

// Samples per variant for the property tests: 10^5 in the suite, more with
// HEXANT_PROPERTY_SAMPLES (e.g. 10000000 for the long run in the README).
inline long property_samples() {
    if (const char* env = std::getenv("HEXANT_PROPERTY_SAMPLES")) {
        const long n = std::atol(env);
        if (n > 0) return n;
    }
    return 100000;
}

}  // namespace object_test
