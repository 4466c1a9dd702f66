// Two unit vectors completing a unit normal to a right-handed frame
// (t1, t2, n), continuous except where n.z changes sign (Duff et al. 2017,
// "Building an Orthonormal Basis, Revisited"). The texture angle of discs,
// cylinders and cones and the plane's texture axes are measured in it.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace hexant::runtime::geometry {

struct OrthonormalBasis {
    glm::dvec3 t1, t2;
};

inline OrthonormalBasis orthonormal_basis(const glm::dvec3& n) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    return {{1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}};
}

// The angle of v around n in the basis, as a fraction of a turn in [0, 1).
inline double turn_fraction(const OrthonormalBasis& basis, const glm::dvec3& v) {
    constexpr double kTwoPi = 6.28318530717958647692;
    double angle = std::atan2(glm::dot(v, basis.t2), glm::dot(v, basis.t1));
    if (angle < 0.0) angle += kTwoPi;
    const double u = angle / kTwoPi;
    return u < 1.0 ? u : 0.0;
}

}  // namespace hexant::runtime::geometry
