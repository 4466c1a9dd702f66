// The hierarchy's statistics: the cells a full build would make, counted
// by building what a lazy build left (--stats), one slab at a time.
#include <mutex>

#include "tracer/hierarchy.hpp"
#include "tracer/hierarchy_builder.hpp"

namespace hexant::tracer {

void Hierarchy::count_full(Counters& counters) const {
    Counters extra;
    // Cells in the lasting part, and in each slab counted once, however
    // often a render built it again.
    std::uint64_t slab_cells = 0;
    const auto visit = [&](auto&& self, NodeRef* slot) -> void {
        NodeRef ref = NodeRef::load(slot);
        PendingCell* slab = nullptr;
        if (ref.kind() == RefKind::Pending) {
            if (ref.as<PendingCell>()->slab_root) slab = ref.as<PendingCell>();
            ref = expand(slot, ref, extra);
        }
        switch (ref.kind()) {
            case RefKind::BoxNode:
                for (auto& c : ref.as<BoxNode>()->child) self(self, &c);
                break;
            case RefKind::MotionNode:
                for (auto& c : ref.as<MotionNode>()->child) self(self, &c);
                break;
            case RefKind::SlabNode:
                for (auto& c : ref.as<SlabNode>()->child) self(self, &c);
                break;
            case RefKind::PieceNode:
                for (auto& c : ref.as<PieceNode>()->child) self(self, &c);
                break;
            case RefKind::TimeNode:
                for (auto& c : ref.as<TimeNode>()->child) self(self, &c);
                break;
            default:
                break;
        }
        if (slab) {
            // Counted: let it go again, so that counting holds one slab at a time.
            slab_cells += slab->own->cells();
            const std::lock_guard<std::mutex> lock(slabs_mutex_);
            peak_bytes_ = std::max(peak_bytes_, held_bytes());
            std::erase_if(live_slabs_, [&](const LiveSlab& s) {
                if (s.cell != slab) return false;
                release(s);
                return true;
            });
        }
    };
    NodeRef root = root_;
    visit(visit, &root);
    {
        const std::lock_guard<std::mutex> lock(slabs_mutex_);
        for (const LiveSlab& s : live_slabs_) slab_cells += s.cell->own->cells();
    }
    counters.cells_full += arena_.cells() + slab_cells;
}

}  // namespace hexant::tracer
