// The first place where a curved path meets a surface: the root finder for
// deformed objects (a straight world ray is a curve in undeformed object
// space) and for rays that travel in time through a moving frame.
//
// Bisection on interval bounds, nearest piece first: a piece of the path
// whose interval box the surface cannot meet is dropped, any other piece is
// halved, so no root is skipped; once a piece's box is small against the
// object's size, the path inside it is straight to far below that size (its
// deviation from the chord is second order), and the exact straight-ray
// routine solves on the chord. No fixed-step marching.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

#include <glm/geometric.hpp>

#include "runtime/geometry/ray3.hpp"
#include "runtime/time/interval.hpp"

namespace hexant::runtime {

struct CurvedPathHit {
    double s;                      // the path's parameter at the hit
    geometry::SurfaceHit surface;  // the chord's hit (its s is the chord's own parameter)
};

// Stops halving when a piece's box is this small against the object's size:
// a relative width, so it holds for objects of any scale. The chord then
// misses the curve by about curvature * width^2 / 8: 1e-13 of the size for a
// path bent on the object's own scale, but about 1e-9 for a twist of 24 turns
// per unit (curvature ~1e4 / size), which is what the dense-sampling test of
// stiff twists (tests/runtime/object_intersect_test.cpp, to 1e-8) allows.
inline constexpr double kCurvedPathRelativeWidth = 1e-6;
// A hard limit on pieces examined, so a pathological path cannot hang the
// tracer; reaching it means a miss (counted by the caller's tests). 2^16
// was too few for a legitimate stiff case: a lathe twisted 10,800 degrees
// about an axis 6 degrees off its own, met by a ray nearly along that
// axis, whose path skims the surface (the path's helix keeps its distance
// from the axis, the pieces' axis-aligned boxes do not) and needs 176,895
// pieces before its first root (object_intersect_test.cpp's ray 73 once
// its draws stopped depending on the compiler). At about 0.5 microseconds
// a piece, a search that reaches the limit takes about 0.14 s.
inline constexpr int kCurvedPathMaxPieces = 1 << 18;
// The limit in force: kCurvedPathMaxPieces, or lower where a caller asks.
// The fuzzer lowers it as it lowers the language's loop limits (tests/fuzz/):
// a search that meets the limit is bounded work, not a hang, but an 8 by 8
// frame of such searches took over 20 s under the sanitizers.
inline std::atomic<int> g_curved_path_max_pieces{kCurvedPathMaxPieces};
// A piece halved down to the doubles' resolution whose box is still wider
// than the stop width is unresolved: the enclosure did not converge there.
// A bend's inverse leaves a few such pieces near a root, where the other
// axes' boxes already rule out the rest (at most 9 in a search, over the
// stress and intersection suites and examples/twister.pov at 160x120); a
// twist of more turns than the doubles can follow (8e18 degrees a unit,
// found by the fuzzer) leaves every piece unresolved, about 32,700 of
// them in a search that ran into the piece limit, 17 ms a ray. Past this
// many the search gives up at once, as at the piece limit.
inline constexpr int kCurvedPathMaxUnresolved = 64;

// How many curved-path solves this process has run: what a scene without
// deformations or time-travelling rays must leave at zero (relaxed: a count
// for tests and statistics, not a synchronisation).
inline std::atomic<std::uint64_t> g_curved_path_solves{0};

inline std::uint64_t curved_path_solves() {
    return g_curved_path_solves.load(std::memory_order_relaxed);
}

// How many searches gave up at the piece limit or kCurvedPathMaxUnresolved
// (and answered "miss"): the stress suite requires none.
inline std::atomic<std::uint64_t> g_curved_path_give_ups{0};

inline std::uint64_t curved_path_give_ups() {
    return g_curved_path_give_ups.load(std::memory_order_relaxed);
}

// How many pieces the searches examined (added once per search).
inline std::atomic<std::uint64_t> g_curved_path_pieces{0};

inline std::uint64_t curved_path_pieces() {
    return g_curved_path_pieces.load(std::memory_order_relaxed);
}

// box_over(Interval s) -> geometry::Box3 holding the path over s;
// point_at(double s) -> glm::dvec3 on the path;
// may_meet(Box3, Interval s) -> bool, false only if the surface has no point
// in the box (at the path's times over s, when the surface moves);
// chord_hit(Ray3, double u_min, double u_max, Interval s) -> optional<SurfaceHit>.
template <class BoxOver, class PointAt, class MayMeet, class ChordHit>
std::optional<CurvedPathHit> first_hit_on_curve(double s_min, double s_max, double object_size,
                                                BoxOver&& box_over, PointAt&& point_at,
                                                MayMeet&& may_meet, ChordHit&& chord_hit) {
    if (!(s_min < s_max) || !std::isfinite(s_min) || !std::isfinite(s_max)) return std::nullopt;
    g_curved_path_solves.fetch_add(1, std::memory_order_relaxed);
    const double stop_width = kCurvedPathRelativeWidth * object_size;
    // A small explicit stack: depth grows with log2 of (path length / stop width).
    std::pair<double, double> stack[256];
    int top = 0;
    stack[top++] = {s_min, s_max};
    const int max_pieces = g_curved_path_max_pieces.load(std::memory_order_relaxed);
    int examined = 0, unresolved = 0;
    bool gave_up = false;
    std::optional<CurvedPathHit> found;
    while (top > 0) {
        if (examined >= max_pieces) {
            gave_up = true;
            break;
        }
        const auto [a, b] = stack[--top];
        ++examined;
        const geometry::Box3 box = box_over(Interval(a, b));
        if (!may_meet(box, Interval(a, b))) continue;
        const glm::dvec3 extent = box.hi - box.lo;
        const double width = std::max({extent.x, extent.y, extent.z});
        const double mid = 0.5 * (a + b);
        const bool tiny = width <= stop_width || !(a < mid && mid < b) || top >= 254;
        if (!tiny) {
            stack[top++] = {mid, b};  // far half examined last
            stack[top++] = {a, mid};
            continue;
        }
        if (width > stop_width && ++unresolved > kCurvedPathMaxUnresolved) {
            gave_up = true;
            break;
        }
        const glm::dvec3 p0 = point_at(a), p1 = point_at(b);
        // Ends that lie apart on a piece halved to the doubles' resolution:
        // the path jumps there (a bend's inverse crossing its branch cut,
        // behind the centre of curvature, takes the other preimage), and
        // the chord between the two preimages is no part of it. A hit on
        // it would lie off the ray (issue 20: a height field met 1e-3 off
        // its path).
        if (width > stop_width && !(glm::length(p1 - p0) <= stop_width)) continue;
        const geometry::Ray3 chord{p0, p1 - p0};
        // The chord's own parameter runs over [0, 1]; a hit exactly at a
        // piece's end belongs to both neighbours, so accept the closed range.
        const double below = std::nextafter(0.0, -1.0);
        if (auto hit = chord_hit(chord, below, std::nextafter(1.0, 2.0), Interval(a, b))) {
            const double u = std::clamp(hit->s, 0.0, 1.0);
            const double s = std::clamp(a + u * (b - a), a, b);
            if (s > s_min && s < s_max) {
                found = CurvedPathHit{s, *hit};
                break;
            }
        }
    }
    g_curved_path_pieces.fetch_add(std::uint64_t(examined), std::memory_order_relaxed);
    if (gave_up) g_curved_path_give_ups.fetch_add(1, std::memory_order_relaxed);
    return found;
}

}  // namespace hexant::runtime
