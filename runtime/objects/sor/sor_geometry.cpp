#include "runtime/objects/sor/sor_geometry.hpp"

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
constexpr double kPovEpsilon = 1e-10;        // POV-Ray's EPSILON
constexpr double kPovDepthTolerance = 1e-4;  // sor.cpp's DEPTH_TOLERANCE

bool valid(const SorGeometry& sor) {
    return !sor.segments.empty() && std::isfinite(sor.radius);
}

double size_of(const SorGeometry& sor) {
    return std::max(
        {sor.radius, std::fabs(sor.height1), std::fabs(sor.height2), sor.height2 - sor.height1});
}

double coefficient_size(const SorSegment& s, double y) {
    const double ay = std::fabs(y);
    return ((std::fabs(s.a) * ay + std::fabs(s.b)) * ay + std::fabs(s.c)) * ay + std::fabs(s.d);
}

double sor_u(const glm::dvec3& p) {
    double theta = 0.0;
    const double len2 = p.x * p.x + p.z * p.z;
    if (len2 > kPovEpsilon) {
        const double len = std::sqrt(len2);
        if (p.z == 0.0) {
            theta = p.x > 0.0 ? 0.0 : 3.14159265358979323846;
        } else {
            theta = std::acos(std::clamp(p.x / len, -1.0, 1.0));
            if (p.z < 0.0) theta = kTwoPi - theta;
        }
        theta /= kTwoPi;
    }
    return theta;
}

}  // namespace

SorGeometry make_sor(const std::vector<glm::dvec2>& points, bool open) {
    SorGeometry g;
    g.open = open;
    const std::size_t n = points.size();
    if (n < 4) return g;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2& p = points[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || p.x < 0.0) return g;
        if (i > 1 && i < n - 1 && p.y <= points[i - 1].y) return g;
    }
    g.height1 = kInf;
    g.height2 = -kInf;
    for (std::size_t i = 0; i + 3 < n; ++i) {
        const glm::dvec2 p0 = points[i], p1 = points[i + 1], p2 = points[i + 2], p3 = points[i + 3];
        if (std::fabs(p2.y - p0.y) < kPovEpsilon || std::fabs(p3.y - p1.y) < kPovEpsilon) {
            g.segments.clear();
            return g;
        }
        // POV-Ray's Hermite conditions on r^2, solved in y - y1 and expanded
        // to powers of y (POV-Ray inverts the 4x4 system: the same cubic up
        // to rounding).
        const double k0 = p1.x * p1.x, k1 = p2.x * p2.x;
        const double k2 = 2.0 * p1.x * ((p2.x - p0.x) / (p2.y - p0.y));
        const double k3 = 2.0 * p2.x * ((p3.x - p1.x) / (p3.y - p1.y));
        const double h = p2.y - p1.y, y1 = p1.y;
        const double rise = (k1 - k0) / h;
        const double c2 = (3.0 * rise - 2.0 * k2 - k3) / h;
        const double c3 = (k2 + k3 - 2.0 * rise) / (h * h);
        SorSegment s;
        s.a = c3;
        s.b = c2 - 3.0 * c3 * y1;
        s.c = k2 - 2.0 * c2 * y1 + 3.0 * c3 * y1 * y1;
        s.d = k0 - k2 * y1 + c2 * y1 * y1 - c3 * y1 * y1 * y1;
        // POV-Ray's quirk: coefficients below its EPSILON become 0.
        for (double* c : {&s.a, &s.b, &s.c, &s.d})
            if (std::fabs(*c) < kPovEpsilon) *c = 0.0;
        s.y_lo = p1.y;
        s.y_hi = p2.y;
        double r2_hi = std::max(s.r2(s.y_lo), s.r2(s.y_hi));
        const std::array<double, 3> slope{s.c, 2.0 * s.b, 3.0 * s.a};
        for (const double y : polynomial_roots(slope, s.y_lo, s.y_hi))
            r2_hi = std::max(r2_hi, s.r2(y));
        r2_hi +=
            16.0 * kEpsilon * coefficient_size(s, std::max(std::fabs(s.y_lo), std::fabs(s.y_hi)));
        s.r_hi = std::sqrt(std::max(r2_hi, 0.0)) * (1.0 + 4.0 * kEpsilon);
        g.radius = std::max(g.radius, s.r_hi);
        g.height1 = std::min(g.height1, s.y_lo);
        g.height2 = std::max(g.height2, s.y_hi);
        g.segments.push_back(s);
    }
    g.cap_radius_squared = std::max(g.segments.back().r2(g.segments.back().y_hi), 0.0);
    g.base_radius_squared = std::max(g.segments.front().r2(g.segments.front().y_lo), 0.0);
    if (!std::isfinite(g.radius)) g.segments.clear();
    return g;
}

