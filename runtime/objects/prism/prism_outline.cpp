#include "runtime/objects/prism/prism_outline.hpp"

#include <cmath>

namespace hexant::runtime::geometry {

namespace {

constexpr double kPovEpsilon = 1e-10;  // POV-Ray's EPSILON

// Parse_Prism's and Compute_Prism's test for "the same point".
bool same(glm::dvec2 p, glm::dvec2 q) {
    return std::fabs(p.x - q.x) < kPovEpsilon && std::fabs(p.y - q.y) < kPovEpsilon;
}

// The Bezier check's test for "a different point" (not quite !same: <=).
bool differ(glm::dvec2 p, glm::dvec2 q) {
    return std::fabs(p.x - q.x) > kPovEpsilon || std::fabs(p.y - q.y) > kPovEpsilon;
}

// Parse_Prism's closure check: whether the last outline closes; for a
// linear spline, `first` is then the last outline's first point (the one
// POV-Ray appends when it does not).
bool closes(PrismSpline spline, std::span<const glm::dvec2> p, std::size_t& first) {
    const std::size_t n = p.size();
    if (spline == PrismSpline::bezier) {
        // An outline ends where a segment's last point differs from the next
        // segment's first; it must end on the outline's first point.
        std::size_t loop_start = 0;
        for (std::size_t i = 4; i < n; i += 4) {
            if (differ(p[i], p[i - 1])) {
                if (differ(p[i - 1], p[loop_start])) return false;
                loop_start = i;
            }
        }
        return !differ(p[n - 1], p[loop_start]);
    }
    // After an outline closes at point i, POV-Ray skips the points its kind
    // needs after it (none for linear, the next outline's control point for
    // quadratic, and also the closing control point for cubic) and takes
    // the next one as the next outline's first.
    const std::size_t skip = spline == PrismSpline::linear      ? 1
                             : spline == PrismSpline::quadratic ? 2
                                                                : 3;
    std::size_t i = spline == PrismSpline::linear ? 1 : 2;
    first = spline == PrismSpline::linear ? 0 : 1;
    bool closed = false;
    for (; i < n; ++i) {
        closed = false;
        if (same(p[first], p[i])) {
            i += skip;
            if (i < n) first = i;
            closed = true;
        }
    }
    return closed;
}

}  // namespace

std::string prism_count_error(PrismSpline spline, long long count) {
    switch (spline) {
        case PrismSpline::linear:
            if (count < 3) return "Prism with linear splines must have at least three points.";
            break;
        case PrismSpline::quadratic:
            if (count < 5) return "Prism with quadratic splines must have at least five points.";
            break;
        case PrismSpline::cubic:
            if (count < 6) return "Prism with cubic splines must have at least six points.";
            break;
        case PrismSpline::bezier:
            // (POV-Ray lets 0 through, then reads before its list.)
            if ((count & 3) != 0 || count <= 0)
                return "Prism with Bezier splines must have four points per segment.";
            break;
    }
    return "";
}

PrismOutline prism_outline(PrismSpline spline, std::span<const glm::dvec2> given) {
    PrismOutline outline;
    if (!prism_count_error(spline, static_cast<long long>(given.size())).empty()) {
        outline.error = prism_count_error(spline, static_cast<long long>(given.size()));
        return outline;
    }
    std::vector<glm::dvec2> p(given.begin(), given.end());
    std::size_t first = 0;
    if (!closes(spline, p, first)) {
        if (spline == PrismSpline::linear)
            p.push_back(p[first]);  // "Linear prism not closed. Closing it."
        else
            outline.ignored = true;  // "Prism not closed. Ignoring it."
    }
    // Compute_Prism's walk (after the check above, so it may still refuse a
    // prism the check let through, or one it flagged to be ignored).
    const std::size_t n = p.size();
    const std::size_t given_count = given.size();
    std::size_t start = spline == PrismSpline::linear ? 0 : 1;  // Compute_Prism's First
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const std::size_t need = spline == PrismSpline::linear      ? 1
                                 : spline == PrismSpline::quadratic ? 2
                                                                    : 3;
        if (i + need >= n) {
            outline.segments.clear();
            outline.error = spline == PrismSpline::bezier || spline == PrismSpline::linear
                                ? "Too few points in prism. Prism not closed? Control points "
                                  "missing?"
                                : "Too few points in prism.";
            return outline;
        }
        // A segment's points; the appended point is p[n - 1] beyond the
        // given list: its index is that of the point it repeats.
        std::array<std::size_t, 4> s{};
        for (std::size_t j = 0; j <= need; ++j) s[j] = i + j < given_count ? i + j : first;
        outline.segments.push_back(s);
        switch (spline) {
            case PrismSpline::linear:
                if (same(p[i + 1], p[start])) {
                    ++i;
                    if (i + 1 < n) start = i + 1;
                }
                break;
            case PrismSpline::quadratic:
                if (same(p[i + 2], p[start])) {
                    i += 2;
                    if (i + 2 < n) start = i + 2;
                }
                break;
            case PrismSpline::cubic:
                if (same(p[i + 2], p[start])) {
                    i += 3;
                    if (i + 2 < n) start = i + 2;
                }
                break;
            case PrismSpline::bezier:
                i += 3;
                break;
        }
    }
    if (outline.ignored) outline.segments.clear();
    return outline;
}

}  // namespace hexant::runtime::geometry
