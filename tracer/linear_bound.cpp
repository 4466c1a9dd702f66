#include "tracer/linear_bound.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>

#include "tracer/bound_rounding.hpp"

namespace hexant::tracer {

namespace {

struct Point {
    double u, v;
};

// The line (value at u = 0, value at u = 1) at or below every point, whose
// value at the middle of the points' span is largest: the edge of the
// lower convex hull over that middle (Andrew's monotone chain). The points
// come sorted by u.
std::pair<double, double> line_below(const Point* p, int n) {
    if (n == 1) return {p[0].v, p[0].v};
    Point hull[kMaxBins + 1];
    int h = 0;
    for (int i = 0; i < n; ++i) {
        // Pop while the last two and p[i] do not turn left (counter-clockwise).
        while (h >= 2) {
            const Point& a = hull[h - 2];
            const Point& b = hull[h - 1];
            const double cross = (b.u - a.u) * (p[i].v - a.v) - (b.v - a.v) * (p[i].u - a.u);
            if (cross > 0.0) break;
            --h;
        }
        hull[h++] = p[i];
    }
    const double middle = 0.5 * (p[0].u + p[n - 1].u);
    int e = 0;
    while (e + 2 < h && hull[e + 1].u < middle) ++e;
    double slope = 0.0;
    if (h >= 2) slope = (hull[e + 1].v - hull[e].v) / (hull[e + 1].u - hull[e].u);
    if (!std::isfinite(slope)) slope = 0.0;
    double a0 = hull[e].v - slope * hull[e].u;
    // Whatever the rounding above, no point may lie below the line.
    double worst = 0.0;
    for (int i = 0; i < n; ++i) worst = std::max(worst, (a0 + slope * p[i].u) - p[i].v);
    a0 -= worst;
    double a1 = a0 + slope;
    // The line is checked at the points only in exact arithmetic; a final
    // check of the two ends keeps it below in doubles too.
    for (int i = 0; i < n; ++i) {
        const double at = a0 + (a1 - a0) * p[i].u;
        if (at > p[i].v) {
            a0 -= at - p[i].v;
            a1 -= at - p[i].v;
        }
    }
    return {a0, a1};
}

// line_below over the two points (0, v0) and (1, v1), step for step
// (the same rounding, so the same line), without the hull.
std::pair<double, double> line_through(double v0, double v1) {
    double slope = v1 - v0;
    if (!std::isfinite(slope)) slope = 0.0;
    double a0 = v0 - std::max(0.0, (v0 + slope) - v1);
    double a1 = a0 + slope;
    for (const auto& [u, v] : {std::pair{0.0, v0}, std::pair{1.0, v1}}) {
        const double at = a0 + (a1 - a0) * u;
        if (at > v) {
            a0 -= at - v;
            a1 -= at - v;
        }
    }
    return {a0, a1};
}

double area_of_extents(double x, double y, double z) {
    return 2.0 * (x * y + y * z + z * x);
}

}  // namespace

double surface_area(const runtime::Box4& box) {
    if (box.is_empty()) return 0.0;
    const glm::dvec4 e = box.hi - box.lo;
    return area_of_extents(e.x, e.y, e.z);
}

double surface_area(const BinBox& box) {
    if (box.is_empty()) return 0.0;
    return area_of_extents(double(box.hi[0]) - box.lo[0], double(box.hi[1]) - box.lo[1],
                           double(box.hi[2]) - box.lo[2]);
}

BinBox BinBox::of(const runtime::Box4& box) {
    BinBox b;
    if (box.is_empty()) return b;
    for (int k = 0; k < 3; ++k) {
        b.lo[k] = float_down(box.lo[k]);
        b.hi[k] = float_up(box.hi[k]);
    }
    return b;
}

BinBox BinBox::of(const glm::dvec3& lo, const glm::dvec3& hi) {
    BinBox b;
    if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z)) return b;
    for (int k = 0; k < 3; ++k) {
        b.lo[k] = float_down(lo[k]);
        b.hi[k] = float_up(hi[k]);
    }
    return b;
}

BinBox BinBox::clipped(const runtime::Box4& region) const {
    BinBox b = *this;
    for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::max(lo[k], float_down(region.lo[k]));
        b.hi[k] = std::min(hi[k], float_up(region.hi[k]));
    }
    return b.is_empty() ? BinBox{} : b;
}

runtime::Box4 BinBox::box(const runtime::Interval& t) const {
    if (is_empty()) return runtime::Box4::empty();
    return {runtime::Event(lo[0], lo[1], lo[2], t.lo), runtime::Event(hi[0], hi[1], hi[2], t.hi)};
}

bool TimeBins::lines() const {
    if (!lined) return false;
    for (int b = 0; b < count; ++b)
        if (!bin[b].is_empty() && (edge[b].is_empty() || edge[b + 1].is_empty())) return false;
    return true;
}

TimeBins TimeBins::clipped(const runtime::Box4& region) const {
    TimeBins c = *this;
    for (int b = 0; b < count; ++b) c.bin[b] = bin[b].clipped(region);
    if (!lined) return c;
    for (int k = 0; k < 3; ++k) {
        const float lo = float_down(region.lo[k]), hi = float_up(region.hi[k]);
        for (int j = 0; j <= count; ++j) {
            bool below = true, above = true;  // edges j - 1 .. j + 1 all outside
            for (int i = std::max(0, j - 1); i <= std::min(count, j + 1); ++i) {
                below = below && edge[i].lo[k] <= lo;
                above = above && edge[i].hi[k] >= hi;
            }
            if (below) c.edge[j].lo[k] = lo;
            if (above) c.edge[j].hi[k] = hi;
        }
    }
    return c;
}

