// Patterns of shapes in space (POV-Ray 3.7's pattern.cpp): planar,
// spherical, cylindrical and boxed (1 at the centre to 0 at 1), gradient,
// onion, radial, leopard, quilted, the spirals, marble and wood (bands
// bent by their own turbulence), waves and ripples (ten wave sources).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "runtime/texture/pattern/families.hpp"

namespace hexant::runtime::pattern {

namespace {

constexpr double kPi = 3.1415926535897932384626;
constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kHalfPi = 1.57079632679489661923;

// Classic turbulence's scalar sum times its x amount: how marble and the
// spirals bend their bands (0 without turbulence).
double turbulence_shift(const glm::dvec3& p, const Values& v) {
    if (!v.has_turbulence) return 0.0;
    return v.turbulence.x * turbulence(p, v.octaves, v.noise_generator);
}

// The angle about z from the y axis, POV-Ray's way (by asin, 0 at r = 0).
double spiral_angle(double x, double y, double r) {
    if (r == 0.0) return 0.0;
    return x < 0.0 ? 3.0 * kHalfPi - std::asin(y / r) : kHalfPi + std::asin(y / r);
}

// The wave sources of waves and ripples, as many as they may sum:
// directions from the vector noise at (i, 0, 0), frequencies from POV-Ray's
// generator (Initialize_Waves; the first N are the same for any count).
struct WaveSources {
    std::array<glm::dvec3, kMaxNumberOfWaves> at;
    std::array<double, kMaxNumberOfWaves> frequency;
    WaveSources() {
        std::uint32_t r = static_cast<std::uint32_t>(-560851967);
        for (int i = 0; i < kMaxNumberOfWaves; ++i) {
            at[static_cast<std::size_t>(i)] =
                glm::normalize(dnoise({static_cast<double>(i), 0.0, 0.0}));
            r = r * 1812433253u + 12345u;
            frequency[static_cast<std::size_t>(i)] =
                static_cast<double>((r >> 16) & 0x7FFF) * 0.000030518509476 + 0.01;
        }
    }
};
const WaveSources& sources() {
    static const WaveSources s;
    return s;
}

}  // namespace

const glm::dvec3& wave_source(std::size_t i) {
    return sources().at[i];
}
double wave_frequency(std::size_t i) {
    return sources().frequency[i];
}

double quilt_shape(double t, double control0, double control1) {
    // A cubic from 0 to 1 with control points control0 and control1,
    // scaled by 1 / sqrt(3/4) (quilt_cubic).
    const double it = 1.0 - t, it2 = it * it, t2 = t * t, t3 = t * t2;
    return (t3 + 3.0 * t * it2 * control0 + 3.0 * t2 * it * control1) * 1.15470053837925152902;
}

namespace {

double distance_or_one(const glm::dvec3& p, const glm::dvec3& q) {
    const glm::dvec3 d = p - q;
    const double l = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return l == 0.0 ? 1.0 : l;
}

}  // namespace

namespace {
// POV-Ray's CLIP_DENSITY: 1 at the centre falling to 0 at distance 1, 0
// beyond.
double density(double r) {
    return r < 0.0 ? 1.0 : r > 1.0 ? 0.0 : 1.0 - r;
}
}  // namespace

double planar_value(const glm::dvec3& p, const Values&) {
    return density(std::fabs(p.y));
}

double spherical_value(const glm::dvec3& p, const Values&) {
    return density(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z));
}

double cylindrical_value(const glm::dvec3& p, const Values&) {
    return density(std::sqrt(p.x * p.x + p.z * p.z));
}

double boxed_value(const glm::dvec3& p, const Values&) {
    return density(std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z))));
}

double gradient_value(const glm::dvec3& p, const Values& v) {
    const double r = p.x * v.vector.x + p.y * v.vector.y + p.z * v.vector.z;
    return r > 1.0 ? std::fmod(r, 1.0) : r;
}

double onion_value(const glm::dvec3& p, const Values&) {
    return std::fmod(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z), 1.0);
}

double radial_value(const glm::dvec3& p, const Values&) {
    if (std::fabs(p.x) < 0.001 && std::fabs(p.z) < 0.001) return 0.25;
    return 0.25 + (std::atan2(p.x, p.z) + kPi) / kTwoPi;
}

double leopard_value(const glm::dvec3& p, const Values&) {
    const double s = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3.0;
    return s * s;
}

double quilted_value(const glm::dvec3& p, const Values& v) {
    glm::dvec3 q(p.x - std::floor(p.x) - 0.5, p.y - std::floor(p.y) - 0.5,
                 p.z - std::floor(p.z) - 0.5);
    const double t =
        quilt_shape(std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z), v.number[0], v.number[1]);
    q *= t;
    return (std::fabs(q.x) + std::fabs(q.y) + std::fabs(q.z)) / 3.0;
}

double spiral1_value(const glm::dvec3& p, const Values& v) {
    const double shift = turbulence_shift(p, v);
    const double r = std::sqrt(p.x * p.x + p.y * p.y);
    return p.z + r + v.number[0] * spiral_angle(p.x, p.y, r) / kTwoPi + shift;
}

double spiral2_value(const glm::dvec3& p, const Values& v) {
    const double shift = turbulence_shift(p, v);
    const double r = std::sqrt(p.x * p.x + p.y * p.y);
    const double band =
        triangle_wave(p.z + r + v.number[0] * spiral_angle(p.x, p.y, r) / kTwoPi + shift);
    return triangle_wave(r) + band;
}

double marble_value(const glm::dvec3& p, const Values& v) {
    return p.x + turbulence_shift(p, v);
}

double wood_value(const glm::dvec3& p, const Values& v) {
    glm::dvec3 q(0.0);
    if (v.has_turbulence) {
        const glm::dvec3 d = dturbulence(p, v.octaves);
        q.x = cycloidal((p.x + d.x) * v.turbulence.x);
        q.y = cycloidal((p.y + d.y) * v.turbulence.y);
    }
    q.x += p.x;
    q.y += p.y;
    return std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
}

double waves_value(const glm::dvec3& p, const Values& v) {
    const WaveSources& s = sources();
    double sum = 0.0;
    const std::size_t n = static_cast<std::size_t>(v.number_of_waves);
    for (std::size_t i = 0; i < n; ++i) {
        const double index = distance_or_one(p, s.at[i]) * v.frequency * s.frequency[i] + v.phase;
        sum += cycloidal(index) / s.frequency[i];
    }
    return 0.2 * (2.5 + (sum / static_cast<double>(n)));
}

double ripples_value(const glm::dvec3& p, const Values& v) {
    const WaveSources& s = sources();
    double sum = 0.0;
    const std::size_t n = static_cast<std::size_t>(v.number_of_waves);
    for (std::size_t i = 0; i < n; ++i)
        sum += cycloidal(distance_or_one(p, s.at[i]) * v.frequency + v.phase);
    return 0.5 * (1.0 + (sum / static_cast<double>(n)));
}

}  // namespace hexant::runtime::pattern
