// The single-precision walk of a ray at one instant (traversal.hpp): each
// node's eight children tested at once with Google's Highway, compiled for
// every SIMD target the compiler knows and chosen at run time by the
// machine (the whole walk is one dispatch, so no call per node is indirect).
// The error argument for the widening is in traversal.hpp; the one for the
// stored bounds in bound_rounding.hpp.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tracer/traversal_simd.cpp"
#include <algorithm>
#include <cfloat>

#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "tracer/bound_rounding.hpp"
#include "tracer/object_test.hpp"
#include "tracer/traversal.hpp"

HWY_BEFORE_NAMESPACE();
namespace hexant::tracer {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using D = hn::CappedTag<float, kNodeWidth>;
using V = hn::Vec<D>;

// At most kMaxDepth levels of cells, and below them groups of objects (a
// level per factor of eight of a leaf's objects, fewer than 12 levels for
// 2^32), each level leaving at most seven siblings behind.
constexpr int kStackSize = (BuildOptions::kMaxDepth + 12) * (kNodeWidth - 1) + 8;

struct Entry {
    NodeRef* slot;
    float enter;
};

// The children a ray meets among those of one node: a bit per child, and
// the widened entry parameters. `planes(j, i, lo, hi)` loads the children
// i.. bounds along direction j at the ray's instant.
template <class Planes>
HWY_INLINE unsigned TestChildren(const TraversalRay& r, int directions, float epsilon, float s_min,
                                 float s_max, const Planes& planes, float* enter) {
    const D d;
    const std::size_t lanes = hn::Lanes(d);
    const V big = hn::Set(d, FLT_MAX);
    const V widening = hn::Set(d, kParameterWidening);
    const V eps = hn::Set(d, epsilon);
    unsigned mask = 0;
    for (std::size_t i = 0; i < std::size_t(kNodeWidth); i += lanes) {
        V near = hn::Set(d, s_min);
        V far = hn::Set(d, s_max);
        auto inside = hn::FirstN(d, lanes);
        for (int j = 0; j < directions; ++j) {
            V lo, hi;
            planes(j, i, lo, hi);
            const V o = hn::Set(d, r.origin[j]);
            if ((r.parallel >> j) & 1) {
                const V slack = hn::Set(d, r.slack[j]);
                inside = hn::And(
                    inside, hn::And(hn::Le(hn::Sub(lo, slack), o), hn::Le(o, hn::Add(hi, slack))));
                continue;
            }
            // The end met first by sign of the direction: an empty child
            // (lo = +inf, hi = -inf) then enters at +inf and never hits.
            const V inv = hn::Set(d, r.inverse[j]);
            const V first = r.negative[j] ? hi : lo;
            const V last = r.negative[j] ? lo : hi;
            near = hn::Max(near, hn::Mul(hn::Sub(first, o), inv));
            far = hn::Min(far, hn::Mul(hn::Sub(last, o), inv));
        }
        // Infinities to the float range, then the widening: never NaN.
        near = hn::Min(near, big);
        far = hn::Max(far, hn::Neg(big));
        near = hn::Sub(near, hn::MulAdd(hn::Abs(near), widening, eps));
        far = hn::Add(far, hn::MulAdd(hn::Abs(far), widening, eps));
        const auto hit = hn::And(inside, hn::Le(near, far));
        hn::StoreU(near, d, enter + i);
        std::uint8_t bits[8] = {};
        hn::StoreMaskBits(d, hit, bits);
        mask |= unsigned(bits[0]) << i;
    }
    return mask;
}

class Walk {
  public:
    Walk(const Hierarchy& h, const TraversalRay& r, const runtime::Ray4& ray, double s_min,
         double s_max, bool occlusion, ThreadState& state, std::optional<runtime::ObjectHit>& best)
        : h_(h),
          r_(r),
          s_min_(float_down(s_min)),
          best_s_(s_max),
          best_f_(float_up(s_max)),
          occlusion_(occlusion),
          test_{ray, s_min, s_max, state},
          state_(state),
          best_(best) {}

