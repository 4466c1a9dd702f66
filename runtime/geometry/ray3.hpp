// The records that every static ray/shape routine in runtime/geometry shares:
// a ray, a closed axis-aligned box and a surface hit, all in object space at
// one instant. Each object kind K has runtime/objects/<folder>/K_geometry.hpp with
//   std::optional<SurfaceHit> intersect(const KGeometry&, const Ray3&, double s_min, double s_max);
//   bool inside(const KGeometry&, glm::dvec3 p);
//   Box3 object_bounds(const KGeometry&);          (not for the plane)
//   bool surface_may_meet(const KGeometry&, const Box3&);
// intersect returns the nearest hit with s_min < s < s_max; no NaN or Inf
// leaves any of them for finite input (degenerate shapes simply have no hits).
#pragma once

#include <cmath>
#include <limits>

#include <glm/glm.hpp>

namespace hexant::runtime::geometry {

struct Ray3 {
    glm::dvec3 origin, direction;  // direction need not be unit length
};

// Axis-aligned and closed: lo <= hi in every coordinate.
struct Box3 {
    glm::dvec3 lo, hi;

    // The box of no point at all (not a box with NaN ends, which must read
    // as "anywhere"): what a search uses for a piece it has ruled out.
    static Box3 nowhere() {
        constexpr double inf = std::numeric_limits<double>::infinity();
        return {glm::dvec3(inf), glm::dvec3(-inf)};
    }
    bool is_nowhere() const {
        constexpr double inf = std::numeric_limits<double>::infinity();
        return lo.x == inf && hi.x == -inf;
    }
};

struct SurfaceHit {
    double s;  // ray parameter: point = origin + s * direction
    // Unit geometric normal in object space: outward for solids; for flat
    // shapes (polygon, triangle, disc, plane) the shape's own normal side,
    // not flipped toward the ray.
    glm::dvec3 normal;
    glm::dvec3 shading_normal;  // = normal except smooth_triangle (interpolated, unit)
    glm::dvec2 uv;              // texture coordinates, documented per shape
    int part = 0;               // which face, cap or side was hit, documented per shape
    // The hit point, computed near the surface (from a ray origin moved close
    // to the shape, or from barycentric weights), so it lies on the surface to
    // a few ulps of its own coordinates even when the ray came from far away,
    // where origin + s * direction is only good to ulps of the origin. Use it
    // (with offset_ray) to start secondary rays.
    glm::dvec3 point{0.0};
    // A bound on each coordinate's distance of `point` from the exact
    // surface, in the shape's space, from the routine's own arithmetic and
    // the magnitudes of its inputs (pbrt-v4's pError; gamma(n) below). Zero
    // where a routine gives none: offset_ray then steps by ulps of the
    // point alone.
    glm::dvec3 error{0.0};
};

// gamma(n) = n u / (1 - n u), u = 2^-53: the relative error bound of n
// rounded operations in double (Higham, "Accuracy and Stability of
// Numerical Algorithms", 3.1; pbrt-v4's gamma).
constexpr double rounding_gamma(int n) {
    constexpr double u = 0x1p-53;
    return n * u / (1.0 - n * u);
}

inline bool is_finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The last guard of every intersect routine: a hit with any non-finite
// number (possible only for absurd inputs near the overflow limit) is no hit.
inline bool is_finite(const SurfaceHit& hit) {
    return std::isfinite(hit.s) && is_finite(hit.normal) && is_finite(hit.shading_normal) &&
           std::isfinite(hit.uv.x) && std::isfinite(hit.uv.y) && is_finite(hit.point);
}

}  // namespace hexant::runtime::geometry
