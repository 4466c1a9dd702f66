// hexant_embree_peer's Embree side: one frame's motion scene, its rays and shading
// as hexant's shader does, and the jittered samples Embree is given
// (tests/bench/embree_peer.cpp says what is measured and how).
#pragma once

#include "tests/bench/embree_peer/scene.hpp"

namespace hexant_embree_peer {

// ---------------------------------------------------------------------------
// Embree: one scene per frame.

// Ray Tracing Gems ch. 6 (Wachter and Binder) at float precision, with the
// paper's constants: hexant's runtime/geometry/offset_ray.hpp is the same
// method for double, whose step (256 double ulps) rounding the start to
// float for Embree would undo.
inline glm::vec3 offset_ray_float(const glm::vec3& p, const glm::vec3& n) {
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

inline void embree_error(void*, RTCError code, const char* message) {
    std::fprintf(stderr, "embree error %d: %s\n", int(code), message ? message : "");
}

// Embree sets itself up on its first commit (tens of milliseconds); a first
// scene of one moving sphere point keeps that out of the first row.
inline void warm_up(RTCDevice device) {
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

// Static triangles as one Embree mesh of one time step, attached to `scene`.
inline unsigned attach_triangles(RTCDevice device, RTCScene scene, const TriangleSet& set) {
    RTCGeometry mesh = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                          set.vertices.size()));
    for (std::size_t i = 0; i < set.vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) v[3 * i + k] = float(set.vertices[i][k]);
    auto* index = static_cast<std::uint32_t*>(
        rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(std::uint32_t), set.triangles.size()));
    for (std::size_t i = 0; i < set.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) index[3 * i + k] = set.triangles[i][k];
    rtcSetGeometryBuildQuality(mesh, RTC_BUILD_QUALITY_MEDIUM);
    rtcCommitGeometry(mesh);
    const unsigned id = rtcAttachGeometry(scene, mesh);
    rtcReleaseGeometry(mesh);
    return id;
}

// The instances' own scenes, built once for all frames (Embree's instancing:
// the instanced scene is shared, only the instance's transform is per frame).
class EmbreeInstances {
  public:
    EmbreeInstances(RTCDevice device, const PeerScene& peer) {
        for (const PeerInstance& instance : peer.instances) {
            RTCScene scene = rtcNewScene(device);
            rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
            attach_triangles(device, scene, instance.local);
            rtcCommitScene(scene);
            scenes_.push_back(scene);
        }
    }
    ~EmbreeInstances() {
        for (RTCScene s : scenes_) rtcReleaseScene(s);
    }
    EmbreeInstances(const EmbreeInstances&) = delete;
    EmbreeInstances& operator=(const EmbreeInstances&) = delete;
    RTCScene scene(std::size_t i) const { return scenes_[i]; }

  private:
    std::vector<RTCScene> scenes_;
};

