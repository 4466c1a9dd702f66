// POV-Ray 3.7's agate pattern: noise bent by its own turbulence (agate_turb)
// into bands. Its value is agate_value, in noise_patterns.cpp with its
// family's; what a kind declares is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Agate {
    static constexpr std::string_view keyword = "agate";
    static constexpr int kAgateTurb = 0;  // Values::number[0]
    static constexpr std::array settings = {Setting::of_number("agate_turb", kAgateTurb, 1.0)};
    static constexpr std::array default_map = {
        MapEntry{0.0, {1, 1, 1, 0, 0}},       MapEntry{0.5, {0.95, 0.75, 0.5, 0, 0}},
        MapEntry{0.5, {0.9, 0.7, 0.5, 0, 0}}, MapEntry{0.6, {0.9, 0.7, 0.4, 0, 0}},
        MapEntry{0.6, {1, 0.7, 0.4, 0, 0}},   MapEntry{1.0, {0.6, 0.3, 0, 0, 0}}};
    static constexpr Function value = agate_value;
};

}  // namespace hexant::runtime::pattern::kinds
