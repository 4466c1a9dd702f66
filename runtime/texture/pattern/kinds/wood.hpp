// POV-Ray 3.7's wood pattern: rings about the z axis, bent by its own
// turbulence. Its value is wood_value, in shape_patterns.cpp with its family's;
// what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Wood {
    static constexpr std::string_view keyword = "wood";
    static constexpr Wave wave = Wave::Triangle;
    static constexpr bool own_turbulence = true;
    static constexpr std::array default_map = {MapEntry{0.6, {0.666, 0.312, 0.2, 0, 0}},
                                               MapEntry{0.6, {0.4, 0.1333, 0.066, 0, 0}}};
    static constexpr Function value = wood_value;
};

}  // namespace hexant::runtime::pattern::kinds
