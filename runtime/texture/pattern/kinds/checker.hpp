// POV-Ray 3.7's checker pattern: unit cubes of two colours, a blend list of 2.
// Its value is checker_value, in block_patterns.cpp with its family's; what a
// kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Checker {
    static constexpr std::string_view keyword = "checker";
    static constexpr Kind::Argument argument = Kind::Argument::Colours;
    static constexpr int colours = 2;
    static constexpr bool frequency = false;
    // (POV-Ray's checker default reads the hexagon's first two entries.)
    static constexpr std::array default_map = {MapEntry{0.0, {0, 0, 1, 0, 0}},
                                               MapEntry{1.0, {0, 1, 0, 0, 0}}};
    static constexpr Function value = checker_value;
};

}  // namespace hexant::runtime::pattern::kinds
