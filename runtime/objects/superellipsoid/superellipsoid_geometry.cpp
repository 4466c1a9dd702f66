#include "runtime/objects/superellipsoid/superellipsoid_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The clip box around the unit box (the surface lies within [-1, 1]^3; the
// margin keeps a cube's faces, e = n = 0, strictly inside the searched stretch).
constexpr double kClip = 1.0 + 1e-6;
// The longest piece of the ray the search leaves unsplit.
constexpr double kLeaf = 1e-7;
// Pieces one ray may visit (see intersect).
constexpr int kPieceBudget = 1 << 16;
// F's rounding: a few ulps of pow's results (relative to F + 1 >= 0).
constexpr double kRangeSlack = 1e-12;

// POV-Ray's Superellipsoid::power (super.cpp): small integer powers by
// multiplication, others by pow.
double power(double x, double e) {
    if (e >= 0.0 && e <= 6.0 && e == std::floor(e)) {
        double b = x;
        switch (static_cast<int>(e)) {
            case 0:
                return 1.0;
            case 1:
                return b;
            case 2:
                return b * b;
            case 3:
                return b * b * b;
            case 4:
                b *= b;
                return b * b;
            case 5:
                b *= b;
                return b * b * x;
            case 6:
                b *= b;
                return b * b * b;
        }
    }
    return std::pow(x, e);
}

// POV-Ray's Superellipsoid::evaluate_g: (x^e + y^e)^(1/e) for x, y >= 0.
double evaluate_g(double x, double y, double e) {
    double g = 0.0;
    if (x > y) {
        g = 1.0 + power(y / x, e);
        if (g != 1.0) g = std::pow(g, 1.0 / e);
        g *= x;
    } else if (y != 0.0) {
        g = 1.0 + power(x / y, e);
        if (g != 1.0) g = std::pow(g, 1.0 / e);
        g *= y;
    }
    return g;
}

double evaluate_abs(const SuperellipsoidGeometry& g, double ax, double ay, double az) {
    return evaluate_g(evaluate_g(ax, ay, g.px), az, g.pz) - 1.0;
}

// The smallest and largest |c| over [lo, hi].
void abs_range(double lo, double hi, double& a_lo, double& a_hi) {
    a_hi = std::max(std::fabs(lo), std::fabs(hi));
    a_lo = lo <= 0.0 && hi >= 0.0 ? 0.0 : std::min(std::fabs(lo), std::fabs(hi));
}

// Whether F may be 0 somewhere in the box [lo, hi] (exact up to rounding:
// F is increasing in |x|, |y|, |z|). NaN answers yes.
bool range_holds_zero(const SuperellipsoidGeometry& g, const glm::dvec3& lo, const glm::dvec3& hi) {
    double xl, xh, yl, yh, zl, zh;
    abs_range(lo.x, hi.x, xl, xh);
    abs_range(lo.y, hi.y, yl, yh);
    abs_range(lo.z, hi.z, zl, zh);
    const double f_lo = evaluate_abs(g, xl, yl, zl);
    const double f_hi = evaluate_abs(g, xh, yh, zh);
    return !(f_lo > kRangeSlack * (2.0 + f_lo) || f_hi < -kRangeSlack);
}

// log(a) - log(b) times m, 0 when the ratio is exactly 1 (m may be infinite).
double log_term(double m, double log_ratio) {
    return log_ratio == 0.0 ? 0.0 : m * log_ratio;
}

}  // namespace

SuperellipsoidGeometry make_superellipsoid(double e, double n) {
    SuperellipsoidGeometry g;
    g.e = e;
    g.n = n;
    if (!(e >= 0.0) || !(n >= 0.0) || !std::isfinite(e) || !std::isfinite(n)) return g;
    // Parse_Superellipsoid: Power[X] = 2 / e, Power[Z] = 2 / n (infinite for 0).
    g.px = e == 0.0 ? kInf : 2.0 / e;
    g.pz = n == 0.0 ? kInf : 2.0 / n;
    g.valid = g.px > 0.0 && g.pz > 0.0;
    return g;
}

double superellipsoid_function(const SuperellipsoidGeometry& g, const glm::dvec3& p) {
    return evaluate_abs(g, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z));
}

