// The price of a cell's split for the cost criterion: one pass over its
// objects' cached sweeps, the areas they present over its halves, quarters
// and octants (CostSummary, split_criterion.hpp).
#include <algorithm>
#include <cmath>

#include "tracer/hierarchy_builder.hpp"

namespace hexant::tracer {

using namespace hierarchy_build;

// A sample's sums of object areas and counts, as the whole cell's.
void Hierarchy::Builder::scale_object_sums(CostSummary& s, double factor) {
    const auto count = [&](std::size_t c) {
        return std::min(s.objects, std::size_t(std::llround(double(c) * factor)));
    };
    for (double& a : s.time_objects) a *= factor;
    s.object_cell *= factor;
    for (double& a : s.object_half) a *= factor;
    for (double& a : s.object_octant) a *= factor;
    for (auto& halves : s.object_octant_half)
        for (double& a : halves) a *= factor;
    for (std::size_t& c : s.count_half) c = count(c);
    for (std::size_t& c : s.count_octant) c = count(c);
    for (auto& halves : s.count_octant_half)
        for (std::size_t& c : halves) c = count(c);
}

// One pass over the cell's objects (or kCostSample of them): each
// object's sweep over 2^L equal
// pieces of the cell's time, clipped to the cell, merged pairwise up to
// the whole time; the halves and quarters also clipped to the octants.
// Where the cell's bounds may be linear-motion boxes, an object's bound
// over the cell's whole time (for a leaf, or an octant) is priced at
// its fitted box's area, not its halves' boxes. (The frame-by-frame
// baseline's cells have one piece of time: every level is that piece.)
CostSummary Hierarchy::Builder::cost_summary(const Box4& region, const CellTime& time,
                                             const std::vector<std::uint32_t>& objects) const {
    CostSummary s;
    s.objects = objects.size();
    const int levels = space_only() ? 0 : time_levels(time, objects);
    s.time_levels = levels;
    const auto level = [&](int k) { return std::min(k, levels); };
    const int halves = level(1), quarters = level(2), fits = level(kFitLevels);
    // (Only where the sweeps resolve the cell's time into its bins: a
    // line fitted to one or two pieces is no tighter than their boxes.)
    const bool linear =
        !space_only() && levels >= kFitLevels &&
        (options_.bounds == BoundStyle::Auto || options_.bounds == BoundStyle::Linear);
    std::array<Box4, 8> octants;
    for (int o = 0; o < 8; ++o) octants[o] = octant(region, o);
    // The union of everything per piece, at every level.
    std::vector<std::vector<Box4>> cell(levels + 1);
    for (int k = 0; k <= levels; ++k) cell[k].assign(std::size_t(1) << k, Box4::empty());
    std::array<std::vector<Box4>, 8> octant_halves, octant_quarters;
    for (int o = 0; o < 8; ++o) {
        octant_halves[o].assign(std::size_t(1) << halves, Box4::empty());
        octant_quarters[o].assign(std::size_t(1) << quarters, Box4::empty());
    }
    std::vector<Box4> pieces;
    const std::size_t n_objects = objects.size();
    const std::size_t sampled = std::min(n_objects, kCostSample);
    for (std::size_t j = 0; j < sampled; ++j) {
        const std::uint32_t i =
            sampled == n_objects ? objects[j] : objects[j * n_objects / sampled];
        // A moving object's test costs more (its placement at the ray's
        // time): its areas weigh more, relative to a still object's.
        const double weight =
            objects_.objects[i]->moves() ? options_.moving_object_cost / options_.object_cost : 1.0;
        const std::size_t n = std::size_t(1) << levels;
        pieces.resize(n);
        // (Boxes only, not the lines of TimeBins: priced from the objects'
        // own lines, a leaf over a whole frame of the swarm at 10^5 spheres
        // looked as cheap as its halves, and its nodes, each holding
        // spheres that move apart over the frame, took 499 node tests a
        // ray where halving time took 70.)
        object_pieces(i, region, time, levels, pieces.data());
        // How much tighter than its halves' boxes a fitted linear-motion
        // box holds this object over the whole cell time.
        double fit_share = 1.0;
        double halves_area = 0.0;
        bool in_half[2] = {false, false}, in_octant[8] = {}, in_octant_half[8][2] = {};
        for (int k = levels; k >= 0; --k) {
            const std::size_t count = std::size_t(1) << k;
            const double share = 1.0 / double(count);
            double level_area = 0.0;
            for (std::size_t p = 0; p < count; ++p) {
                level_area += surface_area(pieces[p]) * share * weight;
                cell[k][p].extend(pieces[p]);
            }
            s.time_objects[k] += level_area;
            if (k == fits && linear && fits > 0) {
                TimeBins bins;
                bins.count = int(count);
                for (std::size_t p = 0; p < count; ++p) bins.bin[p] = BinBox::of(pieces[p]);
                fit_share = fit_linear(bins).mean_area() * weight;
            }
            if (k == halves) {
                halves_area = level_area;
                if (linear && fits > 0 && halves_area > 0.0)
                    fit_share = std::clamp(fit_share / halves_area, 0.0, 1.0);
                else
                    fit_share = 1.0;
                s.object_cell += level_area * fit_share;
            }
            if (k == halves || k == quarters) {
                for (std::size_t p = 0; p < count; ++p) {
                    if (pieces[p].is_empty()) continue;
                    for (int o = 0; o < 8; ++o) {
                        const Box4 part = pieces[p].intersection(octants[o]);
                        if (part.is_empty()) continue;
                        const double area = surface_area(part) * share * weight;
                        if (k == halves) {
                            s.object_octant[o] += area * fit_share;
                            octant_halves[o][p].extend(part);
                            in_octant[o] = true;
                        }
                        if (k == quarters) {
                            s.object_octant_half[o][p * 2 / count] += area;
                            octant_quarters[o][p].extend(part);
                            in_octant_half[o][p * 2 / count] = true;
                        }
                    }
                }
            }
            if (k == quarters)
                for (std::size_t p = 0; p < count; ++p) {
                    s.object_half[p * 2 / count] += surface_area(pieces[p]) * share * weight;
                    if (!pieces[p].is_empty()) in_half[p * 2 / count] = true;
                }
            // Up a level: the union of each pair.
            for (std::size_t p = 0; 2 * p + 1 < count; ++p) {
                Box4 merged = pieces[2 * p];
                merged.extend(pieces[2 * p + 1]);
                pieces[p] = merged;
            }
        }
        for (int h = 0; h < 2; ++h) {
            s.count_half[h] += in_half[h];
            for (int o = 0; o < 8; ++o) s.count_octant_half[o][h] += in_octant_half[o][h];
        }
        for (int o = 0; o < 8; ++o) s.count_octant[o] += in_octant[o];
    }
    if (sampled < n_objects) scale_object_sums(s, double(n_objects) / double(sampled));
    for (int k = 0; k <= levels; ++k) {
        const double share = 1.0 / double(cell[k].size());
        for (const Box4& b : cell[k]) s.time_cell[k] += surface_area(b) * share;
    }
    s.cell = s.time_cell[halves];
    {
        const double share = 1.0 / double(cell[quarters].size());
        for (std::size_t p = 0; p < cell[quarters].size(); ++p)
            s.half[p * 2 / cell[quarters].size()] += surface_area(cell[quarters][p]) * share;
    }
    for (int o = 0; o < 8; ++o) {
        const double hs = 1.0 / double(octant_halves[o].size());
        for (const Box4& b : octant_halves[o]) s.octant[o] += surface_area(b) * hs;
        const double qs = 1.0 / double(octant_quarters[o].size());
        for (std::size_t p = 0; p < octant_quarters[o].size(); ++p)
            s.octant_half[o][p * 2 / octant_quarters[o].size()] +=
                surface_area(octant_quarters[o][p]) * qs;
    }
    return s;
}

// How many halvings of the cell's time the cost criterion looks at:
// down to the finest pieces its objects' sweeps keep (finer ones repeat
// them), at least to quarters, at most CostSummary::kMaxTimeLevels; none
// for a cell no longer than those pieces (its halves' boxes would be
// its own).
//
// A cell inside one piece of the sweeps looks at eighths of its time
// when some of its objects' sweeps refine (chords: finer pieces are
// new answers, at a placement per end), down to 1/64 of a piece.
int Hierarchy::Builder::time_levels(const CellTime& time,
                                    const std::vector<std::uint32_t>& objects) const {
    const double span = time.t.width();
    double finest = span;
    bool refine = false;
    for (const std::uint32_t i : objects) {
        const auto& sweep = objects_.sweeps[i];
        const double piece = sweep.time().width() / double(sweep.piece_count());
        finest = std::min(finest, piece);
        if (sweep.refines() && span <= piece && span > piece / 64.0) refine = true;
    }
    if (!(span > finest)) return refine && time.level >= 0 ? kFitLevels : 0;
    int levels = 2;
    while (levels < CostSummary::kMaxTimeLevels && finest > 0.0 &&
           span / double(std::size_t(1) << levels) > finest)
        ++levels;
    return levels;
}

}  // namespace hexant::tracer
