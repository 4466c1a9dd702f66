// hexant_embree_peer: a peer benchmark against Embree 3's multi-segment
// motion blur (issue 15).
//
// What it measures. For examples/atom.pov and examples/bounce.pov (with
// their .ini files), in one process and one run:
//   - hexant, spacetime mode and frames mode, rendered through hexant's own
//     library (tracer::Renderer, its own Owen-scrambled Sobol' samples);
//   - Embree 3, one scene ("one motion BVH") per frame, every moving sphere
//     a RTC_GEOMETRY_TYPE_SPHERE_POINT with K+1 time steps (K = 2, 4, 8
//     linear motion segments over the frame's shutter), the static polygons,
//     boxes and prism as one triangle mesh of one time step; build quality
//     RTC_BUILD_QUALITY_MEDIUM; single rays (rtcIntersect1, rtcOccluded1),
//     16x16 tiles in parallel with oneTBB as hexant's renderer does.
// For each: build time, render time, rays (primary + shadow) per second,
// and the RMSE (linear light, all three channels) of one frame (the middle
// one by default) against a hexant spacetime reference of that frame at
// --reference-spp (1024) with an independent scramble (sample_seed 1). For
// atom, also a time-to-error table of that frame: hexant spacetime and
// Embree K=4 at 1, 2, 4, ..., 64 spp.
//
// Run it (built only where libembree-dev is installed; `make bench` does
// all of it):
//   build/tests/bench/hexant_embree_peer [--scene atom|bounce|all] [--spp N]
//       [--frames A:B] [--size W] [--reference-spp N] [--error-frame K]
//       [--threads N] [--quick] [--write-images DIR]
//
// What compares and what does not:
//   - The work is the same: the same camera rays through the same pixels,
//     the same shading (POV-Ray's finish as tracer/shader.cpp: ambient,
//     diffuse with brilliance, phong, specular, hard shadows; shadowless
//     lights are fill lights), one shadow ray per sample and light.
//   - The samples differ. hexant uses its Owen-scrambled Sobol' points over
//     (pixel x, pixel y, time). Embree gets a plain, typical choice:
//     stratified jitter in the pixel (a sqrt(spp) x sqrt(spp) grid when spp
//     is a square, else N rooks) and an independent uniform time per sample
//     from PCG32 seeded by (frame, pixel); deterministic. So at equal spp the
//     errors differ by the sampling too, not only by the geometry.
//   - The motion differs. hexant intersects its exact motion at each ray's
//     time; Embree's spheres move along K linear segments per frame through
//     centres and radii that hexant evaluates exactly at the K+1 instants,
//     in single precision. Embree's images are therefore not hexant's: the
//     RMSE holds that bias besides the noise (it shrinks as K grows).
//   - Precision: Embree's rays and geometry are float. Its hit is moved onto
//     the surface in double (a triangle's plane as hexant places it, so that
//     checker squares whose edges lie in a wall fall as in hexant; a sphere
//     at the ray's time, interpolated as Embree interpolates), and the
//     shadow ray starts at the offset of Ray Tracing Gems ch. 6. hexant's
//     runtime/geometry/offset_ray.hpp is that offset for double (256 double
//     ulps); Embree rounds the start to float, which undoes it, so the same
//     method runs here at float precision with the paper's own constants.
//   - Build time: hexant's is its counters' (the sweeps and the lazy cells
//     as rays reach them, summed over threads, as `render --compare`
//     prints); Embree's is per frame: evaluating the sphere motion at K+1
//     instants, filling the buffers and rtcCommitScene. The wall column is
//     measured around everything each row does.
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

namespace {

namespace fs = std::filesystem;
using namespace hexant;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
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
};

// One scene as the benchmark runs it, everything resolved.
struct Job {
    std::string name;
    runtime::SceneDescription scene;
    int first = 1, last = 1;  // frames rendered
    int error_frame = 1;
    int spp = 1, reference_spp = 1024;
    std::vector<int> ladder;  // spp of the time-to-error table
};

Job load_job(const std::string& name, const Options& options) {
    const fs::path examples = fs::path(HEXANT_SOURCE_DIR) / "examples";
    language::ParseOptions parse;
    fs::path scene_file = examples / (name + ".pov");
    const language::IniSettings ini = language::read_ini_file(examples / (name + ".ini"));
    language::apply_ini_settings(ini, parse, scene_file);
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
    job.name = name;
    job.scene = language::parse_scene_file(scene_file, parse);
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
    job.reference_spp = options.reference_spp.value_or(options.quick ? 16 : 1024);
    if (job.spp < 1 || job.reference_spp < 1)
        throw std::runtime_error("--spp and --reference-spp must be at least 1");
    // Up to 64, and at most a quarter of the reference's count so that its
    // own noise stays small beside the errors measured.
    for (int s = 1; s <= 64 && s * 4 <= std::max(4, job.reference_spp); s *= 2)
        job.ladder.push_back(s);
    return job;
}

