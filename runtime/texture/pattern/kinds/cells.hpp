// POV-Ray 3.7's cells pattern: a random value a unit cube. Its value is
// cells_value, in crackle.cpp with its family's; what a kind declares is
// pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Cells {
    static constexpr std::string_view keyword = "cells";
    static constexpr Function value = cells_value;
};

}  // namespace hexant::runtime::pattern::kinds
