// The leaf's own hierarchy: a cell at the bottom holds its objects under a
// small eight-wide bounding volume hierarchy built by binned SAH, each
// object bounded inside the cell by its own bins of time.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec3.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "tracer/hierarchy_builder.hpp"

namespace hexant::tracer {

using namespace hierarchy_build;

namespace {

// The centre of an item's box along `axis`, where the cuts sort it.
// Never NaN: a box unbounded both ways ([-inf, inf]) has centre 0, so
// that the cuts' order is a strict weak one and a bin index is never a
// NaN cast to int (fuzz_found/unbounded_centre.pov, UBSan).
float centre(const LeafItem& item, int axis) {
    const float c = 0.5f * item.box.lo[axis] + 0.5f * item.box.hi[axis];
    return c == c ? c : 0.0f;
}
// Where the centres of [first, last) spread widest: the axis, and the
// spread's low end and width along it.
struct Spread {
    int axis;
    double lo, width;
};
template <class It>
Spread centre_spread(It first, It last) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (It i = first; i != last; ++i)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], double(centre(*i, a)));
            hi[a] = std::max(hi[a], double(centre(*i, a)));
        }
    const glm::dvec3 e = hi - lo;
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
    return {axis, lo[axis], e[axis]};
}
// Orders items by their centres along `axis`.
auto by_centre(int axis) {
    return
        [axis](const LeafItem& a, const LeafItem& b) { return centre(a, axis) < centre(b, axis); };
}

// Reorders [first, last) (items) into two runs
// and returns the length of the first: the cut with the least
// area-times-count over sixteen bins of the centres along their widest
// spread; the median when the centres coincide or no cut helps.
template <class It>
std::size_t sah_cut(It first, It last) {
    const std::size_t n = std::size_t(last - first);
    // (Named, not a structured binding: clang before 16 cannot capture one.)
    const Spread spread = centre_spread(first, last);
    const int axis = spread.axis;
    const double lo = spread.lo, width = spread.width;
    const auto median = [&] {
        std::nth_element(first, first + n / 2, last, by_centre(axis));
        return n / 2;
    };
    if (!(width > 0.0) || !std::isfinite(width)) return median();
    constexpr int kBins = 16;
    std::array<BinBox, kBins> box;
    std::array<std::size_t, kBins> count{};
    const auto bin_of = [&](const auto& item) {
        return std::clamp(int((centre(item, axis) - lo) / width * kBins), 0, kBins - 1);
    };
    for (It i = first; i != last; ++i) {
        const int b = bin_of(*i);
        box[b].extend(i->box);
        ++count[b];
    }
    // Areas of everything left of each cut, then right of it.
    std::array<double, kBins> left_cost{};
    BinBox acc;
    std::size_t acc_count = 0;
    for (int b = 0; b < kBins - 1; ++b) {
        acc.extend(box[b]);
        acc_count += count[b];
        left_cost[b] = surface_area(acc) * double(acc_count);
    }
    acc = BinBox{};
    acc_count = 0;
    int best = -1;
    double best_cost = std::numeric_limits<double>::infinity();
    for (int b = kBins - 1; b > 0; --b) {
        acc.extend(box[b]);
        acc_count += count[b];
        const double cost = left_cost[b - 1] + surface_area(acc) * double(acc_count);
        if (acc_count < n && acc_count > 0 && cost < best_cost) {
            best_cost = cost;
            best = b;
        }
    }
    if (best < 0) return median();
    const It middle =
        std::partition(first, last, [&](const auto& item) { return bin_of(item) < best; });
    const std::size_t left = std::size_t(middle - first);
    return left == 0 || left == n ? median() : left;
}

}  // namespace

// A cell at the bottom: its objects as children, each bounded inside it.
// While it is built a leaf of n objects holds n items of 128 bytes,
// each object's bins packed beside its box (packed_bins.hpp); it held
// 304 bytes an object (the bins in floats, and a 96-byte item), 30 MB
// for a leaf of 10^5 objects, and the two threads build two at once.
NodeRef Hierarchy::Builder::leaf(NodeArena& arena, const Box4& region, const CellTime& time,
                                 const std::vector<std::uint32_t>& objects,
                                 Counters& counters) const {
    const int k = fit_levels();
    std::vector<LeafItem> items(objects.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, objects.size(), kParallelGrain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i < r.end(); ++i) {
                              const TimeBins bins = object_bins(objects[i], region, time, k);
                              // (Nothing in the cell: the item goes.)
                              const BinBox hull = bins.is_empty() ? BinBox{} : bins.frame();
                              items[i].box = hull;
                              items[i].object = objects[i];
                              items[i].bins = PackedBins::pack(bins, hull);
                          }
                      });
    // Objects the cell's bins miss (in place: no second copy of a large leaf).
    std::erase_if(items, [](const LeafItem& item) { return item.box.is_empty(); });
    if (items.empty()) return {};
    counters.object_refs += items.size();
    const Leaf leaf{arena, region, time, k};
    return group_range(leaf, items, 0, items.size(), counters, true).ref;
}