// ---------------------------------------------------------------------------
// The scene as Embree takes it: moving spheres, static triangles, materials.

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
double uniform_scale(const glm::dmat4& m, const runtime::SourcePlace& place) {
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

glm::dvec3 rgb(const runtime::ColourFunction& c, double t) {
    return {c.c[0](t), c.c[1](t), c.c[2](t)};
}

struct PeerScene {
    std::vector<Material> materials;
    std::vector<MovingSphere> spheres;
    // World space in double, as hexant places them: hits are moved onto
    // these planes, so that a checker whose square edges lie in a wall (as
    // bounce's at x = -3.2 with scale 0.8) takes hexant's square, not the one
    // the float plane Embree holds would give. Embree gets float copies.
    std::vector<glm::dvec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<std::uint32_t> triangle_material;
    std::vector<glm::dvec3> triangle_normal;  // unit
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
            add(*record,
                Inherited{runtime::Transform{}, scene_.default_texture, std::nullopt, false});
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
        runtime::Transform to_world;
        std::optional<runtime::Texture> texture;
        std::optional<runtime::Interior> interior;
        bool no_shadow = false;
    };

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
            if (!is_zero(texture.finish.reflection.c[k])) refuse(record, "reflection");
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
        }
        const auto interior = record.interior ? record.interior : parent.interior;
        const bool no_shadow = record.no_shadow || parent.no_shadow;
        if (no_shadow) refuse(record, "no_shadow");
        if (record.inverse) refuse(record, "inverse");
        if (to_world.has_deformation()) refuse(record, "twist, taper or bend");

        if (const auto* csg = std::get_if<runtime::Csg>(&record.shape)) {
            if (csg->kind != runtime::Csg::Kind::Union) refuse(record, "CSG other than union");
            const Inherited down{to_world, texture, interior, no_shadow};
            for (const auto& child : csg->children) add(*child, down);
            return;
        }
        const std::uint32_t material = add_material(*texture, interior, record);
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
        if (const auto* polygon = std::get_if<runtime::Polygon>(&record.shape)) {
            std::vector<glm::dvec3> points;
            for (const auto& p : polygon->points) points.push_back(p(static_time_));
            std::vector<glm::dvec3> outline = one_outline(points, record);
            for (auto& p : outline) p = world(p);
            add_convex_fan(outline, material, record);
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
                add_convex_fan({bottom[i], bottom[j], top[j], top[i]}, material, record);
            }
            if (!prism->open) {
                add_convex_fan(bottom, material, record);
                add_convex_fan(top, material, record);
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
                               record);
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
                        const runtime::ObjectRecord& record) {
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
        const auto base = std::uint32_t(out_.vertices.size());
        for (const auto& p : outline) out_.vertices.push_back(p);
        for (std::uint32_t i = 1; i + 1 < n; ++i) {
            const glm::dvec3& v0 = outline[0];
            const glm::dvec3 c = glm::cross(outline[i] - v0, outline[i + 1] - v0);
            if (!(glm::length(c) > 0.0)) continue;  // collinear points
            out_.triangles.push_back({base, base + i, base + i + 1});
            out_.triangle_material.push_back(material);
            out_.triangle_normal.push_back(glm::normalize(c));
        }
    }

    const runtime::SceneDescription& scene_;
    PeerScene out_;
    double static_time_ = 0.0;
};

// ---------------------------------------------------------------------------
// Embree: one scene per frame.

// Ray Tracing Gems ch. 6 (Wachter and Binder) at float precision, with the
// paper's constants: hexant's runtime/geometry/offset_ray.hpp is the same
// method for double, whose step (256 double ulps) rounding the start to
// float for Embree would undo.
glm::vec3 offset_ray_float(const glm::vec3& p, const glm::vec3& n) {
    constexpr float kOrigin = 1.0f / 32.0f, kFloatScale = 1.0f / 65536.0f, kIntScale = 256.0f;
    glm::vec3 out;
    for (int k = 0; k < 3; ++k) {
        if (std::fabs(p[k]) < kOrigin) {
            out[k] = p[k] + kFloatScale * n[k];
            continue;
        }
        const auto step = static_cast<std::int32_t>(kIntScale * n[k]);
        const auto bits = std::bit_cast<std::int32_t>(p[k]);
        const float moved = std::bit_cast<float>(p[k] < 0.0f ? bits - step : bits + step);
        out[k] = std::isfinite(moved) ? moved : p[k];
    }
    return out;
}

