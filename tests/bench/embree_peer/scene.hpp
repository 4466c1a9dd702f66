// hexant_embree_peer's scenes: the options, a scene loaded as the benchmark runs
// it, and its conversion into the spheres, triangles and lights Embree is given
// (tests/bench/embree_peer.cpp says what is measured and how).
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>
#include <embree3/rtcore.h>
#include <glm/geometric.hpp>
#include <glm/glm.hpp>
#include <tbb/blocked_range2d.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include "language/ini_file.hpp"
#include "language/interpreter.hpp"
#include "language/scene_error.hpp"
#include "runtime/objects/object.hpp"
#include "runtime/objects/object_error.hpp"
#include "runtime/scene/scene.hpp"
#include "runtime/texture/texture_evaluator.hpp"
#include "tracer/image.hpp"
#include "tracer/image_output.hpp"
#include "tracer/renderer.hpp"

namespace hexant_embree_peer {

namespace fs = std::filesystem;
using namespace hexant;
using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// ---------------------------------------------------------------------------
// Options

struct Options {
    std::string scene = "all";
    std::optional<int> spp, size, reference_spp, error_frame;
    std::optional<std::string> frames;  // A:B
    int threads = 0;                    // 0: all
    bool quick = false;
    std::optional<std::string> write_images;
    std::vector<int> swarm_counts{1000, 10000, 100000};  // N of each swarm job
    std::size_t frames_max = 20000;  // hexant's frames mode only up to this many objects
    int rounds = 3;                  // runs of each method; the table gives medians
};

// One scene as the benchmark runs it, everything resolved.
struct Job {
    std::string name;
    runtime::SceneDescription scene;
    int first = 1, last = 1;  // frames rendered
    int error_frame = 1;
    int spp = 1, reference_spp = 1024;
    std::size_t objects = 0;  // the scene's top-level objects
    std::vector<int> ladder;  // spp of the time-to-error table
};

// `count`: the swarm's N (examples/swarm.pov), 0 for the other scenes.
// "instance" is tests/bench/instance_union.pov at N = 108 (23,328
// triangles), 160 by 120, 16 frames over clock 0 to 1.
inline Job load_job(const std::string& name, const Options& options, int count = 0) {
    const fs::path examples = fs::path(HEXANT_SOURCE_DIR) / "examples";
    language::ParseOptions parse;
    fs::path scene_file = examples / (name + ".pov");
    if (name == "instance") {
        scene_file = fs::path(HEXANT_SOURCE_DIR) / "tests" / "bench" / "instance_union.pov";
        parse.declares.emplace_back("N", "108");
        parse.animation.width = 160;
        parse.animation.height = 120;
        parse.animation.initial_frame = 1;
        parse.animation.final_frame = 16;
    } else {
        const language::IniSettings ini = language::read_ini_file(examples / (name + ".ini"));
        language::apply_ini_settings(ini, parse, scene_file);
    }
    if (count > 0) parse.declares.emplace_back("N", std::to_string(count));
    auto& a = parse.animation;
    // --size W keeps the .ini's aspect ratio.
    const std::optional<int> size = options.size    ? options.size
                                    : options.quick ? std::optional(32)
                                                    : std::nullopt;
    if (size) {
        if (*size < 1) throw std::runtime_error("--size must be at least 1");
        a.height = std::max(1, int(std::lround(double(*size) * a.height / a.width)));
        a.width = *size;
    }

    Job job;
    job.name = count > 0 ? name + " N=" + std::to_string(count) : name;
    job.scene = language::parse_scene_file(scene_file, parse);
    job.objects = job.scene.objects.size();
    const runtime::Animation& an = job.scene.animation;
    job.first = an.initial_frame;
    job.last = an.final_frame;
    const int middle = (an.initial_frame + an.final_frame) / 2;
    if (options.frames) {
        const std::string& text = *options.frames;
        const auto colon = text.find(':');
        try {
            if (colon == std::string::npos) throw std::invalid_argument(text);
            std::size_t used = 0;
            job.first = std::stoi(text.substr(0, colon), &used);
            if (used != colon) throw std::invalid_argument(text);
            job.last = std::stoi(text.substr(colon + 1), &used);
            if (used != text.size() - colon - 1) throw std::invalid_argument(text);
        } catch (const std::exception&) {
            throw std::runtime_error("--frames needs A:B, not '" + text + "'");
        }
    } else if (options.quick) {
        job.first = middle;
        job.last = std::min(middle + 1, an.final_frame);
    }
    if (job.first < an.initial_frame || job.last > an.final_frame || job.last < job.first)
        throw std::runtime_error(name + ": --frames must lie within " +
                                 std::to_string(an.initial_frame) + ":" +
                                 std::to_string(an.final_frame));
    job.error_frame = options.error_frame.value_or(
        options.frames ? (job.first + job.last) / 2 : std::clamp(middle, job.first, job.last));
    if (job.error_frame < job.first || job.error_frame > job.last)
        throw std::runtime_error(name + ": --error-frame " + std::to_string(job.error_frame) +
                                 " is not among the frames rendered");
    // Table 1 (atom) was sampled at 32 spp, Table 2's kind (bounce) at 4.
    job.spp = options.spp.value_or(options.quick ? 2 : name == "atom" ? 32 : 4);
    // (The swarm's reference at 256: 10^5 spheres at 1024 spp would take
    // longer than everything else.)
    job.reference_spp = options.reference_spp.value_or(options.quick ? 16 : count > 0 ? 256 : 1024);
    if (job.spp < 1 || job.reference_spp < 1)
        throw std::runtime_error("--spp and --reference-spp must be at least 1");
    // Up to 64, and at most a quarter of the reference's count so that its
    // own noise stays small beside the errors measured.
    for (int s = 1; s <= 64 && s * 4 <= std::max(4, job.reference_spp); s *= 2)
        job.ladder.push_back(s);
    return job;
}

// ---------------------------------------------------------------------------
// The scene as Embree takes it: moving spheres, static triangles, instances
// of still triangles under a moving transform, materials.

struct Material {
    // Solid-colour textures that do not change with time are evaluated once
    // (`fixed`); patterned ones (checker) go through hexant's TextureEvaluator
    // at every hit, so that their pattern and its transforms are hexant's.
    bool fixed = false;
    runtime::MaterialSample sample;
    std::shared_ptr<const runtime::TextureEvaluator> pattern;

