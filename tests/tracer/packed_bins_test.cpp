// Packed bins (tracer/packed_bins.hpp): every unpacked bin holds the bin it
// was packed from, at most a step of the hull wider per side; empty bins
// stay empty; a flat or unbounded hull keeps what it can.
#include "tracer/packed_bins.hpp"

#include <cmath>
#include <limits>
#include <random>

#include <catch2/catch.hpp>

using hexant::tracer::BinBox;
using hexant::tracer::PackedBins;
using hexant::tracer::TimeBins;

namespace {

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
                TimeBins bins = TimeBins::empty(8);
                for (int b = 0; b < 8; ++b) {
                    if (trial % 5 == 0 && b % 3 == 1) continue;  // some bins hold nothing
                    for (int a = 0; a < 3; ++a) {
                        const double x = offset + scale * u(random), y = offset + scale * u(random);
                        bins.bin[b].lo[a] = hexant::tracer::float_down(std::min(x, y));
                        bins.bin[b].hi[a] = hexant::tracer::float_up(std::max(x, y));
                    }
                }
                const BinBox hull = bins.hull();
                const TimeBins back = PackedBins::pack(bins, hull).unpack(hull);
                REQUIRE(back.count == 8);
                for (int b = 0; b < 8; ++b) {
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
    const TimeBins back = PackedBins::pack(bins, hull).unpack(hull);
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