void embree_error(void*, RTCError code, const char* message) {
    std::fprintf(stderr, "embree error %d: %s\n", int(code), message ? message : "");
}

// Embree sets itself up on its first commit (tens of milliseconds); a first
// scene of one moving sphere point keeps that out of the first row.
void warm_up(RTCDevice device) {
    RTCScene scene = rtcNewScene(device);
    RTCGeometry points = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    rtcSetGeometryTimeStepCount(points, 2);
    for (unsigned j = 0; j < 2; ++j) {
        auto* p = static_cast<float*>(rtcSetNewGeometryBuffer(
            points, RTC_BUFFER_TYPE_VERTEX, j, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
        p[0] = float(j), p[1] = 0.0f, p[2] = 0.0f, p[3] = 1.0f;
    }
    rtcCommitGeometry(points);
    rtcAttachGeometry(scene, points);
    rtcReleaseGeometry(points);
    rtcCommitScene(scene);
    rtcReleaseScene(scene);
}

class EmbreeFrame {
  public:
    // Geometry over the shutter of `frame`: ray time 0..1 is [open, open +
    // shutter * clock_delta], the K+1 time steps at open + j/K of it.
    EmbreeFrame(RTCDevice device, const PeerScene& peer, int frame, int segments)
        : peer_(peer), segments_(segments) {
        const runtime::Animation& a = peer.scene->animation;
        open_ = a.clock_of_frame(frame);
        length_ = a.shutter * a.clock_delta();
        scene_ = rtcNewScene(device);
        rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_MEDIUM);
        if (!peer.triangles.empty()) {
            RTCGeometry mesh = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* v = static_cast<float*>(
                rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                        3 * sizeof(float), peer.vertices.size()));
            for (std::size_t i = 0; i < peer.vertices.size(); ++i)
                for (int k = 0; k < 3; ++k) v[3 * i + k] = float(peer.vertices[i][k]);
            auto* index = static_cast<std::uint32_t*>(
                rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                        3 * sizeof(std::uint32_t), peer.triangles.size()));
            for (std::size_t i = 0; i < peer.triangles.size(); ++i)
                for (int k = 0; k < 3; ++k) index[3 * i + k] = peer.triangles[i][k];
            rtcSetGeometryBuildQuality(mesh, RTC_BUILD_QUALITY_MEDIUM);
            rtcCommitGeometry(mesh);
            mesh_id_ = rtcAttachGeometry(scene_, mesh);
            rtcReleaseGeometry(mesh);
        }
        if (!peer.spheres.empty()) {
            RTCGeometry points = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            rtcSetGeometryTimeStepCount(points, unsigned(segments + 1));
            rtcSetGeometryTimeRange(points, 0.0f, 1.0f);
            for (int j = 0; j <= segments; ++j) {
                auto* p = static_cast<float*>(rtcSetNewGeometryBuffer(
                    points, RTC_BUFFER_TYPE_VERTEX, unsigned(j), RTC_FORMAT_FLOAT4,
                    4 * sizeof(float), peer.spheres.size()));
                const double t = open_ + length_ * double(j) / segments;
                for (std::size_t i = 0; i < peer.spheres.size(); ++i) {
                    const glm::dvec4 s = peer.spheres[i].at(t);
                    for (int k = 0; k < 4; ++k) p[4 * i + k] = float(s[k]);
                }
                steps_.push_back(p);
            }
            rtcSetGeometryBuildQuality(points, RTC_BUILD_QUALITY_MEDIUM);
            rtcCommitGeometry(points);
            sphere_id_ = rtcAttachGeometry(scene_, points);
            rtcReleaseGeometry(points);
        }
        rtcCommitScene(scene_);
        if (const RTCError e = rtcGetDeviceError(device); e != RTC_ERROR_NONE)
            throw std::runtime_error("Embree failed to build frame " + std::to_string(frame) +
                                     " (error " + std::to_string(int(e)) + ")");
    }
    ~EmbreeFrame() { rtcReleaseScene(scene_); }
    EmbreeFrame(const EmbreeFrame&) = delete;
    EmbreeFrame& operator=(const EmbreeFrame&) = delete;

    // The colour seen along a primary ray at shutter fraction `time`.
    glm::dvec3 trace(const glm::dvec3& origin, const glm::dvec3& d, float time,
                     std::uint64_t& rays) const;

  private:
    // Sphere `i` at ray time `time`, as Embree interpolates its time steps.
    glm::dvec4 sphere_at(std::uint32_t i, float time) const {
        const float f = time * float(segments_);
        const int j = std::clamp(int(std::floor(f)), 0, segments_ - 1);
        const double u = double(f) - j;
        const float* a = steps_[j] + 4 * i;
        const float* b = steps_[j + 1] + 4 * i;
        glm::dvec4 s;
        for (int k = 0; k < 4; ++k) s[k] = (1.0 - u) * a[k] + u * b[k];
        return s;
    }

    const PeerScene& peer_;
    int segments_;
    double open_ = 0.0, length_ = 0.0;
    RTCScene scene_ = nullptr;
    unsigned mesh_id_ = RTC_INVALID_GEOMETRY_ID, sphere_id_ = RTC_INVALID_GEOMETRY_ID;
    std::vector<const float*> steps_;  // Embree's own buffers, one per time step
};

