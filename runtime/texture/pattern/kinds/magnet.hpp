// POV-Ray 3.7's magnet patterns, `magnet 1|2 mandel ITERATIONS` and
// `magnet 1|2 julia <cr, ci>, ITERATIONS` (magnet1m_pattern,
// magnet1j_pattern, magnet2m_pattern, magnet2j_pattern): the magnetism
// fractals of types 1 and 2 in the x-y plane, over c the point (mandel)
// or from z the point (julia). The grammar reads them by their own rule
// (language/grammar/textures.hpp's magnet_pattern). Its value is
// magnet_value, in fractal_patterns.cpp; its slots and settings are
// fractal_settings.hpp's (no exponent, as POV-Ray); the grey map is its
// default.
#pragma once

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/fractal_settings.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Magnet {
    static constexpr std::string_view keyword = "magnet";
    static constexpr Kind::Argument argument = Kind::Argument::Own;
    static constexpr bool single_numbers = false;
    // Values::number[kForm]: which of the four.
    static constexpr int kForm = FractalSlots::kSecond;
    static constexpr int kOneMandel = 1, kTwoMandel = 2, kOneJulia = 3, kTwoJulia = 4;
    static constexpr std::array settings = {FractalSlots::exterior, FractalSlots::interior};
    static constexpr Function value = magnet_value;
};

}  // namespace hexant::runtime::pattern::kinds
