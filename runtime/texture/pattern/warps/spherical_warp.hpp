// warp { spherical [orientation <v>] [dist_exp E] }: a point as (its
// longitude around y, its latitude, each a fraction in [0, 1], its
// distance from the origin), the first two scaled by distance^dist_exp,
// turned for the orientation; the origin stays where it is (POV-Ray 3.7's
// warp_spherical).
#pragma once

#include <cmath>

#include "runtime/texture/pattern/warps/mapping_warp.hpp"

namespace hexant::runtime::pattern {

inline glm::dvec3 spherical_point(const MappingAt& m, const glm::dvec3& p) {
    constexpr double kPi = 3.1415926535897932384626;
    const double dist = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    if (dist == 0.0) return p;
    const double x = p.x / dist, y = p.y / dist, z = p.z / dist;
    double phi = 0.5 + std::asin(y) / kPi;
    const double len = std::sqrt(x * x + z * z);
    // (At a pole any longitude will do: 0.)
    double theta = len == 0.0 ? 0.0 : turn_fraction(x, z, len);
    if (m.dist_exp == 1.0) {
        theta *= dist;
        phi *= dist;
    } else if (m.dist_exp != 0.0) {
        theta *= std::pow(dist, m.dist_exp);
        phi *= std::pow(dist, m.dist_exp);
    }
    return oriented(m.orientation, theta, phi, dist);
}

}  // namespace hexant::runtime::pattern
