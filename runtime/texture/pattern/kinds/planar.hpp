// POV-Ray 3.7's planar pattern: 1 in the x-z plane falling to 0 at distance 1.
// Its value is planar_value, in shape_patterns.cpp with its family's; what a
// kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Planar {
    static constexpr std::string_view keyword = "planar";
    static constexpr Function value = planar_value;
};

}  // namespace hexant::runtime::pattern::kinds
