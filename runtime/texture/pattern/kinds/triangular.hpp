// POV-Ray 3.7's triangular pattern: the x-z plane tiled with equilateral
// triangles of unit side in six colours, a blend list of 6 (its
// triangular_pattern and Parse_Pattern): the plane folds to a 3 by sqrt(3)
// rectangle, whose lower half's unit columns each hold three triangles,
// numbered around the vertex they share; the upper half mirrors it (5 - n).
// y is not read. Frequency 0, as every block pattern's. Its defaults are
// POV-Ray's Cubic_Entries (pigment.cpp: red, green, blue, yellow, cyan,
// magenta; measured in tests/tracer/pov_reference/patterns/triangular.pov).
#pragma once

#include <cmath>

#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Triangular {
    static constexpr std::string_view keyword = "triangular";
    static constexpr Kind::Argument argument = Kind::Argument::Colours;
    static constexpr int colours = 6;
    static constexpr bool frequency = false;
    static constexpr std::array default_map = {
        MapEntry{0.0, {1, 0, 0, 0, 0}}, MapEntry{1.0, {0, 1, 0, 0, 0}},
        MapEntry{2.0, {0, 0, 1, 0, 0}}, MapEntry{3.0, {1, 1, 0, 0, 0}},
        MapEntry{4.0, {0, 1, 1, 0, 0}}, MapEntry{5.0, {1, 0, 1, 0, 0}}};

    static double value(const glm::dvec3& p, const Values&) {
        if (!std::isfinite(p.x) || !std::isfinite(p.z)) return 0.0;  // no triangle
        constexpr double kSqrt3 = 1.7320508075688772935;
        // The fold to [0, 3) x [0, sqrt 3), then the unit column `a` and the
        // half `upper` (mirrored onto the lower one).
        double xs = p.x - 3.0 * std::floor(p.x / 3.0);
        double zs = p.z - kSqrt3 * std::floor(p.z / kSqrt3);
        // (Rounding may land a fold on its upper end: it is the lower one.)
        if (!(xs < 3.0)) xs = 0.0;
        if (!(zs < kSqrt3)) zs = 0.0;
        const int a = static_cast<int>(std::floor(xs));
        xs -= a;
        const bool upper = zs >= 0.5 * kSqrt3;
        if (upper) zs = kSqrt3 - zs;
        // Which of the column's three triangles: by the slopes to its two
        // lower corners (POV-Ray's; the shared vertex itself, where neither
        // slope is below sqrt 3, is triangle 0 here, undefined there).
        double n = 1.0;
        const double k = 1.0 - xs;
        if (xs != 0.0 && k != 0.0) {
            // Below the edge rising from the left corner, from the right one.
            const bool below_left = zs / xs < kSqrt3, below_right = zs / k < kSqrt3;
            n = below_left && below_right ? 0.0 : below_right ? 1.0 : below_left ? 3.0 : 0.0;
        }
        const int mask = static_cast<int>(n);
        double answer =
            (mask & 1) ? std::fmod(n + 2.0 * a, 6.0) : std::fmod(6.0 + n - 2.0 * a, 6.0);
        if (upper) answer = 5.0 - answer;
        return answer;
    }
};

}  // namespace hexant::runtime::pattern::kinds
