// One ray's walk through a hierarchy (hierarchy.hpp): children nearest
// first among those whose bounds the ray meets, an object tested only where
// the ray meets its own bound and at most once per ray (mailbox.hpp), and
// no child visited whose bound begins beyond the nearest hit found. Every
// surface event of an object lies inside the bound of some child that
// holds it, so nothing nearer is ever missed; an object's test covers the
// ray's whole segment, so a hit beyond the current child is kept and wins
// when nothing nearer turns up.
//
// A ray at one instant (the common case: light is instant) goes straight to
// the time half that holds it and tests eight children's bounds at once in
// single precision (traversal_simd.cpp, with Highway). Any other ray, one
// travelling in time or one whose numbers do not fit single precision,
// takes a scalar walk in double precision over the same nodes.
//
// Single precision without missing anything (Ize, "Robust BVH Ray
// Traversal", JCGT 2013, carried over to floats and to rounded origins):
// for each of the seven directions n (x, y, z and the 12-slab bound's four
// diagonals (1, ±1, ±1) / 2), the ray keeps n·o rounded to float (within
// `origin_error` of the exact n·o, which for the diagonals is first formed
// as a compensated sum) and 1 / (n·d) rounded to float (relative error
// below 2^-24 + 2^-51). A computed entry or exit parameter
// fl(fl(P - o_f) * inv_f) for a plane P is then within 4 * 2^-24 of itself
// plus 2 * origin_error / |n·d| of the exact one, so the traversal widens
// [near, far] by 2^-20 |x| + epsilon (epsilon = 2 max origin_error / |n·d|)
// on each side, after clamping infinities to the float range (an overflowed
// entry is then as wide as anything, never NaN). Bounds evaluated at the
// ray's instant carry their own margin (bound_rounding.hpp). A ray parallel
// to a direction tests n·o_f against the bound widened by twice its
// origin error.
#pragma once

#include <cstdint>
#include <optional>

#include "runtime/geometry/spacetime.hpp"
#include "runtime/objects/intelligent_object.hpp"
#include "tracer/hierarchy.hpp"
#include "tracer/thread_state.hpp"

namespace hexant::tracer {

inline constexpr int kDirections = 7;

// A ray at one instant prepared for the single-precision walk.
struct TraversalRay {
    float origin[kDirections];   // n·o, rounded
    float inverse[kDirections];  // 1 / (n·d), rounded; 0 where parallel
    float slack[kDirections];    // parallel directions: twice the origin error, rounded up
    bool negative[kDirections];  // n·d < 0: the bound's upper end is met first
    std::uint8_t parallel = 0;   // bit j: n·d == 0 exactly
    bool diagonals = false;      // the diagonal directions are usable (slab nodes)
    float epsilon_box = 0.0f;    // the widening for x, y, z
    float epsilon_slab = 0.0f;   // ... for all seven
    double time = 0.0;
    float half_time = 0.0f;  // time / 2, for slab nodes

    // False when the ray's numbers do not fit (the double walk then). The
    // diagonal directions are prepared only when asked (only 12-slab nodes
    // use them).
    bool prepare(const runtime::Ray4& ray, bool with_diagonals);
};

inline constexpr float kParameterWidening = 0x1p-20f;

// The nearest surface event of the hierarchy's objects with
// s_min < s < s_max, or nothing. `state` keeps the mailbox (next_ray()
// already called by the caller) and the counters.
std::optional<runtime::ObjectHit> first_hit(const Hierarchy& h, const runtime::Ray4& ray,
                                            double s_min, double s_max, ThreadState& state);

// Does an object that casts shadows meet the ray with s_min < s < s_max?
bool occluded(const Hierarchy& h, const runtime::Ray4& ray, double s_min, double s_max,
              ThreadState& state);

namespace traversal_detail {

// The single-precision walk (traversal_simd.cpp), by dynamic dispatch to
// the machine's widest SIMD. Returns true when `occlusion` and an occluder
// was found; first hits update best / best_s.
bool walk_instant(const Hierarchy& h, const TraversalRay& r, const runtime::Ray4& ray, double s_min,
                  double s_max, bool occlusion, ThreadState& state,
                  std::optional<runtime::ObjectHit>& best);

}  // namespace traversal_detail

}  // namespace hexant::tracer
