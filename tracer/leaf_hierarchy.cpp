// The leaf's own hierarchy: a cell at the bottom holds its objects under a
// small eight-wide bounding volume hierarchy built by binned SAH, each
// object bounded inside the cell by its own bins of time.
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include <glm/vec3.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "tracer/hierarchy_builder.hpp"

namespace hexant::tracer {

using namespace hierarchy_build;

namespace {

// An object's bound at the start and the end of the leaf's time (or of
// the part of it the object spends in the cell): its first and last
// non-empty bins, narrowed to its lines' ends there where it has lines.
LinearExtent ends(const TimeBins& bins) {
    LinearExtent e;
    int first = 0, last = bins.count - 1;
    while (first < bins.count && bins.bin[first].is_empty()) ++first;
    while (last > first && bins.bin[last].is_empty()) --last;
    if (first > last) return e;
    e.start = bins.bin[first];
    e.end = bins.bin[last];
    if (!bins.lines()) return e;
    const auto narrowed = [](const BinBox& box, const BinBox& edge) {
        BinBox b = box;
        for (int a = 0; a < 3; ++a) {
            b.lo[a] = std::max(b.lo[a], edge.lo[a]);
            b.hi[a] = std::min(b.hi[a], edge.hi[a]);
        }
        return b.is_empty() ? box : b;
    };
    e.start = narrowed(e.start, bins.edge[first]);
    e.end = narrowed(e.end, bins.edge[last + 1]);
    return e;
}

// Items are sorted and cut by the centres of their bounds at the leaf's
// mid-time (halfway between their bounds at its start and end). Never
// NaN: a box unbounded both ways ([-inf, inf]) has centre 0, so that the
// cuts' order is a strict weak one and a bin index is never a NaN cast to
// int (fuzz_found/unbounded_centre.pov, UBSan).
float centre(const LinearExtent& e, int axis) {
    const float c = 0.25f * e.start.lo[axis] + 0.25f * e.start.hi[axis] + 0.25f * e.end.lo[axis] +
                    0.25f * e.end.hi[axis];
    return c == c ? c : 0.0f;
}
// Orders items by their centres along `axis`, then by object (the same
// order in every run).
auto by_centre(int axis) {
    return [axis](const LeafItem& a, const LeafItem& b) {
        const float ca = centre(a.extent, axis), cb = centre(b.extent, axis);
        return ca < cb || (ca == cb && a.object < b.object);
    };
}

// The cut nearest `left` that leaves a multiple of `grain` on one side
// (0 < result < n).
std::size_t snapped(std::size_t left, std::size_t n, std::size_t grain) {
    std::size_t best = n / 2, best_gap = n;
    const auto consider = [&](std::size_t v) {
        if (v == 0 || v >= n) return;
        const std::size_t gap = v > left ? v - left : left - v;
        if (gap < best_gap) best = v, best_gap = gap;
    };
    for (std::size_t m = grain; m < n; m += grain) {
        consider(m);
        consider(n - m);
    }
    return best;
}

// Reorders [first, last) (items) into two runs and returns the length of
// the first: of sixteen bins of the centres along each axis, the cut with
// the least area-times-count, the area being what a group's linear bound
// presents on average over the leaf's time (LinearExtent: a ray at a
// random instant meets it in that proportion), moved to leave a multiple
// of `grain` on one side; the median when the centres coincide. (Priced
// by the boxes over the whole time, groups were as wide as their members'
// paths at every instant.)
template <class It>
std::size_t sah_cut(It first, It last, std::size_t grain) {
    const std::size_t n = std::size_t(last - first);
    constexpr int kBins = 16;
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (It i = first; i != last; ++i)
        for (int a = 0; a < 3; ++a) {
            const double c = centre(i->extent, a);
            lo[a] = std::min(lo[a], c);
            hi[a] = std::max(hi[a], c);
        }
    const glm::dvec3 width = hi - lo;
    bool usable[3];
    for (int a = 0; a < 3; ++a) usable[a] = width[a] > 0.0 && std::isfinite(width[a]);
    const auto bin_of = [&](const LeafItem& item, int a) {
        return std::clamp(int((double(centre(item.extent, a)) - lo[a]) / width[a] * kBins), 0,
                          kBins - 1);
    };
    std::array<std::array<LinearExtent, kBins>, 3> box;
    std::array<std::array<std::size_t, kBins>, 3> count{};
    for (It i = first; i != last; ++i)
        for (int a = 0; a < 3; ++a) {
            if (!usable[a]) continue;
            const int b = bin_of(*i, a);
            box[a][b].extend(i->extent);
            ++count[a][b];
        }
    int best_axis = -1, best_bin = 0;
    double best_cost = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (!usable[a]) continue;
        // Areas of everything left of each cut, then right of it.
        std::array<double, kBins> left_cost{};
        LinearExtent acc;
        std::size_t acc_count = 0;
        for (int b = 0; b < kBins - 1; ++b) {
            acc.extend(box[a][b]);
            acc_count += count[a][b];
            left_cost[b] = acc.mean_area() * double(acc_count);
        }
        acc = LinearExtent{};
        acc_count = 0;
        for (int b = kBins - 1; b > 0; --b) {
            acc.extend(box[a][b]);
            acc_count += count[a][b];
            const double cost = left_cost[b - 1] + acc.mean_area() * double(acc_count);
            if (acc_count < n && acc_count > 0 && cost < best_cost)
                best_axis = a, best_bin = b, best_cost = cost;
        }
    }
    if (best_axis < 0) {
        const std::size_t left = snapped(n / 2, n, grain);
        const int a = width.x >= width.y && width.x >= width.z ? 0 : width.y >= width.z ? 1 : 2;
        std::nth_element(first, first + std::ptrdiff_t(left), last, by_centre(a));
        return left;
    }
    const It middle = std::partition(
        first, last, [&](const LeafItem& item) { return bin_of(item, best_axis) < best_bin; });
    const std::size_t cut = std::size_t(middle - first);
    const std::size_t left = snapped(cut, n, grain);
    // (Moved: the centres nearest the cut cross it.)
    if (left < cut)
        std::nth_element(first, first + std::ptrdiff_t(left), middle, by_centre(best_axis));
    else if (left > cut)
        std::nth_element(middle, first + std::ptrdiff_t(left), last, by_centre(best_axis));
    return left;
}

// The lowest nodes over n items (at most kNodeWidth squared): as few as
// hold them, ceil(n / 8), found by cutting in two where the
// area-times-count is least among the cuts that leave a multiple of eight
// on one side, along each axis. (Runs of the centres in order along one
// axis were slices through the whole group, which a ray crossed one after
// another; binary cuts free of that count left the lowest nodes 60% full.)
// Sorts `order` (the items' places, with their centres and bounds) into
// the runs, and appends their ends (offsets in it) to `runs`.
struct Placed {
    std::array<float, 3> centre;
    LinearExtent extent;
    std::uint32_t place;
};
void bottom_runs(std::span<Placed> order, std::size_t offset,
                 std::vector<std::pair<std::size_t, std::size_t>>& runs) {
    const std::size_t n = order.size();
    const std::size_t w = std::size_t(kNodeWidth);
    if (n <= w) {
        runs.push_back({offset, offset + n});
        return;
    }
    const auto by = [](int a) {
        return [a](const Placed& p, const Placed& q) {
            return p.centre[a] < q.centre[a] || (p.centre[a] == q.centre[a] && p.place < q.place);
        };
    };
    int best_axis = 0;
    std::size_t best_left = (n + w - 1) / w / 2 * w;
    double best_cost = std::numeric_limits<double>::infinity();
    std::array<double, kNodeWidth * kNodeWidth + 1> left_area{};
    for (int a = 0; a < 3; ++a) {
        std::sort(order.begin(), order.end(), by(a));
        const auto allowed = [&](std::size_t j) { return j % w == 0 || (n - j) % w == 0; };
        LinearExtent acc;
        for (std::size_t j = 1; j < n; ++j) {
            acc.extend(order[j - 1].extent);
            if (allowed(j)) left_area[j] = acc.mean_area();
        }
        acc = LinearExtent{};
        for (std::size_t j = n; j-- > 1;) {
            acc.extend(order[j].extent);
            if (!allowed(j)) continue;
            const double cost = left_area[j] * double(j) + acc.mean_area() * double(n - j);
            if (cost < best_cost) best_axis = a, best_left = j, best_cost = cost;
        }
    }
    std::sort(order.begin(), order.end(), by(best_axis));
    bottom_runs(order.first(best_left), offset, runs);
    bottom_runs(order.subspan(best_left), offset + best_left, runs);
}

// Items [begin, end) reordered into bottom_runs's runs, whose ends it
// appends to `runs`.
void bottom_runs(std::vector<LeafItem>& items, std::size_t begin, std::size_t end,
                 std::vector<std::pair<std::size_t, std::size_t>>& runs) {
    std::vector<Placed> order(end - begin);
    for (std::size_t i = begin; i < end; ++i) {
        Placed& p = order[i - begin];
        for (int a = 0; a < 3; ++a) p.centre[a] = centre(items[i].extent, a);
        p.extent = items[i].extent;
        p.place = std::uint32_t(i - begin);
    }
    bottom_runs(order, begin, runs);
    std::vector<LeafItem> sorted;
    sorted.reserve(order.size());
    for (const Placed& p : order) sorted.push_back(items[begin + p.place]);
    std::copy(sorted.begin(), sorted.end(), items.begin() + std::ptrdiff_t(begin));
}

}  // namespace

