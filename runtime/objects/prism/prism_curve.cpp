#include "runtime/objects/prism/prism_curve.hpp"

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
// How far past its ends a segment's side roots are taken: joints between
// segments agree only to rounding.
constexpr double kJoint = 1e-9;
// POV-Ray's EPSILON: a conic sweep has no cap, and no inside, at heights
// closer to its apex than this.
constexpr double kPovEpsilon = 1e-10;

using Cubic = std::array<double, 4>;  // ascending: d, c, b, a

Cubic component(const PrismSegment& s, int k) {
    return {s.d[k], s.c[k], s.b[k], s.a[k]};
}

double low(const PrismGeometry& g) {
    return std::min(g.height1, g.height2);
}
double high(const PrismGeometry& g) {
    return std::max(g.height1, g.height2);
}

bool valid(const PrismGeometry& g) {
    return !g.segments.empty() && std::isfinite(g.height1) && std::isfinite(g.height2);
}

// The box of a cubic over [0, 1] from its Bernstein control points, widened
// by the rounding of evaluating it.
void set_box(PrismSegment& s) {
    for (int k = 0; k < 2; ++k) {
        const double b[4] = {s.d[k], s.d[k] + s.c[k] / 3.0, s.d[k] + (2.0 * s.c[k] + s.b[k]) / 3.0,
                             s.a[k] + s.b[k] + s.c[k] + s.d[k]};
        const double margin =
            16.0 * kEpsilon *
            (std::fabs(s.a[k]) + std::fabs(s.b[k]) + std::fabs(s.c[k]) + std::fabs(s.d[k]));
        s.lo[k] = std::min({b[0], b[1], b[2], b[3]}) - margin;
        s.hi[k] = std::max({b[0], b[1], b[2], b[3]}) + margin;
    }
}

void outline_box(const PrismGeometry& g, glm::dvec2& lo, glm::dvec2& hi) {
    lo = glm::dvec2(kInf);
    hi = glm::dvec2(-kInf);
    for (const PrismSegment& s : g.segments) {
        lo = glm::min(lo, s.lo);
        hi = glm::max(hi, s.hi);
    }
}

// [lo, hi] times every y in [ya, yb]: the extremes are at the corners; a few
// ulps wider for the products' rounding.
void scale_range(double lo, double hi, double ya, double yb, double& out_lo, double& out_hi) {
    const double c[4] = {lo * ya, lo * yb, hi * ya, hi * yb};
    out_lo = std::min({c[0], c[1], c[2], c[3]});
    out_hi = std::max({c[0], c[1], c[2], c[3]});
    const double margin = 4.0 * kEpsilon * std::max(std::fabs(out_lo), std::fabs(out_hi));
    out_lo -= margin;
    out_hi += margin;
}

// Crossings of the outline with the half-line from q along axis `axis` (0:
// x, 1: z) toward `sign`, counted where the distance along is >= 0 (skip <
// 0), or > skip. A crossing is a change of side ("beyond q's line" or not,
// the half-open rule of outline.hpp) along a segment, read at its exact
// ends and between the roots of the other coordinate = q's: a joint on the
// line is then counted once where the outline passes through it and twice
// (or never) where it only touches, whichever of its two segments' roots
// rounding puts at the joint.
int crossings(const PrismGeometry& g, glm::dvec2 q, int axis, double sign, double skip) {
    const int other = 1 - axis;
    const double reach = std::max(skip, 0.0);
    const double v = q[other];
    auto counts = [&](double x) {
        const double along = (x - q[axis]) * sign;
        return skip < 0.0 ? along >= 0.0 : along > skip;
    };
    int count = 0;
    for (const PrismSegment& s : g.segments) {
        if (v < s.lo[other] || v > s.hi[other]) continue;
        if (sign > 0.0 ? s.hi[axis] - q[axis] < reach : q[axis] - s.lo[axis] < reach) continue;
        Cubic h = component(s, other);
        h[0] -= v;
        double breaks[8];
        int n = 0;
        breaks[n++] = 0.0;
        for (const double w : polynomial_roots(h, 0.0, 1.0))
            if (w > breaks[n - 1] && w < 1.0 && n < 7) breaks[n++] = w;
        breaks[n++] = 1.0;
        // Sides: the start, each piece between breaks (at its middle), the end.
        bool side = s.start[other] > v;
        for (int i = 0; i + 1 < n; ++i) {
            const bool piece = s.at(0.5 * (breaks[i] + breaks[i + 1]))[other] > v;
            if (piece != side && counts(i == 0 ? s.start[axis] : s.at(breaks[i])[axis])) ++count;
            side = piece;
        }
        if ((s.end[other] > v) != side && counts(s.end[axis])) ++count;
    }
    return count;
}

