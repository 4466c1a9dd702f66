// warp { toroidal [orientation <v>] [dist_exp E] [major_radius R] }: a
// point as (its angle around y, its angle around the torus's tube of
// major radius R, each a fraction of a turn, its distance from the tube's
// centre line), the angles scaled by distance^dist_exp, turned for the
// orientation; a point on the y axis stays where it is (POV-Ray 3.7's
// warp_toroidal).
#pragma once

#include <cmath>

#include "runtime/texture/pattern/warps/mapping_warp.hpp"

namespace hexant::runtime::pattern {

inline glm::dvec3 toroidal_point(const MappingAt& m, const glm::dvec3& p) {
    constexpr double kPi = 3.1415926535897932384626;
    double len = std::sqrt(p.x * p.x + p.z * p.z);
    if (len == 0.0) return p;
    double theta;
    if (p.z == 0.0)
        theta = p.x > 0 ? 0.0 : kPi;
    else {
        theta = std::acos(p.x / len);
        if (p.z < 0.0) theta = 2.0 * kPi - theta;
    }
    theta = 0.0 - theta;
    // The point turned about y into the x-y plane, measured from the tube.
    const double x = len - m.major_radius;
    len = std::sqrt(x * x + p.y * p.y);
    double phi = std::acos(-x / len);
    if (p.y > 0.0) phi = 2.0 * kPi - phi;
    theta /= (-2.0 * kPi);
    phi /= 2.0 * kPi;
    if (m.dist_exp == 1.0) {
        theta *= len;
        phi *= len;
    } else if (m.dist_exp != 0.0) {
        theta *= std::pow(len, m.dist_exp);
        phi *= std::pow(len, m.dist_exp);
    }
    return oriented(m.orientation, theta, phi, len);
}

}  // namespace hexant::runtime::pattern
