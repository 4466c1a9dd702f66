// What the fractal patterns (kinds/mandel.hpp, julia.hpp, magnet.hpp) share:
// where their numbers live in Values and their settings, as POV-Ray 3.7's
// Parse_Pattern reads them (EXTERIOR_TOKEN, INTERIOR_TOKEN, EXPONENT_TOKEN)
// with its frame.h defaults. POV-Ray keeps these numbers in double (its
// Fractal record's DBL and UV_VECT fields), not in single precision.
#pragma once

#include <cstddef>

#include "runtime/texture/pattern/pattern.hpp"

namespace hexant::runtime::pattern::kinds {

struct FractalSlots {
    // Values::number: the iterations (truncated), then the exponent
    // (mandel, julia) or the form (magnet).
    static constexpr int kIterations = 0;
    static constexpr int kSecond = 1;
    // Values::more: exterior TYPE, FACTOR and interior TYPE, FACTOR.
    static constexpr std::size_t kExteriorType = 0, kExteriorFactor = 1, kInteriorType = 2,
                                 kInteriorFactor = 3;
    // (The julia forms' <cr, ci> is Values::vector's x and y.)

    // exterior TYPE, FACTOR: types 0 to 8, default 1 with factor 1;
    // interior TYPE, FACTOR: types 0 to 6, default 0 with factor 1.
    static constexpr Setting exterior = Setting::of_pair(
        "exterior", Setting::kMoreSlot + static_cast<int>(kExteriorType), 1.0, 1.0, 0, 8);
    static constexpr Setting interior = Setting::of_pair(
        "interior", Setting::kMoreSlot + static_cast<int>(kInteriorType), 0.0, 1.0, 0, 6);
    // exponent E: 2 to 33; outside, POV-Ray warns and uses 2.
    static constexpr Setting exponent = Setting::of_integer("exponent", kSecond, 2.0, 2, 33, true);
};

}  // namespace hexant::runtime::pattern::kinds
