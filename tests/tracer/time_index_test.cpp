// The time index (tracer/time_index.hpp): for every instant of the frame,
// the slot it gives is the one the chain of time nodes leads to (an instant
// on a cut goes to the later piece) and, outside it, the root or that
// same slot; a pending cell of the chain ends a piece (the walk builds it)
// and the index reaches below it once built.
// Also the inline float steps of bound_rounding.hpp against std::nextafter.
#include "tracer/time_index.hpp"

#include <cmath>
#include <deque>
#include <limits>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "tracer/bound_rounding.hpp"

using hexant::tracer::NodeRef;
using hexant::tracer::RefKind;
using hexant::tracer::TimeIndex;
using hexant::tracer::TimeNode;

namespace {

// A chain of time nodes over [t0, t1], halved `depth` times where
// `uneven` says (a leaf is an object reference numbered in time order).
// The nodes live in `store`; pending leaves are marked by object numbers
// at or above 1000 and built into time nodes by expand().
struct Chain {
    std::deque<TimeNode> store;
    int next_leaf = 0;
    NodeRef make(double t0, double t1, int depth, std::mt19937& random) {
        if (depth == 0 || (depth < 4 && random() % 3 == 0))
            return NodeRef::object(std::uint32_t(next_leaf++));
        TimeNode& n = store.emplace_back();
        n.t0 = t0;
        n.t1 = t1;
        n.split = t0 + (t1 - t0) * 0.5;
        n.child[0] = make(t0, n.split, depth - 1, random);
        n.child[1] = make(n.split, t1, depth - 1, random);
        return NodeRef::node(RefKind::TimeNode, &n);
    }
};

NodeRef* descend(NodeRef* slot, double t) {
    for (NodeRef ref = NodeRef::load(slot); ref.kind() == RefKind::TimeNode;
         ref = NodeRef::load(slot)) {
        TimeNode* n = ref.as<TimeNode>();
        slot = &n->child[t >= n->split];
    }
    return slot;
}

// A time node over [t0, t1] halved at its middle, kept in `store`.
TimeNode& time_node(std::deque<TimeNode>& store, double t0, double t1, NodeRef early,
                    NodeRef late) {
    TimeNode& n = store.emplace_back();
    n.t0 = t0;
    n.t1 = t1;
    n.split = 0.5 * (t0 + t1);
    n.child[0] = early;
    n.child[1] = late;
    return n;
}

}  // namespace

TEST_CASE("the time index starts each instant where the chain of time nodes leads",
          "[tracer][time_index]") {
    std::mt19937 random(1988);
    for (int trial = 0; trial < 50; ++trial) {
        Chain chain;
        NodeRef root = chain.make(0.0, 1.0, 8, random);
        REQUIRE(root.kind() == RefKind::TimeNode);
        // A frame's shutter: sometimes on cuts, sometimes between them.
        std::uniform_real_distribution<double> u(0.0, 1.0);
        double t0 = trial % 4 == 0 ? 0.25 : u(random), t1 = trial % 4 == 0 ? 0.5 : u(random);
        if (t0 > t1) std::swap(t0, t1);
        TimeIndex index;
        index.build(&root, t0, t1);
        REQUIRE(index.size() >= 1);
        NodeRef copy = root;
        for (int k = 0; k <= 1000; ++k) {
            const double t = t0 + (t1 - t0) * k / 1000.0;
            CHECK(index.entry(t, &copy) == descend(&root, t));
        }
        // Every cut the chain has inside the shutter, and its neighbours.
        for (const TimeNode& n : chain.store)
            for (const double t : {n.split, std::nextafter(n.split, -1.0)})
                if (t >= t0 && t <= t1) CHECK(index.entry(t, &copy) == descend(&root, t));
        // Outside the shutter: the root (a walk from there is always right)
        // or, within the pieces that hold its ends, the chain's own slot.
        for (int k = 0; k <= 1000; ++k) {
            const double t = k / 1000.0;
            NodeRef* e = index.entry(t, &copy);
            CHECK((e == &copy || e == descend(&root, t)));
        }
        CHECK(index.entry(1.5, &copy) == &copy);
        CHECK(index.entry(std::numeric_limits<double>::quiet_NaN(), &copy) == &copy);
    }
}

