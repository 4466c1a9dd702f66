#include "runtime/objects/poly/poly_geometry.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/polynomial_roots.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"
#include "runtime/time/interval.hpp"

namespace hexant::runtime::geometry {

namespace {

constexpr int kMaxOrder = kMaxPolynomialDegree;
using Coefficients = std::array<double, kMaxOrder + 1>;  // ascending powers of t

// (a + b t)^k for k = 0..order, each ascending in t.
void powers_of_line(double a, double b, int order, std::array<Coefficients, kMaxOrder + 1>& out) {
    out[0].fill(0.0);
    out[0][0] = 1.0;
    for (int k = 1; k <= order; ++k) {
        out[k].fill(0.0);
        for (int m = 0; m < k; ++m) {
            out[k][m] += a * out[k - 1][m];
            out[k][m + 1] += b * out[k - 1][m];
        }
    }
}

// p over the box by interval arithmetic (outward rounded): it holds p's
// exact value at every point of the box.
Interval value_over(const PolyGeometry& g, const Box3& box) {
    const auto& terms = poly_terms(g.order);
    const Interval x(box.lo.x, box.hi.x), y(box.lo.y, box.hi.y), z(box.lo.z, box.hi.z);
    const auto power = [](const Interval& v, int k) {
        Interval r(1.0);
        for (int i = 0; i < k; ++i) r = r * v;
        return r;
    };
    Interval sum(0.0);
    for (std::size_t n = 0; n < g.coefficients.size(); ++n) {
        if (g.coefficients[n] == 0.0) continue;
        const auto& e = terms[n];
        sum = sum + Interval(g.coefficients[n]) * power(x, e[0]) * power(y, e[1]) * power(z, e[2]);
    }
    return sum;
}

}  // namespace

const std::vector<std::array<int, 3>>& poly_terms(int order) {
    static const auto tables = [] {
        std::array<std::vector<std::array<int, 3>>, kMaxOrder + 1> all;
        for (int n = 1; n <= kMaxOrder; ++n)
            for (int i = n; i >= 0; --i)
                for (int j = n - i; j >= 0; --j)
                    for (int k = n - i - j; k >= 0; --k) all[n].push_back({i, j, k});
        return all;
    }();
    return tables.at(static_cast<std::size_t>(order));
}

double evaluate(const PolyGeometry& g, const glm::dvec3& p) {
    const auto& terms = poly_terms(g.order);
    double sum = 0.0;
    for (std::size_t n = 0; n < g.coefficients.size(); ++n) {
        const auto& e = terms[n];
        if (g.coefficients[n] == 0.0) continue;
        sum += g.coefficients[n] * std::pow(p.x, e[0]) * std::pow(p.y, e[1]) * std::pow(p.z, e[2]);
    }
    return sum;
}

glm::dvec3 gradient(const PolyGeometry& g, const glm::dvec3& p) {
    const auto& terms = poly_terms(g.order);
    glm::dvec3 d(0.0);
    for (std::size_t n = 0; n < g.coefficients.size(); ++n) {
        const double c = g.coefficients[n];
        if (c == 0.0) continue;
        const auto& e = terms[n];
        const double px = std::pow(p.x, e[0]), py = std::pow(p.y, e[1]), pz = std::pow(p.z, e[2]);
        if (e[0] > 0) d.x += c * e[0] * std::pow(p.x, e[0] - 1) * py * pz;
        if (e[1] > 0) d.y += c * e[1] * px * std::pow(p.y, e[1] - 1) * pz;
        if (e[2] > 0) d.z += c * e[2] * px * py * std::pow(p.z, e[2] - 1);
    }
    return d;
}

std::optional<SurfaceHit> intersect(const PolyGeometry& g, const Ray3& ray, double s_min,
                                    double s_max) {
    if (g.order < 1 || g.order > kMaxOrder) return std::nullopt;
    // Polys are written about the object's origin, at about unit size.
    const auto local = local_ray(ray, glm::dvec3(0.0), 1.0);
    if (!local) return std::nullopt;
    const auto& terms = poly_terms(g.order);
    std::array<Coefficients, kMaxOrder + 1> px, py, pz;
    powers_of_line(local->origin.x, local->unit.x, g.order, px);
    powers_of_line(local->origin.y, local->unit.y, g.order, py);
    powers_of_line(local->origin.z, local->unit.z, g.order, pz);
    Coefficients along{};
    for (std::size_t n = 0; n < g.coefficients.size(); ++n) {
        const double c = g.coefficients[n];
        if (c == 0.0) continue;
        const auto& e = terms[n];
        // x^i y^j z^k along the ray: the product of three polynomials in t.
        Coefficients xy{};
        for (int a = 0; a <= e[0]; ++a)
            for (int b = 0; b <= e[1]; ++b) xy[a + b] += px[e[0]][a] * py[e[1]][b];
        for (int ab = 0; ab <= e[0] + e[1]; ++ab)
            for (int k = 0; k <= e[2]; ++k) along[ab + k] += c * xy[ab] * pz[e[2]][k];
    }
    const double t_lo = local->to_t(s_min), t_hi = local->to_t(s_max);
    const PolynomialRoots roots = polynomial_roots(
        std::span<const double>(along.data(), static_cast<std::size_t>(g.order) + 1),
        std::max(t_lo, -std::numeric_limits<double>::max()), t_hi);
    for (const double t : roots) {
        const double s = local->to_s(t);
        if (!(s > s_min && s < s_max)) continue;
        SurfaceHit hit;
        hit.s = s;
        hit.point = local->at(t);
        glm::dvec3 n = gradient(g, hit.point);
        const double length = safe_length(n);
        n = length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(1.0, 0.0, 0.0);
        hit.normal = n;
        hit.shading_normal = n;
        hit.uv = glm::dvec2(0.0);
        hit.part = 0;
        // The point's coordinates, rounded from a root good to a few ulps
        // of t and its place along the ray; and the point's distance from
        // the surface, |p| there over the gradient's length (to first
        // order), since the ray's polynomial was rounded from the shape's:
        // on a stiff quartic (POV-Ray's quarcyl, steiner) that distance is
        // far beyond the coordinates' rounding, and a shadow ray leaving
        // from nearer would find the surface it left.
        const Interval at_point = value_over(g, Box3{hit.point, hit.point});
        double off_surface = std::max(std::fabs(at_point.lo), std::fabs(at_point.hi)) / length;
        if (!std::isfinite(off_surface)) off_surface = 0.0;
        hit.error = rounding_gamma(8 + 4 * g.order) * (glm::abs(hit.point) + std::fabs(t)) +
                    glm::dvec3(off_surface);
        if (is_finite(hit)) return hit;
    }
    return std::nullopt;
}

bool inside(const PolyGeometry& g, glm::dvec3 p) {
    return !(evaluate(g, p) > 0.0);
}

// Where p's range over the box excludes 0, the surface does not meet the box.
bool surface_may_meet(const PolyGeometry& g, const Box3& box) {
    const Interval sum = value_over(g, box);
    return !(sum.lo > 0.0 || sum.hi < 0.0);
}

}  // namespace hexant::runtime::geometry
