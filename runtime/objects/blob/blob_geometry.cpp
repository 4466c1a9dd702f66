#include "runtime/objects/blob/blob_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/polynomial_roots.hpp"
#include "runtime/time/interval.hpp"

namespace hexant::runtime::geometry {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// POV-Ray's blob.cpp INSIDE_TOLERANCE.
constexpr double kInsideTolerance = 1.0e-6;
// Shorter cylinders are spheres (POV-Ray refuses them: "Degenerate
// cylindrical component in blob", length < EPSILON).
constexpr double kDegenerateLength = 1.0e-10;

bool finite_matrix(const glm::dmat4& m) {
    for (int i = 0; i < 4; ++i)
        if (!is_finite(glm::dvec3(m[i])) || !std::isfinite(m[i].w)) return false;
    return true;
}

bool usable(const BlobComponent& c) {
    return c.radius > 0.0 && std::isfinite(c.radius) && c.strength != 0.0 &&
           std::isfinite(c.strength) && is_finite(c.a) &&
           (c.kind == BlobComponent::Kind::sphere || is_finite(c.b)) &&
           (!c.transformed || (finite_matrix(c.to_blob) && finite_matrix(c.to_component)));
}

// A point and a direction of blob space in the component's own space.
glm::dvec3 local_point(const BlobComponent& c, const glm::dvec3& p) {
    return c.transformed ? glm::dvec3(c.to_component * glm::dvec4(p, 1.0)) : p;
}
glm::dvec3 local_direction(const BlobComponent& c, const glm::dvec3& d) {
    return c.transformed ? glm::dmat3(c.to_component) * d : d;
}

bool is_cylinder(const BlobComponent& c) {
    return c.kind == BlobComponent::Kind::cylinder && glm::length(c.b - c.a) >= kDegenerateLength;
}

// The point of the component's centre or segment nearest p.
glm::dvec3 nearest(const BlobComponent& c, const glm::dvec3& p) {
    if (!is_cylinder(c)) return c.a;
    const glm::dvec3 axis = c.b - c.a;
    const double t = std::clamp(glm::dot(p - c.a, axis) / glm::dot(axis, axis), 0.0, 1.0);
    return c.a + t * axis;
}

// s (1 - q / R^2)^2 for q < R^2, else 0.
double falloff(const BlobComponent& c, double q) {
    const double r2 = c.radius * c.radius;
    if (!(q < r2)) return 0.0;
    const double f = 1.0 - q / r2;
    return c.strength * f * f;
}

// One piece of a component along the ray: where its influence holds, and
// how its squared distance is measured (from `centre`, or, for a cylinder's
// body, radially from the axis through `centre` along unit `axis`), all in
// the component's space, where the ray is o + t d.
struct Piece {
    const BlobComponent* component;
    glm::dvec3 centre;
    glm::dvec3 axis;  // zero for a ball
    double lo, hi;    // the influence interval in unit-direction parameter
    glm::dvec3 o, d;  // the ray in the component's space
};

// Where |w + t d|^2 <= r2 (d may be zero).
bool quadratic_interval(const glm::dvec3& w, const glm::dvec3& d, double r2, double& lo,
                        double& hi) {
    const double dd = glm::dot(d, d);
    if (!(dd > 1e-300)) {
        if (glm::dot(w, w) < r2) {
            lo = -kInf;
            hi = kInf;
            return true;
        }
        return false;
    }
    const double t0 = -glm::dot(w, d) / dd;
    const glm::dvec3 closest = w + t0 * d;
    const double gap = r2 - glm::dot(closest, closest);
    if (!(gap > 0.0)) return false;
    const double half = std::sqrt(gap / dd);
    lo = t0 - half;
    hi = t0 + half;
    return true;
}

// Where lo_z <= z0 + t dz <= hi_z.
bool slab_interval(double z0, double dz, double lo_z, double hi_z, double& lo, double& hi) {
    if (dz == 0.0) {
        if (z0 >= lo_z && z0 <= hi_z) {
            lo = -kInf;
            hi = kInf;
            return true;
        }
        return false;
    }
    double a = (lo_z - z0) / dz, b = (hi_z - z0) / dz;
    if (a > b) std::swap(a, b);
    lo = a;
    hi = b;
    return true;
}

void add_pieces(const BlobComponent& c, const glm::dvec3& o, const glm::dvec3& d, double t_min,
                double t_max, std::vector<Piece>& out) {
    const double r2 = c.radius * c.radius;
    const auto push = [&](const glm::dvec3& centre, const glm::dvec3& axis, double lo, double hi) {
        lo = std::max(lo, t_min);
        hi = std::min(hi, t_max);
        if (lo < hi) out.push_back({&c, centre, axis, lo, hi, o, d});
    };
    double lo = 0.0, hi = 0.0;
    if (!is_cylinder(c)) {
        if (quadratic_interval(o - c.a, d, r2, lo, hi)) push(c.a, glm::dvec3(0.0), lo, hi);
        return;
    }
    const double length = glm::length(c.b - c.a);
    const glm::dvec3 u = (c.b - c.a) / length;
    const glm::dvec3 w = o - c.a;
    const double z0 = glm::dot(w, u), dz = glm::dot(d, u);
    double slo = 0.0, shi = 0.0;
    // The body: radial distance, 0 <= z <= length.
    if (quadratic_interval(w - z0 * u, d - dz * u, r2, lo, hi) &&
        slab_interval(z0, dz, 0.0, length, slo, shi))
        push(c.a, u, std::max(lo, slo), std::min(hi, shi));
    // The caps: half balls at the base (z <= 0) and the apex (z >= length).
    if (quadratic_interval(w, d, r2, lo, hi) && slab_interval(z0, dz, -kInf, 0.0, slo, shi))
        push(c.a, glm::dvec3(0.0), std::max(lo, slo), std::min(hi, shi));
    if (quadratic_interval(o - c.b, d, r2, lo, hi) && slab_interval(z0, dz, length, kInf, slo, shi))
        push(c.b, glm::dvec3(0.0), std::max(lo, slo), std::min(hi, shi));
}

// The piece's field along p0 + u d as a quartic in u (ascending), added
// into `sum`: s (A + B u + C u^2)^2 with q(u) = qc + qb u + qa u^2,
// A = 1 - qc / R^2, B = -qb / R^2, C = -qa / R^2.
void add_quartic(const Piece& piece, const glm::dvec3& p0, const glm::dvec3& d,
                 std::array<double, 5>& sum) {
    glm::dvec3 w = p0 - piece.centre, e = d;
    if (piece.axis != glm::dvec3(0.0)) {
        w -= glm::dot(w, piece.axis) * piece.axis;
        e -= glm::dot(e, piece.axis) * piece.axis;
    }
    const BlobComponent& c = *piece.component;
    const double k = 1.0 / (c.radius * c.radius);
    const double a = 1.0 - k * glm::dot(w, w), b = -k * 2.0 * glm::dot(w, e),
                 cc = -k * glm::dot(e, e);
    const double s = c.strength;
    sum[0] += s * a * a;
    sum[1] += s * 2.0 * a * b;
    sum[2] += s * (b * b + 2.0 * a * cc);
    sum[3] += s * 2.0 * b * cc;
    sum[4] += s * cc * cc;
}

}  // namespace

