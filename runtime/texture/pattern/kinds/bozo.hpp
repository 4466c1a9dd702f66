// POV-Ray 3.7's bozo pattern: the noise itself. Its value is noise_value, in
// noise_patterns.cpp with its family's; what a kind declares is
// pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Bozo {
    static constexpr std::string_view keyword = "bozo";
    static constexpr std::array default_map = {
        MapEntry{0.4, {1, 1, 1, 0, 0}}, MapEntry{0.4, {0, 1, 0, 0, 0}},
        MapEntry{0.6, {0, 1, 0, 0, 0}}, MapEntry{0.6, {0, 0, 1, 0, 0}},
        MapEntry{0.8, {0, 0, 1, 0, 0}}, MapEntry{0.8, {1, 0, 0, 0, 0}}};
    static constexpr Function value = noise_value;
};

}  // namespace hexant::runtime::pattern::kinds