    bool run() {
        NodeRef root = h_.root();
        Entry stack[kStackSize];
        int top = 0;
        // The frame's time index skips the chain of time nodes above the
        // ray's time slice (time_index.hpp); below it the loop goes on.
        LocalTimeIndex& index = state_.time_index;
        NodeRef* slot = h_.time_entry(r_.time, &root, index);
        NodeRef* const entry = slot;
        for (;;) {
            NodeRef ref = NodeRef::load(slot);
            // Runs of time nodes: the ray's instant picks each half without
            // a branch to mispredict. An instant on the split goes to the
            // later half: a frame that opens there never needs the earlier
            // one (Hierarchy::release_outside lets it go).
            while (ref.kind() == RefKind::TimeNode) {
                // A time node at the thread's own entry was built since its
                // index was: a refresh takes it in for the rays after.
                if (slot == entry && entry != &root && index.index.refreshable())
                    h_.refresh_time_index(index);
                TimeNode* node = ref.as<TimeNode>();
                slot = &node->child[r_.time >= node->split];
                ref = NodeRef::load(slot);
            }
            bool descend = false;
            switch (ref.kind()) {
                case RefKind::Pending:
                    h_.expand(slot, ref, state_.counters);
                    continue;  // read the slot again: it holds the node now
                case RefKind::Object: {
                    const std::uint32_t i = ref.object_index();
                    const auto& object = *h_.objects().objects[i];
                    if (occlusion_) {
                        if (test_.occludes(i, object)) return true;
                    } else if (test_.nearest(i, object, best_, best_s_)) {
                        best_f_ = float_up(best_s_);
                    }
                    break;
                }
                case RefKind::BoxNode:
                    descend = box(ref.as<BoxNode>(), slot, stack, top);
                    break;
                case RefKind::MotionNode:
                    descend = motion(ref.as<MotionNode>(), slot, stack, top);
                    break;
                case RefKind::SlabNode:
                    descend = slabs(ref.as<SlabNode>(), slot, stack, top);
                    break;
                case RefKind::PieceNode:
                    descend = pieces(ref.as<PieceNode>(), slot, stack, top);
                    break;
                default:
                    break;
            }
            if (descend) continue;
            // Next: the nearest child left behind that may still matter.
            for (;;) {
                if (top == 0) return false;
                const Entry& e = stack[--top];
                if (e.enter <= best_f_) {
                    slot = e.slot;
                    break;
                }
            }
        }
    }

  private:
    // After a node's test: the nearest child hit becomes `slot`, the others
    // go on the stack farthest first. False when none was hit.
    template <class Node>
    bool order(Node* node, unsigned mask, const float* enter, NodeRef*& slot, Entry* stack,
               int& top) {
        if (mask == 0) return false;
        int index[kNodeWidth];
        int count = 0;
        for (unsigned m = mask; m; m &= m - 1) index[count++] = __builtin_ctz(m);
        if (count == 1) {
            slot = &node->child[index[0]];
            return true;
        }
        // Insertion sort by entry, nearest last (it is taken, not pushed).
        for (int a = 1; a < count; ++a)
            for (int b = a; b > 0 && enter[index[b]] > enter[index[b - 1]]; --b)
                std::swap(index[b], index[b - 1]);
        for (int k = 0; k + 1 < count; ++k)
            stack[top++] = {&node->child[index[k]], enter[index[k]]};
        slot = &node->child[index[count - 1]];
        return true;
    }

    void count(std::uint32_t children) {
        ++state_.counters.node_tests;
        state_.counters.bound_tests += children;
    }

    bool box(BoxNode* node, NodeRef*& slot, Entry* stack, int& top) {
        count(node->children);
        const D d;
        alignas(32) float enter[kNodeWidth];
        const unsigned mask = TestChildren(
            r_, 3, r_.epsilon_box, s_min_, best_f_,
            [&](int j, std::size_t i, V& lo, V& hi) {
                lo = hn::Load(d, node->lo[j] + i);
                hi = hn::Load(d, node->hi[j] + i);
            },
            enter);
        return order(node, mask, enter, slot, stack, top);
    }

    bool motion(MotionNode* node, NodeRef*& slot, Entry* stack, int& top) {
        count(node->children);
        const D d;
        const double u_exact = std::clamp((r_.time - node->t0) * node->inverse_span, 0.0, 1.0);
        const V u = hn::Set(d, static_cast<float>(u_exact));
        alignas(32) float enter[kNodeWidth];
        const unsigned mask = TestChildren(
            r_, 3, r_.epsilon_box, s_min_, best_f_,
            [&](int j, std::size_t i, V& lo, V& hi) {
                lo = hn::MulAdd(u, hn::Load(d, node->dlo[j] + i), hn::Load(d, node->lo[j] + i));
                hi = hn::MulAdd(u, hn::Load(d, node->dhi[j] + i), hn::Load(d, node->hi[j] + i));
            },
            enter);
        return order(node, mask, enter, slot, stack, top);
    }

