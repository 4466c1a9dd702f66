// POV-Ray 3.7's slope pattern (pattern.cpp's slope_pattern, Parse_Pattern's
// SLOPE_TOKEN): how steep the surface is against a direction, from the
// shading normal at the hit (POV-Ray's PNormal: the normal as the texture's
// latest normal { } left it, not moved by the pattern's transforms), mixed
// with an altitude along a second direction (the point in pattern space,
// which the transforms do move):
//
//   slope { DIRECTION [, LOW [, HIGH]] [altitude VECTOR [, LOW [, HIGH]]] }
//   slope { point_at POINT [, LOW [, HIGH]] }   slope DIRECTION
//
// The slope is asin(N . D) mapped from [-90, 90] degrees to [0, 1],
// rescaled from [LOW, HIGH] to [0, 1]; the altitude P . A the same way;
// the two weighted by the lengths of DIRECTION and VECTOR as written; the
// result wrapped into [0, 1) (1 itself kept just under 1). With point_at,
// D is the direction from the hit to POINT and there is no altitude.
// Without a surface (a sky's pigment) the value is 0, as in POV-Ray.
//
// What the language stores (language/actions/patterns.hpp): the vectors
// as written (Values::vector, Values::vector2), and LOW with HIGH - LOW
// for each (Values::more; a range of 0 leaves the value unscaled), point_at
// in number[kPointAt]. All in double, as POV-Ray keeps them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/geometric.hpp>

#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct Slope {
    static constexpr std::string_view keyword = "slope";
    static constexpr Kind::Argument argument = Kind::Argument::Own;
    static constexpr bool single_numbers = false;
    static constexpr int kPointAt = 0;  // number[kPointAt]: 1 for point_at
    // Values::more
    static constexpr std::size_t kSlopeLow = 0, kSlopeRange = 1, kAltitudeLow = 2,
                                 kAltitudeRange = 3;
    // POV-Ray's EPSILON (configbackend.h).
    static constexpr double kEpsilon = 1.0e-10;

    // x into [0, 1) as POV-Ray wraps it (a value of exactly 1 may be kept
    // just under 1 by the caller).
    static double wrap(double x) { return x < 0.0 ? 1.0 + std::fmod(x, 1.0) : std::fmod(x, 1.0); }

    static double value(const glm::dvec3& p, const Values& v) {
        if (v.hit == nullptr || !v.hit->surface) return 0.0;
        const glm::dvec3& n = v.hit->normal;
        double slope_share = 1.0, altitude_share = 0.0;
        double s;
        if (v.number[kPointAt] != 0.0) {
            const glm::dvec3 d = v.vector - v.hit->point;
            s = glm::dot(n, d * (1.0 / std::sqrt(glm::dot(d, d))));
        } else {
            const double slope_length = std::sqrt(glm::dot(v.vector, v.vector));
            const double altitude_length = std::sqrt(glm::dot(v.vector2, v.vector2));
            const glm::dvec3 d = slope_length != 0.0 ? v.vector * (1.0 / slope_length) : v.vector;
            s = glm::dot(n, d);
            slope_share = slope_length / (slope_length + altitude_length);
            altitude_share = 1.0 - slope_share;
        }
        s = std::clamp(s, -1.0, 1.0);
        s = std::asin(s) / M_PI * 2;
        s = (s + 1.0) * 0.5;
        if (v.more[kSlopeRange] != 0.0) s = (s - v.more[kSlopeLow]) / v.more[kSlopeRange];
        if (altitude_share == 0.0) return s == 1.0 ? s - kEpsilon : wrap(s);
        const double altitude_length = std::sqrt(glm::dot(v.vector2, v.vector2));
        double a = glm::dot(p, v.vector2 * (1.0 / altitude_length));
        if (v.more[kAltitudeRange] != 0.0) a = (a - v.more[kAltitudeLow]) / v.more[kAltitudeRange];
        const double value = slope_share * s + altitude_share * a;
        // (1 is a common value exactly: kept at the top of the map.)
        if (value - 1.0 < kEpsilon && value >= 1.0) return value - kEpsilon;
        return wrap(value);
    }
};

}  // namespace hexant::runtime::pattern::kinds
