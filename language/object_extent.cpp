#include "language/object_extent.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "language/timed_call.hpp"
#include "language/value_ops.hpp"
#include "runtime/objects/object_factory.hpp"

namespace hexant::language {

namespace {

// POV-Ray's BOUND_HUGE / 2: the box of an unbounded object (a plane's
// Make_BBox(-BOUND_HUGE / 2, ..., BOUND_HUGE)).
constexpr double kHalfBoundHuge = 1.0e10;

// Whether nothing about where the object's surface lies moves with clock,
// but for parts that appear and vanish (their lifetimes).
bool placed_still(const runtime::ObjectRecord& r) {
    if (r.transform.depends_on_time()) return false;
    if (const auto* csg = std::get_if<runtime::Csg>(&r.shape)) {
        return std::all_of(csg->children.begin(), csg->children.end(),
                           [](const runtime::ObjectPtr& c) { return placed_still(*c); });
    }
    return !r.shape_depends_on_time();
}

// The instants where some part starts or stops existing.
void lifetime_edges(const runtime::ObjectRecord& r, std::vector<double>& out) {
    if (!r.lifetime.is_always())
        for (const runtime::Interval& piece : r.lifetime.pieces()) {
            out.push_back(piece.lo);
            out.push_back(std::nextafter(piece.hi, INFINITY));
        }
    if (const auto* csg = std::get_if<runtime::Csg>(&r.shape))
        for (const auto& c : csg->children) lifetime_edges(*c, out);
}

std::string corner_name(bool max) {
    return max ? "max_extent()" : "min_extent()";
}

}  // namespace

bool changes_with_clock(const runtime::ObjectRecord& object, const runtime::Interval& time) {
    if (!placed_still(object)) return true;
    std::vector<double> edges;
    lifetime_edges(object, edges);
    for (double e : edges)
        if (e > time.lo && e <= time.hi) return true;
    return false;
}

Value object_extent(const runtime::ObjectRecord& object, bool max, const runtime::Interval& time,
                    std::size_t max_pieces) {
    if (!placed_still(object))
        throw ValueError(
            corner_name(max) +
            " of an object whose shape or transforms move with clock: its box "
            "would change continuously, which hexant does not form yet (take the box of the object "
            "before it moves, then move it)");
    const runtime::IntelligentObjectPtr placed =
        runtime::make_intelligent_object(object, runtime::Texture{});
    const auto corner = [&](double t) {
        if (!placed->bounded()) return glm::dvec3(max ? kHalfBoundHuge : -kHalfBoundHuge);
        const runtime::Box4 box = placed->box_over(runtime::Interval(t));
        // A text of blanks has no surface; POV-Ray's box for it is the
        // thickness along z at the origin, placed by the transforms, and an
        // empty string's is unbounded (truetype.cpp's Compute_BBox).
        if (box.is_empty())
            if (const auto* text = std::get_if<runtime::Text>(&object.shape)) {
                if (text->string.empty()) return glm::dvec3(max ? kHalfBoundHuge : -kHalfBoundHuge);
                const glm::dmat4 m = object.transform.matrix_at(t);
                glm::dvec3 lo(INFINITY), hi(-INFINITY);
                for (double z : {0.0, text->thickness(t)}) {
                    const glm::dvec3 p(m * glm::dvec4(0.0, 0.0, z, 1.0));
                    lo = glm::min(lo, p);
                    hi = glm::max(hi, p);
                }
                return max ? hi : lo;
            }
        if (box.is_empty())
            throw ValueError(corner_name(max) + " of an object that has no surface at clock " +
                             std::to_string(t));
        return max ? glm::dvec3(box.hi) : glm::dvec3(box.lo);
    };
    // The pieces of time between the instants where parts appear or vanish.
    std::vector<double> edges{time.lo};
    lifetime_edges(object, edges);
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    std::vector<runtime::Interval> pieces;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (edges[i] < time.lo || edges[i] > time.hi) continue;
        const double end = i + 1 < edges.size()
                               ? std::min(std::nextafter(edges[i + 1], -INFINITY), time.hi)
                               : time.hi;
        if (end >= edges[i]) pieces.push_back(runtime::Interval(edges[i], end));
    }
    if (pieces.size() <= 1) {
        const glm::dvec3 c = corner(time.lo);
        return make_vector({c.x, c.y, c.z});
    }
    if (pieces.size() > max_pieces)
        throw ValueError(corner_name(max) + " of an object whose parts change " +
                         std::to_string(pieces.size()) + " times, more than " +
                         std::to_string(max_pieces));
    std::vector<double> xs, ys, zs;
    for (const runtime::Interval& piece : pieces) {
        const glm::dvec3 c = corner(piece.mid());
        xs.push_back(c.x);
        ys.push_back(c.y);
        zs.push_back(c.z);
    }
    return make_vector({piecewise_constant(pieces, xs), piecewise_constant(pieces, ys),
                        piecewise_constant(pieces, zs)});
}

}  // namespace hexant::language
