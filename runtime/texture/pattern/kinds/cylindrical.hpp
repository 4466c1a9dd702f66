// POV-Ray 3.7's cylindrical pattern: 1 on the y axis falling to 0 at distance
// 1. Its value is cylindrical_value, in shape_patterns.cpp with its family's;
// what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Cylindrical {
    static constexpr std::string_view keyword = "cylindrical";
    static constexpr Function value = cylindrical_value;
};

}  // namespace hexant::runtime::pattern::kinds
