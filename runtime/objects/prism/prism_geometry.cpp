#include "runtime/objects/prism/prism_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/outline.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"
#include "runtime/objects/prism/prism_curve.hpp"

namespace hexant::runtime::geometry {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

const glm::dvec2& same(const glm::dvec2& q) {
    return q;
}

bool valid(const PrismGeometry& prism) {
    if (!std::isfinite(prism.height1) || !std::isfinite(prism.height2)) return false;
    for (const glm::dvec2& q : prism.points) {
        if (q != prism.points[0]) return true;
    }
    return false;
}

// cross(d, q - o): > 0 when q lies left of the line through o along d.
double side_of_line(glm::dvec2 o, glm::dvec2 d, glm::dvec2 q) {
    return difference_of_products(d.x, q.y - o.y, d.y, q.x - o.x);
}

// Whether the region lies to the right of edge a->b (the side of
// (b - a) rotated clockwise): count the crossings of a ray from the edge's
// midpoint toward that side with all other edges; an odd count means inside.
bool region_right_of_edge(const std::vector<glm::dvec2>& points, std::size_t ei, std::size_t ej) {
    const glm::dvec2 a = points[ei], b = points[ej];
    const glm::dvec2 m = 0.5 * a + 0.5 * b;
    const glm::dvec2 dir(b.y - a.y, a.x - b.x);
    bool odd = false;
    for_each_outline_edge(points.data(), points.size(), [&](std::size_t i, std::size_t j) {
        if (i == ei && j == ej) return;
        const glm::dvec2 c = points[i], d = points[j];
        const double sc = side_of_line(m, dir, c), sd = side_of_line(m, dir, d);
        if ((sc > 0.0) == (sd > 0.0)) return;  // half-open: one end strictly left
        const double lambda = sc / (sc - sd);
        const glm::dvec2 x = c + lambda * (d - c);
        if (glm::dot(x - m, dir) > 0.0) odd = !odd;
    });
    return odd;
}

struct Candidate {
    double t = kInf;
    int part = -1;
    double edge_fraction = 0.0;
    std::size_t ei = 0, ej = 0;
};

}  // namespace

PrismGeometry make_prism(PrismSpline spline, PrismSweep sweep, double height1, double height2,
                         std::vector<glm::dvec2> points, bool open) {
    PrismGeometry g{height1, height2, std::move(points), open, spline, sweep, {}};
    if (curved(g)) g.segments = prism_segments(spline, g.points);
    return g;
}