// POV-Ray's in_curve: the even-odd rule along +x.
bool in_outline(const PrismGeometry& g, glm::dvec2 q) {
    return crossings(g, q, 0, 1.0, -1.0) % 2 == 1;
}

// Whether the filled region lies on side n of the outline's point q: the
// parity of crossings beyond q along the axis nearer n (so the half-line
// leaves the outline at 45 degrees or more).
bool region_toward(const PrismGeometry& g, glm::dvec2 q, glm::dvec2 n, double skip) {
    const int axis = std::fabs(n.x) >= std::fabs(n.y) ? 0 : 1;
    return crossings(g, q, axis, n[axis] > 0.0 ? 1.0 : -1.0, skip) % 2 == 1;
}

}  // namespace

std::vector<PrismSegment> prism_segments(PrismSpline spline, std::span<const glm::dvec2> points) {
    for (const glm::dvec2& p : points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return {};
    const PrismOutline outline = prism_outline(spline, points);
    std::vector<PrismSegment> segments;
    segments.reserve(outline.segments.size());
    for (const auto& index : outline.segments) {
        // lathe_polynomial's segment 0 reads points 0..3 of the window.
        const auto p = lathe_polynomial<double>(
            spline, 0, [&](int j, int k) { return points[index[static_cast<std::size_t>(j)]][k]; });
        PrismSegment s;
        s.a = {p.a[0], p.a[1]};
        s.b = {p.b[0], p.b[1]};
        s.c = {p.c[0], p.c[1]};
        s.d = {p.d[0], p.d[1]};
        const bool ends_inside = spline == PrismSpline::quadratic || spline == PrismSpline::cubic;
        const std::size_t last = spline == PrismSpline::linear ? 1 : 3;
        s.start = points[index[ends_inside ? 1 : 0]];
        s.end = points[index[ends_inside ? 2 : last]];
        set_box(s);
        if (!std::isfinite(s.lo.x + s.lo.y + s.hi.x + s.hi.y)) return {};
        segments.push_back(s);
    }
    return segments;
}

std::optional<SurfaceHit> intersect_curved(const PrismGeometry& g, const Ray3& ray, double s_min,
                                           double s_max) {
    if (!valid(g)) return std::nullopt;
    const Box3 bounds = curved_bounds(g);
    const auto local = local_ray(ray, centre(bounds), half_diagonal(bounds));
    if (!local) return std::nullopt;
    const glm::dvec3& o = local->origin;
    const glm::dvec3& u = local->unit;
    const double y0 = low(g), y1 = high(g);
    const bool conic = g.sweep == PrismSweep::conic;

    double best_k = kInf, best_t = 0.0;
    int best_part = -1;
    auto consider = [&](double k, int part, double t) {
        if (!(k < best_k)) return;
        const double s = local->to_s(k);
        if (!(s > s_min && s < s_max)) return;
        best_k = k;
        best_part = part;
        best_t = t;
    };

    if (!g.open && u.y != 0.0) {
        for (int cap = 0; cap < 2; ++cap) {
            const double h = cap == 0 ? y0 : y1;
            if (conic && !(std::fabs(h) > kPovEpsilon)) continue;
            const double k = (h - o.y) / u.y;
            glm::dvec2 q(o.x + k * u.x, o.z + k * u.z);
            if (conic) q /= h;
            if (in_outline(g, q)) consider(k, cap, 0.0);
        }
    }

    const glm::dvec2 o2(o.x, o.z), d2(u.x, u.z);
    const double d2_squared = glm::dot(d2, d2);
    const glm::dvec3 w = glm::cross(o, u);  // normal of the plane of the ray and the apex
    if (conic || d2_squared > 0.0) {
        for (std::size_t j = 0; j < g.segments.size(); ++j) {
            const PrismSegment& s = g.segments[j];
            Cubic e;
            for (int i = 0; i < 4; ++i) {
                const Cubic x = component(s, 0), z = component(s, 1);
                e[i] = conic ? w.x * x[i] + w.z * z[i] : u.z * x[i] - u.x * z[i];
            }
            // The constant term from differences near the prism (o is near it).
            if (conic)
                e[0] += w.y;
            else
                e[0] = u.z * (s.d.x - o.x) - u.x * (s.d.y - o.z);
            for (const double root : polynomial_roots(e, -kJoint, 1.0 + kJoint)) {
                const double t = std::clamp(root, 0.0, 1.0);
                const glm::dvec2 f = s.at(t);
                double k;
                if (conic) {
                    const glm::dvec3 line(f.x, 1.0, f.y);
                    const glm::dvec3 ol = glm::cross(o, line), ul = glm::cross(u, line);
                    const double den = glm::dot(ul, ul);
                    if (!(den > 0.0)) continue;
                    k = -glm::dot(ol, ul) / den;
                } else {
                    k = glm::dot(f - o2, d2) / d2_squared;
                }
                const double y = o.y + k * u.y;
                if (!(y >= y0 && y <= y1)) continue;
                consider(k, 2 + static_cast<int>(j), t);
            }
        }
    }
    if (best_part < 0) return std::nullopt;

    SurfaceHit hit;
    hit.s = local->to_s(best_k);
    hit.part = best_part;
    hit.point = local->at(best_k);
    if (best_part < 2) {
        hit.point.y = best_part == 0 ? y0 : y1;  // exactly on the cap
        hit.normal = {0.0, best_part == 0 ? -1.0 : 1.0, 0.0};
        hit.uv = {hit.point.x, hit.point.z};
    } else {
        const PrismSegment& s = g.segments[static_cast<std::size_t>(best_part - 2)];
        const glm::dvec2 f = s.at(best_t);
        glm::dvec2 tangent = s.slope(best_t);
        if (tangent == glm::dvec2(0.0))  // a cusp (control points on an end): the chord
            tangent = s.at(std::min(best_t + 1e-6, 1.0)) - s.at(std::max(best_t - 1e-6, 0.0));
        const double y = std::clamp(hit.point.y, y0, y1);
        // On the surface: the outline's point, at the ray's height.
        hit.point = conic ? glm::dvec3(y * f.x, y, y * f.y) : glm::dvec3(f.x, y, f.y);
        glm::dvec2 lo, hi;
        outline_box(g, lo, hi);
        const double outline_size =
            std::max(max_abs({lo.x, lo.y, 0.0}), max_abs({hi.x, hi.y, 0.0}));
        glm::dvec2 n2(tangent.y, -tangent.x);
        if (region_toward(g, f, n2, 1e-9 * outline_size)) n2 = -n2;
        // A conic sweep turns the outline by 180 degrees below its apex.
        const glm::dvec3 n =
            conic ? (y < 0.0 ? -1.0 : 1.0) * glm::dvec3(n2.x, -(f.x * n2.x + f.y * n2.y), n2.y)
                  : glm::dvec3(n2.x, 0.0, n2.y);
        const double length = safe_length(n);
        hit.normal = length > 0.0 ? n / length : glm::dvec3(0.0, 1.0, 0.0);
        const double height = y1 - y0;
        hit.uv = {best_t, height > 0.0 ? std::clamp((y - y0) / height, 0.0, 1.0) : 0.0};
        const double size = std::max(max_abs(bounds.lo), max_abs(bounds.hi));
        hit.error = rounding_gamma(32) * (glm::abs(hit.point) + size);
    }
    hit.shading_normal = hit.normal;
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside_curved(const PrismGeometry& g, glm::dvec3 p) {
    if (!valid(g)) return false;
    if (!(p.y >= low(g) && p.y <= high(g))) return false;
    glm::dvec2 q(p.x, p.z);
    if (g.sweep == PrismSweep::conic) {
        if (!(std::fabs(p.y) > kPovEpsilon)) return false;
        q /= p.y;
    }
    return in_outline(g, q);
}

Box3 curved_bounds(const PrismGeometry& g) {
    if (g.segments.empty()) return {glm::dvec3(0.0), glm::dvec3(0.0)};
    glm::dvec2 lo, hi;
    outline_box(g, lo, hi);
    const double y0 = low(g), y1 = high(g);
    if (g.sweep == PrismSweep::linear) return {{lo.x, y0, lo.y}, {hi.x, y1, hi.y}};
    Box3 b{{0.0, y0, 0.0}, {0.0, y1, 0.0}};
    scale_range(lo.x, hi.x, y0, y1, b.lo.x, b.hi.x);
    scale_range(lo.y, hi.y, y0, y1, b.lo.z, b.hi.z);
    return b;
}

bool curved_surface_may_meet(const PrismGeometry& g, const Box3& box) {
    if (!valid(g)) return false;
    const Box3 bounds = curved_bounds(g);
    const double size = std::max(max_abs(bounds.lo), max_abs(bounds.hi));
    const Box3 wide = widened(box, meet_slack(box, size) + 1e-12 * size);
    if (!overlaps(wide, bounds)) return false;
    const double ya = std::max(low(g), wide.lo.y), yb = std::min(high(g), wide.hi.y);
    if (!(ya <= yb)) return false;
    const bool conic = g.sweep == PrismSweep::conic;
    // Whether the outline's piece in [lo, hi], at heights [y_lo, y_hi], may
    // meet the box's x-z rectangle.
    auto meets = [&](glm::dvec2 lo, glm::dvec2 hi, double y_lo, double y_hi) {
        if (conic) {
            scale_range(lo.x, hi.x, y_lo, y_hi, lo.x, hi.x);
            scale_range(lo.y, hi.y, y_lo, y_hi, lo.y, hi.y);
        }
        return lo.x <= wide.hi.x && hi.x >= wide.lo.x && lo.y <= wide.hi.z && hi.y >= wide.lo.z;
    };
    // The caps: the outline's box at a cap's height (conservative).
    if (!g.open) {
        glm::dvec2 lo, hi;
        outline_box(g, lo, hi);
        for (const double h : {low(g), high(g)})
            if (wide.lo.y <= h && h <= wide.hi.y && meets(lo, hi, h, h)) return true;
    }
    // The sides: each segment's pieces, halved while their enclosure (the
    // mean value form around the middle) may meet the box.
    struct Piece {
        double t0, t1;
        int depth;
    };
    for (const PrismSegment& s : g.segments) {
        if (!meets(s.lo, s.hi, ya, yb)) continue;
        const glm::dvec2 rounding =
            16.0 * kEpsilon * (glm::abs(s.a) + glm::abs(s.b) + glm::abs(s.c) + glm::abs(s.d));
        Piece stack[64];
        int top = 0;
        stack[top++] = {0.0, 1.0, 0};
        while (top > 0) {
            const Piece piece = stack[--top];
            const double mid = 0.5 * (piece.t0 + piece.t1), half = 0.5 * (piece.t1 - piece.t0);
            const double tmax = std::max(std::fabs(piece.t0), std::fabs(piece.t1));
            const glm::dvec2 slope_bound =
                3.0 * glm::abs(s.a) * tmax * tmax + 2.0 * glm::abs(s.b) * tmax + glm::abs(s.c);
            const glm::dvec2 at = s.at(mid), margin = slope_bound * half + rounding;
            if (!meets(at - margin, at + margin, ya, yb)) continue;
            if (piece.depth >= 20 || top >= 62) return true;
            stack[top++] = {mid, piece.t1, piece.depth + 1};
            stack[top++] = {piece.t0, mid, piece.depth + 1};
        }
    }
    return false;
}

}  // namespace hexant::runtime::geometry