double TimeBins::mean_area() const {
    if (count == 0) return 0.0;
    const bool with_lines = lines();
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
        if (bin[i].is_empty()) continue;
        double e[3];
        for (int k = 0; k < 3; ++k) {
            double lo = bin[i].lo[k], hi = bin[i].hi[k];
            if (with_lines) {
                lo = std::max(lo, 0.5 * (double(edge[i].lo[k]) + edge[i + 1].lo[k]));
                hi = std::min(hi, 0.5 * (double(edge[i].hi[k]) + edge[i + 1].hi[k]));
            }
            e[k] = std::max(0.0, hi - lo);
        }
        sum += area_of_extents(e[0], e[1], e[2]);
    }
    return sum / count;
}

double LinearBox::mean_area() const {
    if (empty) return 0.0;
    // Extents e(u) = e0 + u de; the mean of 2 sum e_i(u) e_j(u) over u in
    // [0, 1] is 2 sum (e0_i e0_j + (e0_i de_j + de_i e0_j) / 2 + de_i de_j / 3).
    const glm::dvec3 e0 = hi0 - lo0, de = (hi1 - lo1) - e0;
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        sum += e0[i] * e0[j] + 0.5 * (e0[i] * de[j] + de[i] * e0[j]) + de[i] * de[j] / 3.0;
    }
    return std::max(0.0, 2.0 * sum);
}

double LinearExtent::mean_area() const {
    if (start.is_empty() || end.is_empty()) return surface_area(start) + surface_area(end);
    LinearBox box;
    box.empty = false;
    for (int k = 0; k < 3; ++k) {
        box.lo0[k] = start.lo[k];
        box.hi0[k] = start.hi[k];
        box.lo1[k] = end.lo[k];
        box.hi1[k] = end.hi[k];
    }
    return box.mean_area();
}

namespace {

// A side's value along axis k (mirrored for the upper end: larger is nearer).
double side_of(const BinBox& b, int k, bool upper) {
    return upper ? -double(b.hi[k]) : double(b.lo[k]);
}

// A non-empty bin's side at its start and end: its line's (from edge
// `first` to `last`) where the bin is lined and that is the nearer on
// average, else its box's side.
std::pair<double, double> bin_ends(const BinBox& bin, const BinBox* first, const BinBox* last,
                                   int k, bool upper) {
    const double held = side_of(bin, k, upper);
    if (first == nullptr) return {held, held};
    const double a = side_of(*first, k, upper), z = side_of(*last, k, upper);
    return 0.5 * (a + z) >= held ? std::pair{a, z} : std::pair{held, held};
}

// Stores a side's line, mirrored back for the upper end; none (an object
// without a finite box) leaves that side infinite.
void set_side(LinearBox& box, int k, bool upper, std::optional<std::pair<double, double>> line) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const auto [a0, a1] = line.value_or(std::pair{-kInf, -kInf});
    if (upper) {
        box.hi0[k] = -a0;
        box.hi1[k] = -a1;
    } else {
        box.lo0[k] = a0;
        box.lo1[k] = a1;
    }
}

}  // namespace

LinearBox fit_linear(const BinBox& bin, const BinBox& first, const BinBox& last, bool lined) {
    // The general fit below for n = 1: two points, the bin's start and end.
    LinearBox box;
    if (bin.is_empty()) return box;
    box.empty = false;
    for (int k = 0; k < 3; ++k)
        for (const bool upper : {false, true}) {
            const auto [start, end] =
                bin_ends(bin, lined ? &first : nullptr, lined ? &last : nullptr, k, upper);
            set_side(box, k, upper,
                     std::isfinite(start) && std::isfinite(end)
                         ? std::optional(line_through(start, end))
                         : std::nullopt);
        }
    return box;
}

LinearBox fit_linear(const TimeBins& bins) {
    LinearBox box;
    const int n = bins.count;
    if (n == 1) return fit_linear(bins.bin[0], bins.edge[0], bins.edge[1], bins.lines());
    if (n <= 0 || bins.is_empty()) return box;
    box.empty = false;
    const bool lines = bins.lines();
    constexpr double kNone = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        for (const bool upper : {false, true}) {
            // Each non-empty bin's values at its start and end.
            double start[kMaxBins], end[kMaxBins];
            for (int b = 0; b < n; ++b) {
                if (bins.bin[b].is_empty()) {
                    start[b] = end[b] = kNone;
                    continue;
                }
                std::tie(start[b], end[b]) =
                    bin_ends(bins.bin[b], lines ? &bins.edge[b] : nullptr,
                             lines ? &bins.edge[b + 1] : nullptr, k, upper);
            }
            // One point per bin boundary touching a non-empty bin: the
            // outermost of its neighbours' values there.
            Point points[kMaxBins + 1];
            int count = 0;
            for (int j = 0; j <= n; ++j) {
                const double v = std::min(j > 0 ? end[j - 1] : kNone, j < n ? start[j] : kNone);
                if (v != kNone) points[count++] = {double(j) / double(n), v};
            }
            bool finite = true;
            for (int i = 0; i < count; ++i) finite = finite && std::isfinite(points[i].v);
            set_side(box, k, upper,
                     finite ? std::optional(line_below(points, count)) : std::nullopt);
        }
    }
    return box;
}

}  // namespace hexant::tracer