glm::dvec3 EmbreeFrame::trace(const glm::dvec3& origin, const glm::dvec3& d, float time,
                              std::uint64_t& rays) const {
    const runtime::SceneDescription& scene = *peer_.scene;
    const double t = open_ + double(time) * length_;
    ++rays;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    const glm::vec3 of(origin), df(d);
    rh.ray.org_x = of.x, rh.ray.org_y = of.y, rh.ray.org_z = of.z;
    rh.ray.dir_x = df.x, rh.ray.dir_y = df.y, rh.ray.dir_z = df.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.time = time;
    rh.ray.mask = ~0u;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return rgb(scene.background, t);

    // Embree's float hit, moved onto the surface in double: a triangle's
    // plane as hexant places it (Embree's float plane lies within half a
    // float ulp of it, far inside the shadow ray's offset), a sphere at the
    // ray's time as Embree interpolates it.
    const glm::dvec3 rough = glm::dvec3(of) + double(rh.ray.tfar) * glm::dvec3(df);
    glm::dvec3 point, geometric;
    std::uint32_t material;
    if (rh.hit.geomID == sphere_id_) {
        const glm::dvec4 s = sphere_at(rh.hit.primID, time);
        const glm::dvec3 centre(s);
        geometric = glm::normalize(rough - centre);
        point = centre + s.w * geometric;
        material = peer_.spheres[rh.hit.primID].material;
    } else {
        geometric = peer_.triangle_normal[rh.hit.primID];
        const glm::dvec3& v0 = peer_.vertices[peer_.triangles[rh.hit.primID][0]];
        point = rough - glm::dot(rough - v0, geometric) * geometric;
        material = peer_.triangle_material[rh.hit.primID];
    }
    // Lighting uses the normal on the viewer's side, as tracer/shader.cpp.
    if (glm::dot(geometric, d) > 0.0) geometric = -geometric;
    const glm::dvec3& n = geometric;
    const runtime::MaterialSample m = peer_.materials[material].at(point, t);
    // Filter and transmit were refused when converting: opaque is 1.
    glm::dvec3 colour = m.colour * (m.ambient * rgb(scene.global.ambient_light, t) + m.emission);

    const glm::vec3 start = offset_ray_float(glm::vec3(point), glm::vec3(n));
    for (const PointLight& light : peer_.lights) {
        const glm::dvec3 light_position = light.position_at(t);
        glm::dvec3 to_light = light_position - point;
        const double distance = glm::length(to_light);
        if (!(distance > 0.0)) continue;
        to_light /= distance;
        const double cosine = glm::dot(n, to_light);
        if (cosine <= 0.0) continue;
        if (!light.shadowless) {
            ++rays;
            RTCRay shadow;
            const glm::vec3 lf(to_light);
            shadow.org_x = start.x, shadow.org_y = start.y, shadow.org_z = start.z;
            shadow.dir_x = lf.x, shadow.dir_y = lf.y, shadow.dir_z = lf.z;
            shadow.tnear = 0.0f;
            shadow.tfar = float(glm::length(light_position - glm::dvec3(start)));
            shadow.time = time;
            shadow.mask = ~0u;
            shadow.id = 0;
            shadow.flags = 0;
            rtcOccluded1(scene_, &context, &shadow);
            if (shadow.tfar < 0.0f) continue;  // Embree's mark for "occluded"
        }
        const glm::dvec3 light_colour = rgb(light.colour, t);
        glm::dvec3 lit = m.diffuse * std::pow(cosine, m.brilliance) * m.colour;
        // Shadowless lights are POV-Ray's fill lights: no highlights.
        if (m.phong > 0.0 && !light.shadowless) {
            const glm::dvec3 reflected = d - 2.0 * glm::dot(d, n) * n;
            const double c = glm::dot(reflected, to_light);
            if (c > 0.0) lit += glm::dvec3(m.phong * std::pow(c, m.phong_size));
        }
        if (m.specular > 0.0 && !light.shadowless) {
            const glm::dvec3 half = glm::normalize(to_light - d);
            const double c = glm::dot(half, n);
            if (c > 0.0) lit += glm::dvec3(m.specular * std::pow(c, 1.0 / m.roughness));
        }
        colour += lit * light_colour;
    }
    return colour;
}