double blob_field(const BlobGeometry& blob, const glm::dvec3& p) {
    double sum = 0.0;
    for (const auto& c : blob.components) {
        if (!usable(c)) continue;
        const glm::dvec3 q = local_point(c, p);
        const glm::dvec3 v = q - nearest(c, q);
        sum += falloff(c, glm::dot(v, v));
    }
    return sum;
}

void blob_component_densities(const BlobGeometry& blob, const glm::dvec3& p,
                              std::vector<double>& out) {
    out.clear();
    for (const auto& c : blob.components) {
        double density = 0.0;
        if (usable(c)) {
            const glm::dvec3 q = local_point(c, p);
            const glm::dvec3 v = q - nearest(c, q);
            density = std::fabs(falloff(c, glm::dot(v, v)));
        }
        out.push_back(density);
    }
}

glm::dvec3 blob_field_descent(const BlobGeometry& blob, const glm::dvec3& p) {
    glm::dvec3 sum(0.0);
    for (const auto& c : blob.components) {
        if (!usable(c)) continue;
        const glm::dvec3 v = local_point(c, p) - nearest(c, local_point(c, p));
        const double q = glm::dot(v, v), r2 = c.radius * c.radius;
        if (!(q <= r2)) continue;
        // POV-Ray's element_normal: -2 c0 d^2 - c1 = 2 s / R^2 (1 - d^2 / R^2);
        // a transformed one's gradient goes out by to_component's transpose
        // (its MTransNormal).
        const glm::dvec3 local = (2.0 * c.strength / r2 * (1.0 - q / r2)) * v;
        sum += c.transformed ? glm::transpose(glm::dmat3(c.to_component)) * local : local;
    }
    return sum;
}

