#include "tracer/traversal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "runtime/bounds/slab_ray.hpp"
#include "tracer/bound_rounding.hpp"
#include "tracer/object_test.hpp"

namespace hexant::tracer {

namespace {

using runtime::Box4;
using runtime::ObjectHit;
using runtime::Ray4;

// The largest magnitude the single-precision walk accepts in n·o and
// 1 / (n·d): far inside float's range, so sums and products of a few of
// them neither overflow nor lose their order.
constexpr double kFloatRange = 0x1p100;

// a + b + c with its rounding error bound: an error-free two-sum chain
// (Knuth), whose result is exact up to its last rounding, so it is zero
// exactly when the exact sum is.
struct Sum {
    double value, error;
};
Sum compensated_sum(double a, double b, double c) {
    const auto two_sum = [](double x, double y, double& e) {
        const double s = x + y;
        const double z = s - x;
        e = (x - (s - z)) + (y - z);
        return s;
    };
    double e1, e2;
    const double s1 = two_sum(a, b, e1);
    const double s2 = two_sum(s1, c, e2);
    const double value = s2 + (e1 + e2);
    const double magnitude = std::fabs(a) + std::fabs(b) + std::fabs(c);
    return {value, 0x1p-52 * std::fabs(value) + 0x1p-100 * magnitude};
}

// The first kCount directions (3: the axes; kDirections: the diagonals
// too), a count fixed at compile time so that the axes' loop unrolls and
// their divisions overlap (every ray at an instant passes here).
template <int kCount>
bool prepare_directions(TraversalRay& r, const Ray4& ray) {
    double box = 0.0, slab = 0.0;
#pragma GCC unroll 7
    for (int j = 0; j < kCount; ++j) {
        double on, dn, error;
        bool reliable = true;
        if (j < 3) {
            on = ray.origin[j];
            dn = ray.direction[j];
            error = 0x1p-23 * std::fabs(on);  // the rounding to float, with room
        } else {
            const double sy = (j - 3) & 2 ? -0.5 : 0.5, sz = (j - 3) & 1 ? -0.5 : 0.5;
            const Sum o = compensated_sum(0.5 * ray.origin.x, sy * ray.origin.y, sz * ray.origin.z);
            const Sum d =
                compensated_sum(0.5 * ray.direction.x, sy * ray.direction.y, sz * ray.direction.z);
            on = o.value;
            dn = d.value;
            error = 0x1p-23 * std::fabs(on) + 2.0 * o.error;
            // A direction nearly in the diagonal plane: 1 / (n·d) would
            // carry the sum's error as a large relative one.
            const double magnitude = std::fabs(ray.direction.x) + std::fabs(ray.direction.y) +
                                     std::fabs(ray.direction.z);
            reliable = dn == 0.0 || std::fabs(dn) > 0x1p-40 * magnitude;
        }
        if (!(std::fabs(on) < kFloatRange)) {
            if (j < 3) return false;
            r.diagonals = false;
            continue;
        }
        r.origin[j] = static_cast<float>(on);
        if (dn == 0.0) {
            r.parallel |= std::uint8_t(1u << j);
            r.inverse[j] = 0.0f;
            r.negative[j] = false;
            r.slack[j] = float_up(2.0 * error + std::numeric_limits<double>::denorm_min());
            continue;
        }
        const double inv = 1.0 / dn;
        if (!(std::fabs(inv) < kFloatRange) || !reliable) {
            if (j < 3) return false;
            r.diagonals = false;
            continue;
        }
        r.inverse[j] = static_cast<float>(inv);
        r.negative[j] = dn < 0.0;
        r.slack[j] = 0.0f;
        const double e = error * std::fabs(inv) * (1.0 + 0x1p-20);
        (j < 3 ? box : slab) = std::max(j < 3 ? box : slab, e);
    }
    // Rounded up by the factor, not by nextafter: the conversion to float
    // loses at most 2^-24 of it.
    r.epsilon_box = static_cast<float>(2.0 * box * (1.0 + 0x1p-20));
    r.epsilon_slab = static_cast<float>(2.0 * std::max(box, slab) * (1.0 + 0x1p-20));
    if (!std::isfinite(r.epsilon_box) || !std::isfinite(r.epsilon_slab)) return false;
    r.half_time = static_cast<float>(0.5 * r.time);
    return true;
}

}  // namespace

bool TraversalRay::prepare(const Ray4& ray, bool with_diagonals) {
    if (ray.direction.w != 0.0) return false;
    time = ray.origin.w;
    parallel = 0;
    diagonals = with_diagonals;
    return with_diagonals ? prepare_directions<kDirections>(*this, ray)
                          : prepare_directions<3>(*this, ray);
}

namespace {

// The double-precision walk for rays the single-precision one does not
// take: each child's bound widened to the 4D box it spans over its node's
// time (a linear-motion box's ends at both times, a 12-slab bound's
// principal slabs), tested with runtime::SlabRay's robust clip. Looser than
// the instant tests, never wrong.
class DoubleWalk {
  public:
    DoubleWalk(const Hierarchy& h, const Ray4& ray, double s_min, double s_max, bool occlusion,
               ThreadState& state, std::optional<ObjectHit>& best)
        : h_(h),
          ray_(ray),
          slab_ray_(ray),
          s_min_(s_min),
          best_s_(s_max),
          occlusion_(occlusion),
          test_{ray, s_min, s_max, state},
          state_(state),
          best_(best),
          instant_(ray.direction.w == 0.0) {}

