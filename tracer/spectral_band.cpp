#include "tracer/spectral_band.hpp"

#include <algorithm>

namespace hexant::tracer {

namespace {

constexpr int kHuePoints = 74;  // 375, 380, ..., 740 nm
constexpr double kHueBase = 375.0, kHueStep = 5.0;

// POV-Ray 3.6's colour of a dispersion element at hc (0.03: violet,
// 0.964: red), each channel a parabola clipped at 0.
glm::dvec3 element_hue(double hc) {
    const auto square = [](double x) { return x * x; };
    const double b = std::max(0.0, 0.98 * (1.0 - square(4.0 * (hc - 0.28))));
    const double g = std::max(0.0, 0.97 * (1.1 - square(4.5 * (hc - 0.57))));
    double r = 1.15 - square(5.0 * (hc - 0.75));
    if (r < 0.0) r = 0.12 - square(4.0 * (hc - 0.12));
    return {std::max(0.0, r), g, b};
}

struct HueTable {
    std::array<glm::dvec3, kHuePoints> integral{};
    HueTable() {
        glm::dvec3 sum(0.0);
        for (int i = 0; i < kHuePoints; ++i) {
            sum += element_hue(0.03 + 0.934 * i / (kHuePoints - 1.0));
            integral[std::size_t(i)] = sum;
        }
        for (glm::dvec3& v : integral) v /= sum;
    }
};

}  // namespace

glm::dvec3 spectral_hue_integral(double nm) {
    static const HueTable table;
    double at = std::clamp((nm - kHueBase) / kHueStep, 0.0, kHuePoints - 1.0);
    const int i = std::min(static_cast<int>(at), kHuePoints - 2);
    at -= i;
    return (1.0 - at) * table.integral[std::size_t(i)] + at * table.integral[std::size_t(i + 1)];
}

}  // namespace hexant::tracer
