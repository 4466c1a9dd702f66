#include "runtime/objects/text/text_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/outline.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// cross(d, q - o): > 0 when q lies left of the line through o along d.
double side_of_line(glm::dvec2 o, glm::dvec2 d, glm::dvec2 q) {
    return difference_of_products(d.x, q.y - o.y, d.y, q.x - o.x);
}

// de Casteljau: stays within the control points' hull, exact at the ends.
glm::dvec2 point_at(const TextSegment& seg, double s) {
    if (!seg.quadratic) return s == 1.0 ? seg.p2 : seg.p0 + s * (seg.p2 - seg.p0);
    if (s == 0.0) return seg.p0;
    if (s == 1.0) return seg.p2;
    const glm::dvec2 a = seg.p0 + s * (seg.control - seg.p0);
    const glm::dvec2 b = seg.control + s * (seg.p2 - seg.control);
    return a + s * (b - a);
}

glm::dvec2 tangent_at(const TextSegment& seg, double s) {
    if (!seg.quadratic) return seg.p2 - seg.p0;
    const glm::dvec2 t = (1.0 - s) * (seg.control - seg.p0) + s * (seg.p2 - seg.control);
    if (t.x == 0.0 && t.y == 0.0) return seg.p2 - seg.p0;  // control on an end, at that end
    return t;
}

// The parameters in [0, 1] where the quadratic Bernstein polynomial with
// coefficients f0, f1, f2 ((1-s)^2 f0 + 2s(1-s) f1 + s^2 f2) is zero.
// Written as A s^2 + 2 B s + C with A = f0 - 2 f1 + f2, B = f1 - f0,
// C = f0, whose discriminant B^2 - A C equals f1^2 - f0 f2 (formed by
// difference_of_products, so without cancellation). When f0 and f2 differ in
// sign (or one is zero) there is a root in [0, 1]; rounding cannot lose it:
// the root nearest the interval is then clamped into it.
struct Roots {
    int count = 0;
    double s[2] = {0.0, 0.0};
};

Roots bernstein_roots(double f0, double f1, double f2) {
    Roots out;
    if (f0 == 0.0 && f1 == 0.0 && f2 == 0.0) return out;  // the line holds the whole curve
    const double A = (f0 - 2.0 * f1) + f2, B = f1 - f0, C = f0;
    const double disc = difference_of_products(f1, f1, f0, f2);
    const bool must_cross = (f0 > 0.0) != (f2 > 0.0) || f0 == 0.0 || f2 == 0.0;
    const QuadraticRoots r = solve_quadratic(A, B, C, must_cross ? std::max(disc, 0.0) : disc);
    for (int i = 0; i < r.count; ++i) {
        if (r.t[i] >= 0.0 && r.t[i] <= 1.0) out.s[out.count++] = r.t[i];
    }
    if (must_cross && out.count == 0) {
        if (f0 == 0.0) {
            out.s[out.count++] = 0.0;
        } else if (f2 == 0.0) {
            out.s[out.count++] = 1.0;
        } else if (r.count > 0) {
            // Rounding put the one crossing just outside: the nearest root, clamped.
            double best = r.t[0];
            auto distance = [](double t) { return t < 0.0 ? -t : t - 1.0; };
            for (int i = 1; i < r.count; ++i) {
                if (distance(r.t[i]) < distance(best)) best = r.t[i];
            }
            out.s[out.count++] = std::clamp(best, 0.0, 1.0);
        } else {
            // No root at all (a degenerate quadratic): the linear interpolation's.
            out.s[out.count++] = std::clamp(f0 / (f0 - f2), 0.0, 1.0);
        }
    }
    return out;
}

// Where the line through o along d meets the segment: parameters on the
// segment (closed [0, 1]).
Roots line_meets_segment(glm::dvec2 o, glm::dvec2 d, const TextSegment& seg) {
    Roots out;
    const double f0 = side_of_line(o, d, seg.p0), f2 = side_of_line(o, d, seg.p2);
    if (!seg.quadratic) {
        if ((f0 > 0.0 && f2 > 0.0) || (f0 < 0.0 && f2 < 0.0) || (f0 == 0.0 && f2 == 0.0)) {
            return out;
        }
        out.s[out.count++] = std::clamp(f0 / (f0 - f2), 0.0, 1.0);
        return out;
    }
    const double f1 = side_of_line(o, d, seg.control);
    // The curve lies in the hull of its control points.
    if ((f0 > 0.0 && f1 > 0.0 && f2 > 0.0) || (f0 < 0.0 && f1 < 0.0 && f2 < 0.0)) return out;
    return bernstein_roots(f0, f1, f2);
}

