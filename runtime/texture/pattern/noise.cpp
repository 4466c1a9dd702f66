#include "runtime/texture/pattern/noise.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "runtime/texture/pattern/noise_table.hpp"

namespace hexant::runtime::pattern {

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;
// POV-Ray 3.7's EPSILON, used by the lattice rounding of negative
// coordinates (frame.h).
constexpr double kPovEpsilon = 1.0e-10;
constexpr int kLatticeOffset = 10000;  // MINX: keeps lattice indices positive
constexpr int kSolidEntries = 2048;    // the Perlin gradients
constexpr double kRollover = 10000000.023157213;

// POV-Ray's table generator: r = r * 1812433253 + 12345 (mod 2^32), each
// draw bits 16 to 30 of r.
struct Generator {
    std::uint32_t r;
    int next() {
        r = r * 1812433253u + 12345u;
        return static_cast<int>((r >> 16) & 0x7FFF);
    }
};

struct Tables {
    std::array<unsigned short, 8192> hash{};
    std::array<double, 2 * kNoiseTableSize> offsets{};  // each entry, then its half
    std::array<int, 2 * (kSolidEntries + 1)> permutation{};
    std::array<glm::dvec3, 2 * (kSolidEntries + 1)> gradients{};

    Tables() {
        // The lattice hash: a shuffle of 0..4095, then repeated.
        for (int i = 0; i < 4096; ++i)
            hash[static_cast<std::size_t>(i)] = static_cast<unsigned short>(i);
        Generator g{0};
        for (int i = 4095; i >= 0; --i) {
            const int j = g.next() % 4096;
            std::swap(hash[static_cast<std::size_t>(i)], hash[static_cast<std::size_t>(j)]);
        }
        for (std::size_t i = 0; i < 4096; ++i) hash[4096 + i] = hash[i];
        for (std::size_t i = 0; i < kNoiseTableSize; ++i) {
            offsets[2 * i] = kNoiseTable[i];
            offsets[2 * i + 1] = kNoiseTable[i] * 0.5;
        }
        // The Perlin gradients: directions drawn in the cube and kept in
        // the unit ball, normalized; then a shuffle of the indices.
        Generator s{1};
        for (int i = 0; i < kSolidEntries; ++i) {
            glm::dvec3 v;
            double len2;
            do {
                for (int j = 0; j < 3; ++j)
                    v[j] = static_cast<double>((s.next() % (kSolidEntries << 1)) - kSolidEntries) /
                           static_cast<double>(kSolidEntries);
                len2 = v.x * v.x + v.y * v.y + v.z * v.z;
            } while (len2 > 1.0 || len2 < 1.0e-5);
            const double k = 1.0 / std::sqrt(len2);
            v.x *= k;
            v.y *= k;
            v.z *= k;
            gradients[static_cast<std::size_t>(i)] = v;
        }
        for (int i = 0; i < kSolidEntries; ++i) permutation[static_cast<std::size_t>(i)] = i;
        for (int i = kSolidEntries; i > 0; i -= 2) {
            const int k = permutation[static_cast<std::size_t>(i)];
            const int j = s.next() % kSolidEntries;
            permutation[static_cast<std::size_t>(i)] = permutation[static_cast<std::size_t>(j)];
            permutation[static_cast<std::size_t>(j)] = k;
        }
        for (std::size_t i = 0; i < kSolidEntries + 2; ++i) {
            permutation[kSolidEntries + i] = permutation[i];
            gradients[kSolidEntries + i] = gradients[i];
        }
    }
};

const Tables& tables() {
    static const Tables t;
    return t;
}

// One coordinate's lattice cell: its index in the hash (0..4095) and the
// fraction within it. POV-Ray truncates through int; coordinates beyond
// int's range (where every double is an integer anyway) wrap the same way
// through a wider integer instead of overflowing.
struct Lattice {
    int index;
    double fraction;
};
Lattice lattice(double v) {
    const double cell = v >= 0.0 ? std::trunc(v) : std::trunc(v - (1.0 - kPovEpsilon));
    if (!(std::fabs(cell) < 4.0e18)) return {kLatticeOffset & 0xFFF, 0.0};  // NaN, inf, huge
    const long long c = static_cast<long long>(cell);
    return {static_cast<int>((c + kLatticeOffset) & 0xFFF), v - cell};
}

double scurve(double a) {
    return a * a * (3.0 - 2.0 * a);
}

// One corner's term: s * (m[1] + m[2] x + m[4] y + m[6] z), in POV-Ray's order.
double corner(const double* m, double s, double x, double y, double z) {
    return s * (m[1] + m[2] * x + m[4] * y + m[6] * z);
}

struct Cell {
    Lattice lx, ly, lz;
    double sx, sy, sz, tx, ty, tz;
    int h00, h10, h01, h11;  // hash of (ix, iy), (ix+1, iy), (ix, iy+1), (ix+1, iy+1)
};

Cell cell_of(const glm::dvec3& p) {
    const Tables& t = tables();
    Cell c;
    c.lx = lattice(p.x);
    c.ly = lattice(p.y);
    c.lz = lattice(p.z);
    c.sx = scurve(c.lx.fraction);
    c.sy = scurve(c.ly.fraction);
    c.sz = scurve(c.lz.fraction);
    c.tx = 1.0 - c.sx;
    c.ty = 1.0 - c.sy;
    c.tz = 1.0 - c.sz;
    const auto hash2 = [&](int a, int b) {
        return static_cast<int>(
            t.hash[static_cast<std::size_t>(t.hash[static_cast<std::size_t>(a)] ^ b)]);
    };
    c.h00 = hash2(c.lx.index, c.ly.index);
    c.h10 = hash2(c.lx.index + 1, c.ly.index);
    c.h01 = hash2(c.lx.index, c.ly.index + 1);
    c.h11 = hash2(c.lx.index + 1, c.ly.index + 1);
    return c;
}

const double* entry(int hash, int iz) {
    const Tables& t = tables();
    return &t.offsets[static_cast<std::size_t>(
        (t.hash[static_cast<std::size_t>(hash ^ iz)] & 0xFF) * 2)];
}

double original_noise(const glm::dvec3& p) {
    const Cell c = cell_of(p);
    const double x0 = c.lx.fraction, y0 = c.ly.fraction, z0 = c.lz.fraction;
    const double x1 = x0 - 1, y1 = y0 - 1, z1 = z0 - 1;
    const int iz = c.lz.index;
    const double txty = c.tx * c.ty, sxty = c.sx * c.ty, txsy = c.tx * c.sy, sxsy = c.sx * c.sy;
    double sum = corner(entry(c.h00, iz), txty * c.tz, x0, y0, z0);
    sum += corner(entry(c.h10, iz), sxty * c.tz, x1, y0, z0);
    sum += corner(entry(c.h01, iz), txsy * c.tz, x0, y1, z0);
    sum += corner(entry(c.h11, iz), sxsy * c.tz, x1, y1, z0);
    sum += corner(entry(c.h00, iz + 1), txty * c.sz, x0, y0, z1);
    sum += corner(entry(c.h10, iz + 1), sxty * c.sz, x1, y0, z1);
    sum += corner(entry(c.h01, iz + 1), txsy * c.sz, x0, y1, z1);
    sum += corner(entry(c.h11, iz + 1), sxsy * c.sz, x1, y1, z1);
    return sum;
}

double lerp(double t, double a, double b) {
    return a + t * (b - a);
}

double solid_noise(const glm::dvec3& p) {
    const Tables& t = tables();
    int b0[3], b1[3];
    double r0[3], r1[3];
    for (int i = 0; i < 3; ++i) {
        const double v = p[i] + kRollover;
        const double f = std::floor(v);
        // (int)floor as POV-Ray casts it; beyond int's range any wrap will do.
        const long long it = std::fabs(f) < 4.0e18 ? static_cast<long long>(f) : 0;
        b0[i] = static_cast<int>(it & (kSolidEntries - 1));
        b1[i] = (b0[i] + 1) & (kSolidEntries - 1);
        r0[i] = v - static_cast<double>(it);
        r1[i] = r0[i] - 1.0;
    }
    const auto perm = [&](int k) { return t.permutation[static_cast<std::size_t>(k)]; };
    const auto at = [&](int k, double rx, double ry, double rz) {
        const glm::dvec3& q = t.gradients[static_cast<std::size_t>(k)];
        return rx * q.x + ry * q.y + rz * q.z;
    };
    const int i = perm(b0[0]), j = perm(b1[0]);
    const int b00 = perm(i + b0[1]), b10 = perm(j + b0[1]), b01 = perm(i + b1[1]),
              b11 = perm(j + b1[1]);
    const double sx = scurve(r0[0]), sy = scurve(r0[1]), sz = scurve(r0[2]);
    double a = lerp(sx, at(b00 + b0[2], r0[0], r0[1], r0[2]), at(b10 + b0[2], r1[0], r0[1], r0[2]));
    double b = lerp(sx, at(b01 + b0[2], r0[0], r1[1], r0[2]), at(b11 + b0[2], r1[0], r1[1], r0[2]));
    const double c = lerp(sy, a, b);
    a = lerp(sx, at(b00 + b1[2], r0[0], r0[1], r1[2]), at(b10 + b1[2], r1[0], r0[1], r1[2]));
    b = lerp(sx, at(b01 + b1[2], r0[0], r1[1], r1[2]), at(b11 + b1[2], r1[0], r1[1], r1[2]));
    const double d = lerp(sy, a, b);
    return lerp(sz, c, d);
}

double clamp01(double v) {
    if (v < 0.0) v = 0.0;
    if (v > 1.0) v = 1.0;
    return v;
}

}  // namespace