class EmbreeFrame {
  public:
    // Geometry over the shutter of `frame`: ray time 0..1 is [open, open +
    // shutter * clock_delta], the K+1 time steps at open + j/K of it.
    EmbreeFrame(RTCDevice device, const PeerScene& peer, const EmbreeInstances& instances,
                int frame, int segments)
        : peer_(peer), segments_(segments) {
        const runtime::Animation& a = peer.scene->animation;
        // (Placed and cut as hexant places them: Animation::frame_clock.)
        open_ = a.frame_clock(frame).open;
        length_ = a.frame_clock(frame).shutter_length;
        scene_ = rtcNewScene(device);
        rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_MEDIUM);
        if (!peer.statics.triangles.empty())
            mesh_id_ = attach_triangles(device, scene_, peer.statics);
        // Each instance: its scene of triangles (built once, EmbreeInstances)
        // under its transform at the K+1 instants.
        for (std::size_t i = 0; i < peer.instances.size(); ++i) {
            RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
            rtcSetGeometryInstancedScene(instance, instances.scene(i));
            rtcSetGeometryTimeStepCount(instance, unsigned(segments + 1));
            rtcSetGeometryTimeRange(instance, 0.0f, 1.0f);
            std::vector<std::array<float, 12>> steps;
            for (int j = 0; j <= segments; ++j) {
                const double t = open_ + length_ * double(j) / segments;
                const glm::dmat4 m = peer.instances[i].to_world.matrix_at(t);
                std::array<float, 12> xfm{};
                for (int c = 0; c < 4; ++c)
                    for (int r = 0; r < 3; ++r) xfm[3 * c + r] = float(m[c][r]);
                rtcSetGeometryTransform(instance, unsigned(j), RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR,
                                        xfm.data());
                steps.push_back(xfm);
            }
            rtcCommitGeometry(instance);
            const unsigned id = rtcAttachGeometry(scene_, instance);
            rtcReleaseGeometry(instance);
            if (instance_of_.size() <= id) instance_of_.resize(id + 1, -1);
            instance_of_[id] = int(i);
            instance_steps_.push_back(std::move(steps));
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

    // Instance `i`'s transform at ray time `time`, as Embree interpolates its
    // steps (entry by entry: RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR).
    glm::dmat4 instance_at(std::size_t i, float time) const {
        const float f = time * float(segments_);
        const int j = std::clamp(int(std::floor(f)), 0, segments_ - 1);
        const double u = double(f) - j;
        const auto& a = instance_steps_[i][j];
        const auto& b = instance_steps_[i][j + 1];
        glm::dmat4 m(1.0);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 3; ++r) m[c][r] = (1.0 - u) * a[3 * c + r] + u * b[3 * c + r];
        return m;
    }

    const PeerScene& peer_;
    int segments_;
    double open_ = 0.0, length_ = 0.0;
    RTCScene scene_ = nullptr;
    unsigned mesh_id_ = RTC_INVALID_GEOMETRY_ID, sphere_id_ = RTC_INVALID_GEOMETRY_ID;
    std::vector<const float*> steps_;  // Embree's own buffers, one per time step
    std::vector<int> instance_of_;     // by geometry id: the instance's index, or -1
    std::vector<std::vector<std::array<float, 12>>> instance_steps_;
};

inline glm::dvec3 EmbreeFrame::trace(const glm::dvec3& origin, const glm::dvec3& d, float time,
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
    if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) {
        // An instance's triangle: its plane in the instance's space, placed
        // by the transform Embree interpolated at the ray's time.
        const auto i = std::size_t(instance_of_[rh.hit.instID[0]]);
        const TriangleSet& set = peer_.instances[i].local;
        const glm::dmat4 m = instance_at(i, time);
        const glm::dvec3 local(glm::inverse(m) * glm::dvec4(rough, 1.0));
        const glm::dvec3& n = set.triangle_normal[rh.hit.primID];
        const glm::dvec3& v0 = set.vertices[set.triangles[rh.hit.primID][0]];
        point = glm::dvec3(m * glm::dvec4(local - glm::dot(local - v0, n) * n, 1.0));
        geometric = glm::normalize(glm::transpose(glm::inverse(glm::dmat3(m))) * n);
        material = set.triangle_material[rh.hit.primID];
    } else if (rh.hit.geomID == sphere_id_) {
        const glm::dvec4 s = sphere_at(rh.hit.primID, time);
        const glm::dvec3 centre(s);
        geometric = glm::normalize(rough - centre);
        point = centre + s.w * geometric;
        material = peer_.spheres[rh.hit.primID].material;
    } else {
        const TriangleSet& set = peer_.statics;
        geometric = set.triangle_normal[rh.hit.primID];
        const glm::dvec3& v0 = set.vertices[set.triangles[rh.hit.primID][0]];
        point = rough - glm::dot(rough - v0, geometric) * geometric;
        material = set.triangle_material[rh.hit.primID];
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

inline std::uint64_t splitmix64(std::uint64_t x) {
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
inline void jitter_samples(int frame, int x, int y, int spp, std::vector<JitterSample>& out,
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

inline tracer::Image render_embree_frame(const PeerScene& peer, const EmbreeFrame& embree,
                                         int frame, int spp, std::uint64_t& rays) {
    const runtime::SceneDescription& scene = *peer.scene;
    const runtime::Animation& a = scene.animation;
    const double open = a.frame_clock(frame).open;
    const double length = a.frame_clock(frame).shutter_length;
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

}  // namespace hexant_embree_peer