bool box_contains(glm::dvec2 lo, glm::dvec2 hi, glm::dvec2 p) {
    return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y;
}

// Whether the filled region lies to the right of the hit's tangent (the
// side of R = (t.y, -t.x)): the parity of the crossings of the half-line
// from the hit point q along R with the glyph's segments, leaving out the
// hit itself. Crossings closer than `tiny` (the hit's own vertex, when the
// hit lies at a segment's end) do not count.
bool filled_right_of(const TextGlyph& glyph, std::size_t hit_index, double hit_s, glm::dvec2 q,
                     glm::dvec2 r) {
    const double size = std::max(glm::length(glyph.hi - glyph.lo), 1e-300);
    const double tiny = 1e-12 * size * glm::length(r);
    bool odd = false;
    for (std::size_t j = 0; j < glyph.segments.size(); ++j) {
        const TextSegment& seg = glyph.segments[j];
        if (j == hit_index && !seg.quadratic) continue;
        const Roots roots = line_meets_segment(q, r, seg);
        int skip = -1;
        if (j == hit_index) {  // the hit's own root: the one nearest hit_s
            skip = 0;
            if (roots.count == 2 && std::fabs(roots.s[1] - hit_s) < std::fabs(roots.s[0] - hit_s)) {
                skip = 1;
            }
            if (roots.count == 0) skip = -1;
        }
        for (int k = 0; k < roots.count; ++k) {
            if (k == skip) continue;
            const double s = roots.s[k];
            if (s == 1.0) continue;  // half-open: a shared end belongs to the next segment
            const double along = glm::dot(point_at(seg, s) - q, r);
            if (along > tiny) odd = !odd;
        }
    }
    return odd;
}

bool valid(const TextGeometry& text) {
    if (!std::isfinite(text.thickness)) return false;
    for (const TextGlyph& g : text.glyphs) {
        if (!g.segments.empty()) return true;
    }
    return false;
}

// The t interval (closed) in which the 2D line o + t d lies in the box
// [lo, hi]; false if it never does.
bool line_box_interval(glm::dvec2 o, glm::dvec2 d, glm::dvec2 lo, glm::dvec2 hi, double& t0,
                       double& t1) {
    t0 = -kInf;
    t1 = kInf;
    for (int k = 0; k < 2; ++k) {
        if (d[k] == 0.0) {
            if (o[k] < lo[k] || o[k] > hi[k]) return false;
            continue;
        }
        double ta = (lo[k] - o[k]) / d[k], tb = (hi[k] - o[k]) / d[k];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (!(t0 <= t1)) return false;
    }
    return true;
}

bool boxes_overlap_2d(glm::dvec2 alo, glm::dvec2 ahi, glm::dvec2 blo, glm::dvec2 bhi) {
    return !(alo.x > bhi.x || blo.x > ahi.x || alo.y > bhi.y || blo.y > ahi.y);
}

// Whether the segment may meet the closed rectangle: false only if surely
// not (lines exactly by Liang-Barsky, quadratics by subdividing their
// control hulls' boxes).
bool segment_may_meet_rectangle(glm::dvec2 p0, glm::dvec2 c, glm::dvec2 p2, bool quadratic,
                                glm::dvec2 lo, glm::dvec2 hi, int depth = 0) {
    if (!quadratic) return segment_meets_rectangle(p0, p2, lo, hi);
    const glm::dvec2 blo = glm::min(glm::min(p0, c), p2), bhi = glm::max(glm::max(p0, c), p2);
    if (!boxes_overlap_2d(blo, bhi, lo, hi)) return false;
    if (box_contains(lo, hi, p0) || box_contains(lo, hi, p2)) return true;
    if (depth >= 8) return true;
    const glm::dvec2 a = 0.5 * (p0 + c), b = 0.5 * (c + p2), m = 0.5 * (a + b);
    return segment_may_meet_rectangle(p0, a, m, true, lo, hi, depth + 1) ||
           segment_may_meet_rectangle(m, b, p2, true, lo, hi, depth + 1);
}

