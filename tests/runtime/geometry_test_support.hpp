// Shared helpers of the static geometry tests: random numbers of every
// scale, surface samples, and the checks every shape kind must pass with
// rays aimed at sampled surface points and boxes around them.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <random>

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace geometry_test {

using hexant::runtime::geometry::Box3;
using hexant::runtime::geometry::Ray3;
using hexant::runtime::geometry::SurfaceHit;

inline constexpr double kEps = 0x1p-52;
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

class Random {
  public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}
    double uniform(double lo = 0.0, double hi = 1.0) {
        return std::uniform_real_distribution<double>(lo, hi)(engine_);
    }
    // Magnitudes spread evenly over decades.
    double log_uniform(double lo, double hi) {
        return std::exp(uniform(std::log(lo), std::log(hi)));
    }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
    glm::dvec3 unit_vector() {
        const double z = uniform(-1.0, 1.0), phi = uniform(0.0, 2.0 * kPi);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
    glm::dvec3 in_cube(double half) {
        return {uniform(-half, half), uniform(-half, half), uniform(-half, half)};
    }

  private:
    std::mt19937_64 engine_;
};

inline double length_ld(const glm::dvec3& v) {
    const long double x = v.x, y = v.y, z = v.z;
    return static_cast<double>(std::sqrt(x * x + y * y + z * z));
}

inline bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Every number in a hit finite, the normals of unit length.
inline bool well_formed(const SurfaceHit& hit) {
    return std::isfinite(hit.s) && finite(hit.normal) && finite(hit.shading_normal) &&
           finite(hit.point) && std::isfinite(hit.uv.x) && std::isfinite(hit.uv.y) &&
           std::fabs(length_ld(hit.normal) - 1.0) < 1e-12 &&
           std::fabs(length_ld(hit.shading_normal) - 1.0) < 1e-12;
}

struct SurfaceSample {
    glm::dvec3 point;
    glm::dvec3 normal;  // unit, outward (or the flat shape's own side)
    // How far a ray aimed at the point may pass it and still be sure to hit:
    // the surface's smallest radius of curvature there (infinite if flat)
    // and the distance to the nearest edge of its face (infinite if none).
    double curvature_radius = kInf;
    double edge_distance = kInf;
};

// The distance from q to the line through origin along dir, in long double.
inline double distance_to_line(const glm::dvec3& q, const glm::dvec3& origin,
                               const glm::dvec3& dir) {
    const long double fx = (long double)q.x - origin.x, fy = (long double)q.y - origin.y,
                      fz = (long double)q.z - origin.z;
    const long double ux = dir.x, uy = dir.y, uz = dir.z;
    const long double cx = fy * uz - fz * uy, cy = fz * ux - fx * uz, cz = fx * uy - fy * ux;
    return static_cast<double>(std::sqrt(cx * cx + cy * cy + cz * cz) /
                               std::sqrt(ux * ux + uy * uy + uz * uz));
}

// What the aimed-ray check measured, for the report and the assertions.
struct AimStats {
    int rays = 0, hits = 0, grazing_misses = 0;
    double max_residual = 0.0;  // surface residual / (size + |point|)
    double max_front_s_error =
        0.0;  // |s / s_target - 1| beyond the test's rounding, front hits on convex shapes
    double max_point_mismatch = 0.0;  // |origin + s dir - point| / (|origin| + |s dir|)
};

// Rays from origins at `distance` from a sampled surface point q, aimed at q
// with direction (q - origin) * m for random m (so q lies at s = 1/m). Half
// come from the side the normal faces. The rounded ray passes q at some
// distance (measured in long double) and q itself is off the surface by its
// rounding; together the "miss" u. The hit must exist unless the ray could
// honestly miss: it grazes so that the surface's sag over the curvature
// radius (cos^2 R / 2) is within u, or it passes an edge closer than u allows.
// The hit must not lie beyond q (up to u over the cosine), its point must lie
// on the surface (residual) and agree with origin + s * direction. For convex
// shapes a ray from the front side hits q itself: s = 1/m.
template <class Geometry, class Sampler, class Residual>
AimStats aim_at_surface(const Geometry& g, Sampler&& sample, Residual&& residual, double size,
                        double distance, bool convex, int count, Random& random) {
    AimStats stats;
    for (int i = 0; i < count; ++i) {
        const SurfaceSample q = sample(random);
        glm::dvec3 away = random.unit_vector();
        const bool front = i % 2 == 0;
        if (front && glm::dot(away, q.normal) < 0.0) away = -away;
        const glm::dvec3 origin = q.point + distance * away;
        const double m = random.log_uniform(1e-3, 1e3);
        const glm::dvec3 dir = (q.point - origin) * m;
        const double s_target = 1.0 / m;
        const double cosine = std::fabs(glm::dot(dir, q.normal)) / length_ld(dir);
        const double u =
            distance_to_line(q.point, origin, dir) + 16.0 * kEps * (length_ld(q.point) + size);
        const auto hit = intersect(g, Ray3{origin, dir}, 0.0, kInf);
        ++stats.rays;
        if (!hit) {
            const bool may_miss = cosine * cosine * q.curvature_radius <= 8.0 * u ||
                                  8.0 * u >= q.edge_distance * cosine;
            INFO("miss: q " << q.point.x << " " << q.point.y << " " << q.point.z << " origin "
                            << origin.x << " " << origin.y << " " << origin.z << " cos " << cosine
                            << " u " << u);
            REQUIRE(may_miss);
            ++stats.grazing_misses;
            continue;
        }
        ++stats.hits;
        REQUIRE(well_formed(*hit));
        const double s_tolerance =
            s_target *
            (64.0 * kEps + 8.0 * u / (length_ld(q.point - origin) * std::max(cosine, 1e-300)));
        INFO("s " << hit->s << " target " << s_target << " cos " << cosine);
        REQUIRE(hit->s <= s_target + s_tolerance);
        REQUIRE(hit->s > 0.0);
        const double scale = size + length_ld(hit->point);
        const double res = residual(hit->point) / scale;
        stats.max_residual = std::max(stats.max_residual, res);
        const glm::dvec3 along = origin + hit->s * dir;
        const double mismatch =
            length_ld(along - hit->point) / (length_ld(origin) + length_ld(hit->s * dir));
        stats.max_point_mismatch = std::max(stats.max_point_mismatch, mismatch);
        if (convex && front && cosine > 1e-3) {
            // The part of the error in s that the test's own rounding (u)
            // does not explain.
            const double explained = u / (length_ld(q.point - origin) * cosine);
            stats.max_front_s_error =
                std::max(stats.max_front_s_error, std::fabs(hit->s / s_target - 1.0) - explained);
        }
    }
    return stats;
}

// Boxes that hold a sampled surface point: a single point, tiny, small and
// large boxes placed at random around it. surface_may_meet must say yes to
// every one. Returns how many were tested.
template <class Geometry, class Sampler>
int boxes_around_surface(const Geometry& g, Sampler&& sample, double size, int count,
                         Random& random) {
    for (int i = 0; i < count; ++i) {
        const SurfaceSample q = sample(random);
        Box3 box{q.point, q.point};
        const int kind = i % 4;
        if (kind > 0) {
            const double extent = size * (kind == 1   ? random.log_uniform(1e-15, 1e-9)
                                          : kind == 2 ? random.log_uniform(1e-9, 1e-2)
                                                      : random.log_uniform(1e-2, 3.0));
            for (int k = 0; k < 3; ++k) {
                const double below = random.uniform(0.0, 1.0) * extent;
                box.lo[k] = q.point[k] - below;
                box.hi[k] = q.point[k] + (extent - below);
                if (random.uniform() < 0.1) box.lo[k] = q.point[k];  // point on a face
                if (random.uniform() < 0.1) box.hi[k] = q.point[k];
            }
        }
        INFO("point " << q.point.x << " " << q.point.y << " " << q.point.z << " box kind " << kind);
        REQUIRE(surface_may_meet(g, box));
    }
    return count;
}

// Random rays of every kind: origins near and far, directions with zero
// components, tiny and huge lengths. Every hit must be well formed and lie in
// the asked range.
template <class Geometry>
int random_rays_are_finite(const Geometry& g, double size, const glm::dvec3& centre, int count,
                           Random& random) {
    int hits = 0;
    for (int i = 0; i < count; ++i) {
        const double reach = size * random.log_uniform(1e-3, 1e7);
        const glm::dvec3 origin = centre + reach * random.unit_vector();
        glm::dvec3 dir = random.unit_vector();
        if (i % 3 == 0) dir[random.integer(0, 2)] = 0.0;
        if (i % 7 == 0) {
            dir = glm::dvec3(0.0);
            dir[random.integer(0, 2)] = random.uniform() < 0.5 ? -1.0 : 1.0;
        }
        if (i % 5 == 0) {  // aimed at the centre
            dir = centre - origin;
        }
        if (i % 11 == 0) dir = glm::dvec3(0.0);  // no direction: no hit
        dir *= random.log_uniform(1e-200, 1e200);
        const double s_min = i % 2 == 0 ? 0.0 : -kInf;
        const auto hit = intersect(g, Ray3{origin, dir}, s_min, kInf);
        if (!hit) continue;
        ++hits;
        INFO("ray " << i);
        REQUIRE(well_formed(*hit));
        REQUIRE(hit->s > s_min);
        REQUIRE(dir != glm::dvec3(0.0));
    }
    return hits;
}

}  // namespace geometry_test

namespace geometry_test {

// With HEXANT_GEOMETRY_REPORT set, the measured accuracies are printed (for
// the record; the assertions hold either way).
inline void report(const char* what, const AimStats& s) {
    if (std::getenv("HEXANT_GEOMETRY_REPORT") == nullptr) return;
    std::printf(
        "%-40s rays %6d hits %6d grazing misses %3d  residual %.2e  front s %.2e  "
        "point/ray %.2e\n",
        what, s.rays, s.hits, s.grazing_misses, s.max_residual, s.max_front_s_error,
        s.max_point_mismatch);
}

}  // namespace geometry_test
