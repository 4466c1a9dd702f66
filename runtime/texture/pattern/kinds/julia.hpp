// POV-Ray 3.7's julia pattern, `julia <cr, ci>, ITERATIONS`: the Julia set
// of z^2 + c in the x-y plane (julia_pattern, and julia3_pattern,
// julia4_pattern, juliax_pattern for `exponent 3` to 33). Its value is
// julia_value, in fractal_patterns.cpp with its family's; its slots and
// settings are fractal_settings.hpp's; the grey map is its default.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/fractal_settings.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Julia {
    static constexpr std::string_view keyword = "julia";
    static constexpr Kind::Argument argument = Kind::Argument::PointNumber;
    static constexpr bool single_numbers = false;
    static constexpr int kExponent = FractalSlots::kSecond;
    static constexpr std::array settings = {FractalSlots::exponent, FractalSlots::exterior,
                                            FractalSlots::interior};
    static constexpr Function value = julia_value;
};

}  // namespace hexant::runtime::pattern::kinds
