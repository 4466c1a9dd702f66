// POV-Ray 3.7's dents pattern: the noise cubed; in a normal, dents_normal. Its
// value is dents_value, in noise_patterns.cpp with its family's; what a kind
// declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Dents {
    static constexpr std::string_view keyword = "dents";
    static constexpr NormalFunction normal = dents_normal;
    static constexpr Function value = dents_value;
};

}  // namespace hexant::runtime::pattern::kinds