double noise(const glm::dvec3& p, int generator) {
    if (generator == 3) return clamp01(0.5 * (1.59 * solid_noise(p) + 0.985));
    double sum = original_noise(p);
    if (generator == 2) {
        // POV-Ray's correction of the original's range (-1.05242 to 0.988997).
        sum += 1.05242;
        sum *= 0.48985582;
        return clamp01(sum);
    }
    return clamp01(sum + 0.5);
}

namespace {

double dscurve(double a) {
    return 6.0 * a * (1.0 - a);
}

// d/dp of original_noise (before its range correction and clamp).
glm::dvec3 original_gradient(const glm::dvec3& p) {
    const Cell c = cell_of(p);
    const double f[3] = {c.lx.fraction, c.ly.fraction, c.lz.fraction};
    const double s[3] = {c.sx, c.sy, c.sz};
    const double ds[3] = {dscurve(f[0]), dscurve(f[1]), dscurve(f[2])};
    const int hashes[2][2] = {{c.h00, c.h01}, {c.h10, c.h11}};  // [x side][y side]
    glm::dvec3 g(0.0);
    for (int hx = 0; hx < 2; ++hx)
        for (int hy = 0; hy < 2; ++hy)
            for (int hz = 0; hz < 2; ++hz) {
                const int side[3] = {hx, hy, hz};
                double w[3], dw[3], o[3];
                for (int k = 0; k < 3; ++k) {
                    w[k] = side[k] ? s[k] : 1.0 - s[k];
                    dw[k] = side[k] ? ds[k] : -ds[k];
                    o[k] = side[k] ? f[k] - 1.0 : f[k];
                }
                const double* m = entry(hashes[hx][hy], c.lz.index + hz);
                const double a = m[1] + m[2] * o[0] + m[4] * o[1] + m[6] * o[2];
                const double weight = w[0] * w[1] * w[2];
                g.x += dw[0] * w[1] * w[2] * a + weight * m[2];
                g.y += w[0] * dw[1] * w[2] * a + weight * m[4];
                g.z += w[0] * w[1] * dw[2] * a + weight * m[6];
            }
    return g;
}

// d/dp of solid_noise.
glm::dvec3 solid_gradient(const glm::dvec3& p) {
    const Tables& t = tables();
    int b[2][3];
    double r[2][3];
    for (int i = 0; i < 3; ++i) {
        const double v = p[i] + kRollover;
        const double f = std::floor(v);
        const long long it = std::fabs(f) < 4.0e18 ? static_cast<long long>(f) : 0;
        b[0][i] = static_cast<int>(it & (kSolidEntries - 1));
        b[1][i] = (b[0][i] + 1) & (kSolidEntries - 1);
        r[0][i] = v - static_cast<double>(it);
        r[1][i] = r[0][i] - 1.0;
    }
    const auto perm = [&](int k) { return t.permutation[static_cast<std::size_t>(k)]; };
    glm::dvec3 g(0.0);
    for (int hx = 0; hx < 2; ++hx)
        for (int hy = 0; hy < 2; ++hy)
            for (int hz = 0; hz < 2; ++hz) {
                const int side[3] = {hx, hy, hz};
                double w[3], dw[3], o[3];
                for (int k = 0; k < 3; ++k) {
                    const double sk = scurve(r[0][k]);
                    w[k] = side[k] ? sk : 1.0 - sk;
                    dw[k] = side[k] ? dscurve(r[0][k]) : -dscurve(r[0][k]);
                    o[k] = r[side[k]][k];
                }
                const int k = perm(perm(b[hx][0]) + b[hy][1]) + b[hz][2];
                const glm::dvec3& q = t.gradients[static_cast<std::size_t>(k)];
                const double a = o[0] * q.x + o[1] * q.y + o[2] * q.z;
                const double weight = w[0] * w[1] * w[2];
                g.x += dw[0] * w[1] * w[2] * a + weight * q.x;
                g.y += w[0] * dw[1] * w[2] * a + weight * q.y;
                g.z += w[0] * w[1] * dw[2] * a + weight * q.z;
            }
    return g;
}

}  // namespace