    // (uv_mapping was refused when converting: no surface (u, v) here.)
    runtime::MaterialSample at(const glm::dvec3& point, double t) const {
        return fixed ? sample : pattern->at(point, glm::dvec2(0.0), t);
    }
};

// The linear part of `m` is a rotation times one scale: that scale.
inline double uniform_scale(const glm::dmat4& m, const runtime::SourcePlace& place) {
    const glm::dvec3 c0(m[0]), c1(m[1]), c2(m[2]);
    const double l0 = glm::length(c0), l1 = glm::length(c1), l2 = glm::length(c2);
    const double tolerance = 1e-9 * l0;
    if (!(l0 > 0.0) || std::fabs(l1 - l0) > tolerance || std::fabs(l2 - l0) > tolerance ||
        std::fabs(glm::dot(c0, c1)) > tolerance * l0 ||
        std::fabs(glm::dot(c0, c2)) > tolerance * l0 ||
        std::fabs(glm::dot(c1, c2)) > tolerance * l0)
        throw runtime::ObjectError(place,
                                   "a sphere whose transform is not a uniform scale cannot "
                                   "be an Embree sphere point");
    return l0;
}

struct MovingSphere {
    runtime::Vector3Function center;
    runtime::TimeFunction radius;
    runtime::Transform to_world;
    std::uint32_t material = 0;
    runtime::SourcePlace place;

    // World centre and radius at t, from hexant's own motion.
    glm::dvec4 at(double t) const {
        const glm::dmat4 m = to_world.matrix_at(t);
        const glm::dvec3 c(m * glm::dvec4(center(t), 1.0));
        return {c, radius(t) * uniform_scale(m, place)};
    }
};

struct PointLight {
    runtime::Vector3Function position;
    runtime::Transform transform;
    runtime::ColourFunction colour;
    bool shadowless = false;

