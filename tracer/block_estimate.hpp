// A pixel's error estimated from its one sample set, by the variance
// between the aligned blocks of its sequence.
//
// The first m = 2^k samples of a pixel (sample_pattern.hpp) split into
// aligned blocks of m/2 and m/4 samples, each itself a scrambled net alike
// in law. Write V(b) for the variance of a block of b samples' mean. For the
// halves A, B of the m, E[(A - B)^2] / 4 = V(m/2) - V(m) (not V(m): the
// halves are stratified against each other, so their difference
// overestimates); for the quarters, the same within each half gives
// V(m/4) - V(m/2). Where the error falls as a power, V(b) ~ b^-e, the ratio
// r of the two is 2^-e, and
//     V(m) = (V(m/2) - V(m)) r / (1 - r),
// the halves' term scaled by the rate the quarters show. r is measured over
// a tile's pixels together (a pixel's own is one squared difference, too
// noisy), clamped to [1/8, 1/2]: e from 1 (independent samples, where the
// estimate becomes the independent halves' one) to 3 (a smooth integrand
// under Owen scrambling, Owen 1997). A count n between powers of two is
// its prefix m and a tail of n - m samples, each estimated at the rate e
// (pixel_squared_error). With m = 2 only the halves exist and e = 1.25 is
// assumed, between independent samples (1) and an edge (1.5).
#pragma once

#include <array>
#include <vector>

#include <glm/vec3.hpp>

namespace hexant::tracer {

// One pixel's samples: their sums over aligned blocks of `size` samples,
// `size` a quarter of the largest power of two not above `count` (at
// least 1): at most 8 blocks.
struct PixelBlocks {
    std::array<glm::dvec3, 8> block{};
    int count = 0, size = 1;

    // Adds sample number `count` (samples come in the sequence's order).
    void add(const glm::dvec3& colour);
    glm::dvec3 sum() const;
    glm::dvec3 mean() const { return count ? sum() / double(count) : glm::dvec3(0.0); }
    // The largest power of two not above count (0 for no samples).
    int prefix() const;
};

// What a pixel's blocks say, in linear light averaged over the channels:
// `halves` = (A - B)^2 / 4, `quarters` = the mean of the two halves'
// (Q1 - Q2)^2 / 4 (0 when the prefix is under 4).
struct BlockTerms {
    double halves = 0.0, quarters = 0.0;
    bool has_quarters = false;
};
template <class Linear>
BlockTerms block_terms(const PixelBlocks& p, Linear&& linear) {
    BlockTerms t;
    const int m = p.prefix();
    if (m < 2) return t;
    const auto squared = [&](const glm::dvec3& a, const glm::dvec3& b, double n) {
        const glm::dvec3 d = linear(a / n) - linear(b / n);
        return (d.x * d.x + d.y * d.y + d.z * d.z) / 12.0;  // (/ 4 per channel, / 3 channels)
    };
    if (m == 2) {
        t.halves = squared(p.block[0], p.block[1], 1.0);
        return t;
    }
    const double q = m / 4.0;
    t.halves = squared(p.block[0] + p.block[1], p.block[2] + p.block[3], 2.0 * q);
    t.quarters = 0.5 * (squared(p.block[0], p.block[1], q) + squared(p.block[2], p.block[3], q));
    t.has_quarters = true;
    return t;
}

// The rate a tile's blocks show: r = sum(halves) / sum(quarters) over its
// pixels with quarters, clamped to [1/8, 1/2] (1/2 when there are none).
double block_ratio(const std::vector<BlockTerms>& terms);

// A pixel's estimated squared error (linear light, averaged over the
// channels) at its count, from its terms and its tile's ratio r.
double pixel_squared_error(const BlockTerms& terms, int count, double ratio);

// The exponent e = -log2(r) by which the squared error falls with the
// count, V(n) ~ n^-e.
double error_exponent(double ratio);

}  // namespace hexant::tracer