// PCG32 (O'Neill), the XSH-RR variant.
class Pcg32 {
  public:
    Pcg32(std::uint64_t seed, std::uint64_t stream) : inc_((stream << 1) | 1u) {
        next();
        state_ += seed;
        next();
    }
    std::uint32_t next() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        const auto xorshifted = std::uint32_t(((old >> 18) ^ old) >> 27);
        const auto rot = std::uint32_t(old >> 59);
        return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
    }
    double uniform() { return next() * 0x1p-32; }                    // [0, 1)
    float uniform_float() { return float(next() >> 8) * 0x1p-24f; }  // [0, 1) in float

  private:
    std::uint64_t state_ = 0, inc_;
};

std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

struct JitterSample {
    double x, y;  // in the pixel
    float time;   // in the shutter
};

// Stratified jitter: an m x m grid when spp = m^2, else N rooks (a sample
// in each column and each row of an N x N grid, rows shuffled); a uniform
// time of its own per sample.
void jitter_samples(int frame, int x, int y, int spp, std::vector<JitterSample>& out,
                    std::vector<int>& rows) {
    Pcg32 rng(splitmix64((std::uint64_t(std::uint32_t(frame)) << 40) ^
                         (std::uint64_t(std::uint32_t(y)) << 20) ^ std::uint64_t(std::uint32_t(x))),
              0x68657861ull);
    out.resize(std::size_t(spp));
    const int m = int(std::lround(std::sqrt(double(spp))));
    if (m * m == spp) {
        for (int i = 0; i < spp; ++i) {
            out[i].x = (i % m + rng.uniform()) / m;
            out[i].y = (i / m + rng.uniform()) / m;
            out[i].time = rng.uniform_float();
        }
        return;
    }
    rows.resize(std::size_t(spp));
    for (int i = 0; i < spp; ++i) rows[i] = i;
    for (int i = spp - 1; i > 0; --i) std::swap(rows[i], rows[rng.next() % std::uint32_t(i + 1)]);
    for (int i = 0; i < spp; ++i) {
        out[i].x = (i + rng.uniform()) / spp;
        out[i].y = (rows[i] + rng.uniform()) / spp;
        out[i].time = rng.uniform_float();
    }
}

tracer::Image render_embree_frame(const PeerScene& peer, const EmbreeFrame& embree, int frame,
                                  int spp, std::uint64_t& rays) {
    const runtime::SceneDescription& scene = *peer.scene;
    const runtime::Animation& a = scene.animation;
    const double open = a.clock_of_frame(frame);
    const double length = a.shutter * a.clock_delta();
    const int width = a.width, height = a.height;
    const bool moving_camera = scene.camera.depends_on_time();
    const runtime::CameraFrame fixed_camera = scene.camera.evaluate(open);
    tracer::Image image(width, height);
    std::atomic<std::uint64_t> total{0};
    constexpr int kTile = 16;
    tbb::parallel_for(
        tbb::blocked_range2d<int>(0, height, kTile, 0, width, kTile),
        [&](const tbb::blocked_range2d<int>& tile) {
            thread_local std::vector<JitterSample> samples;
            thread_local std::vector<int> rows;
            std::uint64_t tile_rays = 0;
            for (int y = tile.rows().begin(); y < tile.rows().end(); ++y) {
                for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) {
                    jitter_samples(frame, x, y, spp, samples, rows);
                    glm::dvec3 sum(0.0);
                    for (const JitterSample& s : samples) {
                        const runtime::CameraFrame camera =
                            moving_camera ? scene.camera.evaluate(open + s.time * length)
                                          : fixed_camera;
                        // The screen as tracer/renderer.cpp makes it.
                        const double u = (x + s.x) / width - 0.5;
                        const double v = 0.5 - (y + s.y) / height;
                        const glm::dvec3 d =
                            glm::normalize(camera.direction + u * camera.right + v * camera.up);
                        sum += embree.trace(camera.location, d, s.time, tile_rays);
                    }
                    image.set(x, y, sum / double(spp));
                }
            }
            total += tile_rays;
        });
    rays += total;
    return image;
}

// ---------------------------------------------------------------------------
// Measuring

double rmse(const tracer::Image& image, const tracer::Image& reference) {
    if (image.width != reference.width || image.height != reference.height)
        throw std::logic_error("rmse: images differ in size");
    double sum = 0.0;
    for (std::size_t i = 0; i < image.rgb.size(); ++i) {
        const double e = double(image.rgb[i]) - double(reference.rgb[i]);
        sum += e * e;
    }
    return std::sqrt(sum / double(std::max<std::size_t>(1, image.rgb.size())));
}