    glm::dvec3 position_at(double t) const {
        const glm::dvec3 p = position(t);
        return transform.empty() ? p : glm::dvec3(transform.matrix_at(t) * glm::dvec4(p, 1.0));
    }
};

inline glm::dvec3 rgb(const runtime::ColourFunction& c, double t) {
    return {c.c[0](t), c.c[1](t), c.c[2](t)};
}

// Triangles in double, as hexant places them: hits are moved onto these
// planes, so that a checker whose square edges lie in a wall (as bounce's
// at x = -3.2 with scale 0.8) takes hexant's square, not the one the float
// plane Embree holds would give. Embree gets float copies.
struct TriangleSet {
    std::vector<glm::dvec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<std::uint32_t> triangle_material;
    std::vector<glm::dvec3> triangle_normal;  // unit
};

// A union of still triangles under a moving transform (hexant's instance,
// runtime/objects/instance_object.hpp): Embree's instance of a static scene
// of them, its transform at K+1 time steps.
struct PeerInstance {
    runtime::Transform to_world;  // the union's space to the world
    TriangleSet local;            // in the union's space
};

struct PeerScene {
    std::vector<Material> materials;
    std::vector<MovingSphere> spheres;
    TriangleSet statics;  // in the world
    std::vector<PeerInstance> instances;
    std::vector<PointLight> lights;
    const runtime::SceneDescription* scene = nullptr;
};

// Walks the records as runtime/objects/object_factory.cpp build() does: a child's
// transform, then its parent's appended; textures inherit, and a record's
// own texture maps to its parent's space.
class Converter {
  public:
    explicit Converter(const runtime::SceneDescription& scene) : scene_(scene) {
        out_.scene = &scene;
        static_time_ = scene.animation.time_begin();
    }

    PeerScene convert() {
        for (const auto& record : scene_.objects)
            add(*record, Inherited{runtime::Transform{},
                                   scene_.default_texture,
                                   std::nullopt,
                                   false,
                                   &out_.statics,
                                   {}});
        for (const auto& l : scene_.lights) {
            if (l.kind != runtime::LightKind::Point || l.area || l.parallel ||
                !l.fade_power.is_constant() || l.fade_power.constant() > 0.0)
                throw std::runtime_error(
                    "only plain point lights are supported (no spotlight, cylinder, parallel, area "
                    "light or fade)");
            out_.lights.push_back({l.position, l.transform, l.colour, l.shadowless});
        }
        return std::move(out_);
    }

  private:
    struct Inherited {
        runtime::Transform to_world;  // to the world, or inside an instance to its space
        std::optional<runtime::Texture> texture;  // in the world
        std::optional<runtime::Interior> interior;
        bool no_shadow = false;
        TriangleSet* target = nullptr;  // where its triangles go
        // Inside an instance: its space to the world (textures still go
        // there, as hexant's factory takes them).
        std::optional<runtime::Transform> placement;
    };

    // Still inside the union: no shape, transform or presence that
    // changes with time, and no sphere (the peer's spheres are points).
    static bool still_triangles(const runtime::ObjectRecord& record) {
        if (!record.lifetime.is_always() || record.transform.depends_on_time()) return false;
        if (const auto* csg = std::get_if<runtime::Csg>(&record.shape))
            return std::all_of(csg->children.begin(), csg->children.end(),
                               [](const auto& c) { return still_triangles(*c); });
        return !record.shape_depends_on_time() &&
               !std::holds_alternative<runtime::Sphere>(record.shape);
    }

    static void refuse(const runtime::ObjectRecord& record, const std::string& what) {
        throw runtime::ObjectError(record.place, std::string(runtime::shape_name(record.shape)) +
                                                     ": " + what + " (not in the Embree peer)");
    }

    static bool is_zero(const runtime::TimeFunction& f) {
        return f.is_constant() && f.constant() == 0.0;
    }

    std::uint32_t add_material(const runtime::Texture& texture,
                               const std::optional<runtime::Interior>& interior,
                               const runtime::ObjectRecord& record) {
        if (texture.is_patterned() || !texture.below.empty())
            refuse(record, "texture_map or layered texture");
        if (texture.normal) refuse(record, "normal { }");
        if (texture.uv_mapping != runtime::UvMapping::Off ||
            texture.pigment.uv_mapping != runtime::UvMapping::Off)
            refuse(record, "uv_mapping");
        for (int k = 0; k < 3; ++k)
            if (!is_zero(texture.finish->reflection.c[k])) refuse(record, "reflection");
        for (const auto& colour : texture.pigment.colours)
            if (!is_zero(colour.c[3]) || !is_zero(colour.c[4]))
                refuse(record, "filter or transmit (refraction)");
        auto evaluator = std::make_shared<runtime::TextureEvaluator>(texture, interior);
        Material m;
        m.fixed = texture.pigment.pattern == runtime::Pigment::Pattern::Solid &&
                  !evaluator->depends_on_time();
        if (m.fixed) m.sample = evaluator->at(glm::dvec3(0.0), glm::dvec2(0.0), static_time_);
        m.pattern = std::move(evaluator);
        out_.materials.push_back(std::move(m));
        return std::uint32_t(out_.materials.size() - 1);
    }