std::optional<SurfaceHit> intersect(const PrismGeometry& prism, const Ray3& ray, double s_min,
                                    double s_max) {
    if (curved(prism)) return intersect_curved(prism, ray, s_min, s_max);
    if (!valid(prism)) return std::nullopt;
    const Box3 bounds = object_bounds(prism);
    const auto local = local_ray(ray, centre(bounds), half_diagonal(bounds));
    if (!local) return std::nullopt;
    const glm::dvec3& o = local->origin;
    const glm::dvec3& u = local->unit;
    const double y0 = bounds.lo.y, y1 = bounds.hi.y;
    // The nearest candidate whose s lies in range.
    Candidate best;
    auto consider = [&](const Candidate& c) {
        if (!(c.t < best.t)) return;
        const double s = local->to_s(c.t);
        if (s > s_min && s < s_max) best = c;
    };

    const glm::dvec2 o2(o.x, o.z), d2(u.x, u.z);
    const double d2_squared = glm::dot(d2, d2);
    if (d2_squared > 0.0) {
        int edge_index = 0;
        for_each_outline_edge(
            prism.points.data(), prism.points.size(), [&](std::size_t i, std::size_t j) {
                const int index = edge_index++;
                const glm::dvec2 a = prism.points[i], b = prism.points[j];
                const double sa = side_of_line(o2, d2, a), sb = side_of_line(o2, d2, b);
                // The line through the ray crosses the edge when its ends are on
                // different sides (or one on it); both zero: the ray runs within
                // the face's plane, a grazing ray that sees no area.
                if ((sa > 0.0 && sb > 0.0) || (sa < 0.0 && sb < 0.0) || (sa == 0.0 && sb == 0.0)) {
                    return;
                }
                const double lambda = sa / (sa - sb);
                const glm::dvec2 x = a + lambda * (b - a);
                const double t = glm::dot(x - o2, d2) / d2_squared;
                const double y = o.y + t * u.y;
                if (!(y >= y0 && y <= y1)) return;
                Candidate c;
                c.t = t;
                c.part = 2 + index;
                c.edge_fraction = lambda;
                c.ei = i;
                c.ej = j;
                consider(c);
            });
    }
    if (!prism.open && u.y != 0.0) {
        for (int cap = 0; cap < 2; ++cap) {
            const double t = ((cap == 0 ? y0 : y1) - o.y) / u.y;
            const glm::dvec2 x(o.x + t * u.x, o.z + t * u.z);
            if (!inside_even_odd(prism.points.data(), prism.points.size(), same, x)) continue;
            Candidate c;
            c.t = t;
            c.part = cap;
            consider(c);
        }
    }
    if (best.part < 0) return std::nullopt;

    SurfaceHit hit;
    hit.s = local->to_s(best.t);
    hit.part = best.part;
    hit.point = local->at(best.t);
    const double height = y1 - y0;
    if (best.part < 2) {
        hit.point.y = best.part == 0 ? y0 : y1;  // exactly on the cap
        hit.normal = {0.0, best.part == 0 ? -1.0 : 1.0, 0.0};
        hit.uv = {hit.point.x, hit.point.z};
    } else {
        const glm::dvec2 a = prism.points[best.ei], b = prism.points[best.ej];
        const glm::dvec2 x = a + best.edge_fraction * (b - a);  // exactly on the face
        hit.point.x = x.x;
        hit.point.z = x.y;
        const glm::dvec2 right(b.y - a.y, a.x - b.x);
        const glm::dvec2 outward =
            region_right_of_edge(prism.points, best.ei, best.ej) ? -right : right;
        hit.normal =
            glm::dvec3(outward.x, 0.0, outward.y) / safe_length({outward.x, 0.0, outward.y});
        hit.uv = {best.edge_fraction,
                  height > 0.0 ? std::clamp((hit.point.y - y0) / height, 0.0, 1.0) : 0.0};
    }
    hit.shading_normal = hit.normal;
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside(const PrismGeometry& prism, glm::dvec3 p) {
    if (curved(prism)) return inside_curved(prism, p);
    if (!valid(prism)) return false;
    const double y0 = std::min(prism.height1, prism.height2);
    const double y1 = std::max(prism.height1, prism.height2);
    if (!(p.y >= y0 && p.y <= y1)) return false;
    return inside_even_odd(prism.points.data(), prism.points.size(), same, glm::dvec2(p.x, p.z));
}

Box3 object_bounds(const PrismGeometry& prism) {
    if (curved(prism)) return curved_bounds(prism);
    Box3 b{{kInf, std::min(prism.height1, prism.height2), kInf},
           {-kInf, std::max(prism.height1, prism.height2), -kInf}};
    for (const glm::dvec2& q : prism.points) {
        b.lo.x = std::min(b.lo.x, q.x);
        b.lo.z = std::min(b.lo.z, q.y);
        b.hi.x = std::max(b.hi.x, q.x);
        b.hi.z = std::max(b.hi.z, q.y);
    }
    if (prism.points.empty()) b.lo.x = b.lo.z = b.hi.x = b.hi.z = 0.0;
    return b;
}

bool surface_may_meet(const PrismGeometry& prism, const Box3& box) {
    if (curved(prism)) return curved_surface_may_meet(prism, box);
    if (!valid(prism)) return false;
    const Box3 bounds = object_bounds(prism);
    const double slack = meet_slack(box, std::max(max_abs(bounds.lo), max_abs(bounds.hi)));
    const Box3 wide = widened(box, slack);
    if (!overlaps(wide, bounds)) return false;
    const glm::dvec2 lo(wide.lo.x, wide.lo.z), hi(wide.hi.x, wide.hi.z);
    // The caps: a cap's height inside the box's y range and the filled
    // region meeting the box's x-z rectangle.
    if (!prism.open) {
        for (const double y : {bounds.lo.y, bounds.hi.y}) {
            if (wide.lo.y <= y && y <= wide.hi.y &&
                region_meets_rectangle(prism.points.data(), prism.points.size(), same, lo, hi)) {
                return true;
            }
        }
    }
    // The sides: the box's y range overlaps the heights (checked above) and
    // an edge meets the x-z rectangle.
    bool meets = false;
    for_each_outline_edge(
        prism.points.data(), prism.points.size(), [&](std::size_t i, std::size_t j) {
            if (!meets) meets = segment_meets_rectangle(prism.points[i], prism.points[j], lo, hi);
        });
    return meets;
}

}  // namespace hexant::runtime::geometry