glm::dvec3 noise_gradient(const glm::dvec3& p, int generator) {
    if (generator == 3) {
        const double v = 0.5 * (1.59 * solid_noise(p) + 0.985);
        if (v < 0.0 || v > 1.0) return glm::dvec3(0.0);
        return solid_gradient(p) * (0.5 * 1.59);
    }
    double v = original_noise(p);
    v = generator == 2 ? (v + 1.05242) * 0.48985582 : v + 0.5;
    if (v < 0.0 || v > 1.0) return glm::dvec3(0.0);
    return original_gradient(p) * (generator == 2 ? 0.48985582 : 1.0);
}

double noise_slope_bound(int generator) {
    static const double original = [] {
        const Tables& t = tables();
        double linear = 0.0, slope = 0.0;
        for (int i = 0; i < 256; ++i) {
            const double* m = &t.offsets[static_cast<std::size_t>(i * 2)];
            linear = std::max(
                linear, std::fabs(m[1]) + std::fabs(m[2]) + std::fabs(m[4]) + std::fabs(m[6]));
            slope = std::max({slope, std::fabs(m[2]), std::fabs(m[4]), std::fabs(m[6])});
        }
        return 3.0 * linear + slope;
    }();
    // Solid noise: unit gradients, offsets within a unit cell (|o| <= sqrt 3).
    if (generator == 3) return 0.5 * 1.59 * (3.0 * std::sqrt(3.0) + 1.0);
    return original * (generator == 2 ? 0.48985582 : 1.0);
}

