// cells and crackle (POV-Ray 3.7's cells_pattern, crackle_pattern): a
// random value a unit cube; and cells around random points, one
// in each unit cube, the value a weighted sum (form) of the distances
// (metric) to the nearest three. The points are POV-Ray's: each cube's is
// its corner plus three entries of PatternRands, a table of 32,768 doubles
// from Boost's mt19937 with its default seed through uniform_real on [0, 1)
// (backend/support/randomsequences.cpp), picked by the noise's lattice hash.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "runtime/texture/pattern/families.hpp"

namespace hexant::runtime::pattern {

const std::vector<double>& pattern_rands() {
    static const std::vector<double> table = [] {
        std::mt19937 generator;  // default seed 5489, as boost::mt19937
        std::vector<double> out(32768);
        // boost::uniform_real<double>(0, 1): (x - min) / (max - min + 1).
        for (double& v : out) v = static_cast<double>(generator()) / 4294967296.0;
        return out;
    }();
    return table;
}

namespace {

// The 81 cubes within a "knight's move" (no more than one coordinate 2 away).
const std::vector<std::array<int, 3>>& neighbours() {
    static const std::vector<std::array<int, 3>> list = [] {
        std::vector<std::array<int, 3>> out;
        for (int x = -2; x <= 2; ++x)
            for (int y = -2; y <= 2; ++y)
                for (int z = -2; z <= 2; ++z)
                    if ((std::abs(x) == 2) + (std::abs(y) == 2) + (std::abs(z) == 2) <= 1)
                        out.push_back({x, y, z});
        return out;
    }();
    return list;
}

}  // namespace

double cells_value(const glm::dvec3& p, const Values&) {
    // One random value a unit cube (POV-Ray's cells_pattern).
    constexpr double kPovEpsilon = 1.0e-10;
    const double fx = std::floor(p.x + kPovEpsilon), fy = std::floor(p.y + kPovEpsilon),
                 fz = std::floor(p.z + kPovEpsilon);
    if (!(std::fabs(fx) < 1.0e9 && std::fabs(fy) < 1.0e9 && std::fabs(fz) < 1.0e9)) return 0.0;
    const int seed =
        lattice_hash3(static_cast<int>(fx), static_cast<int>(fy), static_cast<int>(fz));
    return std::min(pattern_rands()[static_cast<std::size_t>(seed)], 1.0);
}

double crackle_value(const glm::dvec3& p, const Values& v) {
    constexpr double kPovEpsilon = 1.0e-10;
    const double fx = std::floor(p.x - kPovEpsilon), fy = std::floor(p.y - kPovEpsilon),
                 fz = std::floor(p.z - kPovEpsilon);
    if (!(std::fabs(fx) < 1.0e9 && std::fabs(fy) < 1.0e9 && std::fabs(fz) < 1.0e9)) return 0.0;
    const int cx = static_cast<int>(fx), cy = static_cast<int>(fy), cz = static_cast<int>(fz);
    const std::vector<double>& rands = pattern_rands();
    const double metric = v.number[0], offset = v.number[1];
    const bool square = metric == 2.0, unity = metric == 1.0;
    const auto distance = [&](const glm::dvec3& d) {
        if (square) return d.x * d.x + d.y * d.y + d.z * d.z;
        if (unity) return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
        return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) +
               std::pow(std::fabs(d.z), metric);
    };
    double m1 = 0.0, m2 = 0.0, m3 = 0.0;
    glm::dvec3 nearest(0.0);
    std::array<glm::dvec3, 3> first{};
    int i = 0;
    for (const auto& n : neighbours()) {
        const int x = cx + n[0], y = cy + n[1], z = cz + n[2];
        const std::size_t seed =
            static_cast<std::size_t>(lattice_hash3(x & 0xFFF, y & 0xFFF, z & 0xFFF));
        const glm::dvec3 point(x + rands[seed], y + rands[seed + 1], z + rands[seed + 2]);
        const double sum = distance(point - p);
        if (i < 3) first[static_cast<std::size_t>(i)] = point;
        // The nearest three, kept as POV-Ray keeps them.
        if (i < 3) {
            (i == 0 ? m1 : i == 1 ? m2 : m3) = sum;
            if (i == 0) nearest = point;
            if (i == 2) {
                // (POV-Ray's first three sorted, the nearest's index kept.)
                if (m2 < m1) std::swap(m1, m2), nearest = first[1];
                if (m3 < m1) std::swap(m1, m3), nearest = point;
                if (m3 < m2) std::swap(m2, m3);
            }
        } else if (sum < m1) {
            m3 = m2;
            m2 = m1;
            m1 = sum;
            nearest = point;
        } else if (sum < m2) {
            m3 = m2;
            m2 = sum;
        } else if (sum < m3) {
            m3 = sum;
        }
        ++i;
    }
    if (offset != 0.0) {
        const double add = square ? offset * offset : unity ? offset : std::pow(offset, metric);
        m1 += add;
        m2 += add;
        m3 += add;
    }
    // solid: each cell the noise at its point (POV-Ray's IsSolid).
    if (v.more[0] != 0.0) return std::max(std::min(noise(nearest, v.noise_generator), 1.0), 0.0);
    const glm::dvec3 form = v.vector;
    double value;
    if (square)
        value = form.x * std::sqrt(m1) + form.y * std::sqrt(m2) + form.z * std::sqrt(m3);
    else if (unity)
        value = form.x * m1 + form.y * m2 + form.z * m3;
    else
        value = form.x * std::pow(m1, 1.0 / metric) + form.y * std::pow(m2, 1.0 / metric) +
                form.z * std::pow(m3, 1.0 / metric);
    return std::max(std::min(value, 1.0), 0.0);
}

}  // namespace hexant::runtime::pattern
