// POV-Ray 3.7's granite pattern: six octaves of the noise's distance from 0.5.
// Its value is granite_value, in noise_patterns.cpp with its family's; what a
// kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Granite {
    static constexpr std::string_view keyword = "granite";
    static constexpr Function value = granite_value;
};

}  // namespace hexant::runtime::pattern::kinds
