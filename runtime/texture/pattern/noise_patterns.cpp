// Patterns read straight from POV-Ray's noise (pattern.cpp in POV-Ray 3.7:
// bozo, spotted and bumps are Noise itself; dents, wrinkles, granite and
// agate shape it).
#include <algorithm>
#include <cmath>

#include "runtime/texture/pattern/families.hpp"

namespace hexant::runtime::pattern {

double noise_value(const glm::dvec3& p, const Values& v) {
    return noise(p, v.noise_generator);
}

double dents_value(const glm::dvec3& p, const Values& v) {
    const double n = noise(p, v.noise_generator);
    return n * n * n;
}

double wrinkles_value(const glm::dvec3& p, const Values& v) {
    // Ten octaves of |noise| at doubling frequency and halving weight.
    const int g = v.noise_generator;
    const auto octave = [g](const glm::dvec3& q) {
        return g > 1 ? std::min(std::max(noise(q, g) * 2.0 - 0.5, 0.0), 1.0) : noise(q, g);
    };
    double lambda = 2.0, omega = 0.5;
    double value = octave(p);
    for (int i = 1; i < 10; ++i) {
        value += omega * octave(p * lambda);
        lambda *= 2.0;
        omega *= 0.5;
    }
    return value / 2.0;
}

double granite_value(const glm::dvec3& p, const Values& v) {
    const glm::dvec3 base = p * 4.0;
    double value = 0.0, freq = 1.0;
    for (int i = 0; i < 6; freq *= 2.0, ++i) {
        const double n = noise(base * freq, v.noise_generator);
        double temp;
        if (v.noise_generator == 1) {
            temp = std::fabs(0.5 - n);
        } else {
            temp = std::fabs(1.0 - 2.0 * n);
            if (temp > 0.5) temp = 0.5;
        }
        value += temp / freq;
    }
    return value;
}

double agate_value(const glm::dvec3& p, const Values& v) {
    const double turb = v.number[0] * turbulence(p, v.octaves, v.noise_generator);
    double n = 0.5 * (cycloidal(1.3 * turb + 1.1 * p.z) + 1.0);
    if (n < 0.0) return 0.0;
    n = std::min(1.0, n);
    return std::pow(n, 0.77);
}

}  // namespace hexant::runtime::pattern