    bool run() {
        NodeRef root = h_.root();
        std::vector<Entry> stack{{&root, s_min_}};
        while (!stack.empty()) {
            const Entry e = stack.back();
            stack.pop_back();
            if (e.enter > best_s_) continue;
            NodeRef ref = NodeRef::load(e.slot);
            if (ref.kind() == RefKind::Pending) ref = h_.expand(e.slot, ref, state_.counters);
            switch (ref.kind()) {
                case RefKind::Object: {
                    const std::uint32_t i = ref.object_index();
                    const auto& object = *h_.objects().objects[i];
                    if (occlusion_) {
                        if (test_.occludes(i, object)) return true;
                    } else {
                        test_.nearest(i, object, best_, best_s_);
                    }
                    break;
                }
                case RefKind::TimeNode: {
                    TimeNode* node = ref.as<TimeNode>();
                    // An instant on the split takes the later half, as
                    // the SIMD walk does (both halves hold it).
                    for (int c = 1; c >= 0; --c) {
                        if (instant_ &&
                            (c == 0 ? ray_.origin.w >= node->split : ray_.origin.w < node->split))
                            continue;
                        stack.push_back({&node->child[c], e.enter});
                    }
                    break;
                }
                case RefKind::BoxNode:
                    push(ref.as<BoxNode>(), stack);
                    break;
                case RefKind::MotionNode:
                    push(ref.as<MotionNode>(), stack);
                    break;
                case RefKind::SlabNode:
                    push(ref.as<SlabNode>(), stack);
                    break;
                case RefKind::PieceNode:
                    push(ref.as<PieceNode>(), stack);
                    break;
                default:
                    break;
            }
        }
        return false;
    }

  private:
    struct Entry {
        NodeRef* slot;
        double enter;
    };

    static Box4 box_of(const BoxNode& n, int i) {
        Box4 b;
        for (int k = 0; k < 3; ++k) b.lo[k] = n.lo[k][i], b.hi[k] = n.hi[k][i];
        return b;
    }
    static Box4 box_of(const SlabNode& n, int i) {
        Box4 b;
        for (int k = 0; k < 3; ++k) b.lo[k] = n.lo[k][i], b.hi[k] = n.hi[k][i];
        return b;
    }
    static Box4 box_of(const MotionNode& n, int i) {
        // The interpolated ends reach their extremes at u = 0 or 1; the sum
        // in double errs far less than the margin stored with them.
        Box4 b;
        for (int k = 0; k < 3; ++k) {
            const double lo = n.lo[k][i], hi = n.hi[k][i];
            b.lo[k] = std::min(lo, n.dlo[k][i] == 0.0f ? lo : lo + double(n.dlo[k][i]));
            b.hi[k] = std::max(hi, n.dhi[k][i] == 0.0f ? hi : hi + double(n.dhi[k][i]));
        }
        return b;
    }

    static Box4 box_of(const PieceNode& n, int i) {
        // The lines' extremes lie at their knots; each decoded knot (exact
        // in double but for a rounding of 2^-53 of it) lies outside the
        // fitted line by the node's margin.
        Box4 b;
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < PieceNode::kKnots; ++j) {
                b.lo[k] = std::min(b.lo[k], n.base[j][k] + double(n.lo[j][k][i]) * n.step[k]);
                b.hi[k] = std::max(b.hi[k], n.base[j][k] + double(n.hi[j][k][i]) * n.step[k]);
            }
        return b;
    }

    template <class Node>
    void push(Node* node, std::vector<Entry>& stack) {
        ++state_.counters.node_tests;
        std::array<std::pair<double, int>, kNodeWidth> hits;
        int count = 0;
        state_.counters.bound_tests += node->children;
        for (int i = 0; i < kNodeWidth; ++i) {
            if (NodeRef::load(&node->child[i]).empty()) continue;
            Box4 b = box_of(*node, i);
            b.lo.w = node->t0;
            b.hi.w = node->t1;
            double enter, exit;
            if (slab_ray_.clip(b, s_min_, best_s_, &enter, &exit)) hits[count++] = {enter, i};
        }
        std::sort(hits.begin(), hits.begin() + count);
        for (int k = count - 1; k >= 0; --k)
            stack.push_back({&node->child[hits[k].second], hits[k].first});
    }

    const Hierarchy& h_;
    const Ray4& ray_;
    runtime::SlabRay slab_ray_;
    double s_min_, best_s_;
    bool occlusion_;
    ObjectTest test_;
    ThreadState& state_;
    std::optional<ObjectHit>& best_;
    bool instant_;
};

bool at_time_of(const Hierarchy& h, const Ray4& ray) {
    // A ray at one instant outside the hierarchy's time meets none of its
    // cells (their bounds hold nothing then).
    if (ray.direction.w != 0.0) return true;
    return ray.origin.w >= h.region().lo.w && ray.origin.w <= h.region().hi.w;
}

}  // namespace

std::optional<ObjectHit> first_hit(const Hierarchy& h, const Ray4& ray, double s_min, double s_max,
                                   ThreadState& state) {
    std::optional<ObjectHit> best;
    if (h.empty() || !(s_min < s_max) || !at_time_of(h, ray)) return best;
    TraversalRay r;
    if (r.prepare(ray, h.options().bounds == BoundStyle::Slabs))
        traversal_detail::walk_instant(h, r, ray, s_min, s_max, false, state, best);
    else
        DoubleWalk(h, ray, s_min, s_max, false, state, best).run();
    return best;
}

bool occluded(const Hierarchy& h, const Ray4& ray, double s_min, double s_max, ThreadState& state) {
    std::optional<ObjectHit> none;
    if (h.empty() || !(s_min < s_max) || !at_time_of(h, ray)) return false;
    TraversalRay r;
    if (r.prepare(ray, h.options().bounds == BoundStyle::Slabs))
        return traversal_detail::walk_instant(h, r, ray, s_min, s_max, true, state, none);
    return DoubleWalk(h, ray, s_min, s_max, true, state, none).run();
}

}  // namespace hexant::tracer