struct Candidate {
    double t = kInf;
    int part = -1;
    std::size_t glyph = 0, segment = 0;
    double s = 0.0;
};

}  // namespace

TextGlyph make_text_glyph(const std::vector<std::vector<TextSegment>>& contours,
                          glm::dvec2 translation) {
    TextGlyph glyph;
    glyph.translation = translation;
    auto add = [&glyph](const TextSegment& seg) {
        if (!seg.quadratic) {
            if (seg.p0 != seg.p2) glyph.segments.push_back(seg);
            return;
        }
        if (seg.p0 == seg.p2 && seg.control == seg.p0) return;
        const double y0 = seg.p0.y, y1 = seg.control.y, y2 = seg.p2.y;
        const bool monotone = (y0 <= y1 && y1 <= y2) || (y0 >= y1 && y1 >= y2);
        const double denominator = (y0 - 2.0 * y1) + y2;
        const double t = monotone || denominator == 0.0 ? -1.0 : (y0 - y1) / denominator;
        if (!(t > 0.0 && t < 1.0)) {
            TextSegment piece = seg;
            if (!monotone) piece.control.y = std::clamp(y1, std::min(y0, y2), std::max(y0, y2));
            glyph.segments.push_back(piece);
            return;
        }
        // Split at the extreme in y; both halves' controls at its height
        // (as they are exactly), so each half is monotone in y.
        const glm::dvec2 a = seg.p0 + t * (seg.control - seg.p0);
        const glm::dvec2 b = seg.control + t * (seg.p2 - seg.control);
        glm::dvec2 m = a + t * (b - a);
        TextSegment first{seg.p0, {a.x, m.y}, m, true};
        TextSegment second{m, {b.x, m.y}, seg.p2, true};
        glyph.segments.push_back(first);
        glyph.segments.push_back(second);
    };
    for (const auto& contour : contours) {
        if (contour.empty()) continue;
        for (const TextSegment& seg : contour) add(seg);
        const glm::dvec2 start = contour.front().p0, end = contour.back().p2;
        if (start != end) add(TextSegment{end, 0.5 * (end + start), start, false});
    }
    if (glyph.segments.empty()) {
        glyph.lo = glyph.hi = translation;
        return glyph;
    }
    glyph.lo = glm::dvec2(kInf);
    glyph.hi = glm::dvec2(-kInf);
    for (const TextSegment& seg : glyph.segments) {
        glyph.lo = glm::min(glyph.lo, glm::min(seg.p0, seg.p2));
        glyph.hi = glm::max(glyph.hi, glm::max(seg.p0, seg.p2));
        if (seg.quadratic) {
            glyph.lo = glm::min(glyph.lo, seg.control);
            glyph.hi = glm::max(glyph.hi, seg.control);
        }
    }
    return glyph;
}

bool inside_outline(const TextGlyph& glyph, glm::dvec2 p) {
    if (glyph.segments.empty() || !box_contains(glyph.lo, glyph.hi, p)) return false;
    bool inside = false;
    for (const TextSegment& seg : glyph.segments) {
        const glm::dvec2 a = seg.p0 - p, b = seg.p2 - p;
        const bool a_above = a.y > 0.0, b_above = b.y > 0.0;
        if (a_above == b_above) continue;
        if (!seg.quadratic) {
            // As outline.hpp: the sign of a.x b.y - a.y b.x, exact.
            const double side = difference_of_products(a.x, b.y, a.y, b.x);
            if (b_above ? side > 0.0 : side < 0.0) inside = !inside;
            continue;
        }
        // Monotone in y (make_text_glyph): one parameter where y(s) = p.y.
        const glm::dvec2 c = seg.control - p;
        if (a.x > 0.0 && b.x > 0.0 && c.x > 0.0) {
            inside = !inside;
            continue;
        }
        if (a.x <= 0.0 && b.x <= 0.0 && c.x <= 0.0) continue;
        const Roots roots = bernstein_roots(a.y, c.y, b.y);
        if (roots.count == 0) continue;
        double s = roots.s[0];
        if (roots.count == 2 && std::fabs(roots.s[1] - 0.5) < std::fabs(s - 0.5)) s = roots.s[1];
        const double u = 1.0 - s;
        const double x = u * u * a.x + 2.0 * s * u * c.x + s * s * b.x;
        if (x > 0.0) inside = !inside;
    }
    return inside;
}

