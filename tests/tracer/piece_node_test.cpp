// The piecewise-linear bottom node (tracer/piece_node.hpp, issue 43): at
// every instant of its time, the box the walk evaluates in float for each
// child holds what the child's bins hold then (the bin's box, inside its
// lines where lined), whatever the scale and offset, with empty bins, with
// boxes alone; and it follows the motion: a child's box at an instant is
// about its own size where one line over the node's time is not.
#include "tracer/piece_node.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "tracer/bound_rounding.hpp"

using hexant::runtime::Interval;
using hexant::tracer::BinBox;
using hexant::tracer::fit_linear;
using hexant::tracer::fit_piece_node;
using hexant::tracer::float_down;
using hexant::tracer::float_up;
using hexant::tracer::kNodeWidth;
using hexant::tracer::piece_box_at;
using hexant::tracer::PieceBox;
using hexant::tracer::PieceNode;
using hexant::tracer::TimeBins;

namespace {

constexpr int kBins = hexant::tracer::kMaxBins;

// A child on a circular path of radius `orbit` about `centre`, turning
// `turns` times over [0, 1] of the node's time, of half-size `size`: its
// bins over kBins pieces, lined (each cut's box, the chord's error added:
// orbit * (angle of a piece)^2 / 8), or boxes alone; bins in `empty` hold
// nothing.
TimeBins orbit_bins(double centre, double orbit, double turns, double phase, double size,
                    bool lined, unsigned empty) {
    const auto at = [&](double u, int a) {
        const double angle = phase + 2.0 * M_PI * turns * u;
        return centre + orbit * (a == 0   ? std::cos(angle)
                                 : a == 1 ? std::sin(angle)
                                          : 0.3 * std::sin(angle + 1.0));
    };
    const double piece = 2.0 * M_PI * turns / kBins;
    const double chord = orbit * piece * piece / 8.0 * 1.01 + 1e-12 * std::fabs(centre);
    TimeBins bins = TimeBins::empty(kBins);
    bins.lined = lined;
    for (int j = 0; j <= kBins; ++j)
        for (int a = 0; a < 3; ++a) {
            const double c = at(double(j) / kBins, a);
            bins.edge[j].lo[a] = float_down(c - size - chord);
            bins.edge[j].hi[a] = float_up(c + size + chord);
        }
    for (int b = 0; b < kBins; ++b) {
        if (empty & (1u << b)) continue;
        // The box over the piece: the path's extremes over it, sampled
        // densely and widened by more than the sampling misses.
        for (int a = 0; a < 3; ++a) {
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (int n = 0; n <= 64; ++n) {
                const double c = at((b + n / 64.0) / kBins, a);
                lo = std::min(lo, c);
                hi = std::max(hi, c);
            }
            const double slack = orbit * (piece / 64.0) + 1e-12 * std::fabs(centre);
            bins.bin[b].lo[a] = float_down(lo - size - slack);
            bins.bin[b].hi[a] = float_up(hi + size + slack);
        }
    }
    if (!lined) bins.lined = false;
    return bins;
}

// What bin b holds at place w in [0, 1] of it: its box, inside its lines
// where lined (each side the nearer).
BinBox held(const TimeBins& bins, int b, double w) {
    BinBox box = bins.bin[b];
    if (box.is_empty() || !bins.lines()) return box;
    for (int a = 0; a < 3; ++a) {
        const double lo =
            double(bins.edge[b].lo[a]) + w * (double(bins.edge[b + 1].lo[a]) - bins.edge[b].lo[a]);
        const double hi =
            double(bins.edge[b].hi[a]) + w * (double(bins.edge[b + 1].hi[a]) - bins.edge[b].hi[a]);
        box.lo[a] = std::max(box.lo[a], float_down(lo));
        box.hi[a] = std::min(box.hi[a], float_up(hi));
    }
    return box;
}

}  // namespace

TEST_CASE("a piece node's box at every instant holds what its children's bins hold",
          "[tracer][bins][piece]") {
    std::mt19937 random(43);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    long checked = 0;
    for (const double scale : {1e-4, 1.0, 1e3})
        for (const double offset : {0.0, 1e2, -3e4})
            for (const bool lined : {true, false})
                for (const Interval time :
                     {Interval(0.25, 0.3125), Interval(1000.1, 1000.13), Interval(-2.0, 6.0)}) {
                    for (int trial = 0; trial < 6; ++trial) {
                        const int n = 1 + int(unit(random) * kNodeWidth) % kNodeWidth;
                        std::vector<TimeBins> bins;
                        for (int i = 0; i < n; ++i) {
                            const unsigned empty =
                                unit(random) < 0.3 ? unsigned(unit(random) * 255) : 0u;
                            bins.push_back(
                                orbit_bins(offset * scale + scale * (unit(random) - 0.5) * 4,
                                           scale * (0.1 + 5 * unit(random)), 0.5 * unit(random) * i,
                                           6.3 * unit(random), scale * (0.01 + 0.2 * unit(random)),
                                           lined, empty == 255 ? 0u : empty));
                        }
                        std::vector<const TimeBins*> of;
                        for (const TimeBins& b : bins) of.push_back(&b);
                        PieceNode node;
                        REQUIRE(fit_piece_node(node, time, of));
                        CHECK(node.children == unsigned(n));
                        for (int i = 0; i < n; ++i)
                            for (int s = 0; s < 2000; ++s) {
                                // Random instants, and every cut between bins.
                                const double w = s <= kBins ? double(s) / kBins : unit(random);
                                double t = time.lo + (time.hi - time.lo) * w;
                                t = std::clamp(t, time.lo, time.hi);
                                const double place =
                                    std::clamp((t - time.lo) / (time.hi - time.lo), 0.0, 1.0) *
                                    kBins;
                                // The bins that hold instant t (both at a cut).
                                for (int b = std::max(0, int(std::ceil(place)) - 1);
                                     b <= std::min(kBins - 1, int(std::floor(place))); ++b) {
                                    const BinBox inner = held(bins[std::size_t(i)], b,
                                                              std::clamp(place - b, 0.0, 1.0));
                                    if (inner.is_empty()) continue;
                                    const PieceBox box = piece_box_at(node, i, t);
                                    for (int a = 0; a < 3; ++a)
                                        if (!(box.lo[a] <= inner.lo[a] &&
                                              inner.hi[a] <= box.hi[a])) {
                                            INFO("scale " << scale << " offset " << offset
                                                          << " lined " << lined << " t " << t
                                                          << " child " << i << " axis " << a);
                                            INFO("box " << box.lo[a] << " " << box.hi[a]
                                                        << " holds " << inner.lo[a] << " "
                                                        << inner.hi[a]);
                                            FAIL("a piece node's box loses what a bin holds");
                                        }
                                    ++checked;
                                }
                            }
                    }
                }
    CHECK(checked > 1000000);
}

