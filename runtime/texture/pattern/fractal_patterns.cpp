// Fractal patterns (POV-Ray 3.7's pattern.cpp): mandel, julia and magnet,
// iterated in the x-y plane in double precision as POV-Ray iterates them,
// each coloured by its exterior and interior types (fractal_exterior_color,
// fractal_interior_color). The kinds' files (kinds/mandel.hpp, julia.hpp,
// magnet.hpp) say which of Values' slots hold what.
#include <array>
#include <cmath>

#include "runtime/texture/pattern/families.hpp"
#include "runtime/texture/pattern/kinds/julia.hpp"
#include "runtime/texture/pattern/kinds/magnet.hpp"
#include "runtime/texture/pattern/kinds/mandel.hpp"

namespace hexant::runtime::pattern {

namespace {

using kinds::FractalSlots;

// POV-Ray's FRACTAL_MAX_EXPONENT.
constexpr int kMaxExponent = 33;

// POV-Ray's BinomialCoefficients (InitializeBinomialCoefficients): row n
// holds C(n, k) for k = 0..n, each with the sign of i^k's real or
// imaginary part (negated where k & 2).
constexpr auto kBinomials = [] {
    std::array<int, (kMaxExponent + 1) * (kMaxExponent + 2) / 2> c{};
    std::size_t at = 0;
    c[at++] = 1;
    for (std::size_t n = 1; n <= kMaxExponent; ++n) {
        c[at++] = 1;
        for (std::size_t k = 1; k < n; ++k, ++at) c[at] = c[at - (n + 1)] + c[at - n];
        c[at++] = 1;
    }
    at = 1;
    for (std::size_t m = 1; m <= kMaxExponent; ++m) {
        ++at;
        for (std::size_t k = 1; k < m; ++k, ++at)
            if ((k & 2) != 0) c[at] = -c[at];
        if ((m & 2) != 0) c[at] = -c[at];
        ++at;
    }
    return c;
}();

// The iterations (POV-Ray: an unsigned int; hexant bounds it).
int iterations(const Values& v) {
    const double limit = v.number[FractalSlots::kIterations];
    return limit >= 1.0 ? (limit < 1.0e6 ? static_cast<int>(limit) : 1000000) : 0;
}

// fractal_exterior_color: the value of a point that escaped at iteration
// `iters` at (a, b).
double exterior_colour(const Values& v, int iters, double a, double b) {
    const double factor = v.more[FractalSlots::kExteriorFactor];
    switch (static_cast<int>(v.more[FractalSlots::kExteriorType])) {
        case 0:
            return factor;
        case 1:
            return static_cast<double>(iters) / static_cast<double>(iterations(v));
        case 2:
            return a * factor;
        case 3:
            return b * factor;
        case 4:
            return a * a * factor;
        case 5:
            return b * b * factor;
        case 6:
            return std::sqrt(a * a + b * b) * factor;
        case 7:
        case 8: {
            // iters % (unsigned)FACTOR / FACTOR, and % (unsigned)(1 + FACTOR)
            // for 8. (POV-Ray divides by zero where the divisor is 0;
            // hexant gives 0.)
            const double d = v.more[FractalSlots::kExteriorType] == 7.0 ? factor : 1.0 + factor;
            const auto m = static_cast<unsigned>(static_cast<long long>(d));
            if (m == 0) return 0.0;
            return static_cast<double>(static_cast<unsigned>(iters) % m) / factor;
        }
        default:
            return 0.0;
    }
}

// fractal_interior_color: the value of a point that never escaped, at
// (a, b) after the last iteration, mindist2 the least |z|^2 on the way.
double interior_colour(const Values& v, double a, double b, double mindist2) {
    const double factor = v.more[FractalSlots::kInteriorFactor];
    switch (static_cast<int>(v.more[FractalSlots::kInteriorType])) {
        case 0:
            return factor;
        case 1:
            return std::sqrt(mindist2) * factor;
        case 2:
            return a * factor;
        case 3:
            return b * factor;
        case 4:
            return a * a * factor;
        case 5:
            return b * b * factor;
        case 6:
            return a * a + b * b * factor;  // (POV-Ray's precedence, kept)
        default:
            return 0.0;
    }
}

// The loop every fractal pattern shares: `step` takes (a, b) and their
// squares to the next (a, b); a point escapes where `escaped(a, b2,
// dist2)`.
template <class Step, class Escaped>
double iterate(double a, double b, double mindist2, const Values& v, Step step, Escaped escaped) {
    const int it_max = iterations(v);
    double a2 = a * a, b2 = b * b;
    for (int col = 0; col < it_max; ++col) {
        step(a, b, a2, b2);
        a2 = a * a;
        b2 = b * b;
        const double dist2 = a2 + b2;
        if (dist2 < mindist2) mindist2 = dist2;
        if (escaped(a, b2, dist2)) return exterior_colour(v, col, a, b);
    }
    return interior_colour(v, a, b, mindist2);
}

bool beyond_two(double, double, double dist2) {
    return dist2 > 4.0;
}

// z^e + c, from a point z0 = (a, b) (mandel_pattern, mandel3_pattern,
// mandel4_pattern, mandelx_pattern; the julia ones with c fixed).
double power_fractal(double a, double b, double cr, double ci, int exponent, const Values& v) {
    const double mindist2 = a * a + b * b;
    switch (exponent) {
        case 3:
            return iterate(
                a, b, mindist2, v,
                [cr, ci](double& x, double& y, double x2, double y2) {
                    y = 3.0 * x2 * y - y2 * y + ci;
                    x = x2 * x - 3.0 * x * y2 + cr;
                },
                beyond_two);
        case 4:
            return iterate(
                a, b, mindist2, v,
                [cr, ci](double& x, double& y, double x2, double y2) {
                    y = 4.0 * (x2 * x * y - x * y2 * y) + ci;
                    x = x2 * x2 - 6.0 * x2 * y2 + y2 * y2 + cr;
                },
                beyond_two);
        default:
            break;
    }
    if (exponent > 4 && exponent <= kMaxExponent) {
        const int* c = &kBinomials[static_cast<std::size_t>((exponent + 1) * exponent / 2)];
        return iterate(
            a, b, mindist2, v,
            [cr, ci, exponent, c](double& x, double& y, double, double) {
                double new_a = std::pow(x, exponent);
                for (int k = 2; k <= exponent; k += 2)
                    new_a += c[k] * std::pow(x, exponent - k) * std::pow(y, k);
                double new_b = 0;
                for (int l = 1; l <= exponent; l += 2)
                    new_b += c[l] * std::pow(x, exponent - l) * std::pow(y, l);
                x = new_a + cr;
                y = new_b + ci;
            },
            beyond_two);
    }
    return iterate(
        a, b, mindist2, v,
        [cr, ci](double& x, double& y, double x2, double y2) {
            y = 2.0 * x * y + ci;
            x = x2 - y2 + cr;
        },
        beyond_two);
}

// The magnets' escape: far out, or at the fixed point 1.
bool magnet_escaped(double a, double b2, double dist2) {
    const double d = a - 1;
    return dist2 > 10000.0 || d * d + b2 < 1 / 10000.0;
}

// magnet1m_pattern, magnet1j_pattern: z = ((z^2 + c - 1) / (2z + c - 2))^2,
// written as POV-Ray writes it.
double magnet1(double a, double b, double cr, double ci, double mindist2, const Values& v) {
    return iterate(
        a, b, mindist2, v,
        [cr, ci](double& x, double& y, double x2, double y2) {
            const double tmp1r = x2 - y2 + cr - 1;
            const double tmp1i = 2 * x * y + ci;
            const double tmp2r = 2 * x + cr - 2;
            const double tmp2i = 2 * y + ci;
            const double tmp = tmp2r * tmp2r + tmp2i * tmp2i;
            x = (tmp1r * tmp2r + tmp1i * tmp2i) / tmp;
            y = (tmp1i * tmp2r - tmp1r * tmp2i) / tmp;
            const double bb = y * y;
            y = 2 * x * y;
            x = x * x - bb;
        },
        magnet_escaped);
}

// magnet2m_pattern, magnet2j_pattern: z = ((z^3 + 3(c - 1)z + (c - 1)(c -
// 2)) / (3z^2 + 3(c - 2)z + (c - 1)(c - 2) + 1))^2.
double magnet2(double a, double b, double cr, double ci, double mindist2, const Values& v) {
    const double c1r = cr - 1, c2r = cr - 2;
    const double c1c2r = c1r * c2r - ci * ci;
    const double c1c2i = (c1r + c2r) * ci;
    return iterate(
        a, b, mindist2, v,
        [=](double& x, double& y, double x2, double y2) {
            const double tmp1r = x2 * x - 3 * x * y2 + 3 * (x * c1r - y * ci) + c1c2r;
            const double tmp1i = 3 * x2 * y - y2 * y + 3 * (x * ci + y * c1r) + c1c2i;
            const double tmp2r = 3 * (x2 - y2) + 3 * (x * c2r - y * ci) + c1c2r + 1;
            const double tmp2i = 6 * x * y + 3 * (x * ci + y * c2r) + c1c2i;
            const double tmp = tmp2r * tmp2r + tmp2i * tmp2i;
            x = (tmp1r * tmp2r + tmp1i * tmp2i) / tmp;
            y = (tmp1i * tmp2r - tmp1r * tmp2i) / tmp;
            const double bb = y * y;
            y = 2 * x * y;
            x = x * x - bb;
        },
        magnet_escaped);
}

}  // namespace

double mandel_value(const glm::dvec3& p, const Values& v) {
    const int exponent = static_cast<int>(v.number[kinds::Mandel::kExponent]);
    return power_fractal(p.x, p.y, p.x, p.y, exponent, v);
}

double julia_value(const glm::dvec3& p, const Values& v) {
    const int exponent = static_cast<int>(v.number[kinds::Julia::kExponent]);
    return power_fractal(p.x, p.y, v.vector.x, v.vector.y, exponent, v);
}

double magnet_value(const glm::dvec3& p, const Values& v) {
    using M = kinds::Magnet;
    const int form = static_cast<int>(v.number[M::kForm]);
    const bool julia = form == M::kOneJulia || form == M::kTwoJulia;
    // The mandel forms start at 0 with c the point; the julia ones at the
    // point with c their <cr, ci>.
    const double a = julia ? p.x : 0.0, b = julia ? p.y : 0.0;
    const double cr = julia ? v.vector.x : p.x, ci = julia ? v.vector.y : p.y;
    const double mindist2 = julia ? a * a + b * b : 10000.0;
    return form == M::kOneMandel || form == M::kOneJulia ? magnet1(a, b, cr, ci, mindist2, v)
                                                         : magnet2(a, b, cr, ci, mindist2, v);
}

}  // namespace hexant::runtime::pattern