// More objects than a node holds: a small bounding volume hierarchy
// over them, eight-wide. The cluster with the largest area times count
// is cut in two where the surface-area heuristic says (sixteen bins of
// box centres along their widest spread, as binned SAH builders do),
// until there are eight or none holds more than a node does; each
// cluster of several becomes a node below. (Cutting on to eight
// clusters filled the lowest nodes with three objects on average: 31,000
// nodes for a leaf of 10^5 objects.) Returns the node over items
// [begin, end) with the bins of everything in it, its objects' bins
// unpacked at the bottom; the items are reordered in place. A
// lone object below the leaf's top is its parent's child itself.
Child Hierarchy::Builder::group_range(const Leaf& leaf, std::vector<LeafItem>& items,
                                      std::size_t begin, std::size_t end, Counters& counters,
                                      bool top) const {
    const Interval& time = leaf.time.t;
    if (end - begin <= std::size_t(kNodeWidth)) {
        std::vector<Child> members;
        members.reserve(end - begin);
        Child merged{{}, TimeBins::empty(1 << leaf.k)};
        for (std::size_t i = begin; i < end; ++i) {
            members.push_back({NodeRef::object(items[i].object),
                               items[i].bins.unpack(items[i].box, leaf.region)});
            merged.bins.add(members.back().bins);
        }
        if (members.size() == 1 && !top) return members.front();
        merged.ref = bound_node(leaf.arena, time, members, counters);
        return merged;
    }
    struct Cluster {
        std::size_t begin, end;  // in items
        double weight;           // area times count: what splitting it may save
    };
    const auto weigh = [&](std::size_t b, std::size_t e) {
        BinBox box;
        for (std::size_t i = b; i < e; ++i) box.extend(items[i].box);
        return Cluster{b, e, surface_area(box) * double(e - b)};
    };
    std::vector<Cluster> clusters;
    const std::size_t n = end - begin;
    if (n <= std::size_t(kNodeWidth * kNodeWidth)) {
        // The last level above the objects: as few nodes as hold them,
        // runs of the centres in order along their widest spread (binary
        // cuts left the lowest nodes 60% full: 23,000 nodes for a leaf of
        // 10^5 objects where 14,300 hold them).
        std::sort(items.begin() + begin, items.begin() + end,
                  by_centre(centre_spread(items.begin() + begin, items.begin() + end).axis));
        const std::size_t runs = (n + kNodeWidth - 1) / kNodeWidth;
        for (std::size_t r = 0; r < runs; ++r)
            clusters.push_back({begin + n * r / runs, begin + n * (r + 1) / runs, 0.0});
    } else {
        clusters.push_back(weigh(begin, end));
    }
    while (clusters.size() < std::size_t(kNodeWidth) && n > std::size_t(kNodeWidth * kNodeWidth)) {
        std::size_t pick = clusters.size();
        for (std::size_t c = 0; c < clusters.size(); ++c)
            if (clusters[c].end - clusters[c].begin > std::size_t(kNodeWidth) &&
                (pick == clusters.size() || clusters[c].weight > clusters[pick].weight))
                pick = c;
        if (pick == clusters.size()) break;
        const Cluster c = clusters[pick];
        const std::size_t middle =
            sah_cut(items.begin() + c.begin, items.begin() + c.end) + c.begin;
        clusters[pick] = weigh(c.begin, middle);
        clusters.push_back(weigh(middle, c.end));
    }
    // The clusters' nodes, built side by side where they are large (they
    // own disjoint runs of the items).
    std::vector<Child> grouped(clusters.size());
    std::vector<Counters> each(clusters.size());
    const auto make = [&](std::size_t c) {
        grouped[c] = group_range(leaf, items, clusters[c].begin, clusters[c].end, each[c]);
    };
    if (end - begin >= kParallelGrain)
        tbb::parallel_for(std::size_t(0), clusters.size(), make);
    else
        for (std::size_t c = 0; c < clusters.size(); ++c) make(c);
    for (const Counters& c : each) counters += c;
    Child merged{{}, TimeBins::empty(1 << leaf.k)};
    for (const Child& c : grouped) merged.bins.add(c.bins);
    merged.ref = bound_node(leaf.arena, time, grouped, counters);
    return merged;
}

}  // namespace hexant::tracer
