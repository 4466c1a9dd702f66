// POV-Ray 3.7's leopard pattern: regular spots, the square of a sum of sines.
// Its value is leopard_value, in shape_patterns.cpp with its family's; what a
// kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Leopard {
    static constexpr std::string_view keyword = "leopard";
    static constexpr Function value = leopard_value;
};

}  // namespace hexant::runtime::pattern::kinds
