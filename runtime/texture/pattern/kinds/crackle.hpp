// POV-Ray 3.7's crackle pattern: cells around a random point in each unit cube:
// a form of the distances (metric) to the nearest three, plus offset; with
// `solid`, the noise at the nearest point (each cell one value). Its value
// is crackle_value, in crackle.cpp with its family's; what a kind declares is
// pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Crackle {
    static constexpr std::string_view keyword = "crackle";
    // POV-Ray keeps crackle's metric and offset in double precision.
    static constexpr bool single_numbers = false;
    static constexpr int kMetric = 0;  // Values::number[0]
    static constexpr int kOffset = 1;  // Values::number[1]
    static constexpr int kSolid = 2;   // Values::more[0]
    static constexpr std::array settings = {
        Setting::of_number("metric", kMetric, 2.0), Setting::of_number("offset", kOffset, 0.0),
        Setting::of_vector("form", {-1.0, 1.0, 0.0}), Setting::of_flag("solid", kSolid)};
    static constexpr Function value = crackle_value;
};

}  // namespace hexant::runtime::pattern::kinds