std::optional<SurfaceHit> intersect(const TextGeometry& text, const Ray3& ray, double s_min,
                                    double s_max) {
    if (!valid(text)) return std::nullopt;
    const Box3 bounds = object_bounds(text);
    const double size = half_diagonal(bounds);
    const auto local = local_ray(ray, centre(bounds), size);
    if (!local) return std::nullopt;
    const glm::dvec3& o = local->origin;
    const glm::dvec3& u = local->unit;
    const double thickness = text.thickness;
    const double z_lo = bounds.lo.z, z_hi = bounds.hi.z;

    // The t range in the slab z_lo <= z <= z_hi (for pruning only).
    double slab0 = -kInf, slab1 = kInf;
    if (u.z == 0.0) {
        if (o.z < z_lo || o.z > z_hi) return std::nullopt;
    } else {
        slab0 = (z_lo - o.z) / u.z;
        slab1 = (z_hi - o.z) / u.z;
        if (slab0 > slab1) std::swap(slab0, slab1);
    }

    Candidate best;
    auto consider = [&](const Candidate& c) {
        if (!(c.t < best.t)) return;
        const double s = local->to_s(c.t);
        if (s > s_min && s < s_max) best = c;
    };

    // Caps: z = 0 (part 0) then z = thickness (part 1).
    if (u.z != 0.0) {
        for (int cap = 0; cap < 2; ++cap) {
            const double t = ((cap == 0 ? 0.0 : thickness) - o.z) / u.z;
            if (!(t < best.t)) continue;
            const glm::dvec3 x = local->at(t);
            const glm::dvec2 x2(x.x, x.y);
            for (std::size_t g = 0; g < text.glyphs.size(); ++g) {
                if (!inside_outline(text.glyphs[g], x2)) continue;
                Candidate c;
                c.t = t;
                c.part = cap;
                c.glyph = g;
                consider(c);
                break;
            }
        }
    }

    // Walls (only for a positive thickness, as in POV-Ray).
    const glm::dvec2 o2(o.x, o.y), d2(u.x, u.y);
    const double d2_squared = glm::dot(d2, d2);
    if (thickness > 0.0 && d2_squared > 0.0) {
        const double margin = 1e-7 * (size + glm::length(o - centre(bounds)));
        for (std::size_t g = 0; g < text.glyphs.size(); ++g) {
            const TextGlyph& glyph = text.glyphs[g];
            if (glyph.segments.empty()) continue;
            double ta, tb;
            if (!line_box_interval(o2, d2, glyph.lo - margin, glyph.hi + margin, ta, tb)) continue;
            // The line's t runs along the unit direction, scaled by |d2|
            // in the plane: the box interval is in the same units.
            if (tb < slab0 - margin || ta > std::min(slab1, best.t) + margin) continue;
            for (std::size_t i = 0; i < glyph.segments.size(); ++i) {
                const TextSegment& seg = glyph.segments[i];
                const Roots roots = line_meets_segment(o2, d2, seg);
                for (int k = 0; k < roots.count; ++k) {
                    const glm::dvec2 x = point_at(seg, roots.s[k]);
                    const double t = glm::dot(x - o2, d2) / d2_squared;
                    const double z = std::fma(t, u.z, o.z);
                    if (!(z >= 0.0 && z <= thickness)) continue;
                    Candidate c;
                    c.t = t;
                    c.part = 2;
                    c.glyph = g;
                    c.segment = i;
                    c.s = roots.s[k];
                    consider(c);
                }
            }
        }
    }
    if (best.part < 0) return std::nullopt;

    SurfaceHit hit;
    hit.s = local->to_s(best.t);
    hit.part = best.part;
    hit.point = local->at(best.t);
    if (best.part < 2) {
        hit.point.z = best.part == 0 ? 0.0 : thickness;  // exactly on the cap
        hit.normal = {0.0, 0.0, best.part == 0 ? -1.0 : 1.0};
    } else {
        const TextGlyph& glyph = text.glyphs[best.glyph];
        const TextSegment& seg = glyph.segments[best.segment];
        const glm::dvec2 x = point_at(seg, best.s);  // on the curve
        hit.point.x = x.x;
        hit.point.y = x.y;
        hit.point.z = std::clamp(hit.point.z, 0.0, thickness);
        const glm::dvec2 tangent = tangent_at(seg, best.s);
        const glm::dvec2 right(tangent.y, -tangent.x);
        const glm::dvec2 outward =
            filled_right_of(glyph, best.segment, best.s, x, right) ? -right : right;
        const glm::dvec3 n(outward.x, outward.y, 0.0);
        hit.normal = n / safe_length(n);
    }
    hit.shading_normal = hit.normal;
    hit.uv = {hit.point.x, hit.point.y};
    // The point's error bound, as a triangle's (barycentric_error: a few
    // roundings of each coordinate's size): a cap's z is exact here, but a
    // secondary ray from it is carried into object space by a transform that
    // rounds at the size of the coordinates, and a glyph far from the text's
    // origin (a long line) would otherwise shadow itself.
    hit.error = rounding_gamma(10) * glm::abs(hit.point);
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside(const TextGeometry& text, glm::dvec3 p) {
    if (!valid(text)) return false;
    // POV-Ray's Inside: 0 <= z <= depth (never for a negative depth).
    if (!(p.z >= 0.0 && p.z <= text.thickness)) return false;
    const glm::dvec2 q(p.x, p.y);
    for (const TextGlyph& glyph : text.glyphs) {
        if (inside_outline(glyph, q)) return true;
    }
    return false;
}

Box3 object_bounds(const TextGeometry& text) {
    if (!valid(text)) return Box3::nowhere();
    glm::dvec2 lo(kInf), hi(-kInf);
    for (const TextGlyph& glyph : text.glyphs) {
        if (glyph.segments.empty()) continue;
        lo = glm::min(lo, glyph.lo);
        hi = glm::max(hi, glyph.hi);
    }
    return {{lo.x, lo.y, std::min(0.0, text.thickness)},
            {hi.x, hi.y, std::max(0.0, text.thickness)}};
}

bool surface_may_meet(const TextGeometry& text, const Box3& box) {
    if (!valid(text)) return false;
    const Box3 bounds = object_bounds(text);
    const double slack = meet_slack(box, std::max(max_abs(bounds.lo), max_abs(bounds.hi)));
    const Box3 wide = widened(box, slack);
    if (!overlaps(wide, bounds)) return false;
    const glm::dvec2 lo(wide.lo.x, wide.lo.y), hi(wide.hi.x, wide.hi.y);
    const double thickness = text.thickness;
    const bool cap0 = wide.lo.z <= 0.0 && 0.0 <= wide.hi.z;
    const bool cap1 = wide.lo.z <= thickness && thickness <= wide.hi.z;
    // Walls: the box's z range meets [0, thickness] (for thickness > 0).
    const bool walls = thickness > 0.0 && wide.lo.z <= thickness && wide.hi.z >= 0.0;
    for (const TextGlyph& glyph : text.glyphs) {
        if (glyph.segments.empty() || !boxes_overlap_2d(glyph.lo, glyph.hi, lo, hi)) continue;
        bool edge = false;
        for (const TextSegment& seg : glyph.segments) {
            if (segment_may_meet_rectangle(seg.p0, seg.control, seg.p2, seg.quadratic, lo, hi)) {
                edge = true;
                break;
            }
        }
        // A wall meets the box where an edge does; a cap where an edge does
        // or (no edge in the rectangle) where the rectangle lies inside.
        if (edge && (walls || cap0 || cap1)) return true;
        if ((cap0 || cap1) && inside_outline(glyph, 0.5 * lo + 0.5 * hi)) return true;
    }
    return false;
}

}  // namespace hexant::runtime::geometry
