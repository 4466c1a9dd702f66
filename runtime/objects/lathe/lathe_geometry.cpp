#include "runtime/objects/lathe/lathe_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/polynomial_roots.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTwoPi = 6.28318530717958647692;

using Cubic = std::array<double, 4>;  // ascending: d, c, b, a

Cubic component(const LatheSegment& s, int k) {
    return {s.d[k], s.c[k], s.b[k], s.a[k]};
}

double eval(const Cubic& p, double t) {
    return ((p[3] * t + p[2]) * t + p[1]) * t + p[0];
}

// The range of a cubic over [0, 1]: its ends and critical points, widened by
// the rounding of evaluating it (a few ulps of its coefficients' size).
void cubic_range(const Cubic& p, double& lo, double& hi) {
    lo = std::min(eval(p, 0.0), eval(p, 1.0));
    hi = std::max(eval(p, 0.0), eval(p, 1.0));
    const std::array<double, 3> slope{p[1], 2.0 * p[2], 3.0 * p[3]};
    for (const double t : polynomial_roots(slope, 0.0, 1.0)) {
        lo = std::min(lo, eval(p, t));
        hi = std::max(hi, eval(p, t));
    }
    const double margin =
        16.0 * kEpsilon * (std::fabs(p[0]) + std::fabs(p[1]) + std::fabs(p[2]) + std::fabs(p[3]));
    lo -= margin;
    hi += margin;
}

bool valid(const LatheGeometry& lathe) {
    return !lathe.segments.empty() && std::isfinite(lathe.radius) && std::isfinite(lathe.height1) &&
           std::isfinite(lathe.height2);
}

double size_of(const LatheGeometry& lathe) {
    return std::max({lathe.radius, std::fabs(lathe.height1), std::fabs(lathe.height2),
                     lathe.height2 - lathe.height1});
}

// Crossings of the profile with the horizontal half-line {(r', y): r' >= r}
// (r' > r + skip when skip >= 0), roots of y(t) = y in [0, 1).
int crossings(const LatheGeometry& lathe, double r, double y, double skip) {
    int count = 0;
    for (const LatheSegment& s : lathe.segments) {
        if (y < s.y_lo || y > s.y_hi) continue;
        Cubic h = component(s, 1);
        h[0] -= y;
        for (const double w : polynomial_roots(h, 0.0, 1.0)) {
            if (w >= 1.0) continue;
            const double rw = s.at(w).x;
            if (skip < 0.0 ? rw >= r : rw > r + skip) ++count;
        }
    }
    return count;
}

glm::dvec2 lathe_uv(const LatheGeometry& lathe, const glm::dvec3& p, int segment, double t) {
    // POV-Ray's Lathe::UVCoord.
    double theta = 0.0;
    const double len2 = p.x * p.x + p.z * p.z;
    if (len2 > 1e-10) {
        const double len = std::sqrt(len2);
        if (p.z == 0.0) {
            theta = p.x > 0.0 ? 0.0 : 3.14159265358979323846;
        } else {
            theta = std::acos(std::clamp(p.x / len, -1.0, 1.0));
            if (p.z < 0.0) theta = kTwoPi - theta;
        }
        theta /= kTwoPi;
    }
    const double v = std::min((t + segment) / static_cast<double>(lathe.segments.size()), 1.0);
    return {theta, v};
}

// The ray's image: height and distance from the axis at k.
struct RayTerms {
    glm::dvec3 o, u;
    double rho(double k) const { return std::hypot(std::fma(k, u.x, o.x), std::fma(k, u.z, o.z)); }
    double rho_slope(double k, double rho_k) const {
        if (!(rho_k > 0.0)) return 0.0;
        return (std::fma(k, u.x, o.x) * u.x + std::fma(k, u.z, o.z) * u.z) / rho_k;
    }
};

struct Solution {
    double k, t, residual;
};

