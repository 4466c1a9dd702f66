// POV-Ray 3.7's brick pattern: bricks (colour 2) in mortar (colour 1), a blend
// list of 2. Its value is brick_value, in block_patterns.cpp with its family's;
// what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Brick {
    static constexpr std::string_view keyword = "brick";
    static constexpr Kind::Argument argument = Kind::Argument::Colours;
    static constexpr int colours = 2;
    static constexpr bool frequency = false;
    // The default mortar is POV-Ray's 0.5 - 2 EPSILON.
    static constexpr int kMortar = 0;  // Values::number[0]
    static constexpr std::array settings = {Setting::of_number("mortar", kMortar, 0.5 - 2.0e-10),
                                            Setting::of_vector("brick_size", {8.0, 3.0, 4.5})};
    static constexpr std::array default_map = {MapEntry{0.0, {0.5, 0.5, 0.5, 0, 0}},
                                               MapEntry{1.0, {0.6, 0.15, 0.15, 0, 0}}};
    static constexpr Function value = brick_value;
};

}  // namespace hexant::runtime::pattern::kinds