TEST_CASE("a piece node's knot beside an empty piece may be inverted, and is kept",
          "[tracer][bins][piece]") {
    // From the swarm under the paper's criterion (a sphere leaving a cell
    // in its last bin, then bin 7 of eight): over the last piece the object
    // is only in the last bin; its lower line, from the edges, rises back
    // to the knot before it above its upper side, the bin's box. The knot
    // is inverted and alone there: the frame must still hold it (it held
    // nothing, and the lower end decoded to 0, far above the sphere: a
    // lost hit).
    constexpr int kLast = kBins - 1;
    TimeBins bins = TimeBins::empty(kBins);
    for (int a = 0; a < 3; ++a) {
        for (int e = 0; e < kLast; ++e)
            bins.edge[e].lo[a] = -7.94670868f, bins.edge[e].hi[a] = -8.13349724f;
        bins.edge[kLast].lo[a] = -7.94670868f;  // (-8.30022621 at eight bins, the
        bins.edge[kLast].hi[a] = -7.94670868f;  // lone bin's inverted knot one earlier)
        bins.edge[kBins].lo[a] = -8.64085293f;
        bins.edge[kBins].hi[a] = -8.2873354f;
        bins.bin[kLast].lo[a] = -8.64085293f;
        bins.bin[kLast].hi[a] = -8.13350391f;
    }
    REQUIRE(bins.lines());
    const std::vector<const TimeBins*> of{&bins};
    PieceNode node;
    REQUIRE(fit_piece_node(node, Interval(0.0, 0.03125), of));
    for (int s = 0; s <= 100; ++s) {
        const double w = s / 100.0;
        const BinBox inner = held(bins, kLast, w);
        if (inner.is_empty()) continue;
        const PieceBox box = piece_box_at(node, 0, 0.03125 * (kLast + w) / kBins);
        for (int a = 0; a < 3; ++a) {
            CHECK(box.lo[a] <= inner.lo[a]);
            CHECK(inner.hi[a] <= box.hi[a]);
        }
    }
}

TEST_CASE("a piece node follows a turn that one line over its time cannot",
          "[tracer][bins][piece]") {
    // A quarter turn of radius 10 over the node's time, of half-size 0.1,
    // its edges 0.3 wide with the chords' error: one line over the whole
    // time misses the arc by up to its sagitta, 10 (1 - cos 45) = 2.9; the
    // four pieces' lines by a sixteenth of that each side of a knot they
    // share, 2 * 10 (1 - cos 11.25) = 0.38 at most.
    const TimeBins bins = orbit_bins(0.0, 10.0, 0.25, 0.3, 0.1, true, 0u);
    const std::vector<const TimeBins*> of{&bins};
    PieceNode node;
    REQUIRE(fit_piece_node(node, Interval(0.0, 1.0), of));
    const auto line = fit_linear(bins);
    double widest_piece = 0.0, widest_line = 0.0;
    for (int s = 0; s <= 64; ++s) {
        const double u = s / 64.0;
        const PieceBox box = piece_box_at(node, 0, u);
        for (int a = 0; a < 2; ++a) {
            widest_piece = std::max(widest_piece, double(box.hi[a]) - box.lo[a]);
            const double lo = line.lo0[a] + u * (line.lo1[a] - line.lo0[a]);
            const double hi = line.hi0[a] + u * (line.hi1[a] - line.hi0[a]);
            widest_line = std::max(widest_line, hi - lo);
        }
    }
    CHECK(widest_piece < 0.3 + 0.4);
    CHECK(widest_line > 3.0);
}

TEST_CASE("a piece node refuses what its frames cannot hold", "[tracer][bins][piece]") {
    TimeBins far = orbit_bins(0.0, 1.0, 0.1, 0.0, 0.1, true, 0u);
    far.edge[3].hi[0] = std::numeric_limits<float>::infinity();
    far.bin[2].hi[0] = far.bin[3].hi[0] = std::numeric_limits<float>::infinity();
    const std::vector<const TimeBins*> of{&far};
    PieceNode node;
    CHECK_FALSE(fit_piece_node(node, Interval(0.0, 1.0), of));
    TimeBins few = TimeBins::empty(2);
    few.bin[0] = few.bin[1] = far.bin[0];
    const std::vector<const TimeBins*> two{&few};
    CHECK_FALSE(fit_piece_node(node, Interval(0.0, 1.0), two));
}
