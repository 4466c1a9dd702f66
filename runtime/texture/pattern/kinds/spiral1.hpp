// POV-Ray 3.7's spiral1 pattern: a spiral about the z axis, its argument the
// arms. Its value is spiral1_value, in shape_patterns.cpp with its family's;
// what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Spiral1 {
    static constexpr std::string_view keyword = "spiral1";
    static constexpr Kind::Argument argument = Kind::Argument::Number;
    static constexpr Wave wave = Wave::Triangle;
    static constexpr Function value = spiral1_value;
};

}  // namespace hexant::runtime::pattern::kinds