glm::dvec3 superellipsoid_normal(const SuperellipsoidGeometry& g, const glm::dvec3& p) {
    // G = N_q(N_p(|x|, |y|), |z|) with dN_p(a, b)/da = (a / N_p)^(p - 1):
    //   dG/dx = (g1 / G)^(q - 1) (|x| / g1)^(p - 1) sign x,
    //   dG/dz = (|z| / G)^(q - 1) sign z,
    // each as exp of its logarithm less the largest.
    const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
    const double g1 = evaluate_g(ax, ay, g.px);
    const double big = evaluate_g(g1, az, g.pz);
    glm::dvec3 n(0.0);
    if (g.valid && big > 0.0 && std::isfinite(big) && std::isfinite(g1)) {
        const double lg = std::log(big);
        const double qm = g.pz - 1.0, pm = g.px - 1.0;
        double l[3] = {-kInf, -kInf, -kInf};
        if (g1 > 0.0) {
            const double lg1 = std::log(g1);
            const double outer = log_term(qm, lg1 - lg);
            if (ax > 0.0) l[0] = outer + log_term(pm, std::log(ax) - lg1);
            if (ay > 0.0) l[1] = outer + log_term(pm, std::log(ay) - lg1);
        }
        if (az > 0.0) l[2] = log_term(qm, std::log(az) - lg);
        const double top = std::max({l[0], l[1], l[2]});
        if (std::isfinite(top)) {
            const double sx = p.x < 0.0 ? -1.0 : 1.0, sy = p.y < 0.0 ? -1.0 : 1.0,
                         sz = p.z < 0.0 ? -1.0 : 1.0;
            n = {sx * std::exp(l[0] - top), sy * std::exp(l[1] - top), sz * std::exp(l[2] - top)};
        }
    }
    double length = safe_length(n);
    if (!(length > 0.0) || !std::isfinite(length)) {
        n = p;
        length = safe_length(n);
        if (!(length > 0.0) || !std::isfinite(length)) return {0.0, 1.0, 0.0};
    }
    return n / length;
}

double superellipsoid_volume(const SuperellipsoidGeometry& g) {
    if (!g.valid) return -1.0;
    // 2 n e B(n/2 + 1, n) B(e/2, e/2)
    //   = 8 G(n/2 + 1) G(n + 1) / G(3n/2 + 1) * G(e/2 + 1)^2 / G(e + 1).
    const double e = g.e, n = g.n;
    const double ln =
        std::lgamma(0.5 * n + 1.0) + std::lgamma(n + 1.0) - std::lgamma(1.5 * n + 1.0);
    const double le = 2.0 * std::lgamma(0.5 * e + 1.0) - std::lgamma(e + 1.0);
    const double v = 8.0 * std::exp(ln + le);
    return std::isfinite(v) ? v : -1.0;
}

