// Packed bins (tracer/packed_bins.hpp): every unpacked bin holds the bin it
// was packed from, at most a step of the hull wider per side; empty bins
// stay empty; a flat or unbounded hull keeps what it can. Lined bins
// (issue 43): packed by their edges, clipped without cutting off what a
// line holds inside the region, and fitted outside every line.
#include "tracer/packed_bins.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <random>

#include <catch2/catch.hpp>

using hexant::tracer::BinBox;
using hexant::tracer::fit_linear;
using hexant::tracer::LinearBox;
using hexant::tracer::PackedBins;
using hexant::tracer::TimeBins;

// As many bins as the builder makes at most.
constexpr int kBins = hexant::tracer::kMaxBins;

namespace {

hexant::runtime::Box4 everywhere() {
    const double inf = std::numeric_limits<double>::infinity();
    return {hexant::runtime::Event(-inf, -inf, -inf, -inf),
            hexant::runtime::Event(inf, inf, inf, inf)};
}

bool holds(const BinBox& outer, const BinBox& inner) {
    for (int a = 0; a < 3; ++a)
        if (!(outer.lo[a] <= inner.lo[a] && inner.hi[a] <= outer.hi[a])) return false;
    return true;
}

}  // namespace

TEST_CASE("packed bins hold their originals, a step of the hull wider at most", "[tracer][bins]") {
    std::mt19937 random(7);
    // Scales from tiny to huge, offsets far from the origin: the steps are
    // the hull's, whatever the scene's scale.
    for (const double scale : {1e-6, 1.0, 3e4, 1e30})
        for (const double offset : {0.0, -7e3, 1e7}) {
            std::uniform_real_distribution<double> u(0.0, 1.0);
            for (int trial = 0; trial < 200; ++trial) {
                TimeBins bins = TimeBins::empty(kBins);
                for (int b = 0; b < kBins; ++b) {
                    if (trial % 5 == 0 && b % 3 == 1) continue;  // some bins hold nothing
                    for (int a = 0; a < 3; ++a) {
                        const double x = offset + scale * u(random), y = offset + scale * u(random);
                        bins.bin[b].lo[a] = hexant::tracer::float_down(std::min(x, y));
                        bins.bin[b].hi[a] = hexant::tracer::float_up(std::max(x, y));
                    }
                }
                const BinBox hull = bins.hull();
                const TimeBins back = PackedBins::pack(bins, hull).unpack(hull, everywhere());
                REQUIRE(back.count == kBins);
                for (int b = 0; b < kBins; ++b) {
                    CHECK(back.bin[b].is_empty() == bins.bin[b].is_empty());
                    if (bins.bin[b].is_empty()) continue;
                    REQUIRE(holds(back.bin[b], bins.bin[b]));
                    for (int a = 0; a < 3; ++a) {
                        // A step of the hull plus the float rounding of each end.
                        const double step = (double(hull.hi[a]) - hull.lo[a]) / PackedBins::kTop;
                        const double slack = step + 2.0 * std::abs(double(hull.hi[a])) * 0x1p-23 +
                                             2.0 * std::abs(double(hull.lo[a])) * 0x1p-23;
                        CHECK(double(bins.bin[b].lo[a]) - back.bin[b].lo[a] <= slack);
                        CHECK(double(back.bin[b].hi[a]) - bins.bin[b].hi[a] <= slack);
                    }
                }
            }
        }
}

TEST_CASE("a flat or unbounded hull packs without losing anything", "[tracer][bins]") {
    const float inf = std::numeric_limits<float>::infinity();
    TimeBins bins = TimeBins::empty(2);
    // Flat in z (a polygon lying in a plane), unbounded below in x.
    bins.bin[0].lo = {-inf, 1.0f, 5.0f};
    bins.bin[0].hi = {2.0f, 3.0f, 5.0f};
    bins.bin[1].lo = {0.5f, 2.0f, 5.0f};
    bins.bin[1].hi = {1.5f, 2.5f, 5.0f};
    const BinBox hull = bins.hull();
    const TimeBins back = PackedBins::pack(bins, hull).unpack(hull, everywhere());
    for (int b = 0; b < 2; ++b) {
        CHECK(holds(back.bin[b], bins.bin[b]));
        CHECK(back.bin[b].lo[2] == 5.0f);  // a flat axis is exact
        CHECK(back.bin[b].hi[2] == 5.0f);
        CHECK(back.bin[b].lo[1] >= 1.0f);  // a finite axis stays inside the hull
        CHECK(back.bin[b].hi[1] <= 3.0f);
    }
    // The unbounded axis keeps the hull's ends, conservative.
    CHECK(back.bin[1].lo[0] == -inf);
    CHECK(back.bin[1].hi[0] == 2.0f);
}

