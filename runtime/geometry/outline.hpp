// Closed outlines in a plane, filled by the even-odd rule: the 2D part of
// POV-Ray's polygon and of its prism (linear_spline).
//
// POV-Ray's point lists: an outline closes when a point repeats the outline's
// first point; the next point starts a new outline; an outline still open at
// the end of the list is closed by an edge back to its first point. The
// repeated points are not vertices, so no edge joins two outlines.
//
// Everything works on the point list as given (no copies, so no allocation
// per ray); `project` maps a list element to its 2D coordinates.
#pragma once

#include <algorithm>
#include <cstddef>

#include <glm/glm.hpp>

#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

// Calls edge(i, j) with the list indices of each edge's two ends, in list
// order. Edges of zero length (a point repeated twice in a row) are skipped.
template <class Point, class EdgeFn>
void for_each_outline_edge(const Point* points, std::size_t count, EdgeFn&& edge) {
    std::size_t i = 0;
    while (i < count) {
        const std::size_t first = i++;
        while (i < count && !(points[i] == points[first])) {
            if (!(points[i] == points[i - 1])) edge(i - 1, i);
            ++i;
        }
        if (i - 1 != first && !(points[i - 1] == points[first])) edge(i - 1, first);
        if (i < count) ++i;  // the repeated first point closes the outline
    }
}

// Even-odd: an odd number of edges crossed on the way from p to +x infinity.
// Each vertex is first taken relative to p (the same rounding whichever edge
// it ends); an edge counts when its ends lie on different sides of the line
// y = 0 (the half-open rule: "above" is strictly greater) and it passes right
// of p, decided by the sign of a.x b.y - a.y b.x, which difference_of_products
// gives exactly. That sign only flips when the edge is walked the other way,
// so two regions sharing an edge never both miss (nor both claim) a point
// near it: the test is watertight.
// Whether the edge a->b (ends relative to the point tested) crosses the
// ray from the origin to +x infinity, as inside_even_odd counts it.
inline bool crosses_right(glm::dvec2 a, glm::dvec2 b) {
    const bool a_above = a.y > 0.0, b_above = b.y > 0.0;
    if (a_above == b_above) return false;
    // > 0 when the origin lies left of a->b.
    const double side = difference_of_products(a.x, b.y, a.y, b.x);
    // Going up, the crossing lies right of the origin when it is left of the edge.
    return b_above ? side > 0.0 : side < 0.0;
}

template <class Point, class Project>
bool inside_even_odd(const Point* points, std::size_t count, Project&& project, glm::dvec2 p) {
    bool inside = false;
    for_each_outline_edge(points, count, [&](std::size_t i, std::size_t j) {
        if (crosses_right(project(points[i]) - p, project(points[j]) - p)) inside = !inside;
    });
    return inside;
}

// The same test over vertices already taken relative to the point
// (`relative[k]` for list element k) and the list's edges as
// for_each_outline_edge gives them: each vertex projected once, not once
// for each edge it ends. (Subtracting the point 0 changes no value, so
// this decides exactly as inside_even_odd with p = 0.)
template <class Edge>
bool inside_even_odd_relative(const glm::dvec2* relative, const Edge* edges, std::size_t count) {
    bool inside = false;
    for (std::size_t e = 0; e < count; ++e)
        if (crosses_right(relative[edges[e][0]], relative[edges[e][1]])) inside = !inside;
    return inside;
}

// Whether the segment a-b meets the closed rectangle [lo, hi] (Liang-Barsky).
inline bool segment_meets_rectangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 lo, glm::dvec2 hi) {
    double t0 = 0.0, t1 = 1.0;
    const glm::dvec2 d = b - a;
    for (int k = 0; k < 2; ++k) {
        if (d[k] == 0.0) {
            if (a[k] < lo[k] || a[k] > hi[k]) return false;
            continue;
        }
        double ta = (lo[k] - a[k]) / d[k], tb = (hi[k] - a[k]) / d[k];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

// Whether the filled region meets the closed rectangle [lo, hi]: an edge
// meets it, or (no edge meeting it, so it lies wholly in or out) its centre
// lies in the region.
template <class Point, class Project>
bool region_meets_rectangle(const Point* points, std::size_t count, Project&& project,
                            glm::dvec2 lo, glm::dvec2 hi) {
    bool meets = false;
    for_each_outline_edge(points, count, [&](std::size_t i, std::size_t j) {
        if (!meets) meets = segment_meets_rectangle(project(points[i]), project(points[j]), lo, hi);
    });
    return meets || inside_even_odd(points, count, project, 0.5 * lo + 0.5 * hi);
}

}  // namespace hexant::runtime::geometry
