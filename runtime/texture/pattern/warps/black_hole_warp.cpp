#include "runtime/texture/pattern/warps/black_hole_warp.hpp"

#include <cmath>
#include <cstddef>
#include <limits>

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/noise.hpp"

namespace hexant::runtime::pattern {

namespace {

constexpr double kPovEpsilon = 1.0e-10;  // POV-Ray 3.7's EPSILON

// POV-Ray's Check_BH_Parameters for one axis: a repeated hole's centre at
// least its radius from 0, and the repeat at least as long as the centre
// plus radius plus the turbulence (its warnings aside).
void check_axis(BlackHoleAt& h, int i) {
    if (!(h.repeat[i] > 0.0)) return;
    if (h.center[i] < h.radius) h.center[i] = h.radius;
    if (h.repeat[i] < h.center[i] + h.radius + h.uncertainty[i])
        h.repeat[i] = h.center[i] + h.radius + h.uncertainty[i];
    if (h.repeat[i] < kPovEpsilon) h.repeat[i] = 0.0;
}

// (int)floor(v) as POV-Ray's x86 build does it: out of int's range (or
// NaN), INT_MIN.
int block_of(double v) {
    const double f = std::floor(v);
    return f >= -2147483648.0 && f < 2147483648.0 ? static_cast<int>(f)
                                                  : std::numeric_limits<int>::min();
}

}  // namespace

bool BlackHoleWarp::depends_on_time() const {
    if (center.depends_on_time() || radius.depends_on_time() || strength.depends_on_time() ||
        falloff.depends_on_time())
        return true;
    for (const Placement& p : placements)
        if (p.amount.depends_on_time()) return true;
    return false;
}

std::vector<TimeFunction> black_hole_numbers(const BlackHoleWarp& warp) {
    std::vector<TimeFunction> n = {warp.center.c[0], warp.center.c[1], warp.center.c[2],
                                   warp.radius,      warp.strength,    warp.falloff};
    for (const BlackHoleWarp::Placement& p : warp.placements)
        n.insert(n.end(), p.amount.c.begin(), p.amount.c.end());
    return n;
}

BlackHoleAt black_hole_at(const BlackHoleWarp& warp, const double* n) {
    BlackHoleAt h;
    h.center = {n[0], n[1], n[2]};
    h.radius = n[3];
    h.strength = n[4];
    h.power = n[5];
    h.inverse = warp.inverse;
    h.type = warp.type;
    const double* amount = n + 6;
    for (const BlackHoleWarp::Placement& p : warp.placements) {
        const glm::dvec3 v(amount[0], amount[1], amount[2]);
        amount += 3;
        if (p.repeat) {
            h.repeat = v;
            h.repeats = true;
        } else {
            h.uncertainty = v;
            h.uncertain = true;
        }
        if (h.repeats)
            for (int i = 0; i < 3; ++i) check_axis(h, i);
    }
    return h;
}

glm::dvec3 black_hole_point(const BlackHoleAt& h, const glm::dvec3& p) {
    glm::dvec3 c = h.center;
    if (h.repeats) {
        // The copy the point is in along each repeated axis (numbered from
        // 0), its centre moved by WarpRands (POV-Ray's PatternRands
        // sequence) picked by the copy's lattice hash.
        int block[3] = {0, 0, 0};
        for (int i = 0; i < 3; ++i)
            if (h.repeat[i] >= kPovEpsilon) block[i] = block_of(p[i] / h.repeat[i]);
        if (h.uncertain) {
            const auto seed = static_cast<std::size_t>(lattice_hash3(block[0], block[1], block[2]));
            const std::vector<double>& rands = pattern_rands();
            for (std::size_t i = 0; i < 3; ++i)
                c[static_cast<int>(i)] +=
                    rands[(seed + i) % rands.size()] * h.uncertainty[static_cast<int>(i)];
        }
        for (int i = 0; i < 3; ++i) c[i] += h.repeat[i] * block[i];
    }
    glm::dvec3 delta = p - c;
    const double length = std::sqrt(delta.x * delta.x + delta.y * delta.y + delta.z * delta.z);
    if (length >= h.radius || h.type != 0) return p;
    double s = std::pow((h.radius - length) / h.radius, h.power) * h.strength;
    if (s > 1.0) s = 1.0;
    delta *= h.inverse ? -s : s;
    return p + delta;
}

}  // namespace hexant::runtime::pattern
