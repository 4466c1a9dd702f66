#include "tracer/hierarchy.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

#include "runtime/work_counts.hpp"

namespace hexant::tracer {

namespace {

using runtime::Box4;
using runtime::IntelligentObject;
using runtime::SlabBound;

// A cell under construction; cells are laid out in the final array only
// once their children are known, so that children stay consecutive.
struct Node {
    Box4 region;
    SlabBound bound = SlabBound::empty();
    std::vector<Node> children;
    std::vector<std::uint32_t> objects;  // leaves only
};

class Builder {
public:
    Builder(std::span<const IntelligentObject* const> objects, const BuildOptions& options,
            Counters& counters)
        : objects_(objects), options_(options), counters_(counters) {}

    // The node for `region`, or nothing when no candidate meets it.
    std::optional<Node> build(const Box4& region, const std::vector<std::uint32_t>& candidates,
                              int depth) {
        Node node;
        node.region = region;
        std::vector<std::uint32_t> inside;
        std::vector<SlabBound> answers;
        for (const std::uint32_t index : candidates) {
            answers.clear();
            objects_[index]->bound(region, answers);
            ++counters_.bounds_built;
            bool meets = false;
            for (SlabBound b : answers) {
                if (options_.split == SplitMode::Space && options_.boxes_in_space) {
                    // The baseline's static bound: the box the object spans
                    // over the whole shutter interval.
                    b = SlabBound::of_box(b.box());
                }
                b.clip(region);
                if (b.is_empty()) continue;
                node.bound.add(b);
                meets = true;
            }
            if (meets) inside.push_back(index);
        }
        if (inside.empty()) return std::nullopt;
        depth_ = std::max(depth_, depth);

        const Split split = depth < options_.max_depth ? choose_split(region, inside) : Split{};
        if (split.space || split.time) {
            for (const Box4& part : parts(region, split)) {
                if (auto child = build(part, inside, depth + 1))
                    node.children.push_back(std::move(*child));
            }
            if (node.children.size() == 1) return std::move(node.children.front());
            if (!node.children.empty()) {
                node.bound = SlabBound::empty();
                for (const Node& child : node.children) node.bound.add(child.bound);
                return node;
            }
        }
        node.objects = std::move(inside);
        return node;
    }

    int depth() const { return depth_; }

private:
    struct Split {
        bool space = false, time = false;
    };

    // The paper's criterion says whether to split; what moves says along
    // which axes. Halving time helps only where something moves (a static
    // scene builds no time splits); halving space only where there is more
    // than one object to separate or the objects leave much of the cell
    // empty (a lone object's own bound is already as tight as its cell's).
    Split choose_split(const Box4& region, const std::vector<std::uint32_t>& inside) const {
        bool moving = false;
        for (const std::uint32_t index : inside) moving = moving || objects_[index]->moves();
        Split split;
        split.time = moving && options_.split == SplitMode::Spacetime;
        if (inside.size() > options_.max_objects) {
            split.space = true;
        } else if (inside.size() > 1) {
            double filled = 0.0;
            for (const std::uint32_t index : inside) filled += objects_[index]->occupancy(region);
            split.space = filled < options_.max_occupancy;
        }
        // With nothing to separate in space, a moving object's swept bound
        // still tightens when its time is halved.
        return split;
    }

    static std::vector<Box4> parts(const Box4& region, Split split) {
        std::vector<Box4> out;
        const int count = split.space ? 8 : 1;
        for (int c = 0; c < count; ++c) {
            for (int half = 0; half < (split.time ? 2 : 1); ++half) {
                Box4 part = region.child(c | (half << 3));
                if (!split.time) {
                    part.lo.w = region.lo.w;
                    part.hi.w = region.hi.w;
                }
                if (!split.space) {
                    for (int i = 0; i < 3; ++i) {
                        part.lo[i] = region.lo[i];
                        part.hi[i] = region.hi[i];
                    }
                }
                out.push_back(part);
            }
        }
        return out;
    }

    std::span<const IntelligentObject* const> objects_;
    const BuildOptions& options_;
    Counters& counters_;
    int depth_ = 0;
};

}  // namespace

Hierarchy Hierarchy::build(std::span<const IntelligentObject* const> objects, const Box4& root,
                           const BuildOptions& options, Counters& counters) {
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t deformation_maps = runtime::this_thread_work.deformation_maps;
    Hierarchy h;
    std::vector<std::uint32_t> all(objects.size());
    for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    Builder builder(objects, options, counters);
    std::optional<Node> top = builder.build(root, all, 0);
    if (top) {
        // Breadth-first layout: each node's children are consecutive.
        std::vector<const Node*> order{&*top};
        h.cells_.push_back(Cell{top->region, top->bound});
        for (std::size_t i = 0; i < order.size(); ++i) {
            const Node& node = *order[i];
            Cell& cell = h.cells_[i];
            if (node.children.empty()) {
                cell.first_object = static_cast<std::uint32_t>(h.object_refs_.size());
                cell.object_count = static_cast<std::uint32_t>(node.objects.size());
                h.object_refs_.insert(h.object_refs_.end(), node.objects.begin(),
                                      node.objects.end());
                continue;
            }
            cell.first_child = static_cast<std::uint32_t>(h.cells_.size());
            cell.child_count = static_cast<std::uint32_t>(node.children.size());
            cell.splits_time_only = std::all_of(
                node.children.begin(), node.children.end(), [&](const Node& child) {
                    for (int k = 0; k < 3; ++k)
                        if (child.region.lo[k] != node.region.lo[k] ||
                            child.region.hi[k] != node.region.hi[k])
                            return false;
                    return true;
                });
            if (node.children.front().region.hi.w != node.region.hi.w ||
                node.children.front().region.lo.w != node.region.lo.w ||
                node.children.back().region.hi.w != node.region.hi.w)
                ++counters.time_splits;
            for (const Node& child : node.children) {
                order.push_back(&child);
                h.cells_.push_back(Cell{child.region, child.bound});
            }
        }
    }
    h.depth_ = builder.depth();
    counters.cells += h.cells_.size();
    counters.deformation_maps += runtime::this_thread_work.deformation_maps - deformation_maps;
    counters.build_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return h;
}

}  // namespace hexant::tracer
