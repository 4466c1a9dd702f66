// POV-Ray 3.7's gradient pattern: the distance along a direction (its argument,
// normalized), repeating. Its value is gradient_value, in shape_patterns.cpp
// with its family's; what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Gradient {
    static constexpr std::string_view keyword = "gradient";
    static constexpr Kind::Argument argument = Kind::Argument::Vector;
    static constexpr Function value = gradient_value;
};

}  // namespace hexant::runtime::pattern::kinds