// Newton's method on F1 = oy + k uy - y(t), F2 = rho(k) - sign r(t) for
// (k, t) from a start; the best iterate.
Solution polish(const RayTerms& ray, const LatheSegment& s, double k, double t) {
    const double sign = s.at(std::clamp(t, 0.0, 1.0)).x < 0.0 ? -1.0 : 1.0;
    auto residuals = [&](double kk, double tt, double& f1, double& f2) {
        const glm::dvec2 q = s.at(tt);
        f1 = std::fma(kk, ray.u.y, ray.o.y) - q.y;
        f2 = ray.rho(kk) - sign * q.x;
    };
    double f1, f2;
    residuals(k, t, f1, f2);
    Solution best{k, t, std::fabs(f1) + std::fabs(f2)};
    for (int iteration = 0; iteration < 12 && best.residual > 0.0; ++iteration) {
        const glm::dvec2 dq = s.slope(t);
        const double rho_k = ray.rho(k);
        const double j11 = ray.u.y, j12 = -dq.y, j21 = ray.rho_slope(k, rho_k), j22 = -sign * dq.x;
        const double det = difference_of_products(j11, j22, j12, j21);
        if (det == 0.0 || !std::isfinite(det)) break;
        const double dk = -difference_of_products(f1, j22, j12, f2) / det;
        const double dt = -difference_of_products(j11, f2, f1, j21) / det;
        if (!std::isfinite(dk) || !std::isfinite(dt)) break;
        k += dk;
        t += dt;
        if (t < -0.5 || t > 1.5) break;
        residuals(k, t, f1, f2);
        const double r = std::fabs(f1) + std::fabs(f2);
        if (r < best.residual) {
            best = {k, t, r};
        } else if (r > 4.0 * best.residual) {
            break;
        }
        if (std::fabs(dk) <= kEpsilon * (std::fabs(k) + 1e-300) && std::fabs(dt) <= kEpsilon) break;
    }
    return best;
}

}  // namespace

int lathe_segment_count(LatheSpline spline, std::size_t points) {
    const long long n = static_cast<long long>(points);
    long long segments = 0;
    switch (spline) {
        case LatheSpline::linear:
            segments = n - 1;
            break;
        case LatheSpline::quadratic:
            segments = n - 2;
            break;
        case LatheSpline::cubic:
            segments = n - 3;
            break;
        case LatheSpline::bezier:
            segments = n / 4;
            break;
    }
    return static_cast<int>(std::max(segments, 0LL));
}

