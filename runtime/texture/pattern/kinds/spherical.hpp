// POV-Ray 3.7's spherical pattern: 1 at the origin falling to 0 at distance 1.
// Its value is spherical_value, in shape_patterns.cpp with its family's; what a
// kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Spherical {
    static constexpr std::string_view keyword = "spherical";
    static constexpr Function value = spherical_value;
};

}  // namespace hexant::runtime::pattern::kinds