std::optional<SurfaceHit> intersect(const BlobGeometry& blob, const Ray3& ray, double s_min,
                                    double s_max) {
    if (!(s_min < s_max) || !is_finite(ray.origin) || !is_finite(ray.direction))
        return std::nullopt;
    const double length = glm::length(ray.direction);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    // A unit direction, parameter t = s |D|.
    const glm::dvec3 d = ray.direction / length;
    const double t_min = s_min * length, t_max = s_max * length;
    std::vector<Piece> pieces;
    for (const auto& c : blob.components)
        if (usable(c))
            add_pieces(c, local_point(c, ray.origin), local_direction(c, d), t_min, t_max, pieces);
    if (pieces.empty()) return std::nullopt;
    std::vector<double> events;
    events.reserve(2 * pieces.size());
    for (const auto& p : pieces) {
        events.push_back(p.lo);
        events.push_back(p.hi);
    }
    std::sort(events.begin(), events.end());
    events.erase(std::unique(events.begin(), events.end()), events.end());
    for (std::size_t i = 0; i + 1 < events.size(); ++i) {
        const double lo = events[i], hi = events[i + 1];
        const double mid = 0.5 * lo + 0.5 * hi;
        std::array<double, 5> quartic{};
        bool any = false;
        for (const auto& p : pieces)
            if (p.lo <= mid && mid <= p.hi) {
                add_quartic(p, p.o + lo * p.d, p.d, quartic);
                any = true;
            }
        if (!any) continue;
        quartic[0] -= blob.threshold;
        const PolynomialRoots roots = polynomial_roots(quartic, 0.0, hi - lo);
        for (const double u : roots) {
            const double t = lo + u;
            if (!(t > t_min && t < t_max)) continue;
            SurfaceHit hit;
            hit.s = t / length;
            hit.point = ray.origin + t * d;
            glm::dvec3 n = blob_field_descent(blob, hit.point);
            const double nl = glm::length(n);
            n = nl > 0.0 && std::isfinite(nl) ? n / nl : glm::dvec3(1.0, 0.0, 0.0);
            hit.normal = hit.shading_normal = n;
            hit.uv = glm::dvec2(0.0);
            hit.part = 0;
            if (!is_finite(hit) || !(hit.s > s_min && hit.s < s_max)) continue;
            return hit;
        }
    }
    return std::nullopt;
}

bool inside(const BlobGeometry& blob, glm::dvec3 p) {
    return blob_field(blob, p) > blob.threshold - kInsideTolerance;
}

namespace {

// The box around the image of `box` under the affine map m, by outward
// rounded interval arithmetic (each coordinate appears once per row, so
// the enclosure is the exact box, rounded out).
Box3 mapped_box(const glm::dmat4& m, const Box3& box) {
    const Interval x(box.lo.x, box.hi.x), y(box.lo.y, box.hi.y), z(box.lo.z, box.hi.z);
    Box3 out;
    for (int i = 0; i < 3; ++i) {
        const Interval v = Interval(m[0][i]) * x + Interval(m[1][i]) * y + Interval(m[2][i]) * z +
                           Interval(m[3][i]);
        out.lo[i] = v.lo;
        out.hi[i] = v.hi;
    }
    return out;
}

// The box of blob space `box` in the component's space (a box around the
// parallelepiped it becomes there).
Box3 local_box(const BlobComponent& c, const Box3& box) {
    return c.transformed ? mapped_box(c.to_component, box) : box;
}

}  // namespace

Box3 object_bounds(const BlobGeometry& blob) {
    Box3 box = Box3::nowhere();
    for (const auto& c : blob.components) {
        if (!usable(c)) continue;
        const glm::dvec3 lo = is_cylinder(c) ? glm::min(c.a, c.b) : c.a;
        const glm::dvec3 hi = is_cylinder(c) ? glm::max(c.a, c.b) : c.a;
        Box3 reach{lo - c.radius, hi + c.radius};
        if (c.transformed) reach = mapped_box(c.to_blob, reach);
        box.lo = glm::min(box.lo, reach.lo);
        box.hi = glm::max(box.hi, reach.hi);
    }
    return box;
}