TEST_CASE("the time index stops at a pending cell of its chain, which the walk builds",
          "[tracer][time_index]") {
    std::mt19937 random(5);
    Chain chain;
    NodeRef root = chain.make(0.0, 1.0, 3, random);
    TimeIndex index;
    index.build(&root, 0.0, 1.0);
    NodeRef copy = root;
    for (int k = 0; k <= 64; ++k) CHECK(index.entry(k / 64.0, &copy) == descend(&root, k / 64.0));
    // An instant at the chain's very end belongs to its last piece.
    CHECK(index.entry(1.0, &copy) == descend(&root, 1.0));

    // A chain whose later half is not built yet: its slot is a piece of
    // its own, and stays the entry once a walk has built a time node there.
    std::deque<TimeNode> built;
    int marker = 0;
    TimeNode& top =
        time_node(built, 0.0, 1.0, NodeRef::object(1), NodeRef::node(RefKind::Pending, &marker));
    NodeRef pending_root = NodeRef::node(RefKind::TimeNode, &top);
    index.build(&pending_root, 0.6, 0.9);
    CHECK(index.size() == 1);  // [0.5, 1]; the earlier half is outside the shutter
    CHECK(index.entry(0.7, &copy) == &top.child[1]);
    CHECK(index.entry(0.4, &copy) == &copy);
    TimeNode& half = time_node(built, 0.5, 1.0, NodeRef::object(2), NodeRef::object(3));
    NodeRef::store(&top.child[1], NodeRef::node(RefKind::TimeNode, &half));
    CHECK(index.entry(0.7, &copy) == &top.child[1]);
    CHECK(descend(index.entry(0.8, &copy), 0.8) == &half.child[1]);
    // Built again for the next frame, it reaches below.
    index.build(&pending_root, 0.6, 0.9);
    CHECK(index.size() == 2);
    CHECK(index.entry(0.7, &copy) == &half.child[0]);
    CHECK(index.entry(0.75, &copy) == &half.child[1]);
    index.clear();
    CHECK(index.entry(0.7, &copy) == &copy);
}

TEST_CASE("a thread's copy of the index, refreshed, starts below the time nodes built since",
          "[tracer][time_index]") {
    // The frame's index stops at a pending half; a walk builds a time node
    // there. The thread's copy, refreshed, leads straight below it, while
    // the shared index it was copied from stays as it was.
    std::deque<TimeNode> built;
    int marker = 0;
    TimeNode& top =
        time_node(built, 0.0, 1.0, NodeRef::object(1), NodeRef::node(RefKind::Pending, &marker));
    NodeRef root = NodeRef::node(RefKind::TimeNode, &top);
    NodeRef copy = root;
    TimeIndex shared;
    shared.build(&root, 0.25, 0.9);
    REQUIRE(shared.refreshable());
    TimeIndex local = shared;
    TimeNode& half = time_node(built, 0.5, 1.0, NodeRef::object(2), NodeRef::object(3));
    NodeRef::store(&top.child[1], NodeRef::node(RefKind::TimeNode, &half));
    CHECK(local.entry(0.7, &copy) == &top.child[1]);  // one time node to walk
    local.refresh(&root);
    CHECK(local.size() == 3);
    for (int k = 0; k <= 100; ++k) {
        const double t = 0.25 + 0.65 * k / 100.0;
        CHECK(local.entry(t, &copy) == descend(&root, t));
        CHECK(NodeRef::load(local.entry(t, &copy)).kind() != RefKind::TimeNode);
    }
    CHECK(shared.entry(0.7, &copy) == &top.child[1]);
    // The refresh keeps the shutter it was built over: outside it, the
    // root or the chain's own slot in the pieces that hold its ends.
    for (const double t : {0.1, 0.2, 0.95, 1.0})
        CHECK((local.entry(t, &copy) == &copy || local.entry(t, &copy) == descend(&root, t)));
    CHECK(local.entry(1.5, &copy) == &copy);

    // An index that filled up leaves its last pieces' time nodes to the
    // walk: refreshing it would gain nothing, on every ray.
    std::mt19937 random(3);
    Chain deep;
    NodeRef deep_root = deep.make(0.0, 1.0, 14, random);
    TimeIndex full;
    full.build(&deep_root, 0.0, 1.0);
    CHECK(full.size() <= TimeIndex::kMaxEntries);
    CHECK_FALSE(full.refreshable());
    NodeRef deep_copy = deep_root;
    for (int k = 0; k <= 1000; ++k) {
        const double t = k / 1000.0;
        CHECK(descend(full.entry(t, &deep_copy), t) == descend(&deep_root, t));
    }
    TimeIndex none;
    CHECK_FALSE(none.refreshable());
}

TEST_CASE("the inline float steps are std::nextafter's", "[tracer][bound_rounding]") {
    using hexant::tracer::float_step_down;
    using hexant::tracer::float_step_up;
    const float inf = std::numeric_limits<float>::infinity();
    std::mt19937 random(3);
    std::vector<float> values = {0.0f,
                                 -0.0f,
                                 std::numeric_limits<float>::denorm_min(),
                                 -std::numeric_limits<float>::denorm_min(),
                                 std::numeric_limits<float>::min(),
                                 std::numeric_limits<float>::max(),
                                 -std::numeric_limits<float>::max(),
                                 1.0f,
                                 -1.0f};
    std::uniform_real_distribution<double> exponent(-140.0, 127.0);
    for (int i = 0; i < 10000; ++i) {
        const float f = float(std::exp2(exponent(random)));
        values.push_back(i % 2 ? f : -f);
    }
    for (const float f : values) {
        CHECK(float_step_up(f) == std::nextafter(f, inf));
        CHECK(float_step_down(f) == std::nextafter(f, -inf));
    }
    CHECK(float_step_up(-inf) == -std::numeric_limits<float>::max());
    CHECK(float_step_down(inf) == std::numeric_limits<float>::max());
    // And the outward roundings they serve.
    for (const double v : {0.1, -0.1, 1e-40, -1e-40, 3e38, -3e38, 1e300}) {
        CHECK(double(hexant::tracer::float_up(v)) >= v);
        CHECK(double(hexant::tracer::float_down(v)) <= v);
    }
}
