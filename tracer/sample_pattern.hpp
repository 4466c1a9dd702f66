// Where in a pixel, when in the shutter, where on the lens and where on an
// area light each sample falls: one low-discrepancy sequence over all of a
// sample's dimensions jointly, Sobol's (Joe and Kuo's direction numbers) in
// kJointDimensions dimensions, each Owen-scrambled by hashing (Burley,
// "Practical Hash-based Owen Scrambling", JCGT 2020) with seeds of the
// (frame, pixel). Jointly: the first 2^k samples of a pixel are a (t, k,
// s)-net over pixel, time, lens and lights together, not a net in each
// pair alone, so an image whose blur couples them (a defocused edge that
// moves, a penumbra seen through a lens) converges faster than with
// independent ("padded") pairs. Dimensions past the joint ones (a ninth
// area light, deep reflections, crand) are padded pairs, as pbrt-v4's
// PaddedSobolSampler.
//
// Sample i of a pixel is a pure function of (frame, x, y, i): images do not
// depend on the thread count or the order of work, and the sequence is
// progressive (a pixel extended from n to n' samples keeps its first n).
#pragma once

#include <array>
#include <cstdint>

namespace hexant::tracer {

namespace sobol_detail {

// Joe and Kuo's direction numbers ("new-joe-kuo-6.21201", their dimensions
// 2 to 22, chosen for good two-dimensional projections): per dimension the
// degree s of its primitive polynomial, the polynomial's inner
// coefficients a, and the initial odd numbers m_1 .. m_s. Dimension 0 is
// van der Corput's.
struct Polynomial {
    int s;
    std::uint32_t a;
    std::array<std::uint32_t, 7> m;
};
inline constexpr std::array<Polynomial, 21> kJoeKuo{{
    {1, 0, {1}},
    {2, 1, {1, 3}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}},
    {4, 4, {1, 3, 5, 13}},
    {5, 2, {1, 1, 5, 5, 17}},
    {5, 4, {1, 1, 5, 5, 5}},
    {5, 7, {1, 1, 7, 11, 19}},
    {5, 11, {1, 1, 5, 1, 1}},
    {5, 13, {1, 1, 1, 3, 11}},
    {5, 14, {1, 3, 5, 5, 31}},
    {6, 1, {1, 3, 3, 9, 7, 49}},
    {6, 13, {1, 1, 1, 15, 21, 21}},
    {6, 16, {1, 3, 1, 13, 27, 49}},
    {6, 19, {1, 1, 1, 15, 7, 5}},
    {6, 22, {1, 3, 1, 15, 13, 25}},
    {6, 25, {1, 1, 5, 5, 19, 61}},
    {7, 1, {1, 3, 7, 11, 23, 15, 103}},
    {7, 4, {1, 3, 7, 13, 13, 15, 69}},
    {7, 7, {1, 1, 3, 13, 7, 35, 63}},
}};

// The 32 direction numbers of each dimension, by Bratley and Fox's
// recurrence (Joe and Kuo 2003, eq. 3).
struct Directions {
    std::array<std::array<std::uint32_t, 32>, kJoeKuo.size() + 1> v{};
    constexpr Directions() {
        for (int i = 0; i < 32; ++i) v[0][i] = 1u << (31 - i);
        for (std::size_t d = 0; d < kJoeKuo.size(); ++d) {
            const Polynomial& p = kJoeKuo[d];
            auto& w = v[d + 1];
            for (int i = 0; i < p.s; ++i) w[i] = p.m[i] << (31 - i);
            for (int i = p.s; i < 32; ++i) {
                std::uint32_t x = w[i - p.s] ^ (w[i - p.s] >> p.s);
                for (int k = 1; k < p.s; ++k)
                    if ((p.a >> (p.s - 1 - k)) & 1u) x ^= w[i - k];
                w[i] = x;
            }
        }
    }
};
inline constexpr Directions kDirections{};

inline std::uint32_t sobol(std::uint32_t index, int dimension) {
    // (Each direction masked in by its bit, not chosen by a branch: the
    // bits of a pixel's sample indices are as good as random, and a
    // mispredicted branch per bit cost more than the sample's scramble.)
    std::uint32_t x = 0;
    for (int bit = 0; index != 0; index >>= 1, ++bit)
        x ^= kDirections.v[dimension][bit] & (0u - (index & 1u));
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

// The sequence's dimensions: pixel x and y, time, the lens' pair, then
// kJointLightPairs pairs for area lights (a light's pair key below it),
// and last the spectral band a dispersive surface gives a ray
// (tracer/spectral_band.hpp; the seed's fifth dimension, wavelength).
inline constexpr int kPixelX = 0, kPixelY = 1, kTime = 2, kLensU = 3, kFirstLightDimension = 5;
inline constexpr int kJointDimensions = static_cast<int>(sobol_detail::kJoeKuo.size()) + 1;
inline constexpr int kWavelength = kJointDimensions - 1;
inline constexpr std::uint32_t kJointLightPairs = (kWavelength - kFirstLightDimension) / 2;
// The lens' pair key (sample_pair): none of the lights'.
inline constexpr std::uint32_t kLensPair = 0x7fffffffu;

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

// Dimension `dimension` (< kJointDimensions) of sample `index` of a pixel,
// in [0, 1). Without jitter, the unscrambled point shifted to the middle of
// its stratum among `count` samples: one sample is the pixel's centre at
// the middle of the shutter.
inline double joint_dimension(std::uint32_t seed, std::uint32_t index, std::uint32_t count,
                              int dimension, bool jitter) {
    using namespace sobol_detail;
    constexpr double kScale = 1.0 / 4294967296.0;
    if (!jitter) {
        const double u =
            sobol(index, dimension) * kScale + 0.5 / static_cast<double>(count == 0 ? 1 : count);
        return u >= 1.0 ? u - 1.0 : u;
    }
    return owen_scramble(sobol(index, dimension),
                         hash(seed ^ static_cast<std::uint32_t>(dimension + 1))) *
           kScale;
}

// Sample `index` of a pixel's place and time (the first three dimensions).
inline PixelSample pixel_sample(std::uint32_t seed, std::uint32_t index, std::uint32_t count,
                                bool jitter) {
    return {joint_dimension(seed, index, count, kPixelX, jitter),
            joint_dimension(seed, index, count, kPixelY, jitter),
            joint_dimension(seed, index, count, kTime, jitter)};
}

// A further pair of a sample's dimensions: the lens' (kLensPair), an area
// light's point (`pair` = light index + lights x trace depth), crand's.
// The lens and the first kJointLightPairs light keys are dimensions of the
// joint sequence; any other key is a padded pair: the first two dimensions
// of Sobol's sequence Owen-scrambled with a seed of its own, stratified
// over the pixel's samples and independent of the other dimensions.
inline std::array<double, 2> sample_pair(std::uint32_t seed, std::uint32_t index,
                                         std::uint32_t count, std::uint32_t pair, bool jitter) {
    using namespace sobol_detail;
    if (pair == kLensPair || pair < kJointLightPairs) {
        const int first =
            pair == kLensPair ? kLensU : kFirstLightDimension + 2 * static_cast<int>(pair);
        return {joint_dimension(seed, index, count, first, jitter),
                joint_dimension(seed, index, count, first + 1, jitter)};
    }
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
