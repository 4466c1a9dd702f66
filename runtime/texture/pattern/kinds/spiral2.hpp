// POV-Ray 3.7's spiral2 pattern: two spirals about the z axis, crossed, its
// argument the arms. Its value is spiral2_value, in shape_patterns.cpp with its
// family's; what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Spiral2 {
    static constexpr std::string_view keyword = "spiral2";
    static constexpr Kind::Argument argument = Kind::Argument::Number;
    static constexpr Wave wave = Wave::Triangle;
    static constexpr Function value = spiral2_value;
};

}  // namespace hexant::runtime::pattern::kinds
