// POV-Ray 3.7's waves pattern: waves about ten sources; in a normal,
// waves_normal. Its value is waves_value, in shape_patterns.cpp with its
// family's; what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Waves {
    static constexpr std::string_view keyword = "waves";
    static constexpr NormalFunction normal = waves_normal;
    static constexpr Function value = waves_value;
};

}  // namespace hexant::runtime::pattern::kinds