glm::dvec3 dnoise(const glm::dvec3& p) {
    const Cell c = cell_of(p);
    const double x0 = c.lx.fraction, y0 = c.ly.fraction, z0 = c.lz.fraction;
    const double x1 = x0 - 1, y1 = y0 - 1, z1 = z0 - 1;
    const int iz = c.lz.index;
    const double txty = c.tx * c.ty, sxty = c.sx * c.ty, txsy = c.tx * c.sy, sxsy = c.sx * c.sy;
    glm::dvec3 r(0.0);
    bool first = true;
    // POV-Ray's corner order for the vector noise; each component reads
    // the entries 8 further on.
    const auto add = [&](int hash, int z, double s, double x, double y, double zz) {
        const double* m = entry(hash, z);
        for (int k = 0; k < 3; ++k) {
            const double term = corner(m + 8 * k, s, x, y, zz);
            r[k] = first ? term : r[k] + term;
        }
        first = false;
    };
    add(c.h00, iz, txty * c.tz, x0, y0, z0);
    add(c.h10, iz, sxty * c.tz, x1, y0, z0);
    add(c.h11, iz, sxsy * c.tz, x1, y1, z0);
    add(c.h01, iz, txsy * c.tz, x0, y1, z0);
    add(c.h01, iz + 1, txsy * c.sz, x0, y1, z1);
    add(c.h11, iz + 1, sxsy * c.sz, x1, y1, z1);
    add(c.h10, iz + 1, sxty * c.sz, x1, y0, z1);
    add(c.h00, iz + 1, txty * c.sz, x0, y0, z1);
    return r;
}

