#include "runtime/objects/cylinder/frustum.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/orthonormal_basis.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"
#include "runtime/objects/disc/disc_geometry.hpp"

namespace hexant::runtime::geometry {

namespace {

// The axis frame: unit axis w from base to cap, length L, and the slope k of
// the radius along the axis (r(h) = base_radius + k h for h in [0, L]).
struct Axis {
    glm::dvec3 w;
    double length;
    double slope;
};

bool make_axis(const Frustum& fr, Axis& axis) {
    const double r0 = fr.base_radius, r1 = fr.cap_radius;
    if (!(r0 >= 0.0) || !(r1 >= 0.0) || !(r0 > 0.0 || r1 > 0.0)) return false;
    if (!std::isfinite(r0) || !std::isfinite(r1)) return false;
    if (!is_finite(fr.base) || !is_finite(fr.cap)) return false;
    const glm::dvec3 along = fr.cap - fr.base;
    const double length = safe_length(along);
    if (!(length > 0.0) || !std::isfinite(length)) return false;
    axis = {along / length, length, (r1 - r0) / length};
    return true;
}

glm::dvec3 safe_unit(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double len = safe_length(v);
    return len > 0.0 && std::isfinite(len) ? v / len : fallback;
}

struct Candidate {
    double t;
    int part;  // 0 side, 1 base cap, 2 cap end
    glm::dvec3 radial;
};

}  // namespace

std::optional<SurfaceHit> intersect_frustum(const Frustum& fr, const Ray3& ray, double s_min,
                                            double s_max) {
    Axis axis;
    if (!make_axis(fr, axis)) return std::nullopt;
    const glm::dvec3& w = axis.w;
    const double k = axis.slope;
    const double r0 = fr.base_radius, r1 = fr.cap_radius;
    const double size = std::max({0.5 * axis.length, r0, r1});
    const auto local = local_ray(ray, 0.5 * fr.base + 0.5 * fr.cap, size);
    if (!local) return std::nullopt;
    const glm::dvec3& u = local->unit;

    // Split the origin's offset f and the direction u into parts along the
    // axis (fa, ua) and across it (fp, up): the side is |fp + t up| = r(h)
    // with h = fa + t ua, i.e. A t^2 + 2 B t + C = 0 with
    //   A = |up|^2 - kd^2,  B = fp.up - rho0 kd,  C = |fp|^2 - rho0^2,
    // rho0 = r(fa) the radius at the origin's height, kd = k ua. As for the
    // sphere (Ray Tracing Gems ch. 7), B^2 - A C is rewritten without the
    // cancelling products: B^2 - A C = |rho0 up - kd fp|^2 - |fp x up|^2
    // (Lagrange's identity), a difference of squares formed as (x - y)(x + y).
    const glm::dvec3 f = local->origin - fr.base;
    const double fa = glm::dot(f, w);
    const glm::dvec3 fp = f - fa * w;
    const double ua = glm::dot(u, w);
    const glm::dvec3 up = u - ua * w;
    const double rho0 = r0 + k * fa;
    const double kd = k * ua;
    const double A = difference_of_squares(safe_length(up), std::fabs(kd));
    const double B = glm::dot(fp, up) - rho0 * kd;
    const double C = difference_of_squares(safe_length(fp), std::fabs(rho0));
    const double disc =
        difference_of_squares(safe_length(rho0 * up - kd * fp), safe_length(glm::cross(fp, up)));

    Candidate found[4];
    int count = 0;
    const QuadraticRoots roots = solve_quadratic(A, B, C, disc);
    for (int i = 0; i < roots.count; ++i) {
        const double t = roots.t[i];
        const double h = fa + t * ua;
        // On the finite side, and on the nappe with a non-negative radius.
        if (!(h >= 0.0 && h <= axis.length) || r0 + k * h < 0.0) continue;
        glm::dvec3 q = fp + t * up;
        q -= glm::dot(q, w) * w;
        found[count++] = {t, 0, q};
    }
    if (!fr.open) {
        if (r0 > 0.0) {
            if (auto c = cross_disc(*local, fr.base, -w, r0, 0.0))
                found[count++] = {c->t, 1, c->radial};
        }
        if (r1 > 0.0) {
            if (auto c = cross_disc(*local, fr.cap, w, r1, 0.0))
                found[count++] = {c->t, 2, c->radial};
        }
    }
    for (int i = 1; i < count; ++i) {  // at most four: insertion sort by t
        for (int j = i; j > 0 && found[j].t < found[j - 1].t; --j)
            std::swap(found[j], found[j - 1]);
    }
    const OrthonormalBasis basis = orthonormal_basis(w);
    for (int i = 0; i < count; ++i) {
        const Candidate& c = found[i];
        SurfaceHit hit;
        hit.s = local->to_s(c.t);
        if (!(hit.s > s_min && hit.s < s_max)) continue;
        hit.part = c.part;
        hit.point = local->at(c.t);
        // The offset from the base (rounded to ulps of the origin and the
        // base), the quadratic's root (a few ulps of the frustum's size and
        // that offset) and origin + t u (ulps of the point): gamma(16) of
        // those magnitudes bounds the point's distance from the surface.
        hit.error = rounding_gamma(16) *
                    (glm::abs(hit.point) + glm::abs(fr.base) + glm::abs(fr.cap) + 2.0 * size);
        if (c.part == 0) {
            // The gradient of |q| - r(h): the radial unit vector tilted by the slope.
            const glm::dvec3 radial_unit = safe_unit(c.radial, basis.t1);
            hit.normal = safe_unit(radial_unit - k * w, radial_unit);
            const double h = glm::dot(hit.point - fr.base, w);
            hit.uv = {turn_fraction(basis, c.radial), std::clamp(h / axis.length, 0.0, 1.0)};
        } else {
            hit.normal = c.part == 1 ? -w : w;
            const double r = c.part == 1 ? r0 : r1;
            hit.uv = {turn_fraction(basis, c.radial), std::min(safe_length(c.radial) / r, 1.0)};
        }
        hit.shading_normal = hit.normal;
        if (is_finite(hit)) return hit;
    }
    return std::nullopt;
}

bool inside_frustum(const Frustum& fr, glm::dvec3 p) {
    Axis axis;
    if (!make_axis(fr, axis)) return false;
    const glm::dvec3 f = p - fr.base;
    const double h = glm::dot(f, axis.w);
    if (!(h >= 0.0 && h <= axis.length)) return false;
    return safe_length(f - h * axis.w) <= fr.base_radius + axis.slope * h;
}

Box3 frustum_bounds(const Frustum& fr) {
    Axis axis;
    if (!make_axis(fr, axis)) return {glm::min(fr.base, fr.cap), glm::max(fr.base, fr.cap)};
    // A frustum is the convex hull of its two end circles.
    return hull(disc_bounds(fr.base, axis.w, fr.base_radius),
                disc_bounds(fr.cap, axis.w, fr.cap_radius));
}

bool frustum_may_meet(const Frustum& fr, const Box3& box) {
    Axis axis;
    if (!make_axis(fr, axis)) return false;
    const double slack =
        meet_slack(box, max_abs(fr.base) + max_abs(fr.cap) + fr.base_radius + fr.cap_radius);
    const Box3 wide = widened(box, slack);
    if (!overlaps(wide, widened(frustum_bounds(fr), slack))) return false;
    if (!fr.open && (disc_may_meet(fr.base, axis.w, fr.base_radius, 0.0, box) ||
                     disc_may_meet(fr.cap, axis.w, fr.cap_radius, 0.0, box))) {
        return true;
    }
    // The side: points with g(p) = |q(p)| - r(h(p)) = 0 and h in [0, L]. g is
    // convex (a norm of a linear map minus a linear function), so its maximum
    // over the box is at a corner; it is Lipschitz with constant
    // sqrt(1 + k^2), so its minimum is at least g(centre) - that * half
    // diagonal. Both ends of h are at corners (h is linear).
    const glm::dvec3& w = axis.w;
    auto g = [&](const glm::dvec3& p, double& h) {
        const glm::dvec3 f = p - fr.base;
        h = glm::dot(f, w);
        return safe_length(f - h * w) - (fr.base_radius + axis.slope * h);
    };
    double g_max = -std::numeric_limits<double>::infinity();
    double h_min = std::numeric_limits<double>::infinity(), h_max = -h_min;
    for (const glm::dvec3& corner : corners(wide)) {
        double h;
        g_max = std::max(g_max, g(corner, h));
        h_min = std::min(h_min, h);
        h_max = std::max(h_max, h);
    }
    if (h_max < -slack || h_min > axis.length + slack) return false;
    if (g_max < -slack) return false;  // wholly inside the (infinite) cone
    double h_centre;
    const double lipschitz = std::sqrt(1.0 + axis.slope * axis.slope);
    const double g_min = g(centre(wide), h_centre) - lipschitz * half_diagonal(wide);
    return !(g_min > slack);
}

}  // namespace hexant::runtime::geometry
