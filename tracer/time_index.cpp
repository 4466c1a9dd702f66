// The time index: reading the chain of time nodes over a shutter
// (time_index.hpp).
#include "tracer/time_index.hpp"

namespace hexant::tracer {

void TimeIndex::clear() {
    cuts_.clear();
    slots_.clear();
    end_closed_ = false;
    capped_ = false;
}

void TimeIndex::build(NodeRef* root, double t0, double t1) {
    clear();
    t0_ = t0;
    t1_ = t1;
    if (!(t0 <= t1)) return;
    NodeRef ref = NodeRef::load(root);
    if (ref.kind() != RefKind::TimeNode) return;
    // Depth first, earlier half first, so pieces arrive in time order. A
    // piece is kept whole once the index is full; its time nodes are then
    // walked as before.
    struct Piece {
        NodeRef* slot;
        double lo, hi;
    };
    std::vector<Piece> todo;
    const TimeNode* top = ref.as<TimeNode>();
    todo.push_back({root, top->t0, top->t1});
    std::vector<Piece> pieces;
    while (!todo.empty()) {
        const Piece p = todo.back();
        todo.pop_back();
        const NodeRef r = NodeRef::load(p.slot);
        if (r.kind() != RefKind::TimeNode) {
            pieces.push_back(p);
            continue;
        }
        if (pieces.size() + todo.size() + 2 > kMaxEntries) {
            capped_ = true;
            pieces.push_back(p);
            continue;
        }
        TimeNode* node = r.as<TimeNode>();
        // A ray at instant t takes child[t >= split]: the later half is
        // needed when t1 reaches the split, the earlier when t0 is before it.
        if (t1 >= node->split) todo.push_back({&node->child[1], node->split, p.hi});
        if (t0 < node->split) todo.push_back({&node->child[0], p.lo, node->split});
    }
    if (pieces.empty()) return;
    cuts_.reserve(pieces.size() + 1);
    slots_.reserve(pieces.size());
    for (const Piece& p : pieces) {
        cuts_.push_back(p.lo);
        slots_.push_back(p.slot);
    }
    cuts_.push_back(pieces.back().hi);
    end_closed_ = pieces.back().hi == top->t1;
}

}  // namespace hexant::tracer