double single(double v) {
    // Through a volatile: GCC 12.2 at -O2 vectorizes two neighbouring
    // double -> float -> double round trips into nothing (the pair came
    // back unrounded; tests/runtime/pattern_noise_test caught it).
    volatile float f = static_cast<float>(v);
    return f;
}

Octaves octaves_of(double octaves, double omega, double lambda) {
    Octaves o;
    o.octaves = !(octaves >= 1.0) ? 1 : octaves >= 10.0 ? 10 : static_cast<int>(octaves);
    o.omega = single(omega);
    o.lambda = single(lambda);
    return o;
}

double turbulence(const glm::dvec3& p, const Octaves& o, int generator) {
    const auto octave = [&](const glm::dvec3& q) {
        return generator > 1 ? 2.0 * noise(q, generator) - 0.5 : noise(q, generator);
    };
    double value = generator > 1 ? std::min(std::max(octave(p), 0.0), 1.0) : octave(p);
    double l = o.lambda, w = o.omega;
    for (int i = 2; i <= o.octaves; ++i) {
        value += w * octave(p * l);
        if (i < o.octaves) {
            l *= o.lambda;
            w *= o.omega;
        }
    }
    return value;
}

glm::dvec3 dturbulence(const glm::dvec3& p, const Octaves& o) {
    glm::dvec3 result = dnoise(p);
    double l = o.lambda, w = o.omega;
    for (int i = 2; i <= o.octaves; ++i) {
        const glm::dvec3 v = dnoise(p * l);
        result.x += w * v.x;
        result.y += w * v.y;
        result.z += w * v.z;
        if (i < o.octaves) {
            l *= o.lambda;
            w *= o.omega;
        }
    }
    return result;
}

int lattice_hash3(int a, int b, int c) {
    const auto& h = tables().hash;
    return h[static_cast<std::size_t>(
        h[static_cast<std::size_t>(h[static_cast<std::size_t>(a & 0xFFF)] ^ (b & 0xFFF))] ^
        (c & 0xFFF))];
}

double cycloidal(double v) {
    if (v >= 0.0) return std::sin((v - std::floor(v)) * 50000.0 / 50000.0 * kTwoPi);
    return 0.0 - std::sin((0.0 - (v + std::floor(0.0 - v))) * 50000.0 / 50000.0 * kTwoPi);
}

double triangle_wave(double v) {
    const double offset = v >= 0.0 ? v - std::floor(v) : v + 1.0 + std::floor(std::fabs(v));
    return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

}  // namespace hexant::runtime::pattern