bool surface_may_meet(const BlobGeometry& blob, const Box3& box) {
    double lo = 0.0, hi = 0.0, magnitude = std::fabs(blob.threshold);
    for (const auto& c : blob.components) {
        if (!usable(c)) continue;
        const Box3 local = local_box(c, box);
        // Least distance: from the box to the centre, or (a lower bound) to
        // the segment's box; greatest: at a corner (distance to a point or
        // segment is convex).
        const glm::dvec3 slo = is_cylinder(c) ? glm::min(c.a, c.b) : c.a;
        const glm::dvec3 shi = is_cylinder(c) ? glm::max(c.a, c.b) : c.a;
        const glm::dvec3 gap = glm::max(glm::max(local.lo - shi, slo - local.hi), glm::dvec3(0.0));
        const double q_min = glm::dot(gap, gap);
        double q_max = 0.0;
        for (const auto& corner : corners(local)) {
            const glm::dvec3 v = corner - nearest(c, corner);
            q_max = std::max(q_max, glm::dot(v, v));
        }
        const double near = falloff(c, q_min), far = falloff(c, q_max);
        lo += std::min(near, far);
        hi += std::max(near, far);
        magnitude += std::fabs(c.strength);
    }
    if (std::isnan(lo) || std::isnan(hi)) return true;
    const double slack = 1e-9 * magnitude;
    if (!(lo - slack <= blob.threshold && blob.threshold <= hi + slack)) return false;
    // A second bound, tight where the first is loose (components whose
    // gradients cancel, as between two spheres, and boxes larger than the
    // gaps between them): Taylor's about the box's centre c,
    //   |f(x) - f(c) - grad f(c) . (x - c)| <= M |x - c|^2 / 2,
    // M a Lipschitz constant of grad f. Each component is s phi(q) with
    // phi(q) = (1 - q / R^2)^2 inside its reach and 0 beyond, q the squared
    // distance to a point or a segment (whose gradient 2 (x - nearest) is
    // 2-Lipschitz); phi is C^1 at q = R^2, and the Hessian of phi(q),
    // phi'(q) grad^2 q + phi''(q) grad q grad q^T, is at most
    // 4 / R^2 + 8 q / R^4 <= 12 / R^2 in norm:
    // M = sum of 12 |s| / R^2 over the components that reach the box, a
    // transformed one's times |J|^2 (its Hessian is J^T H J, J its
    // to_component's linear part; |J| at most J's Frobenius norm).
    const glm::dvec3 c = 0.5 * box.lo + 0.5 * box.hi;
    const glm::dvec3 half = 0.5 * (box.hi - box.lo);
    double m = 0.0;
    for (const auto& comp : blob.components) {
        if (!usable(comp)) continue;
        const Box3 local = local_box(comp, box);
        const glm::dvec3 slo = is_cylinder(comp) ? glm::min(comp.a, comp.b) : comp.a;
        const glm::dvec3 shi = is_cylinder(comp) ? glm::max(comp.a, comp.b) : comp.a;
        const glm::dvec3 gap = glm::max(glm::max(local.lo - shi, slo - local.hi), glm::dvec3(0.0));
        if (!(glm::dot(gap, gap) < comp.radius * comp.radius)) continue;
        double stretch = 1.0;
        if (comp.transformed) {
            const glm::dmat3 j(comp.to_component);
            stretch = glm::dot(j[0], j[0]) + glm::dot(j[1], j[1]) + glm::dot(j[2], j[2]);
            // (Rounded up: the bound must not fall short.)
            stretch *= 1.0 + 1e-12;
        }
        m += 12.0 * std::fabs(comp.strength) / (comp.radius * comp.radius) * stretch;
    }
    const double f = blob_field(blob, c);
    // (blob_field_descent is POV-Ray's half of -grad f.)
    const glm::dvec3 g = -2.0 * blob_field_descent(blob, c);
    const double linear =
        std::fabs(g.x) * half.x + std::fabs(g.y) * half.y + std::fabs(g.z) * half.z;
    const double reach = linear + 0.5 * m * glm::dot(half, half);
    if (!std::isfinite(reach) || !std::isfinite(f)) return true;
    // Rounding: the field and gradient sums, a few ulps of the magnitude.
    return f - reach - slack <= blob.threshold && blob.threshold <= f + reach + slack;
}

}  // namespace hexant::runtime::geometry
