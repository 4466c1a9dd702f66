// Where in a pixel and when in the shutter each sample falls: the first three
// dimensions of Sobol's sequence (pixel x, pixel y, time), jointly
// stratified, with Owen scrambling by hashing (Burley, "Practical Hash-based
// Owen Scrambling", JCGT 2020) seeded by (frame, pixel). Sample i of a pixel
// is a pure function of (frame, x, y, i): images do not depend on the thread
// count or the order of work.
#pragma once

#include <array>
#include <cstdint>

namespace hexant::tracer {

namespace sobol_detail {

// Direction numbers of the first three dimensions (Joe and Kuo): the van der
// Corput sequence, then the primitive polynomials x + 1 and x^2 + x + 1.
struct Directions {
    std::array<std::array<std::uint32_t, 32>, 3> v{};
    constexpr Directions() {
        for (int i = 0; i < 32; ++i) v[0][i] = 1u << (31 - i);
        v[1][0] = 1u << 31;
        for (int i = 1; i < 32; ++i) v[1][i] = v[1][i - 1] ^ (v[1][i - 1] >> 1);
        v[2][0] = 1u << 31;  // m1 = 1
        v[2][1] = 3u << 30;  // m2 = 3
        for (int i = 2; i < 32; ++i) v[2][i] = v[2][i - 1] ^ v[2][i - 2] ^ (v[2][i - 2] >> 2);
    }
};
inline constexpr Directions kDirections{};

inline std::uint32_t sobol(std::uint32_t index, int dimension) {
    std::uint32_t x = 0;
    for (int bit = 0; index != 0; index >>= 1, ++bit)
        if (index & 1u) x ^= kDirections.v[dimension][bit];
    return x;
}

inline std::uint32_t reverse_bits(std::uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

// Laine and Karras' hash, as improved by Burley: a nested uniform scramble
// of the reversed bits.
inline std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed) {
    x = reverse_bits(x);
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return reverse_bits(x);
}

inline std::uint32_t hash(std::uint32_t x) {  // lowbias32 (Wellons)
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

}  // namespace sobol_detail

struct PixelSample {
    double x, y;  // in [0, 1) across the pixel
    double time;  // in [0, 1) across the shutter
};

// `sample_seed` 0 keeps the seeds every earlier image was made with; any
// other value gives independent scrambles.
inline std::uint32_t pixel_seed(int frame, int x, int y, std::uint32_t sample_seed = 0) {
    using sobol_detail::hash;
    const std::uint32_t seed = hash(
        static_cast<std::uint32_t>(frame) ^
        hash(static_cast<std::uint32_t>(x) ^ hash(static_cast<std::uint32_t>(y) + 0x9e3779b9u)));
    return sample_seed == 0 ? seed : hash(seed ^ hash(sample_seed));
}

// The seed of a pixel's second, independent set of samples (the frame
// estimate's half B, tracer/frame_estimate.hpp): hashed in its own domain,
// so it is none of the seeds a --seed gives.
inline std::uint32_t second_set_seed(std::uint32_t seed) {
    using sobol_detail::hash;
    return hash(hash(seed ^ 0x5ec0d5e7u) + 0x7f4a7c15u);
}

// Sample `index` of a pixel. Without jitter, the same unscrambled points
// shifted to the middles of their strata: one sample is the pixel's centre
// at the middle of the shutter.
inline PixelSample pixel_sample(std::uint32_t seed, std::uint32_t index, std::uint32_t count,
                                bool jitter) {
    using namespace sobol_detail;
    constexpr double kScale = 1.0 / 4294967296.0;
    if (!jitter) {
        const double half = 0.5 / static_cast<double>(count == 0 ? 1 : count);
        auto wrap = [](double u) { return u >= 1.0 ? u - 1.0 : u; };
        return {wrap(sobol(index, 0) * kScale + half), wrap(sobol(index, 1) * kScale + half),
                wrap(sobol(index, 2) * kScale + half)};
    }
    return {owen_scramble(sobol(index, 0), hash(seed ^ 0x1u)) * kScale,
            owen_scramble(sobol(index, 1), hash(seed ^ 0x2u)) * kScale,
            owen_scramble(sobol(index, 2), hash(seed ^ 0x3u)) * kScale};
}

// The dimensions past pixel and time (an area light's point, one pair per
// light and trace depth): each pair is the first two dimensions of Sobol's
// sequence Owen-scrambled with a seed of its own ("padded", as pbrt-v4's
// PaddedSobolSampler), so sample i's pair is stratified over the pixel's
// samples and independent of the other pairs. Without jitter, the
// unscrambled points at the middles of their strata, as pixel_sample.
inline std::array<double, 2> padded_pair(std::uint32_t seed, std::uint32_t index,
                                         std::uint32_t count, std::uint32_t pair, bool jitter) {
    using namespace sobol_detail;
    constexpr double kScale = 1.0 / 4294967296.0;
    if (!jitter) {
        const double half = 0.5 / static_cast<double>(count == 0 ? 1 : count);
        auto wrap = [](double u) { return u >= 1.0 ? u - 1.0 : u; };
        return {wrap(sobol(index, 0) * kScale + half), wrap(sobol(index, 1) * kScale + half)};
    }
    const std::uint32_t own = hash(seed ^ hash(pair * 0x9e3779b9u + 0x632be5abu));
    // (Burley's shuffle: the pair's own nested permutation of the index.
    // Without it the pair would be a fixed function of the pixel's first
    // two dimensions, scrambled from the same Sobol' points, and more
    // samples would not average it. The first 2^k shuffled indices are an
    // aligned block of the sequence, itself stratified: progressive still.)
    const std::uint32_t shuffled = owen_scramble(index, hash(own ^ 0x3u));
    return {owen_scramble(sobol(shuffled, 0), hash(own ^ 0x1u)) * kScale,
            owen_scramble(sobol(shuffled, 1), hash(own ^ 0x2u)) * kScale};
}

}  // namespace hexant::tracer