    void add(const runtime::ObjectRecord& record, const Inherited& parent) {
        runtime::Transform to_world = record.transform;
        to_world.append(parent.to_world);
        std::optional<runtime::Texture> texture = parent.texture;
        if (record.texture) {
            texture = *record.texture;
            texture->transform_by(parent.to_world);
            if (parent.placement) texture->transform_by(*parent.placement);
        }
        const std::optional<runtime::Interior> interior =
            record.interior ? record.interior.optional() : parent.interior;
        const bool no_shadow = record.no_shadow || parent.no_shadow;
        if (no_shadow) refuse(record, "no_shadow");
        if (record.inverse) refuse(record, "inverse");
        if (to_world.has_deformation()) refuse(record, "twist, taper or bend");

        if (const auto* csg = std::get_if<runtime::Csg>(&record.shape)) {
            if (csg->kind != runtime::Csg::Kind::Union) refuse(record, "CSG other than union");
            Inherited down{to_world, texture, interior, no_shadow, parent.target, parent.placement};
            // (As hexant's factory: a moving union of still members is
            // one instance, however many; the rest as its rules.)
            if (!parent.placement && to_world.depends_on_time() && !to_world.has_deformation() &&
                std::all_of(csg->children.begin(), csg->children.end(),
                            [](const auto& c) { return still_triangles(*c); })) {
                out_.instances.push_back({to_world, {}});
                down.to_world = runtime::Transform{};
                down.placement = to_world;
                down.target = &out_.instances.back().local;
            }
            for (const auto& child : csg->children) add(*child, down);
            return;
        }
        const std::uint32_t material = add_material(*texture, interior, record);
        TriangleSet& target = *parent.target;
        if (const auto* sphere = std::get_if<runtime::Sphere>(&record.shape)) {
            MovingSphere s{sphere->center, sphere->radius, to_world, material, record.place};
            s.at(static_time_);  // refuses a non-uniform scale now, not mid-render
            out_.spheres.push_back(std::move(s));
            return;
        }
        // Everything else is a static triangle mesh.
        if (record.shape_depends_on_time() || to_world.depends_on_time())
            refuse(record, "a moving polygon, box or prism");
        const glm::dmat4 m = to_world.matrix_at(static_time_);
        const auto world = [&](const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); };
        if (const auto* triangle = std::get_if<runtime::Triangle>(&record.shape)) {
            std::vector<glm::dvec3> corners;
            for (const auto& p : triangle->points) corners.push_back(world(p(static_time_)));
            if (!(glm::length(glm::cross(corners[1] - corners[0], corners[2] - corners[0])) > 0.0))
                return;  // (hexant drops a degenerate triangle too)
            add_convex_fan(corners, material, record, target);
        } else if (const auto* polygon = std::get_if<runtime::Polygon>(&record.shape)) {
            std::vector<glm::dvec3> points;
            for (const auto& p : polygon->points) points.push_back(p(static_time_));
            std::vector<glm::dvec3> outline = one_outline(points, record);
            for (auto& p : outline) p = world(p);
            add_convex_fan(outline, material, record, target);
        } else if (const auto* prism = std::get_if<runtime::Prism>(&record.shape)) {
            std::vector<glm::dvec3> points;  // <x, z> as (x, 0, z)
            for (const auto& p : prism->points)
                points.emplace_back(p.c[0](static_time_), 0.0, p.c[1](static_time_));
            const std::vector<glm::dvec3> outline = one_outline(points, record);
            const double h1 = prism->height1(static_time_), h2 = prism->height2(static_time_);
            std::vector<glm::dvec3> bottom, top;
            for (const auto& p : outline) {
                bottom.push_back(world({p.x, h1, p.z}));
                top.push_back(world({p.x, h2, p.z}));
            }
            const std::size_t n = outline.size();
            for (std::size_t i = 0; i < n; ++i) {
                const std::size_t j = (i + 1) % n;
                add_convex_fan({bottom[i], bottom[j], top[j], top[i]}, material, record, target);
            }
            if (!prism->open) {
                add_convex_fan(bottom, material, record, target);
                add_convex_fan(top, material, record, target);
            }
        } else if (const auto* box = std::get_if<runtime::Box>(&record.shape)) {
            const glm::dvec3 a = box->corner1(static_time_), b = box->corner2(static_time_);
            const glm::dvec3 lo = glm::min(a, b), hi = glm::max(a, b);
            const auto corner = [&](int i) {
                return world({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
            };
            static constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                                 {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
            for (const auto& f : kFaces)
                add_convex_fan({corner(f[0]), corner(f[1]), corner(f[2]), corner(f[3])}, material,
                               record, target);
        } else if (const auto* plane = std::get_if<runtime::Plane>(&record.shape)) {
            // An unbounded plane as one square of side 2 kPlaneHalf centred
            // on its point nearest the origin (as hexant places it: the
            // normal scaled to unit length, times the distance). The
            // swarm's camera sees its floor within about 120 units and its
            // shadow rays leave the floor upwards, so the edges never show.
            constexpr double kPlaneHalf = 1e4;
            const glm::dvec3 normal = plane->normal(static_time_);
            const double length = glm::length(normal);
            if (!(length > 0.0)) refuse(record, "a plane without a normal");
            const glm::dvec3 n = normal / length;
            const glm::dvec3 u = glm::normalize(
                glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
            const glm::dvec3 v = glm::cross(n, u);
            const glm::dvec3 p0 = n * plane->distance(static_time_);
            add_convex_fan({world(p0 - kPlaneHalf * u - kPlaneHalf * v),
                            world(p0 + kPlaneHalf * u - kPlaneHalf * v),
                            world(p0 + kPlaneHalf * u + kPlaneHalf * v),
                            world(p0 - kPlaneHalf * u + kPlaneHalf * v)},
                           material, record, target);
        } else {
            refuse(record, "this shape");
        }
    }

    // POV-Ray's point list as one closed outline (an outline closes where a
    // point repeats its first one; repeated neighbours are dropped).
    static std::vector<glm::dvec3> one_outline(const std::vector<glm::dvec3>& points,
                                               const runtime::ObjectRecord& record) {
        std::vector<glm::dvec3> outline;
        std::size_t i = 0;
        for (; i < points.size(); ++i) {
            if (i > 0 && points[i] == points[0]) break;
            if (outline.empty() || points[i] != outline.back()) outline.push_back(points[i]);
        }
        if (i + 1 < points.size()) refuse(record, "more than one outline");
        if (outline.size() < 3) refuse(record, "fewer than three distinct points");
        return outline;
    }

    // A convex planar outline as a fan of triangles.
    void add_convex_fan(const std::vector<glm::dvec3>& outline, std::uint32_t material,
                        const runtime::ObjectRecord& record, TriangleSet& out) {
        const std::size_t n = outline.size();
        glm::dvec3 normal(0.0);  // Newell's
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec3& a = outline[i];
            const glm::dvec3& b = outline[(i + 1) % n];
            normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                                 (a.x - b.x) * (a.y + b.y));
        }
        double extent = 0.0;
        for (const auto& p : outline) extent = std::max(extent, glm::length(p - outline[0]));
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec3 e0 = outline[(i + 1) % n] - outline[i];
            const glm::dvec3 e1 = outline[(i + 2) % n] - outline[(i + 1) % n];
            const glm::dvec3 turn = glm::cross(e0, e1);
            if (glm::dot(turn, normal) < -1e-9 * glm::length(turn) * glm::length(normal))
                refuse(record, "a concave outline");
            if (std::fabs(glm::dot(outline[i] - outline[0], normal)) >
                1e-9 * extent * glm::length(normal))
                refuse(record, "an outline not in one plane");
        }
        const auto base = std::uint32_t(out.vertices.size());
        for (const auto& p : outline) out.vertices.push_back(p);
        for (std::uint32_t i = 1; i + 1 < n; ++i) {
            const glm::dvec3& v0 = outline[0];
            const glm::dvec3 c = glm::cross(outline[i] - v0, outline[i + 1] - v0);
            if (!(glm::length(c) > 0.0)) continue;  // collinear points
            out.triangles.push_back({base, base + i, base + i + 1});
            out.triangle_material.push_back(material);
            out.triangle_normal.push_back(glm::normalize(c));
        }
    }

    const runtime::SceneDescription& scene_;
    PeerScene out_;
    double static_time_ = 0.0;
};

}  // namespace hexant_embree_peer