struct Row {
    std::string method;
    double build = 0.0, render = 0.0, wall = 0.0;
    std::uint64_t rays = 0;
    double rmse = 0.0;
    tracer::Image error_image;
};

Row run_hexant(const Job& job, tracer::Mode mode, int spp, int first, int last, int threads) {
    Row row;
    row.method = std::string("hexant ") + tracer::mode_name(mode);
    const auto start = Clock::now();
    tracer::RenderSettings settings;
    settings.mode = mode;
    settings.samples_per_pixel = spp;
    settings.threads = threads;
    settings.first_frame = first;  // the hierarchy spans these frames' time
    settings.last_frame = last;
    tracer::Renderer renderer(job.scene, settings);
    for (int f = first; f <= last; ++f) {
        tracer::Image image = renderer.render_frame(f);
        if (f == job.error_frame) row.error_image = std::move(image);
    }
    row.wall = seconds_since(start);
    const tracer::Counters& c = renderer.counters();
    row.build = c.build_seconds;
    row.render = c.render_seconds;
    row.rays = c.rays();
    return row;
}

Row run_embree(const Job& job, const PeerScene& peer, RTCDevice device, int segments, int spp,
               int first, int last) {
    Row row;
    row.method = "embree K=" + std::to_string(segments);
    const auto start = Clock::now();
    for (int f = first; f <= last; ++f) {
        const auto build_start = Clock::now();
        const EmbreeFrame frame(device, peer, f, segments);
        row.build += seconds_since(build_start);
        const auto render_start = Clock::now();
        tracer::Image image = render_embree_frame(peer, frame, f, spp, row.rays);
        row.render += seconds_since(render_start);
        if (f == job.error_frame) row.error_image = std::move(image);
    }
    row.wall = seconds_since(start);
    return row;
}

std::string thousands(std::uint64_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

void print_table(const Job& job, const std::vector<Row>& rows) {
    std::printf("  %-17s %9s %9s %9s %9s %14s %8s %14s\n", "method", "build s", "render s",
                "total s", "wall s", "rays", "Mrays/s",
                ("RMSE(frame " + std::to_string(job.error_frame) + ")").c_str());
    for (const Row& r : rows)
        std::printf("  %-17s %9.3f %9.3f %9.3f %9.3f %14s %8.2f %14.4e\n", r.method.c_str(),
                    r.build, r.render, r.build + r.render, r.wall, thousands(r.rays).c_str(),
                    r.render > 0.0 ? double(r.rays) / r.render * 1e-6 : 0.0, r.rmse);
}

// Time to reach `error` along a curve of (time, error) points, by log-log
// interpolation between neighbours (as `hexant bench error-time`).
std::optional<double> time_to_reach(const std::vector<std::pair<double, double>>& curve,
                                    double error) {
    for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
        const auto [t0, e0] = curve[i];
        const auto [t1, e1] = curve[i + 1];
        if ((e0 >= error && error >= e1) || (e1 >= error && error >= e0)) {
            if (e0 == e1) return t0;
            const double f = std::log(error / e0) / std::log(e1 / e0);
            return std::exp(std::log(t0) + f * std::log(t1 / t0));
        }
    }
    if (!curve.empty() && curve.front().second <= error) return curve.front().first;
    return std::nullopt;
}