// A cell at the bottom: its objects as children, each bounded inside it.
// While it is built a leaf of n objects holds n items of 56 bytes, each an
// object's bound at the leaf's start and end. Below options_.kept_bins objects (2^14)
// that bound is the ends of the object's bins, which are made once and
// kept packed beside their box (136 bytes more, packed_bins.hpp). A larger
// leaf keeps no bins: the bound it prices and sorts by is the object's
// placed box at the leaf's start and end, inside the cell (two placements
// where the bins make five to nine), and the bins are made at the bottom,
// where they are used (issue 43: it held 188 bytes an object, 18.8 MB for
// a leaf of 10^5, on top of the frame's nodes: the swarm's peak). An
// object whose cached sweep misses the cell goes; one whose bins miss it
// goes at the bottom.
NodeRef Hierarchy::Builder::leaf(NodeArena& arena, const Box4& region, const CellTime& time,
                                 const std::vector<std::uint32_t>& objects,
                                 Counters& counters) const {
    const int k = fit_levels();
    const bool keep = objects.size() < options_.kept_bins;
    std::vector<LeafItem> items(objects.size());
    std::vector<KeptBins> kept(keep ? objects.size() : 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, objects.size(), kParallelGrain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i < r.end(); ++i) {
                              items[i].object = objects[i];
                              items[i].kept = std::uint32_t(i);
                              // (Nothing in the cell: the item goes, its extent empty.)
                              if (!keep) {
                                  items[i].extent = placed_ends(objects[i], region, time);
                                  continue;
                              }
                              const TimeBins bins = object_bins(objects[i], region, time, k);
                              items[i].extent = ends(bins);
                              const BinBox hull = bins.is_empty() ? BinBox{} : bins.frame();
                              kept[i] = {hull, PackedBins::pack(bins, hull)};
                          }
                      });
    // Objects the cell's bins miss (in place: no second copy of a large leaf).
    std::erase_if(items, [](const LeafItem& item) { return item.extent.start.is_empty(); });
    if (items.empty()) return {};
    counters.object_refs += items.size();
    const Leaf leaf{arena, region, time, k, keep ? &kept : nullptr};
    return group_range(leaf, items, 0, items.size(), counters, true).ref;
}

