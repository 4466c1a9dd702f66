// The fraction of a 4D region that a solid fills, by stratified sampling
// where no closed form applies: 4 strata in time times 4 x 4 x 4 in space,
// one jittered sample in each (kOccupancySamples in all). The jitter comes
// from a hash of the stratum, so the answer is the same on every run and
// thread. Its error is about 1/sqrt(256) = 6% of the region at worst, and far
// less for a solid whose boundary crosses few strata; the hierarchy's density
// criterion (0.3) needs no more.
#pragma once

#include <cstdint>

#include "runtime/geometry/spacetime.hpp"

namespace hexant::runtime {

inline constexpr int kOccupancyStrata = 4;  // per axis, in x, y, z and t
inline constexpr int kOccupancySamples =
    kOccupancyStrata * kOccupancyStrata * kOccupancyStrata * kOccupancyStrata;

// A uniform number in [0, 1) from an integer (SplitMix64's finaliser).
inline double stratum_jitter(std::uint64_t key) {
    key += 0x9e3779b97f4a7c15ull;
    key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ull;
    key = (key ^ (key >> 27)) * 0x94d049bb133111ebull;
    key ^= key >> 31;
    return static_cast<double>(key >> 11) * 0x1.0p-53;
}

// inside(Event) -> bool.
template <class Inside>
double sampled_occupancy(const Box4& region, Inside&& inside) {
    if (region.is_empty()) return 0.0;
    int count = 0;
    const glm::dvec4 extent = region.hi - region.lo;
    for (int i = 0; i < kOccupancySamples; ++i) {
        Event e;
        int stratum = i;
        for (int axis = 0; axis < 4; ++axis) {
            const int cell = stratum % kOccupancyStrata;
            stratum /= kOccupancyStrata;
            const double u = (cell + stratum_jitter(4 * static_cast<std::uint64_t>(i) + axis)) /
                             kOccupancyStrata;
            e[axis] = region.lo[axis] + u * extent[axis];
        }
        if (inside(e)) ++count;
    }
    return static_cast<double>(count) / kOccupancySamples;
}

}  // namespace hexant::runtime
