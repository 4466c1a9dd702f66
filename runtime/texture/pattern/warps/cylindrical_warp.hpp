// warp { cylindrical [orientation <v>] [dist_exp E] }: a point as (the
// angle around y as a fraction of a turn, y, the distance from y), the
// angle scaled by distance^dist_exp, turned for the orientation; a point
// on the y axis stays where it is (POV-Ray 3.7's warp_cylindrical).
#pragma once

#include <cmath>

#include "runtime/texture/pattern/warps/mapping_warp.hpp"

namespace hexant::runtime::pattern {

inline glm::dvec3 cylindrical_point(const MappingAt& m, const glm::dvec3& p) {
    const double len = std::sqrt(p.x * p.x + p.z * p.z);
    if (len == 0.0) return p;
    double theta = turn_fraction(p.x, p.z, len);
    if (m.dist_exp == 1.0)
        theta *= len;
    else if (m.dist_exp != 0.0)
        theta *= std::pow(len, m.dist_exp);
    return oriented(m.orientation, theta, p.y, len);
}

}  // namespace hexant::runtime::pattern
