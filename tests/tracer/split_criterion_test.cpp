// The split criteria (tracer/split_criterion.hpp): the paper's rule as the
// paper states it, and the cost criterion's choices on summaries whose best
// answer is known, with and without pricing the build against the rays.
#include "tracer/split_criterion.hpp"

#include <string>

#include <catch2/catch.hpp>

#include "../runtime/object_test_support.hpp"
#include "tracer/ray_query.hpp"

namespace tr = hexant::tracer;

namespace {

// n objects, each of area `each` over the cell's time, in a cell of area 1.
// `octant_share`: the objects' areas summed inside one octant, as a share
// of their areas in the whole cell (small objects each in one octant:
// 1/8; a long diagonal object whose pieces hug it: less than 1/8 of its
// box's area in each octant; a box filling the cell: 1/4).
tr::CostSummary summary(std::size_t n, double each, double octant_share = 1.0 / 8.0) {
    tr::CostSummary s;
    s.objects = n;
    s.cell = 1.0;
    s.object_cell = double(n) * each;
    for (int h = 0; h < 2; ++h) {
        s.half[h] = 0.5;
        s.object_half[h] = 0.5 * s.object_cell;  // halving time changes nothing
        s.count_half[h] = n;
    }
    for (int o = 0; o < 8; ++o) {
        s.octant[o] = 0.25;  // each octant's bound a quarter of the cell's area
        s.object_octant[o] = octant_share * s.object_cell;
        s.count_octant[o] = n;
        for (int h = 0; h < 2; ++h) {
            s.octant_half[o][h] = 0.125;
            s.object_octant_half[o][h] = 0.5 * octant_share * s.object_cell;
            s.count_octant_half[o][h] = n;
        }
    }
    s.time_levels = 0;
    return s;
}

}  // namespace

TEST_CASE("the paper's criterion: count, then density, time only where something moves",
          "[tracer][split]") {
    tr::PaperSummary s;
    s.objects = 4;
    CHECK(tr::paper_split(s, 3, 0.3, false) == tr::Split::Space);
    s.moving = true;
    CHECK(tr::paper_split(s, 3, 0.3, false) == tr::Split::Both);
    CHECK(tr::paper_split(s, 3, 0.3, true) == tr::Split::Space);  // the baseline: space only
    s.objects = 2;
    s.occupancy = 0.5;  // dense enough
    CHECK(tr::paper_split(s, 3, 0.3, false) == tr::Split::Time);
    s.moving = false;
    CHECK(tr::paper_split(s, 3, 0.3, false) == tr::Split::Leaf);
    s.occupancy = 0.1;
    CHECK(tr::paper_split(s, 3, 0.3, false) == tr::Split::Space);
    CHECK(tr::paper_needs_occupancy(s, 3));
}

TEST_CASE(
    "the cost criterion cuts objects whose boxes it tightens, keeps the rest together, and "
    "weighs the build against the rays",
    "[tracer][split]") {
    tr::CostPrices free;
    // 16 long diagonal objects across the cell: their pieces in the octants
    // hug them (a fortieth of each box's area per octant): splitting pays.
    CHECK(tr::cost_split(summary(16, 0.8, 1.0 / 40.0), free, false) == tr::Split::Space);
    // 16 boxes that fill the cell: cutting them only copies them (their
    // pieces' areas add up to more than theirs), and each is tested once
    // per ray anyway (the mailbox): a leaf.
    CHECK(tr::cost_split(summary(16, 0.8, 1.0 / 4.0), free, false) == tr::Split::Leaf);
    // The diagonal ones when few rays will ever meet the cell: not worth
    // building (8 * 16 references at 100 node tests each).
    tr::CostPrices priced;
    priced.build = 100.0;
    priced.rays = 10.0;
    CHECK(tr::cost_split(summary(16, 0.8, 1.0 / 40.0), priced, false) == tr::Split::Leaf);
    priced.rays = 1e6;
    CHECK(tr::cost_split(summary(16, 0.8, 1.0 / 40.0), priced, false) == tr::Split::Space);
}

TEST_CASE("the cost criterion looks several halvings ahead in time", "[tracer][split]") {
    // A fast turn: halving time once leaves each half's box as large as the
    // whole (half a turn sweeps the circle), but 16 pieces are each a tenth.
    tr::CostSummary s = summary(2, 0.5);
    for (int o = 0; o < 8; ++o) {  // and space does not separate them
        s.octant[o] = 0.5;
        s.object_octant[o] = s.object_cell;
        s.count_octant[o] = 2;
        for (int h = 0; h < 2; ++h) {
            s.octant_half[o][h] = 0.25;
            s.object_octant_half[o][h] = 0.5 * s.object_cell;
            s.count_octant_half[o][h] = 2;
        }
    }
    s.time_levels = 5;
    for (int k = 0; k <= 5; ++k) {
        s.time_cell[k] = k < 3 ? 1.0 : 0.1;
        s.time_objects[k] = k < 3 ? s.object_cell : 0.1 * s.object_cell;
    }
    CHECK(tr::cost_split(s, tr::CostPrices{}, false) == tr::Split::Time);
    // Without looking ahead, nothing pays.
    s.time_levels = 2;
    CHECK(tr::cost_split(s, tr::CostPrices{}, false) == tr::Split::Leaf);
}

TEST_CASE("a hierarchy for more rays is built deeper", "[tracer][split]") {
    std::string sdl;
    for (int i = 0; i < 120; ++i) {
        char line[200];
        std::snprintf(line, sizeof line,
                      "sphere { <%d, %d, %d>, 0.2 rotate y * 360 * %d * clock }\n", i % 6,
                      (i / 6) % 5, i / 30, 1 + i % 3);
        sdl += line;
    }
    const object_test::Parsed parsed = object_test::parse(sdl);
    const auto set = tr::ObjectSet::of(parsed.objects);
    const auto cells = [&](double rays_per_frame) {
        tr::BuildOptions options;
        options.build = tr::BuildKind::Eager;
        options.rays_per_frame = rays_per_frame;
        options.frame_interval = 0.125;
        options.shutter_time = 0.125;
        tr::Counters counters;
        tr::make_ray_query(tr::Mode::Spacetime, set, tr::enclosing_box(set, 0.0, 1.0), options,
                           counters);
        return counters.cells;
    };
    const auto few = cells(100.0), many = cells(1e6), unpriced = cells(0.0);
    INFO("cells: " << few << " for 100 rays a frame, " << many << " for 10^6, " << unpriced
                   << " unpriced");
    CHECK(few < many);
    CHECK(many <= unpriced);
}
