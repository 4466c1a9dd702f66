// POV-Ray 3.7's mandel pattern: the Mandelbrot set in the x-y plane, its
// argument the iterations (mandel_pattern, and mandel3_pattern,
// mandel4_pattern, mandelx_pattern for `exponent 3` to 33). Its value is
// mandel_value, in fractal_patterns.cpp with its family's; its slots and
// settings are fractal_settings.hpp's; what a kind declares is
// pattern_kind.hpp's contract.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/fractal_settings.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Mandel {
    static constexpr std::string_view keyword = "mandel";
    static constexpr Kind::Argument argument = Kind::Argument::Number;
    static constexpr bool single_numbers = false;
    static constexpr int kExponent = FractalSlots::kSecond;
    static constexpr std::array settings = {FractalSlots::exponent, FractalSlots::exterior,
                                            FractalSlots::interior};
    // (POV-Ray's Mandel_Default_Map, for exponent 2 only: another exponent
    // is another pattern there, with the grey map. language/actions/
    // patterns.hpp's close_pigment gives it that.)
    static constexpr std::array default_map = {
        MapEntry{0.001, {0, 0, 0, 0, 0}}, MapEntry{0.001, {0, 1, 1, 0, 0}},
        MapEntry{0.012, {1, 1, 0, 0, 0}}, MapEntry{0.015, {1, 0, 1, 0, 0}},
        MapEntry{0.1, {0, 1, 1, 0, 0}}};
    static constexpr Function value = mandel_value;
};

}  // namespace hexant::runtime::pattern::kinds
