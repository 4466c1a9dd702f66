// Fractal patterns (POV-Ray 3.7's pattern.cpp): mandel, with POV-Ray's
// default colouring (outside: the iteration it escaped at over the
// iterations; inside: 1).
#include <cmath>

#include "runtime/texture/pattern/families.hpp"

namespace hexant::runtime::pattern {

double mandel_value(const glm::dvec3& p, const Values& v) {
    const double limit = v.number[0];
    const int iterations = limit >= 1.0 ? (limit < 1.0e6 ? static_cast<int>(limit) : 1000000) : 0;
    double a = p.x, b = p.y;
    const double x = a, y = b;
    double a2 = a * a, b2 = b * b;
    for (int i = 0; i < iterations; ++i) {
        b = 2.0 * a * b + y;
        a = a2 - b2 + x;
        a2 = a * a;
        b2 = b * b;
        if (a2 + b2 > 4.0) return static_cast<double>(i) / static_cast<double>(iterations);
    }
    return 1.0;
}

}  // namespace hexant::runtime::pattern