void time_to_error(const Job& job, const PeerScene& peer, RTCDevice device,
                   const tracer::Image& reference, int threads) {
    constexpr int kSegments = 4;
    std::printf("\n%s, frame %d: time to error, one frame (%dx%d), against the %d-spp reference\n",
                job.name.c_str(), job.error_frame, job.scene.animation.width,
                job.scene.animation.height, job.reference_spp);
    std::printf(
        "  hexant spacetime: a new Renderer per count, over that frame's time: build + render;\n"
        "  embree K=%d: that frame's scene build + render.\n",
        kSegments);
    std::printf("  %5s %18s %12s %16s %12s\n", "spp", "hexant spacetime s", "RMSE",
                ("embree K=" + std::to_string(kSegments) + " s").c_str(), "RMSE");
    std::vector<std::pair<double, double>> hexant_curve, embree_curve;
    for (const int spp : job.ladder) {
        const Row h = run_hexant(job, tracer::Mode::Spacetime, spp, job.error_frame,
                                 job.error_frame, threads);
        const Row e =
            run_embree(job, peer, device, kSegments, spp, job.error_frame, job.error_frame);
        const double he = rmse(h.error_image, reference), ee = rmse(e.error_image, reference);
        hexant_curve.emplace_back(h.build + h.render, he);
        embree_curve.emplace_back(e.build + e.render, ee);
        std::printf("  %5d %18.4f %12.4e %16.4f %12.4e\n", spp, h.build + h.render, he,
                    e.build + e.render, ee);
    }
    const auto at = std::find(job.ladder.begin(), job.ladder.end(), 32);
    const std::size_t i =
        at != job.ladder.end() ? std::size_t(at - job.ladder.begin()) : job.ladder.size() - 1;
    const auto [embree_time, embree_error] = embree_curve[i];
    std::printf("  embree K=%d at %d spp: RMSE %.4e in %.4f s; ", kSegments, job.ladder[i],
                embree_error, embree_time);
    if (const auto t = time_to_reach(hexant_curve, embree_error))
        std::printf("hexant spacetime reaches it in %.4f s (%.2f times embree's time)\n", *t,
                    *t / embree_time);
    else
        std::printf("hexant spacetime does not reach it within %d spp\n", job.ladder.back());
    const auto [hexant_time, hexant_error] = hexant_curve[i];
    std::printf("  hexant spacetime at %d spp: RMSE %.4e in %.4f s; ", job.ladder[i], hexant_error,
                hexant_time);
    if (const auto t = time_to_reach(embree_curve, hexant_error))
        std::printf("embree K=%d reaches it in %.4f s (%.2f times hexant's time)\n", kSegments, *t,
                    *t / hexant_time);
    else
        std::printf("embree K=%d does not reach it within %d spp\n", kSegments, job.ladder.back());
}

// The first three fields of /proc/loadavg: on a shared machine the times
// mean little without them.
std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    if (!(in >> one >> five >> fifteen)) return "unknown";
    return one + " " + five + " " + fifteen;
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("model name", 0) != 0) continue;
        const auto colon = line.find(':');
        if (colon != std::string::npos)
            return line.substr(line.find_first_not_of(" \t", colon + 1));
    }
    return "unknown";
}

void run_job(const Job& job, const Options& options, RTCDevice device, int threads) {
    const runtime::Animation& a = job.scene.animation;
    const auto convert_start = Clock::now();
    const PeerScene peer = Converter(job.scene).convert();
    const double convert_seconds = seconds_since(convert_start);

    std::printf(
        "\n== %s: %dx%d, frames %d..%d of %d..%d, %d spp, shutter %g of the clock step "
        "%g, error frame %d ==\n",
        job.name.c_str(), a.width, a.height, job.first, job.last, a.initial_frame, a.final_frame,
        job.spp, a.shutter, a.clock_delta(), job.error_frame);
    std::printf(
        "  Embree scene per frame: %zu sphere points (one geometry, K+1 time steps), "
        "%zu static triangles, %zu light sources; records converted in %.1f ms (once)\n",
        peer.spheres.size(), peer.triangles.size(), peer.lights.size(), convert_seconds * 1e3);

    const auto reference_start = Clock::now();
    tracer::Image reference;
    {
        tracer::RenderSettings settings;
        settings.mode = tracer::Mode::Spacetime;
        settings.samples_per_pixel = job.reference_spp;
        settings.sample_seed = 1;  // independent of the measured renders' samples
        settings.threads = threads;
        settings.first_frame = settings.last_frame = job.error_frame;
        tracer::Renderer renderer(job.scene, settings);
        reference = renderer.render_frame(job.error_frame);
    }
    std::printf("  reference: hexant spacetime, frame %d, %d spp, sample_seed 1: %.1f s\n\n",
                job.error_frame, job.reference_spp, seconds_since(reference_start));
    std::fflush(stdout);

    std::vector<Row> rows;
    rows.push_back(run_hexant(job, tracer::Mode::Spacetime, job.spp, job.first, job.last, threads));
    rows.push_back(run_hexant(job, tracer::Mode::Frames, job.spp, job.first, job.last, threads));
    for (const int k : {2, 4, 8})
        rows.push_back(run_embree(job, peer, device, k, job.spp, job.first, job.last));
    for (Row& r : rows) r.rmse = rmse(r.error_image, reference);
    print_table(job, rows);
    std::fflush(stdout);

    if (options.write_images) {
        const fs::path dir(*options.write_images);
        fs::create_directories(dir);
        const std::string frame = "frame" + std::to_string(job.error_frame);
        tracer::write_image(reference, dir / (job.name + "_" + frame + "_reference.png"));
        for (const Row& r : rows) {
            std::string method = r.method;
            for (char& c : method)
                if (c == ' ' || c == '=') c = '_';
            tracer::write_image(r.error_image,
                                dir / (job.name + "_" + frame + "_" + method + ".png"));
        }
        std::printf("  images of frame %d written to %s\n", job.error_frame, dir.c_str());
    }

    if (job.name == "atom") time_to_error(job, peer, device, reference, threads);
    std::fflush(stdout);
}

