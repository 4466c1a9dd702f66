// POV-Ray 3.7's hexagon pattern: hexagons of three colours in the x-z plane, a
// blend list of 3. Its value is hexagon_value, in block_patterns.cpp with its
// family's; what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Hexagon {
    static constexpr std::string_view keyword = "hexagon";
    static constexpr Kind::Argument argument = Kind::Argument::Colours;
    static constexpr int colours = 3;
    static constexpr bool frequency = false;
    static constexpr std::array default_map = {MapEntry{0.0, {0, 0, 1, 0, 0}},
                                               MapEntry{1.0, {0, 1, 0, 0, 0}},
                                               MapEntry{2.0, {1, 0, 0, 0, 0}}};
    static constexpr Function value = hexagon_value;
};

}  // namespace hexant::runtime::pattern::kinds
