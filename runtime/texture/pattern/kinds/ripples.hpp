// POV-Ray 3.7's ripples pattern: rings about ten sources; in a normal,
// ripples_normal. Its value is ripples_value, in shape_patterns.cpp with its
// family's; what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Ripples {
    static constexpr std::string_view keyword = "ripples";
    static constexpr NormalFunction normal = ripples_normal;
    static constexpr Function value = ripples_value;
};

}  // namespace hexant::runtime::pattern::kinds
