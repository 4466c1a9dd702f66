// POV-Ray 3.7's quilted pattern: cushions in each unit cube, shaped by control0
// and control1; in a normal, quilted_normal. Its value is quilted_value, in
// shape_patterns.cpp with its family's; what a kind declares is
// pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Quilted {
    static constexpr std::string_view keyword = "quilted";
    static constexpr bool frequency = false;
    static constexpr int kControl0 = 0;  // Values::number[0]
    static constexpr int kControl1 = 1;  // Values::number[1]
    static constexpr std::array settings = {Setting::of_number("control0", kControl0, 1.0),
                                            Setting::of_number("control1", kControl1, 1.0)};
    static constexpr NormalFunction normal = quilted_normal;
    static constexpr Function value = quilted_value;
};

}  // namespace hexant::runtime::pattern::kinds
