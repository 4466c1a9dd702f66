// POV-Ray 3.7's marble pattern: bands along x bent by its own turbulence. Its
// value is marble_value, in shape_patterns.cpp with its family's; what a kind
// declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Marble {
    static constexpr std::string_view keyword = "marble";
    static constexpr Wave wave = Wave::Triangle;
    static constexpr bool own_turbulence = true;
    static constexpr std::array default_map = {MapEntry{0.0, {0.9, 0.8, 0.8, 0, 0}},
                                               MapEntry{0.9, {0.9, 0.08, 0.08, 0, 0}},
                                               MapEntry{0.9, {0, 0, 0, 0, 0}}};
    static constexpr Function value = marble_value;
};

}  // namespace hexant::runtime::pattern::kinds