namespace {

// Random lined bins: a point moving along a random path with a random
// size, each bin's box the hull of its edges (as the sweeps make them).
TimeBins random_lined(std::mt19937& random, double scale, double offset) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    TimeBins bins = TimeBins::empty(kBins);
    glm::dvec3 at(offset), velocity(u(random), u(random), u(random));
    for (int j = 0; j <= kBins; ++j) {
        velocity += 0.5 * glm::dvec3(u(random), u(random), u(random));
        at += scale * 0.1 * velocity;
        const double size = scale * (0.01 + 0.05 * (u(random) + 1.0));
        bins.edge[j] = BinBox::of(at - size, at + size);
    }
    for (int b = 0; b < kBins; ++b) {
        bins.bin[b] = bins.edge[b];
        bins.bin[b].extend(bins.edge[b + 1]);
    }
    return bins;
}

// The lines' box at u in [0, 1] of bin b.
BinBox line_at(const TimeBins& bins, int b, double u) {
    BinBox r;
    for (int a = 0; a < 3; ++a) {
        r.lo[a] =
            float(bins.edge[b].lo[a] + u * (double(bins.edge[b + 1].lo[a]) - bins.edge[b].lo[a]));
        r.hi[a] =
            float(bins.edge[b].hi[a] + u * (double(bins.edge[b + 1].hi[a]) - bins.edge[b].hi[a]));
    }
    return r;
}

}  // namespace

TEST_CASE("lined bins pack their edges, and unpack lines and boxes that hold the originals",
          "[tracer][bins]") {
    std::mt19937 random(11);
    for (const double scale : {1e-6, 1.0, 1e6})
        for (int trial = 0; trial < 200; ++trial) {
            TimeBins bins = random_lined(random, scale, trial % 2 ? 0.0 : 3.0 * scale);
            if (trial % 7 == 0) bins.bin[3] = BinBox{};  // a bin holding nothing
            REQUIRE(bins.lines());
            const BinBox hull = bins.frame();
            const TimeBins back = PackedBins::pack(bins, hull).unpack(hull, everywhere());
            REQUIRE(back.lines());
            for (int j = 0; j <= kBins; ++j) CHECK(holds(back.edge[j], bins.edge[j]));
            for (int b = 0; b < kBins; ++b) {
                CHECK(back.bin[b].is_empty() == bins.bin[b].is_empty());
                if (!bins.bin[b].is_empty()) CHECK(holds(back.bin[b], bins.bin[b]));
            }
        }
}

TEST_CASE("clipped lines hold every part of the original lines inside the region",
          "[tracer][bins]") {
    std::mt19937 random(12);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 2000; ++trial) {
        const TimeBins bins = random_lined(random, 1.0, 0.0);
        // A region through the path, cutting some lines and not others.
        const BinBox h = bins.hull();
        hexant::runtime::Box4 region;
        for (int a = 0; a < 3; ++a) {
            const double x = h.lo[a] + u(random) * (double(h.hi[a]) - h.lo[a]);
            const double y = h.lo[a] + u(random) * (double(h.hi[a]) - h.lo[a]);
            region.lo[a] = std::min(x, y) - (trial % 3 == 0 ? 10.0 : 0.0);
            region.hi[a] = std::max(x, y);
        }
        const TimeBins c = bins.clipped(region);
        for (int b = 0; b < kBins; ++b)
            for (int s = 0; s <= 16; ++s) {
                const BinBox original = line_at(bins, b, s / 16.0);
                const BinBox inside = original.clipped(region);
                if (inside.is_empty()) continue;
                const BinBox kept = line_at(c, b, s / 16.0);
                // (A float's rounding of the interpolation either way.)
                for (int a = 0; a < 3; ++a) {
                    CHECK(kept.lo[a] <= inside.lo[a] + 1e-6f);
                    CHECK(kept.hi[a] >= inside.hi[a] - 1e-6f);
                }
            }
        // Clipping only ever raises a lower edge.
        for (int j = 0; j <= kBins; ++j)
            for (int a = 0; a < 3; ++a) CHECK(c.edge[j].lo[a] >= bins.edge[j].lo[a]);
    }
}

