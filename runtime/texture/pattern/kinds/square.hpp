// POV-Ray 3.7's square pattern: the x-z plane paved with unit squares in four
// colours, a blend list of 4 (its square_pattern and Parse_Pattern): a
// square's value is 0 where floor(x) and floor(z) are both even, 1 where only
// floor(z) is odd, 2 where both are odd and 3 where only floor(x) is; y is
// not read. Frequency 0, as every block pattern's, so no wave reshapes the
// index. Its defaults are red, green, blue and yellow (measured on POV-Ray
// 3.7.0.10, tests/tracer/pov_reference/patterns/square.pov).
#pragma once

#include <cmath>

#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Square {
    static constexpr std::string_view keyword = "square";
    static constexpr Kind::Argument argument = Kind::Argument::Colours;
    static constexpr int colours = 4;
    static constexpr bool frequency = false;
    static constexpr std::array default_map = {
        MapEntry{0.0, {1, 0, 0, 0, 0}}, MapEntry{1.0, {0, 1, 0, 0, 0}},
        MapEntry{2.0, {0, 0, 1, 0, 0}}, MapEntry{3.0, {1, 1, 0, 0, 0}}};

    static double value(const glm::dvec3& p, const Values&) {
        // The parity of each floor from fmod, exact for every double:
        // POV-Ray casts the floors to int, which past 2^31 is undefined;
        // here every double past 2^53 is even, and a non-finite point is
        // square 0.
        if (!std::isfinite(p.x) || !std::isfinite(p.z)) return 0.0;
        const bool odd_x = std::fmod(std::floor(p.x), 2.0) != 0.0;
        const bool odd_z = std::fmod(std::floor(p.z), 2.0) != 0.0;
        if (odd_x) return odd_z ? 2.0 : 3.0;
        return odd_z ? 1.0 : 0.0;
    }
};

}  // namespace hexant::runtime::pattern::kinds
