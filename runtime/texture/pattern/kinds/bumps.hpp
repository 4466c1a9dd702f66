// POV-Ray 3.7's bumps pattern: the noise; in a normal, its gradient
// (bumps_normal). Its value is noise_value, in noise_patterns.cpp with its
// family's; what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Bumps {
    static constexpr std::string_view keyword = "bumps";
    static constexpr NormalFunction normal = bumps_normal;
    static constexpr Function value = noise_value;
};

}  // namespace hexant::runtime::pattern::kinds