TEST_CASE("the linear fit of lined bins lies outside every line, and nearer than the boxes'",
          "[tracer][bins]") {
    std::mt19937 random(13);
    int nearer = 0;
    constexpr int kTrials = 2000;
    for (int trial = 0; trial < kTrials; ++trial) {
        const TimeBins bins = random_lined(random, 1.0, 0.0);
        const LinearBox fit = fit_linear(bins);
        REQUIRE_FALSE(fit.empty);
        for (int b = 0; b < kBins; ++b)
            for (int s = 0; s <= 8; ++s) {
                const double w = s / 8.0, u = (b + w) / kBins;
                const BinBox line = line_at(bins, b, w);
                for (int a = 0; a < 3; ++a) {
                    const double lo = fit.lo0[a] + u * (fit.lo1[a] - fit.lo0[a]);
                    const double hi = fit.hi0[a] + u * (fit.hi1[a] - fit.hi0[a]);
                    CHECK(lo <= double(line.lo[a]) + 1e-6);
                    CHECK(hi >= double(line.hi[a]) - 1e-6);
                }
            }
        TimeBins boxes = bins;
        boxes.lined = false;
        if (fit.mean_area() < fit_linear(boxes).mean_area()) ++nearer;
        CHECK(bins.mean_area() <= boxes.mean_area());
    }
    // The lines leave out the path inside each bin: nearly always tighter.
    CHECK(nearer > kTrials * 9 / 10);
}

TEST_CASE("one bin's linear fit is its chord or its box, whichever is nearer, and holds it",
          "[tracer][bins]") {
    // A piece node fits each piece of one bin so (fit_linear's one-bin
    // form): the line through the bin's two edges where that lies inside
    // the box on average, else the box's side, never inside either.
    std::mt19937 random(17);
    int chords = 0;
    for (const double scale : {1e-6, 1.0, 3e4, 1e30})
        for (int trial = 0; trial < 500; ++trial) {
            const TimeBins all = random_lined(random, scale, 7.0 * scale);
            TimeBins one = TimeBins::empty(1);
            one.bin[0] = all.bin[1];
            one.edge[0] = all.edge[1];
            one.edge[1] = all.edge[2];
            // Now and then a box far wider than the chord's ends, or a bin
            // without lines.
            if (trial % 7 == 3)
                for (int a = 0; a < 3; ++a) one.bin[0].lo[a] -= float(scale);
            if (trial % 11 == 5) one.lined = false;
            const LinearBox fit = fit_linear(one);
            REQUIRE_FALSE(fit.empty);
            // The general fit (the hull) over two bins, the second empty,
            // fits the first the same line over its half of the time: an
            // independent path to the same answer, but for rounding (a few
            // ulps of the values, the slope doubled and halved again).
            TimeBins two = TimeBins::empty(2);
            two.lined = one.lined;
            two.bin[0] = one.bin[0];
            two.edge[0] = one.edge[0];
            two.edge[1] = one.edge[1];
            const LinearBox general = fit_linear(two);
            for (int a = 0; a < 3; ++a)
                for (const auto& [e0, e1, g0, g1] :
                     {std::array{fit.lo0[a], fit.lo1[a], general.lo0[a], general.lo1[a]},
                      std::array{fit.hi0[a], fit.hi1[a], general.hi0[a], general.hi1[a]}}) {
                    const double slack =
                        1e-14 * std::max({std::fabs(e0), std::fabs(e1), std::fabs(g1)});
                    CHECK(std::fabs(g0 - e0) <= slack);
                    CHECK(std::fabs(g0 + 0.5 * (g1 - g0) - e1) <= slack);
                }
            for (int a = 0; a < 3; ++a) {
                const double e0 = one.edge[0].lo[a], e1 = one.edge[1].lo[a];
                const double box = one.bin[0].lo[a];
                const bool chord = one.lined && 0.5 * (e0 + e1) >= box;
                chords += chord;
                // Exactly the chord's ends or the box's side, but for the
                // last rounding of a line kept below its points.
                const double tolerance = 4e-16 * std::max(std::fabs(e0), std::fabs(e1));
                CHECK(fit.lo0[a] <= (chord ? e0 : box));
                CHECK(fit.lo1[a] <= (chord ? e1 : box));
                CHECK(fit.lo0[a] >= (chord ? e0 : box) - tolerance);
                CHECK(fit.lo1[a] >= (chord ? e1 : box) - tolerance);
                // Over the bin, below the chord (or the box) in doubles.
                const double h0 = one.edge[0].hi[a], h1 = one.edge[1].hi[a];
                const double top = one.bin[0].hi[a];
                for (int s = 0; s <= 16; ++s) {
                    const double u = s / 16.0;
                    const double lo = fit.lo0[a] + u * (fit.lo1[a] - fit.lo0[a]);
                    const double hi = fit.hi0[a] + u * (fit.hi1[a] - fit.hi0[a]);
                    CHECK(lo <= std::max(e0 + u * (e1 - e0), box) + tolerance);
                    CHECK(hi >= std::min(h0 + u * (h1 - h0), top) - tolerance);
                }
            }
        }
    CHECK(chords > 1000);  // (both sides of the choice are taken)
    CHECK(chords < 5800);  // (of 6,000)
}
