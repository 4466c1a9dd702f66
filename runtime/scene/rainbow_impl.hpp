// through_rainbows, templated on the jitter's random source
// (runtime/scene/rainbow.hpp).
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace hexant::runtime {

template <class Random>
glm::dvec3 through_rainbows(const std::vector<Rainbow>& rainbows, const glm::dvec3& colour,
                            const glm::dvec3& d, double depth, Random&& random) {
    constexpr double kEpsilon = 1.0e-10;  // POV-Ray's EPSILON
    glm::dvec3 sum(0.0);
    int n = 0;
    for (const Rainbow& r : rainbows) {
        if (r.colour_map.empty() || r.distance == 0.0 || r.width == 0.0) continue;
        // The angle between the ray and the rainbow's up vector.
        const double x = glm::dot(d, r.right);
        double y = glm::dot(d, r.up);
        const double l = x * x + y * y;
        if (l > 0.0) y /= std::sqrt(l);
        const double angle = std::fabs(std::acos(std::clamp(y, -1.0, 1.0)));
        if (!(angle <= r.arc_angle)) continue;
        const double dot = glm::dot(d, r.direction);
        if (!(dot >= 0.0)) continue;
        double index = (std::acos(std::min(dot, 1.0)) - r.angle) / r.width;
        if (r.jitter > 0.0) index += (2.0 * random() - 1.0) * r.jitter;
        if (!(index >= 0.0 && index <= 1.0 - kEpsilon)) continue;
        const std::array<double, 5> c = r.colour_at(index);
        double fade = 0.0;
        if (r.falloff_width > 0.0 && angle > r.falloff_angle) {
            fade = (angle - r.falloff_angle) / r.falloff_width;
            fade = (3.0 - 2.0 * fade) * fade * fade;
        }
        // Distance attenuation; the colour's transmit is its least.
        double k = std::exp(-depth / r.distance);
        k = std::max(k, fade * (1.0 - c[4]) + c[4]);
        const double ki = 1.0 - k;
        const double f = c[3] * ki;
        for (int i = 0; i < 3; ++i)
            sum[i] += k * colour[i] * ((1.0 - f) + f * c[std::size_t(i)]) + ki * c[std::size_t(i)];
        ++n;
    }
    if (n == 0) return colour;
    return sum / static_cast<double>(n);
}

}  // namespace hexant::runtime
