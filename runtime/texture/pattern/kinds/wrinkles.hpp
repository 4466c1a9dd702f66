// POV-Ray 3.7's wrinkles pattern: ten octaves of the noise; in a normal,
// wrinkles_normal. Its value is wrinkles_value, in noise_patterns.cpp with its
// family's; what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Wrinkles {
    static constexpr std::string_view keyword = "wrinkles";
    static constexpr NormalFunction normal = wrinkles_normal;
    static constexpr Function value = wrinkles_value;
};

}  // namespace hexant::runtime::pattern::kinds