std::optional<SurfaceHit> intersect(const SuperellipsoidGeometry& g, const Ray3& ray, double s_min,
                                    double s_max) {
    if (!g.valid) return std::nullopt;
    const auto local = local_ray(ray, glm::dvec3(0.0), 1.7320508075688772);
    if (!local) return std::nullopt;
    const glm::dvec3& o = local->origin;
    const glm::dvec3& u = local->unit;

    // The stretch inside the clip box (POV-Ray's intersect_box).
    double k0 = -kInf, k1 = kInf;
    for (int i = 0; i < 3; ++i) {
        if (u[i] != 0.0) {
            double a = (-kClip - o[i]) / u[i], b = (kClip - o[i]) / u[i];
            if (a > b) std::swap(a, b);
            k0 = std::max(k0, a);
            k1 = std::min(k1, b);
        } else if (!(std::fabs(o[i]) <= kClip)) {
            return std::nullopt;
        }
    }
    const double slack = 1e-9;
    k0 = std::max(k0, local->to_t(s_min) - slack);
    k1 = std::min(k1, local->to_t(s_max) + slack);
    if (!(k0 <= k1) || !std::isfinite(k0) || !std::isfinite(k1)) return std::nullopt;

    const auto f = [&](double k) { return superellipsoid_function(g, local->at(k)); };
    const auto out = [](double v) { return v > 0.0; };  // F <= 0 is the solid

    struct Piece {
        double a, b, fa, fb;
    };
    Piece stack[96];
    int top = 0;
    stack[top++] = {k0, k1, f(k0), f(k1)};
    double k_hit = kInf;
    // A ray that runs within the surface (along a face of a near-cube, say)
    // keeps every piece's range around zero: split without end, its pieces
    // would number 2^depth. So splitting stops after kPieceBudget pieces
    // (an ordinary ray needs a few hundred, one tangent to a flat face up to
    // about 22,000); the pieces still on the stack
    // (at most 94) are then searched for a sign change at their ends or
    // middles only, which finds a crossing that is not a thin sliver.
    int budget = kPieceBudget;
    while (top > 0) {
        const Piece piece = stack[--top];
        const bool split = budget > 0;
        --budget;
        const glm::dvec3 pa = local->at(piece.a), pb = local->at(piece.b);
        if (!range_holds_zero(g, glm::min(pa, pb), glm::max(pa, pb))) continue;
        const double mid = 0.5 * (piece.a + piece.b);
        const double fm = f(mid);
        if (split && piece.b - piece.a > kLeaf && mid > piece.a && mid < piece.b && top < 94) {
            stack[top++] = {mid, piece.b, fm, piece.fb};
            stack[top++] = {piece.a, mid, piece.fa, fm};
            continue;
        }
        // A leaf: a sign change at its ends, or two about its middle.
        double lo = piece.a, hi = piece.b, flo = piece.fa, fhi = piece.fb;
        if (out(flo) == out(fhi)) {
            if (out(fm) == out(flo)) {
                // No sign change: a touch where F comes within its rounding
                // of 0 (a ray tangent to the surface), else nothing.
                // Only at a least |F| along the ray: before a crossing |F|
                // falls to the leaf's end, and the crossing is the next
                // leaf's (a half leaf beyond the end says which).
                double k = mid, least = std::fabs(fm);
                if (std::fabs(flo) < least) k = lo, least = std::fabs(flo);
                if (std::fabs(fhi) < least) k = hi, least = std::fabs(fhi);
                if (k != mid && least <= kRangeSlack) {
                    const double beyond = f(k + (k == lo ? -0.5 : 0.5) * (hi - lo));
                    if (out(beyond) != out(fm) || std::fabs(beyond) < least) continue;
                }
                const double s = local->to_s(k);
                if (least <= kRangeSlack && s > s_min && s < s_max) {
                    k_hit = k;
                    break;
                }
                continue;
            }
            hi = mid;
            fhi = fm;
        }
        for (int i = 0; i < 200; ++i) {
            const double m = 0.5 * (lo + hi);
            if (!(m > lo && m < hi)) break;
            const double fv = f(m);
            if (out(fv) == out(flo)) {
                lo = m;
                flo = fv;
            } else {
                hi = m;
                fhi = fv;
            }
        }
        const double k = std::fabs(flo) <= std::fabs(fhi) ? lo : hi;
        const double s = local->to_s(k);
        if (s > s_min && s < s_max) {
            k_hit = k;
            break;
        }
        // (At or before s_min: the search goes on behind it.)
    }
    if (!(k_hit < kInf)) return std::nullopt;

    SurfaceHit hit;
    hit.s = local->to_s(k_hit);
    hit.point = local->at(k_hit);
    hit.part = 0;
    hit.uv = glm::dvec2(0.0);
    hit.normal = superellipsoid_normal(g, hit.point);
    hit.shading_normal = hit.normal;
    hit.error = rounding_gamma(64) * (glm::abs(hit.point) + 1.0);
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside(const SuperellipsoidGeometry& g, glm::dvec3 p) {
    if (!g.valid) return false;
    // POV-Ray's Inside: F < EPSILON (1e-10).
    return superellipsoid_function(g, p) < 1e-10;
}

Box3 object_bounds(const SuperellipsoidGeometry& g) {
    if (!g.valid) return {glm::dvec3(0.0), glm::dvec3(0.0)};
    return {glm::dvec3(-1.0), glm::dvec3(1.0)};
}

bool surface_may_meet(const SuperellipsoidGeometry& g, const Box3& box) {
    if (!g.valid) return false;
    const Box3 wide = widened(box, meet_slack(box, 1.0) + 1e-12);
    if (!overlaps(wide, object_bounds(g))) return false;
    return range_holds_zero(g, wide.lo, wide.hi);
}

}  // namespace hexant::runtime::geometry