std::optional<SurfaceHit> intersect(const SorGeometry& sor, const Ray3& ray, double s_min,
                                    double s_max) {
    if (!valid(sor)) return std::nullopt;
    const Box3 bounds = object_bounds(sor);
    const auto local = local_ray(ray, centre(bounds), half_diagonal(bounds));
    if (!local) return std::nullopt;
    const glm::dvec3& o = local->origin;
    const glm::dvec3& u = local->unit;
    const double size = size_of(sor);
    const double slack = 1e-9 * size;
    const double r = u.x * u.x + u.z * u.z, m = o.x * u.x + o.z * u.z, q = o.x * o.x + o.z * o.z;
    const double rho0 = std::hypot(o.x, o.z);
    const double across = std::fabs(difference_of_products(o.x, u.z, o.z, u.x));
    const double root_r = std::sqrt(r);
    if (across > (sor.radius + slack) * root_r) return std::nullopt;

    double k_best = kInf;
    int part = -1, segment = -1;
    auto consider = [&](double k, int which) {
        if (!(k < k_best)) return;
        const double s = local->to_s(k);
        if (!(s > s_min && s < s_max)) return;
        k_best = k;
        part = which;
    };
    // The caps (POV-Ray: closed, |D.y| > EPSILON, radius^2 > DEPTH_TOLERANCE).
    if (!sor.open && std::fabs(u.y) > kPovEpsilon) {
        const double heights[2] = {sor.height1, sor.height2};
        const double radii[2] = {sor.base_radius_squared, sor.cap_radius_squared};
        for (int cap = 0; cap < 2; ++cap) {
            if (!(radii[cap] > kPovDepthTolerance)) continue;
            const double k = (heights[cap] - o.y) / u.y;
            const double x = std::fma(k, u.x, o.x), z = std::fma(k, u.z, o.z);
            if (x * x + z * z <= radii[cap]) consider(k, cap);
        }
    }
    for (std::size_t j = 0; j < sor.segments.size(); ++j) {
        const SorSegment& s = sor.segments[j];
        // The ray's stretch within the segment's heights and radius.
        double a = local->to_t(s_min) - slack, b = std::min(local->to_t(s_max), k_best) + slack;
        if (u.y != 0.0) {
            double ya = (s.y_lo - o.y) / u.y, yb = (s.y_hi - o.y) / u.y;
            if (ya > yb) std::swap(ya, yb);
            a = std::max(a, ya - slack);
            b = std::min(b, yb + slack);
        } else if (o.y < s.y_lo || o.y > s.y_hi) {
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
        if (!(a <= b) || !std::isfinite(a) || !std::isfinite(b)) continue;
        // r2(oy + k uy) - (r k^2 + 2 m k + q), ascending in k.
        const double y0 = o.y, w = u.y;
        std::array<double, 4> p{};
        p[3] = s.a * w * w * w;
        p[2] = 3.0 * s.a * y0 * w * w + s.b * w * w - r;
        p[1] = 3.0 * s.a * y0 * y0 * w + 2.0 * s.b * y0 * w + s.c * w - 2.0 * m;
        p[0] = s.r2(y0) - q;
        // The excess x^2 + z^2 - r^2(y) along the ray, evaluated directly
        // (not from the rounded coefficients above), for a Newton polish.
        const auto excess = [&](double k, double& slope) {
            const double x = std::fma(k, u.x, o.x), z = std::fma(k, u.z, o.z),
                         y = std::fma(k, w, y0);
            slope = 2.0 * (x * u.x + z * u.z) - s.r2_slope(y) * w;
            return x * x + z * z - s.r2(y);
        };
        for (double k : polynomial_roots(p, a, b)) {
            double slope = 0.0;
            double e = excess(k, slope);
            for (int step = 0; step < 3 && e != 0.0 && slope != 0.0; ++step) {
                const double next = k - e / slope;
                double next_slope = 0.0;
                const double next_e = excess(next, next_slope);
                if (!(std::fabs(next_e) < std::fabs(e))) break;
                k = next;
                e = next_e;
                slope = next_slope;
            }
            const double y = std::fma(k, w, y0);
            if (!(y >= s.y_lo && y <= s.y_hi)) continue;
            const double before = k_best;
            consider(k, 2 + static_cast<int>(j));
            if (k_best != before) segment = static_cast<int>(j);
        }
    }
    if (part < 0) return std::nullopt;

    SurfaceHit hit;
    hit.s = local->to_s(k_best);
    hit.part = part;
    hit.point = local->at(k_best);
    hit.error = rounding_gamma(64) * (glm::abs(hit.point) + size);
    glm::dvec3& p = hit.point;
    const double rho = std::hypot(p.x, p.z);
    if (part < 2) {
        p.y = part == 0 ? sor.height1 : sor.height2;
        hit.normal = {0.0, part == 0 ? -1.0 : 1.0, 0.0};
        const double radius =
            std::sqrt(part == 0 ? sor.base_radius_squared : sor.cap_radius_squared);
        hit.uv = {sor_u(p), part == 0 ? rho / radius - 1.0 : 2.0 - rho / radius};
    } else {
        const SorSegment& s = sor.segments[static_cast<std::size_t>(segment)];
        const glm::dvec3 n(p.x, -0.5 * s.r2_slope(p.y), p.z);
        const double length = safe_length(n);
        hit.normal = length > 0.0 ? n / length : glm::dvec3(0.0, 1.0, 0.0);
        const double h = s.y_hi - s.y_lo;
        const double per = 1.0 / static_cast<double>(sor.segments.size());
        hit.uv = {sor_u(p), (p.y - s.y_lo) / h * per + segment * per};
    }
    hit.shading_normal = hit.normal;
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside(const SorGeometry& sor, glm::dvec3 p) {
    if (!valid(sor)) return false;
    if (!(p.y >= sor.height1 && p.y <= sor.height2)) return false;
    const double r0 = p.x * p.x + p.z * p.z;
    if (!(r0 <= sor.radius * sor.radius)) return false;
    for (const SorSegment& s : sor.segments)
        if (p.y >= s.y_lo && p.y <= s.y_hi) return r0 <= s.r2(p.y);
    return false;
}

Box3 object_bounds(const SorGeometry& sor) {
    if (sor.segments.empty()) return {glm::dvec3(0.0), glm::dvec3(0.0)};
    return {{-sor.radius, sor.height1, -sor.radius}, {sor.radius, sor.height2, sor.radius}};
}

bool surface_may_meet(const SorGeometry& sor, const Box3& box) {
    if (!valid(sor)) return false;
    const double size = size_of(sor);
    const Box3 wide = widened(box, meet_slack(box, size) + 1e-12 * size);
    if (!overlaps(wide, object_bounds(sor))) return false;
    const double nx = std::clamp(0.0, wide.lo.x, wide.hi.x),
                 nz = std::clamp(0.0, wide.lo.z, wide.hi.z);
    const double rho_lo = std::hypot(nx, nz);
    const double rho_hi = std::hypot(std::max(std::fabs(wide.lo.x), std::fabs(wide.hi.x)),
                                     std::max(std::fabs(wide.lo.z), std::fabs(wide.hi.z)));
    const double lo2 = rho_lo * rho_lo * (1.0 - 4.0 * kEpsilon),
                 hi2 = rho_hi * rho_hi * (1.0 + 4.0 * kEpsilon);
    if (!sor.open) {
        if (wide.lo.y <= sor.height1 && sor.height1 <= wide.hi.y && lo2 <= sor.base_radius_squared)
            return true;
        if (wide.lo.y <= sor.height2 && sor.height2 <= wide.hi.y && lo2 <= sor.cap_radius_squared)
            return true;
    }
    for (const SorSegment& s : sor.segments) {
        const double y0 = std::max(s.y_lo, wide.lo.y), y1 = std::min(s.y_hi, wide.hi.y);
        if (!(y0 <= y1)) continue;
        // r^2 over pieces of [y0, y1] by the mean value form, halved while
        // it meets [lo2, hi2].
        struct Piece {
            double a, b;
            int depth;
        };
        Piece stack[64];
        int top = 0;
        stack[top++] = {y0, y1, 0};
        while (top > 0) {
            const Piece piece = stack[--top];
            const double mid = 0.5 * (piece.a + piece.b), half = 0.5 * (piece.b - piece.a);
            const double ymax = std::max(std::fabs(piece.a), std::fabs(piece.b));
            const double slope =
                (3.0 * std::fabs(s.a) * ymax + 2.0 * std::fabs(s.b)) * ymax + std::fabs(s.c);
            const double margin = slope * half + 16.0 * kEpsilon * coefficient_size(s, ymax);
            const double v = s.r2(mid);
            if (v + margin < lo2 || v - margin > hi2) continue;
            if (piece.depth >= 24 || top >= 62) return true;
            stack[top++] = {mid, piece.b, piece.depth + 1};
            stack[top++] = {piece.a, mid, piece.depth + 1};
        }
    }
    return false;
}

}  // namespace hexant::runtime::geometry