LatheGeometry make_lathe(LatheSpline spline, const std::vector<glm::dvec2>& points) {
    LatheGeometry g;
    for (const glm::dvec2& p : points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return g;
    const int count = lathe_segment_count(spline, points.size());
    if (count <= 0) return g;
    g.segments.reserve(count);
    g.height1 = kInf;
    g.height2 = -kInf;
    for (int i = 0; i < count; ++i) {
        const auto p = lathe_polynomial<double>(
            spline, i, [&](int j, int k) { return points[static_cast<std::size_t>(j)][k]; });
        LatheSegment s;
        s.a = {p.a[0], p.a[1]};
        s.b = {p.b[0], p.b[1]};
        s.c = {p.c[0], p.c[1]};
        s.d = {p.d[0], p.d[1]};
        double x_lo, x_hi;
        cubic_range(component(s, 0), x_lo, x_hi);
        cubic_range(component(s, 1), s.y_lo, s.y_hi);
        s.r_hi = std::max(std::fabs(x_lo), std::fabs(x_hi));
        s.r_lo = x_lo <= 0.0 && x_hi >= 0.0 ? 0.0 : std::min(std::fabs(x_lo), std::fabs(x_hi));
        g.radius = std::max(g.radius, s.r_hi);
        g.height1 = std::min(g.height1, s.y_lo);
        g.height2 = std::max(g.height2, s.y_hi);
        g.segments.push_back(s);
    }
    if (!std::isfinite(g.radius) || !std::isfinite(g.height1) || !std::isfinite(g.height2))
        g.segments.clear();
    return g;
}

std::optional<SurfaceHit> intersect(const LatheGeometry& lathe, const Ray3& ray, double s_min,
                                    double s_max) {
    if (!valid(lathe)) return std::nullopt;
    const Box3 bounds = object_bounds(lathe);
    const auto local = local_ray(ray, centre(bounds), half_diagonal(bounds));
    if (!local) return std::nullopt;
    const glm::dvec3& o = local->origin;
    const glm::dvec3& u = local->unit;
    const double size = size_of(lathe);
    if (!(size > 0.0)) return std::nullopt;

    // In x-z: rho(k)^2 = r k^2 + 2 m k + q; the line's distance from the axis
    // times sqrt(r) is `across`.
    const double r = u.x * u.x + u.z * u.z;
    const double m = o.x * u.x + o.z * u.z;
    const double q = o.x * o.x + o.z * o.z;
    const double rho0 = std::hypot(o.x, o.z);
    const double across = std::fabs(difference_of_products(o.x, u.z, o.z, u.x));
    const double root_r = std::sqrt(r);
    const double slack = 1e-9 * size;
    if (across > (lathe.radius + slack) * root_r) return std::nullopt;

    const double k_lo = std::max(local->to_t(s_min), -kInf) - slack;
    double k_best = kInf;
    const double k_hi = local->to_t(s_max) + slack;
    int best_segment = -1;
    double best_t = 0.0;
    const RayTerms terms{o, u};
    const double uy = u.y;

    for (std::size_t j = 0; j < lathe.segments.size(); ++j) {
        const LatheSegment& s = lathe.segments[j];
        // The stretch of the ray within the segment's bounding cylinder shell.
        double a = k_lo, b = std::min(k_hi, k_best + slack);
        if (uy != 0.0) {
            double ya = (s.y_lo - slack - o.y) / uy, yb = (s.y_hi + slack - o.y) / uy;
            if (ya > yb) std::swap(ya, yb);
            a = std::max(a, ya);
            b = std::min(b, yb);
        } else if (o.y < s.y_lo - slack || o.y > s.y_hi + slack) {
            continue;
        }
        const double reach = s.r_hi + slack;
        if (r > 0.0) {
            const QuadraticRoots ring =
                solve_quadratic(r, m, difference_of_squares(rho0, reach),
                                difference_of_squares(reach * root_r, across));
            if (ring.count == 0) continue;
            a = std::max(a, ring.t[0] - slack);
            b = std::min(b, ring.t[ring.count - 1] + slack);
        } else if (rho0 > reach) {
            continue;
        }
        if (!(a <= b)) continue;

        // Seeds: POV-Ray's polynomial in t, and for nearly horizontal rays the
        // roots of y(t) = the ray's height.
        Cubic x = component(s, 0), h = component(s, 1);
        h[0] -= o.y;
        std::array<double, 7> g{};
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 4; ++k) g[i + k] += r * h[i] * h[k] - uy * uy * x[i] * x[k];
        for (int i = 0; i < 4; ++i) g[i] += 2.0 * uy * m * h[i];
        g[0] += uy * uy * q;
        double seeds[16];
        int seed_count = 0;
        for (const double t : polynomial_roots(g, 0.0, 1.0)) seeds[seed_count++] = t;
        if (std::fabs(uy) < 1e-4)
            for (const double t : polynomial_roots(h, 0.0, 1.0))
                if (seed_count < 16) seeds[seed_count++] = t;

        for (int i = 0; i < seed_count; ++i) {
            const double t0 = seeds[i];
            const glm::dvec2 p0 = s.at(t0);
            double candidates[3];
            int n = 0;
            if (uy != 0.0) candidates[n++] = (p0.y - o.y) / uy;
            if (r > 0.0) {
                const double radius = std::fabs(p0.x);
                const QuadraticRoots hits =
                    solve_quadratic(r, m, difference_of_squares(rho0, radius),
                                    difference_of_squares(radius * root_r, across));
                for (int c = 0; c < hits.count; ++c) candidates[n++] = hits.t[c];
            }
            for (int c = 0; c < n; ++c) {
                if (!std::isfinite(candidates[c])) continue;
                const Solution sol = polish(terms, s, candidates[c], t0);
                if (!(sol.residual <= 1e-9 * (size + std::fabs(sol.k)))) continue;
                if (sol.t < -1e-9 || sol.t > 1.0 + 1e-9) continue;
                if (!(sol.k < k_best)) continue;
                const double s_hit = local->to_s(sol.k);
                if (!(s_hit > s_min && s_hit < s_max)) continue;
                k_best = sol.k;
                best_segment = static_cast<int>(j);
                best_t = std::clamp(sol.t, 0.0, 1.0);
            }
        }
    }
    if (best_segment < 0) return std::nullopt;

    const LatheSegment& s = lathe.segments[static_cast<std::size_t>(best_segment)];
    SurfaceHit hit;
    hit.s = local->to_s(k_best);
    hit.part = best_segment;
    hit.point = local->at(k_best);
    hit.error = rounding_gamma(64) * (glm::abs(hit.point) + size);
    const glm::dvec3& p = hit.point;
    const glm::dvec2 profile = s.at(best_t);
    const glm::dvec2 d = s.slope(best_t);
    const double sign = profile.x < 0.0 ? -1.0 : 1.0;
    // The normal in (radius, height): (dy, -d|r|) along the curve.
    glm::dvec2 n2(d.y, -sign * d.x);
    const double n2_length = std::hypot(n2.x, n2.y);
    if (n2_length > 0.0) {
        n2 /= n2_length;
    } else {
        n2 = {0.0, 1.0};
    }
    // Outward by the inside rule: where the normal is mostly radial, the
    // parity of the profile's crossings beyond the hit at its height; else
    // whether the point a little above the hit is inside.
    const double radius = std::fabs(profile.x);
    bool inside_toward_normal;
    if (std::fabs(n2.x) >= 0.1) {
        const bool odd = crossings(lathe, radius, profile.y, 1e-9 * size) % 2 == 1;
        inside_toward_normal = odd == (n2.x > 0.0);
    } else {
        const double step = 1e-7 * size;
        const bool above_inside = crossings(lathe, radius, profile.y + step, -1.0) % 2 == 1;
        inside_toward_normal = above_inside == (n2.y > 0.0);
    }
    if (inside_toward_normal) n2 = -n2;
    const double rho = std::hypot(p.x, p.z);
    if (rho > 0.0) {
        hit.normal = glm::dvec3(n2.x * p.x / rho, n2.y, n2.x * p.z / rho);
    } else {
        hit.normal = glm::dvec3(0.0, n2.y >= 0.0 ? 1.0 : -1.0, 0.0);
    }
    const double length = safe_length(hit.normal);
    hit.normal = length > 0.0 ? hit.normal / length : glm::dvec3(0.0, 1.0, 0.0);
    hit.shading_normal = hit.normal;
    hit.uv = lathe_uv(lathe, p, best_segment, best_t);
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside(const LatheGeometry& lathe, glm::dvec3 p) {
    if (!valid(lathe)) return false;
    if (!(p.y >= lathe.height1 && p.y <= lathe.height2)) return false;
    const double r = std::hypot(p.x, p.z);
    if (!(r <= lathe.radius)) return false;
    return crossings(lathe, r, p.y, -1.0) % 2 == 1;
}

Box3 object_bounds(const LatheGeometry& lathe) {
    if (lathe.segments.empty()) return {glm::dvec3(0.0), glm::dvec3(0.0)};
    const double r = lathe.radius;
    return {{-r, lathe.height1, -r}, {r, lathe.height2, r}};
}

bool surface_may_meet(const LatheGeometry& lathe, const Box3& box) {
    if (!valid(lathe)) return false;
    const Box3 bounds = object_bounds(lathe);
    const Box3 wide = widened(box, meet_slack(box, size_of(lathe)) + 1e-12 * size_of(lathe));
    if (!overlaps(wide, bounds)) return false;
    // The box's range of distance from the axis and of height.
    const double nx = std::clamp(0.0, wide.lo.x, wide.hi.x),
                 nz = std::clamp(0.0, wide.lo.z, wide.hi.z);
    const double rho_lo = std::hypot(nx, nz);
    const double rho_hi = std::hypot(std::max(std::fabs(wide.lo.x), std::fabs(wide.hi.x)),
                                     std::max(std::fabs(wide.lo.z), std::fabs(wide.hi.z)));
    // Each segment's profile pieces, halved while their (|r|, y) box meets
    // the box's (rho, y) box; a piece small enough that still meets it may.
    struct Piece {
        std::size_t segment;
        double t0, t1;
        int depth;
    };
    for (std::size_t j = 0; j < lathe.segments.size(); ++j) {
        const LatheSegment& s = lathe.segments[j];
        if (s.r_hi < rho_lo || s.r_lo > rho_hi || s.y_hi < wide.lo.y || s.y_lo > wide.hi.y)
            continue;
        Piece stack[64];
        int top = 0;
        stack[top++] = {j, 0.0, 1.0, 0};
        while (top > 0) {
            const Piece piece = stack[--top];
            // Enclosures over [t0, t1] by the mean value form around the
            // middle: f(m) + f'([t0, t1]) (t - m), f' bounded coefficient-wise.
            const double mid = 0.5 * (piece.t0 + piece.t1), half = 0.5 * (piece.t1 - piece.t0);
            const glm::dvec2 at = s.at(mid);
            const double tmax = std::max(std::fabs(piece.t0), std::fabs(piece.t1));
            const glm::dvec2 slope_bound =
                3.0 * glm::abs(s.a) * tmax * tmax + 2.0 * glm::abs(s.b) * tmax + glm::abs(s.c);
            const glm::dvec2 margin =
                slope_bound * half +
                16.0 * kEpsilon * (glm::abs(s.a) + glm::abs(s.b) + glm::abs(s.c) + glm::abs(s.d));
            const double x_lo = at.x - margin.x, x_hi = at.x + margin.x;
            const double r_hi = std::max(std::fabs(x_lo), std::fabs(x_hi));
            const double r_lo =
                x_lo <= 0.0 && x_hi >= 0.0 ? 0.0 : std::min(std::fabs(x_lo), std::fabs(x_hi));
            if (r_hi < rho_lo || r_lo > rho_hi || at.y + margin.y < wide.lo.y ||
                at.y - margin.y > wide.hi.y)
                continue;
            if (piece.depth >= 24 || top >= 62) return true;
            stack[top++] = {j, mid, piece.t1, piece.depth + 1};
            stack[top++] = {j, piece.t0, mid, piece.depth + 1};
        }
    }
    return false;
}

}  // namespace hexant::runtime::geometry
