#include "tracer/block_estimate.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace hexant::tracer {

int PixelBlocks::prefix() const {
    return count > 0 ? static_cast<int>(std::bit_floor(static_cast<unsigned>(count))) : 0;
}

void PixelBlocks::add(const glm::dvec3& colour) {
    // The block size sample `count` needs: a quarter of the power of two
    // the count reaches with it. It doubles at most (one sample more):
    // pairs of blocks merge, aligned blocks of the new size.
    const int m = static_cast<int>(std::bit_floor(static_cast<unsigned>(count + 1)));
    if (std::max(1, m / 4) > size) {
        for (int j = 0; j < 4; ++j) block[j] = block[2 * j] + block[2 * j + 1];
        for (int j = 4; j < 8; ++j) block[j] = glm::dvec3(0.0);
        size *= 2;
    }
    block[static_cast<std::size_t>(count / size)] += colour;
    ++count;
}

glm::dvec3 PixelBlocks::sum() const {
    glm::dvec3 s(0.0);
    for (const glm::dvec3& b : block) s += b;
    return s;
}

double block_ratio(const std::vector<BlockTerms>& terms) {
    double halves = 0.0, quarters = 0.0;
    for (const BlockTerms& t : terms)
        if (t.has_quarters) {
            halves += t.halves;
            quarters += t.quarters;
        }
    if (!(quarters > 0.0)) return 0.5;
    return std::clamp(halves / quarters, 0.125, 0.5);
}

double error_exponent(double ratio) {
    return -std::log2(ratio);
}

double pixel_squared_error(const BlockTerms& terms, int count, double ratio) {
    if (count < 2) return 0.0;
    const int m = static_cast<int>(std::bit_floor(static_cast<unsigned>(count)));
    // (m = 2: halves only, the rate unknown: e = 1.25 assumed, between
    // independent samples' 1 and a pixel's edge's 1.5, so that either is
    // within 1.2 of its truth: measured 1.20-1.54 on the examples at 2
    // samples when e = 1 was assumed.)
    const double r = terms.has_quarters ? ratio : std::exp2(-1.25);
    const double at_prefix = terms.halves * r / (1.0 - r);
    if (m == count) return at_prefix;
    // The mean of n = m + k samples is (m A + k B) / n, A the prefix's and
    // B the tail's: k samples at the start of the next aligned block, their
    // variance V(m) (m / k)^e by the same rate. The two are not positively
    // correlated in a scrambled net (a tail stratified against its prefix
    // is negatively), so leaving their covariance out errs on the safe
    // side. (Not V(m) (m / n)^e: a prefix between powers of two is a net
    // plus a part of the next one, and falls slower than the power law.)
    const int k = count - m;
    const double tail = at_prefix * std::pow(double(m) / k, error_exponent(r));
    return (double(m) * m * at_prefix + double(k) * k * tail) / (double(count) * count);
}

}  // namespace hexant::tracer
