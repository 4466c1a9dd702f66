// Patterns whose value picks one of a list of colours (POV-Ray's blend
// lists): checker and brick (2), hexagon (3). Their value is the colour's
// index; frequency is 0 for them, so no wave reshapes it.
#include <cmath>

#include "runtime/texture/pattern/families.hpp"

namespace hexant::runtime::pattern {

namespace {

// The fraction of v within its unit cell as POV-Ray's brick takes it
// (through a truncation toward zero, then made positive); beyond the range
// of a long long every double is an integer and the fraction is 0.
double cell_fraction(double v) {
    if (!(std::fabs(v) < 9.0e18)) return 0.0;
    double f = v - static_cast<double>(static_cast<long long>(v));
    if (f < 0.0) f += 1.0;
    return f;
}

}  // namespace

double checker_value(const glm::dvec3& p, const Values&) {
    // POV-Ray 3.7's rule (CheckerPattern): each coordinate floored after
    // adding EPSILON = 1e-10, so a face lying on a boundary in pattern
    // space takes the upper cell whichever way its points rounded. In the
    // pattern's own units (one cell): it holds at every scale.
    constexpr double kBoundary = 1.0e-10;
    const double sum =
        std::floor(p.x + kBoundary) + std::floor(p.y + kBoundary) + std::floor(p.z + kBoundary);
    // fmod of an integer-valued double is exact; no int overflow far away.
    return std::fabs(std::fmod(sum, 2.0)) == 1.0 ? 1.0 : 0.0;
}

double brick_value(const glm::dvec3& p, const Values& v) {
    const double mortar = v.number[0];
    const double shift = 1.0e-10 + mortar;  // POV-Ray's EPSILON + mortar
    const double x = p.x + shift, y = p.y + shift, z = p.z + shift;
    const glm::dvec3 size = v.vector;
    const double mw = mortar / size.x, mh = mortar / size.y, md = mortar / size.z;
    // Mortar between courses (the top view).
    if (cell_fraction(y / size.y) <= mh) return 0.0;
    // Odd and even courses: which half of a two-course period.
    const double course = cell_fraction((y / size.y) * 0.5);
    // Ends of the bricks, offset by half a brick every other course.
    if (cell_fraction(x / size.x) <= mw && course <= 0.5) return 0.0;
    if (cell_fraction(x / size.x + 0.5) <= mw && course > 0.5) return 0.0;
    // The same across the depth.
    if (cell_fraction(z / size.z) <= md && course > 0.5) return 0.0;
    if (cell_fraction(z / size.z + 0.5) <= md && course <= 0.5) return 0.0;
    return 1.0;
}

double hexagon_value(const glm::dvec3& p, const Values&) {
    // A grid of 6 x 6 blocks of half-width 0.5 and height sqrt(3)/2, the
    // blocks with slanted edges split by their diagonal (POV-Ray's
    // hexagon_pattern, with its constants).
    constexpr double kXFactor = 0.5, kZFactor = 0.866025404;
    double x = std::fabs(p.x);
    double z = p.z < 0.0 ? 5.196152424 - std::fabs(p.z) : p.z;  // no mirror across x
    double xs = x / kXFactor, zs = z / kZFactor;
    xs -= std::floor(xs / 6.0) * 6.0;
    zs -= std::floor(zs / 6.0) * 6.0;
    if (!std::isfinite(xs) || !std::isfinite(zs)) return 0.0;
    const int xm = static_cast<int>(std::floor(xs)) % 6;
    const int zm = static_cast<int>(std::floor(zs)) % 6;
    double value = 0.0;
    switch (xm) {
        case 0:
        case 5:
            value = (zm == 0 || zm == 5) ? 0 : (zm <= 2) ? 1 : 2;
            break;
        case 2:
        case 3:
            value = (zm <= 1) ? 2 : (zm <= 3) ? 0 : 1;
            break;
        default: {  // 1, 4: split along a diagonal
            double xl = xs - xm;
            const double zl = zs - zm;
            if ((xm + zm) % 2 == 1) xl = 1.0 - xl;
            if (xl == 0.0) xl = 0.0001;
            if (zl / xl < 1.0)
                value = (zm == 0 || zm == 3) ? 0 : (zm == 2 || zm == 5) ? 1 : 2;
            else
                value = (zm == 0 || zm == 3) ? 2 : (zm == 2 || zm == 5) ? 0 : 1;
        }
    }
    return std::fmod(value, 3.0);
}

}  // namespace hexant::runtime::pattern
