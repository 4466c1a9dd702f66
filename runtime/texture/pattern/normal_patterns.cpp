// Normal perturbations (POV-Ray 3.7's normal.cpp): the normal-only
// patterns' own functions, and the slope of any other pattern's value.
#include <cmath>

#include "runtime/texture/pattern/families.hpp"

namespace hexant::runtime::pattern {

glm::dvec3 bumps_normal(const glm::dvec3& p, const Values&, double amount, const glm::dvec3& n) {
    return n + amount * dnoise(p);
}

glm::dvec3 dents_normal(const glm::dvec3& p, const Values& v, double amount, const glm::dvec3& n) {
    double k = noise(p, v.noise_generator);
    k = k * k * k * amount;
    return n + k * dnoise(p);
}

glm::dvec3 wrinkles_normal(const glm::dvec3& p, const Values&, double amount, const glm::dvec3& n) {
    glm::dvec3 sum(0.0);
    double scale = 1.0;
    for (int i = 0; i < 10; scale *= 2.0, ++i) {
        const glm::dvec3 d = dnoise(p * scale);
        sum.x += std::fabs(d.x / scale);
        sum.y += std::fabs(d.y / scale);
        sum.z += std::fabs(d.z / scale);
    }
    return n + amount * sum;
}

glm::dvec3 quilted_normal(const glm::dvec3& p, const Values& v, double amount,
                          const glm::dvec3& n) {
    glm::dvec3 q(p.x - std::floor(p.x) - 0.5, p.y - std::floor(p.y) - 0.5,
                 p.z - std::floor(p.z) - 0.5);
    const double t =
        quilt_shape(std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z), v.number[0], v.number[1]);
    return n + amount * (q * t);
}

glm::dvec3 ripples_normal(const glm::dvec3& p, const Values& v, double amount,
                          const glm::dvec3& n) {
    glm::dvec3 out = n;
    const std::size_t waves = static_cast<std::size_t>(v.number_of_waves);
    for (std::size_t i = 0; i < waves; ++i) {
        const glm::dvec3 d = p - wave_source(i);
        double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (length == 0.0) length = 1.0;
        const double scalar = cycloidal(length * v.frequency + v.phase) * amount;
        out += (scalar / (length * static_cast<double>(waves))) * d;
    }
    return out;
}

glm::dvec3 waves_normal(const glm::dvec3& p, const Values& v, double amount, const glm::dvec3& n) {
    glm::dvec3 out = n;
    const std::size_t waves = static_cast<std::size_t>(v.number_of_waves);
    for (std::size_t i = 0; i < waves; ++i) {
        const glm::dvec3 d = p - wave_source(i);
        double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (length == 0.0) length = 1.0;
        const double f = wave_frequency(i);
        const double scalar = cycloidal(length * v.frequency * f + v.phase) * amount / f;
        out += (scalar / (length * static_cast<double>(waves))) * d;
    }
    return out;
}

glm::dvec3 slope_normal(const Kind& kind, const glm::dvec3& point, const Values& values, Wave wave,
                        double exponent, double amount, double delta, const glm::dvec3& normal,
                        const std::vector<SlopeEntry>* slope_map) {
    // POV-Ray's Pyramid_Vect, with its digits.
    static const glm::dvec3 kPyramid[4] = {{0.942809041, -0.333333333, 0.0},
                                           {-0.471404521, -0.333333333, 0.816496581},
                                           {-0.471404521, -0.333333333, -0.816496581},
                                           {0.0, 1.0, 0.0}};
    const double weight = amount * -5.0 * (0.02 / delta);
    glm::dvec3 out = normal;
    for (const glm::dvec3& d : kPyramid) {
        const glm::dvec3 at(point.x + delta * d.x, point.y + delta * d.y, point.z + delta * d.z);
        double value = evaluate(kind, at, values, wave, exponent);
        if (slope_map != nullptr) value = slope_map_value(*slope_map, value);
        out += (value * weight) * d;
    }
    return out;
}

double slope_map_value(const std::vector<SlopeEntry>& map, double value) {
    if (map.empty()) return value;
    const BlendPick pick =
        search_blend_map(value, map.size(), [&](std::size_t i) { return map[i].value; });
    const SlopeEntry& cur = map[pick.cur];
    if (pick.prev == pick.cur) return cur.height;
    const SlopeEntry& prev = map[pick.prev];
    // (POV-Ray's Hermite_Cubic, its terms in its order.)
    const double t = pick.f, tt = t * t, ttt = tt * t;
    double r = ttt * (prev.slope + cur.slope + 2.0 * (prev.height - cur.height));
    r += -tt * (2.0 * prev.slope + cur.slope + 3.0 * (prev.height - cur.height));
    r += t * prev.slope + prev.height;
    return r;
}

}  // namespace hexant::runtime::pattern
