// POV-Ray 3.7's average pattern: no value of its own; its map's entries
// (pigment_map, normal_map or texture_map), all of them, averaged by the
// weights written as their values (pigment.cpp's Do_Average_Pigments,
// normal.cpp's Do_Average_Normals, trace.cpp's ComputeAverageTextureColours:
// each entry at the point warped by the average's own transforms and
// warps, times its value in single precision, the sum divided by the sum of
// the values). The language requires the map (POV-Ray: "Average must have
// map"); the texture evaluator reads `average` and never the value.
#pragma once

#include <cstddef>

#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Average {
    static constexpr std::string_view keyword = "average";
    static constexpr bool average = true;
    static constexpr bool frequency = false;

    static double value(const glm::dvec3&, const Values&) { return 0.0; }
};

// The weighted average of `count` entries (POV-Ray's loops: the weights
// and their sum in single precision): add(i, share) adds entry i times its
// share, its weight over the sum. Weights that sum to zero add nothing
// (POV-Ray divides by the zero: no finite colour).
template <class WeightAt, class Add>
void average_entries(std::size_t count, WeightAt weight_at, Add add) {
    float total = 0.0f;
    for (std::size_t i = 0; i < count; ++i) total += static_cast<float>(weight_at(i));
    if (total == 0.0f) return;
    for (std::size_t i = 0; i < count; ++i)
        add(i, static_cast<double>(static_cast<float>(weight_at(i))) / static_cast<double>(total));
}

}  // namespace hexant::runtime::pattern::kinds
