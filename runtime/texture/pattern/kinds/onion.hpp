// POV-Ray 3.7's onion pattern: concentric spheres about the origin. Its value
// is onion_value, in shape_patterns.cpp with its family's; what a kind declares
// is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Onion {
    static constexpr std::string_view keyword = "onion";
    static constexpr Function value = onion_value;
};

}  // namespace hexant::runtime::pattern::kinds
