// POV-Ray 3.7's radial pattern: the angle about the y axis. Its value is
// radial_value, in shape_patterns.cpp with its family's; what a kind declares
// is pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Radial {
    static constexpr std::string_view keyword = "radial";
    static constexpr std::array default_map = {
        MapEntry{0.0, {0, 1, 1, 0, 0}}, MapEntry{0.333, {1, 1, 0, 0, 0}},
        MapEntry{0.666, {1, 0, 1, 0, 0}}, MapEntry{1.0, {0, 1, 1, 0, 0}}};
    static constexpr Function value = radial_value;
};

}  // namespace hexant::runtime::pattern::kinds