// Object i's placed boxes at the start and end of the cell's time, inside
// the region (the cached sweep's box there where a placed box misses it);
// empty where the cached sweep misses the cell. A heuristic, for the
// surface-area heuristic alone: the nodes are fitted to the bins.
LinearExtent Hierarchy::Builder::placed_ends(std::uint32_t i, const Box4& region,
                                             const CellTime& time) const {
    const Box4 cached = object_over(i, time, region);
    if (cached.is_empty()) return {};
    const runtime::IntelligentObject& object = *objects_.objects[i];
    const auto at = [&](double t) {
        const BinBox placed = BinBox::of(object.placed_box_at(t).intersection(region));
        return placed.is_empty() ? BinBox::of(cached) : placed;
    };
    return {at(time.t.lo), at(time.t.hi)};
}

// More objects than a node holds: a small bounding volume hierarchy
// over them, eight-wide. The cluster with the largest area times count
// is cut in two where the surface-area heuristic says (sah_cut), until
// none holds more than the levels below a child hold when full; each
// cluster of several becomes a node below, the lowest ones from
// bottom_runs. (Cutting on to eight clusters filled the lowest nodes
// with three objects on average: 31,000 nodes for a leaf of 10^5
// objects.) Returns the node over items
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
            const std::uint32_t object = items[i].object;
            if (leaf.kept) {
                const KeptBins& kept = (*leaf.kept)[items[i].kept];
                members.push_back(
                    {NodeRef::object(object), kept.bins.unpack(kept.box, leaf.region)});
            } else {
                TimeBins bins = object_bins(object, leaf.region, leaf.time, leaf.k);
                if (bins.is_empty()) continue;  // (its sweep met the cell, its bins do not)
                members.push_back({NodeRef::object(object), bins});
            }
            merged.bins.add(members.back().bins);
        }
        if (members.empty()) return merged;
        if (members.size() == 1 && !top) return members.front();
        merged.ref = object_node(leaf.arena, time, members, counters);
        return merged;
    }
    struct Cluster {
        std::size_t begin, end;  // in items
        double weight;           // area times count: what splitting it may save
    };
    const auto weigh = [&](std::size_t b, std::size_t e) {
        LinearExtent extent;
        for (std::size_t i = b; i < e; ++i) extent.extend(items[i].extent);
        return Cluster{b, e, extent.mean_area() * double(e - b)};
    };
    std::vector<Cluster> clusters;
    const std::size_t n = end - begin;
    // What each child may hold: the most that as many levels below as
    // this node needs hold, so that the levels below are full and an
    // unfilled node is this one (a leaf of 10^4 had nodes over 20 objects
    // with three children, each a level a ray paid for with no fan-out).
    std::size_t cap = std::size_t(kNodeWidth * kNodeWidth);
    while (cap * std::size_t(kNodeWidth) < n) cap *= std::size_t(kNodeWidth);
    if (n <= std::size_t(kNodeWidth * kNodeWidth)) {
        // The last level above the objects: as few nodes as hold them.
        std::vector<std::pair<std::size_t, std::size_t>> runs;
        bottom_runs(items, begin, end, runs);
        for (const auto& [b, e] : runs) clusters.push_back({b, e, 0.0});
    } else {
        clusters.push_back(weigh(begin, end));
    }
    while (n > std::size_t(kNodeWidth * kNodeWidth)) {
        std::size_t pick = clusters.size();
        for (std::size_t c = 0; c < clusters.size(); ++c)
            if (clusters[c].end - clusters[c].begin > cap &&
                (pick == clusters.size() || clusters[c].weight > clusters[pick].weight))
                pick = c;
        if (pick == clusters.size()) break;
        const Cluster c = clusters[pick];
        const std::size_t middle =
            sah_cut(items.begin() + c.begin, items.begin() + c.end, cap) + c.begin;
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
    // (A group whose objects' bins all missed the cell is nothing.)
    std::erase_if(grouped, [](const Child& c) { return c.ref.empty(); });
    Child merged{{}, TimeBins::empty(1 << leaf.k)};
    if (grouped.empty()) return merged;
    if (grouped.size() == 1 && !top) return grouped.front();
    for (const Child& c : grouped) merged.bins.add(c.bins);
    merged.ref = bound_node(leaf.arena, time, grouped, counters);
    return merged;
}

}  // namespace hexant::tracer