int run(const Options& options) {
    std::vector<std::string> names;
    if (options.scene == "all")
        names = {"atom", "bounce"};
    else if (options.scene == "atom" || options.scene == "bounce")
        names = {options.scene};
    else
        throw std::runtime_error("--scene must be atom, bounce or all, not '" + options.scene +
                                 "'");
    if (options.threads < 0) throw std::runtime_error("--threads must be 0 (all) or more");

    // Both tracers run under the same limit.
    std::unique_ptr<tbb::global_control> limit;
    if (options.threads > 0)
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      options.threads);
    const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
    const std::string config =
        options.threads > 0 ? "threads=" + std::to_string(options.threads) : "";
    RTCDevice device = rtcNewDevice(config.empty() ? nullptr : config.c_str());
    if (!device) throw std::runtime_error("rtcNewDevice failed");
    rtcSetDeviceErrorFunction(device, embree_error, nullptr);
    warm_up(device);
    const long tasking = rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_TASKING_SYSTEM);

    char date[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M:%S %Z", std::localtime(&now));
    std::printf(
        "hexant_embree_peer: hexant against Embree 3 multi-segment motion blur (issue 15)\n");
    std::printf("date      %s\n", date);
    std::printf("cpu       %s (%u hardware threads)\n", cpu_model().c_str(),
                std::thread::hardware_concurrency());
    std::printf("load      %s (1, 5, 15 minutes, at start)\n", load_average().c_str());
    std::printf("threads   %d (both tracers; 16x16 tiles, tbb::parallel_for)\n", threads);
    std::printf(
        "embree    %s (RTC_VERSION_STRING), tasking: %s, build quality "
        "RTC_BUILD_QUALITY_MEDIUM, single rays (rtcIntersect1, rtcOccluded1)\n",
        RTC_VERSION_STRING,
        tasking == 1   ? "TBB"
        : tasking == 0 ? "internal"
                       : "other");
    std::printf(
        "%s", options.quick ? "mode      --quick (a smoke test: the figures mean nothing)\n" : "");
    std::printf(
        "legend    hexant spacetime/frames: hexant's Renderer (Owen-scrambled Sobol' samples over\n"
        "          pixel and shutter); build s = its build before the frames (sweeps, the root;\n"
        "          a lazy build's cells are built inside the render), render s = its frames'.\n"
        "          embree K=n: one Embree scene per frame, spheres on n linear motion segments\n"
        "          through hexant's exact motion at n+1 instants; stratified jitter (sqrt(spp)^2\n"
        "          grid, else N rooks) with an independent uniform time per sample (PCG32 by "
        "frame\n"
        "          and pixel); build s = per frame: motion evaluation, buffers, rtcCommitScene.\n"
        "          total s = build + render; wall s = measured around the whole row; rays =\n"
        "          primary + shadow; Mrays/s = rays / render s; RMSE in linear light over RGB\n"
        "          against a hexant spacetime reference of that frame with sample_seed 1.\n");
    std::fflush(stdout);

    for (const auto& name : names) {
        Job job = load_job(name, options);
        run_job(job, options, device, options.threads);
    }
    rtcReleaseDevice(device);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"hexant against Embree 3's multi-segment motion blur on atom and bounce"};
    Options options;
    app.add_option("--scene", options.scene, "atom, bounce or all (default)");
    app.add_option("--spp", options.spp, "Samples per pixel (default: atom 32, bounce 4)");
    app.add_option("--frames", options.frames, "Frames A:B (default: the .ini's)");
    app.add_option("--size", options.size, "Image width; the height keeps the .ini's aspect");
    app.add_option("--reference-spp", options.reference_spp, "The reference's spp (default 1024)");
    app.add_option("--error-frame", options.error_frame,
                   "The frame whose RMSE is measured (default: the middle one)");
    app.add_option("--threads", options.threads, "Worker threads (default: all)");
    app.add_flag("--quick", options.quick,
                 "A tiny run for a smoke test: 32 wide, 2 frames, 2 spp, reference 16 spp");
    app.add_option("--write-images", options.write_images,
                   "Write the error frame of every row and the reference as PNG files here");
    CLI11_PARSE(app, argc, argv);
    try {
        return run(options);
    } catch (const language::SceneError& e) {
        std::cerr << e.formatted();
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "hexant_embree_peer: error: " << e.what() << "\n";
        return 1;
    }
}
