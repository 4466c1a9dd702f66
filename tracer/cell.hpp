// The hierarchy's nodes as the traversal reads them (docs/design.md, "Cell"):
// a cell of spacetime becomes either a time node (its two time halves), a
// node of up to eight children with their bounds side by side, or, at the
// bottom, a node whose children are the objects themselves, each with its
// own bound inside the cell.
//
// Children's bounds are stored in single precision, one array per
// coordinate with the eight children side by side, so one SIMD pass tests
// them all (tracer/traversal_simd.cpp). Three styles of bound, chosen per
// node (the paper: "the style of bound at each cell may be different"):
//  - BoxNode: an axis-aligned box holding the child over the node's whole
//    time range (what does not move, and the frame-by-frame baseline);
//  - MotionNode: a linear-motion box, the box at the node's start time and
//    its change to the end time, interpolated: at time t the child lies in
//    lo + u dlo .. hi + u dhi, u = (t - t0) / (t1 - t0). In spacetime this
//    is a bound by eight 4D slabs whose normals follow the motion; for a ray
//    at one instant it is a 3D box, three fused multiply-adds per side;
//  - SlabNode: the 12-slab bound (runtime/bounds/slab_bound.hpp) without its time
//    slab: at an instant its eight auxiliary slabs pair up into four
//    diagonal 3D slabs, so the child lies in a 3D box cut by four planes.
// Every stored bound is rounded outward, with the margin that the float
// evaluation at traversal time needs (tracer/bound_rounding.hpp argues it).
#pragma once

#include <cstdint>

namespace hexant::tracer {

inline constexpr int kNodeWidth = 8;

enum class RefKind : std::uint8_t {
    Empty = 0,
    BoxNode = 1,
    MotionNode = 2,
    SlabNode = 3,
    TimeNode = 4,
    Object = 5,   // an index into the bounded objects
    Pending = 6,  // a cell not built yet (lazy build): a PendingCell*
    PieceNode = 7,
};

// A child: a tagged pointer to a node (nodes are 64-byte aligned), or an
// object index shifted past the tag.
class NodeRef {
  public:
    NodeRef() = default;
    static NodeRef node(RefKind kind, const void* p) {
        return NodeRef(reinterpret_cast<std::uintptr_t>(p) | std::uintptr_t(kind));
    }
    static NodeRef object(std::uint32_t index) {
        return NodeRef((std::uintptr_t(index) << 3) | std::uintptr_t(RefKind::Object));
    }
    RefKind kind() const { return RefKind(bits_ & 7); }
    bool empty() const { return bits_ == 0; }
    template <class T>
    T* as() const {
        return reinterpret_cast<T*>(bits_ & ~std::uintptr_t(7));
    }
    std::uint32_t object_index() const { return std::uint32_t(bits_ >> 3); }
    std::uintptr_t bits() const { return bits_; }
    static NodeRef from_bits(std::uintptr_t bits) { return NodeRef(bits); }

    // A lazy build replaces a pending child by its node while other threads
    // read the slot: every read of a child slot is an acquire load, the
    // replacement a release store (hierarchy.cpp, Hierarchy::expand).
    static NodeRef load(const NodeRef* slot) {
        return NodeRef(__atomic_load_n(&slot->bits_, __ATOMIC_ACQUIRE));
    }
    static void store(NodeRef* slot, NodeRef value) {
        __atomic_store_n(&slot->bits_, value.bits_, __ATOMIC_RELEASE);
    }

  private:
    explicit NodeRef(std::uintptr_t bits) : bits_(bits) {}
    std::uintptr_t bits_ = 0;
};

// Empty child slots hold an empty bound (lo = +inf, hi = -inf), which no
// ray meets, so the SIMD test needs no mask.
struct alignas(64) BoxNode {
    float lo[3][kNodeWidth], hi[3][kNodeWidth];
    NodeRef child[kNodeWidth];
    double t0, t1;           // the time range the bounds hold over
    std::uint32_t children;  // non-empty slots (first ones)
};

struct alignas(64) MotionNode {
    float lo[3][kNodeWidth], hi[3][kNodeWidth];    // at t0
    float dlo[3][kNodeWidth], dhi[3][kNodeWidth];  // change from t0 to t1
    NodeRef child[kNodeWidth];
    double t0, t1, inverse_span;  // u = (t - t0) * inverse_span, clamped to [0, 1]
    std::uint32_t children;
};

// Slabs 0-2: x, y, z. Slabs 3-10: the auxiliary normals (.5, ±.5, ±.5, ±.5)
// in runtime::slab_normals() order (index 4 + k there, k's bit 0 the sign
// of t), so slabs 3 + 2j and 4 + 2j share the 3D direction j.
struct alignas(64) SlabNode {
    static constexpr int kSlabs = 11;
    float lo[kSlabs][kNodeWidth], hi[kSlabs][kNodeWidth];
    NodeRef child[kNodeWidth];
    double t0, t1;
    std::uint32_t children;
};

// A node at the bottom of a leaf whose children are objects that move: each
// object's bound over the node's time is piecewise linear, a line over each
// of kPieces equal pieces of the time joined at kPieces + 1 knots (issue 43:
// one line over a leaf's quarter frame missed a swarm sphere's arc by up to
// three times its radius; a line over a quarter of that by a sixteenth as
// much). A ray at instant t takes its piece j and its place v in it; a side
// there is the line between knots j and j + 1. The knots are kept in 8 bits
// of a frame per knot and axis (the values base + q * step, lower ends
// rounded down, upper up), so that the node is smaller than a MotionNode
// (448 bytes against 512); node_piece.cpp argues the rounding.
struct alignas(64) PieceNode {
    static constexpr int kPieces = 4;
    static constexpr int kKnots = kPieces + 1;
    NodeRef child[kNodeWidth];
    double t0, t1, inverse_span;  // u = (t - t0) * inverse_span, clamped to [0, 1]
    float base[kKnots][3];        // per knot and axis, the frame's bottom
    float step[3];                // per axis, the frames' step
    std::uint32_t children;
    std::uint8_t lo[kKnots][3][kNodeWidth], hi[kKnots][3][kNodeWidth];
};
static_assert(sizeof(PieceNode) == 448);

// A cell whose children halve its time: child[0] holds [t0, split],
// child[1] [split, t1]. A ray at one instant goes straight to its half
// (an instant on the split: the later one); no bound is tested.
struct alignas(64) TimeNode {
    double t0, split, t1;
    NodeRef child[2];
};

}  // namespace hexant::tracer
