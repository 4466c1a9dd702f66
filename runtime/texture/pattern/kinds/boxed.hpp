// POV-Ray 3.7's boxed pattern: 1 at the origin falling to 0 at the faces of the
// unit cube. Its value is boxed_value, in shape_patterns.cpp with its family's;
// what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Boxed {
    static constexpr std::string_view keyword = "boxed";
    static constexpr Function value = boxed_value;
};

}  // namespace hexant::runtime::pattern::kinds