    // The ray's piece j of the node's time and its place v in it: each
    // side the line between knots j and j + 1, decoded from 8 bits of the
    // knots' frames (node_piece.cpp argues the rounding). Slots past the
    // children are masked off.
    bool pieces(PieceNode* node, NodeRef*& slot, Entry* stack, int& top) {
        count(node->children);
        const D d;
        const hn::Rebind<std::uint8_t, D> d8;
        const hn::Rebind<std::int32_t, D> di;
        const double u = std::clamp((r_.time - node->t0) * node->inverse_span, 0.0, 1.0);
        const double s = u * PieceNode::kPieces;
        const int j = std::min(int(s), PieceNode::kPieces - 1);
        const V v = hn::Set(d, static_cast<float>(s - j));
        const auto knot = [&](const std::uint8_t* q, const V& step, const V& base) {
            return hn::MulAdd(hn::ConvertTo(d, hn::PromoteTo(di, hn::LoadU(d8, q))), step, base);
        };
        alignas(32) float enter[kNodeWidth];
        unsigned mask = TestChildren(
            r_, 3, r_.epsilon_box, s_min_, best_f_,
            [&](int a, std::size_t i, V& lo, V& hi) {
                const V step = hn::Set(d, node->step[a]);
                const V b0 = hn::Set(d, node->base[j][a]), b1 = hn::Set(d, node->base[j + 1][a]);
                const V lo0 = knot(node->lo[j][a] + i, step, b0);
                const V lo1 = knot(node->lo[j + 1][a] + i, step, b1);
                const V hi0 = knot(node->hi[j][a] + i, step, b0);
                const V hi1 = knot(node->hi[j + 1][a] + i, step, b1);
                lo = hn::MulAdd(v, hn::Sub(lo1, lo0), lo0);
                hi = hn::MulAdd(v, hn::Sub(hi1, hi0), hi0);
            },
            enter);
        mask &= (1u << node->children) - 1u;
        return order(node, mask, enter, slot, stack, top);
    }

    bool slabs(SlabNode* node, NodeRef*& slot, Entry* stack, int& top) {
        count(node->children);
        const D d;
        const V h = hn::Set(d, r_.half_time);
        alignas(32) float enter[kNodeWidth];
        // Direction j >= 3 is the 3D diagonal shared by slabs 3 + 2(j - 3)
        // (t weight +.5: n·x in [lo - t/2, hi - t/2]) and 4 + 2(j - 3)
        // (t weight -.5: [lo + t/2, hi + t/2]); both hold, so their common
        // part does.
        const unsigned mask = TestChildren(
            r_, r_.diagonals ? 7 : 3, r_.diagonals ? r_.epsilon_slab : r_.epsilon_box, s_min_,
            best_f_,
            [&](int j, std::size_t i, V& lo, V& hi) {
                if (j < 3) {
                    lo = hn::Load(d, node->lo[j] + i);
                    hi = hn::Load(d, node->hi[j] + i);
                    return;
                }
                const int plus = 3 + 2 * (j - 3), minus = plus + 1;
                lo = hn::Max(hn::Sub(hn::Load(d, node->lo[plus] + i), h),
                             hn::Add(hn::Load(d, node->lo[minus] + i), h));
                hi = hn::Min(hn::Sub(hn::Load(d, node->hi[plus] + i), h),
                             hn::Add(hn::Load(d, node->hi[minus] + i), h));
            },
            enter);
        return order(node, mask, enter, slot, stack, top);
    }

    const Hierarchy& h_;
    const TraversalRay& r_;
    float s_min_;
    double best_s_;
    float best_f_;
    bool occlusion_;
    ObjectTest test_;
    ThreadState& state_;
    std::optional<runtime::ObjectHit>& best_;
};

bool WalkInstant(const Hierarchy& h, const TraversalRay& r, const runtime::Ray4& ray, double s_min,
                 double s_max, bool occlusion, ThreadState& state,
                 std::optional<runtime::ObjectHit>& best) {
    return Walk(h, r, ray, s_min, s_max, occlusion, state, best).run();
}

}  // namespace HWY_NAMESPACE
}  // namespace hexant::tracer
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace hexant::tracer {
HWY_EXPORT(WalkInstant);
namespace traversal_detail {
bool walk_instant(const Hierarchy& h, const TraversalRay& r, const runtime::Ray4& ray, double s_min,
                  double s_max, bool occlusion, ThreadState& state,
                  std::optional<runtime::ObjectHit>& best) {
    return HWY_DYNAMIC_DISPATCH(WalkInstant)(h, r, ray, s_min, s_max, occlusion, state, best);
}
}  // namespace traversal_detail
}  // namespace hexant::tracer
#endif
