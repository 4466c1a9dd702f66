// POV-Ray 3.7's spotted pattern: the noise itself. Its value is noise_value, in
// noise_patterns.cpp with its family's; what a kind declares is
// pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Spotted {
    static constexpr std::string_view keyword = "spotted";
    static constexpr Function value = noise_value;
};

}  // namespace hexant::runtime::pattern::kinds
