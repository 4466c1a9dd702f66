#include "runtime/motion/spline_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hexant::runtime {

namespace {

// Spline::evaluate computes each segment in at most ~20 rounded steps, so its
// error is at most gamma_k * F~ with k <= 20 (Higham, "Accuracy and Stability
// of Numerical Algorithms", ch. 3), where F~ is its formula evaluated on the
// magnitudes of every term. 64 eps = 128 unit roundoffs leaves ample room and
// is still 1.4e-14 relative: nothing next to a bound's slack.
constexpr double kRoundingFactor = 64.0 * std::numeric_limits<double>::epsilon();

// POV-Ray's segment index, as spline.cpp computes it.
std::size_t segment_end(const std::vector<double>& t, double p) {
    const std::size_t n = t.size();
    if (n == 0 || p <= t.front()) return 0;
    if (p >= t.back()) return n;
    std::size_t lo = 0, hi = n - 1;  // t[lo] < p <= t[hi]
    while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (p > t[mid])
            lo = mid;
        else
            hi = mid;
    }
    return hi;
}

Interval widen(const Interval& x, double by) {
    return {interval_detail::next_down(x.lo - by), interval_detail::next_up(x.hi + by)};
}

// The natural spline's second derivatives, computed exactly as Spline's
// constructor computes them (same operations in the same order, so the same
// doubles; tests/runtime/spline_bounds_test.cpp checks the values agree).
std::vector<Vector5> natural_second_derivatives(const std::vector<Spline::Key>& keys) {
    const std::size_t n = keys.size();
    std::vector<Vector5> m(n, Vector5{});
    if (n < 3) return m;
    std::vector<double> h(n - 1), diag(n), rhs(n);
    for (std::size_t i = 0; i + 1 < n; ++i) h[i] = keys[i + 1].t - keys[i].t;
    for (int k = 0; k < 5; ++k) {
        for (std::size_t i = 1; i + 1 < n; ++i) {
            const double s0 = (keys[i].value[k] - keys[i - 1].value[k]) / h[i - 1];
            const double s1 = (keys[i + 1].value[k] - keys[i].value[k]) / h[i];
            diag[i] = 2 * (h[i - 1] + h[i]);
            rhs[i] = 6 * (s1 - s0);
            if (i > 1) {
                const double f = h[i - 1] / diag[i - 1];
                diag[i] -= f * h[i - 1];
                rhs[i] -= f * rhs[i - 1];
            }
        }
        for (std::size_t i = n - 2; i >= 1; --i) m[i][k] = (rhs[i] - h[i] * m[i + 1][k]) / diag[i];
    }
    return m;
}

// The pieces' polynomials in u on their segment, and F~ for each (the
// magnitude sum that bounds Spline::evaluate's rounding there).
struct Polynomial {
    std::array<Interval, 4> c{};
    double magnitude = 0.0;
};

using I = Interval;

// linear(a, b): va + (p - ta) (vb - va) / (tb - ta) = va + u (vb - va).
Polynomial linear(double va, double vb) {
    return {{I(va), I(vb) - I(va), I(0.0), I(0.0)}, std::fabs(va) + std::fabs(vb - va)};
}

// The parabola through (ta, va), (tb, vb), (tc, vc) on the segment [t0, t1],
// from its Newton form va + (p - ta) F1 + (p - ta)(p - tb) F2.
Polynomial parabola(const Spline::Key& a, const Spline::Key& b, const Spline::Key& c, int k,
                    double t0, double t1) {
    const I va = a.value[k], vb = b.value[k], vc = c.value[k];
    const I f1 = (vb - va) / (I(b.t) - I(a.t));
    const I f12 = (vc - vb) / (I(c.t) - I(b.t));
    const I f2 = (f12 - f1) / (I(c.t) - I(a.t));
    const I h = I(t1) - I(t0), da = I(t0) - I(a.t), db = I(t0) - I(b.t);
    Polynomial poly;
    poly.c = {va + da * f1 + da * db * f2, h * (f1 + (da + db) * f2), sqr(h) * f2, I(0.0)};
    // Lagrange form as spline.cpp computes it: sum of |l_j| |v_j|.
    const auto reach = [&](double tm) { return std::max(std::fabs(t0 - tm), std::fabs(t1 - tm)); };
    const auto basis = [&](const Spline::Key& j, const Spline::Key& m, const Spline::Key& n) {
        return reach(m.t) * reach(n.t) / std::fabs((j.t - m.t) * (j.t - n.t));
    };
    poly.magnitude = basis(a, b, c) * std::fabs(a.value[k]) +
                     basis(b, a, c) * std::fabs(b.value[k]) +
                     basis(c, a, b) * std::fabs(c.value[k]);
    return poly;
}

// Catmull-Rom on keys j .. j+1 in Hermite form, as spline.cpp computes it.
Polynomial catmull_rom(const std::vector<Spline::Key>& keys, std::size_t j, int k) {
    const Spline::Key &k0 = keys[j - 1], &k1 = keys[j], &k2 = keys[j + 1], &k3 = keys[j + 2];
    const I v0 = k0.value[k], v1 = k1.value[k], v2 = k2.value[k], v3 = k3.value[k];
    const I dt = I(k2.t) - I(k1.t);
    const I s01 = (v1 - v0) / (I(k1.t) - I(k0.t));
    const I s12 = (v2 - v1) / dt;
    const I s23 = (v3 - v2) / (I(k3.t) - I(k2.t));
    const I m1 = I(0.5) * (s01 + s12) * dt;
    const I m2 = I(0.5) * (s12 + s23) * dt;
    Polynomial poly;
    poly.c = {v1, m1, I(3.0) * (v2 - v1) - I(2.0) * m1 - m2, I(2.0) * (v1 - v2) + m1 + m2};
    // Basis magnitudes on [0, 1]: 2u^3+3u^2+1 <= 6, 3u^2+2u^3 <= 5,
    // u^3+2u^2+u <= 4, u^3+u^2 <= 2.
    const double h = k2.t - k1.t;
    const double a01 = std::fabs(k1.value[k] - k0.value[k]) / std::fabs(k1.t - k0.t);
    const double a12 = std::fabs(k2.value[k] - k1.value[k]) / std::fabs(h);
    const double a23 = std::fabs(k3.value[k] - k2.value[k]) / std::fabs(k3.t - k2.t);
    poly.magnitude = 6 * std::fabs(k1.value[k]) + 5 * std::fabs(k2.value[k]) +
                     4 * 0.5 * (a01 + a12) * h + 2 * 0.5 * (a12 + a23) * h;
    return poly;
}

// The natural cubic on keys a .. b in Taylor form about a, as spline.cpp
// computes it: va + x (slope + x (ma / 2 + x (mb - ma) / (6 h))), x = h u.
Polynomial natural(const Spline::Key& a, const Spline::Key& b, int k, double ma, double mb) {
    const I va = a.value[k], vb = b.value[k];
    const I h = I(b.t) - I(a.t);
    const I slope = (vb - va) / h - h * (I(2.0) * I(ma) + I(mb)) / I(6.0);
    Polynomial poly;
    poly.c = {va, slope * h, I(0.5) * I(ma) * sqr(h), (I(mb) - I(ma)) * sqr(h) / I(6.0)};
    const double hd = b.t - a.t;
    const double am = std::fabs(ma), bm = std::fabs(mb);
    const double slope_magnitude = std::fabs(b.value[k] - a.value[k]) / hd + hd * (2 * am + bm) / 6;
    poly.magnitude =
        std::fabs(a.value[k]) + hd * (slope_magnitude + hd * (am / 2 + hd * (am + bm) / (6 * hd)));
    return poly;
}

// The range of the cubic over [a, b] from its Bernstein coefficients there,
// which hold the range and have the end values first and last. When an inner
// coefficient sticks out beyond the ends, halve and try again.
Interval bernstein_range(const std::array<Interval, 4>& c, double a, double b, int depth) {
    const I x = a, w = I(b) - I(a);
    // Taylor coefficients at a, scaled to s in [0, 1] (u = a + w s).
    const I d0 = ((c[3] * x + c[2]) * x + c[1]) * x + c[0];
    const I d1 = ((I(3.0) * c[3] * x + I(2.0) * c[2]) * x + c[1]) * w;
    const I d2 = (I(3.0) * c[3] * x + c[2]) * sqr(w);
    const I d3 = c[3] * sqr(w) * w;
    const I b1 = d0 + d1 / I(3.0);
    const I b2 = d0 + (I(2.0) * d1 + d2) / I(3.0);
    const I b3 = d0 + d1 + d2 + d3;
    const I ends = hull(d0, b3);
    const I all = hull(ends, hull(b1, b2));
    const double overshoot = (ends.lo - all.lo) + (all.hi - ends.hi);
    // An overshoot of a few ulps is rounding, not a sticking-out coefficient.
    if (depth == 0 || overshoot <= 1e-12 * (ends.width() + ends.magnitude())) return all;
    const double m = 0.5 * (a + b);
    return hull(bernstein_range(c, a, m, depth - 1), bernstein_range(c, m, b, depth - 1));
}

}  // namespace

Interval SplineBounds::cubic_range(const std::array<Interval, 4>& c, double u0, double u1) {
    // Split at the critical points (roots of the derivative, from the middle
    // coefficients) so that each stretch is monotone and its range lies at its
    // ends. An inexact root only costs a halving in bernstein_range.
    double splits[4];
    int count = 0;
    splits[count++] = u0;
    const double a = 3.0 * c[3].mid(), b = 2.0 * c[2].mid(), e = c[1].mid();
    double roots[2];
    int root_count = 0;
    if (a == 0.0) {
        if (b != 0.0) roots[root_count++] = -e / b;
    } else {
        const double disc = b * b - 4.0 * a * e;
        if (disc >= 0.0) {
            const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
            roots[root_count++] = q / a;
            if (q != 0.0) roots[root_count++] = e / q;
        }
    }
    if (root_count == 2 && roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    for (int i = 0; i < root_count; ++i)
        if (roots[i] > splits[count - 1] && roots[i] < u1) splits[count++] = roots[i];
    splits[count++] = u1;

    Interval range = bernstein_range(c, splits[0], splits[1], 3);
    for (int i = 1; i + 1 < count; ++i)
        range = hull(range, bernstein_range(c, splits[i], splits[i + 1], 3));
    return range;
}

SplineBounds::SplineBounds(const Spline& spline) {
    const std::vector<Spline::Key>& keys = spline.keys();
    const std::size_t n = keys.size();
    for (const Spline::Key& key : keys) t_.push_back(key.t);
    const std::vector<Vector5> second = spline.kind() == SplineKind::Natural
                                            ? natural_second_derivatives(keys)
                                            : std::vector<Vector5>();

    for (int k = 0; k < 5; ++k) {
        std::vector<Piece>& pieces = pieces_[k];
        pieces.assign(n + 1, Piece{});
        const auto hold = [&](std::size_t i, double v) {
            pieces[i].held = true;
            pieces[i].value = v;
            pieces[i].whole = v;
        };
        const auto set = [&](std::size_t i, const Polynomial& poly) {
            Piece& piece = pieces[i];
            piece.held = false;
            piece.c = poly.c;
            piece.rounding = kRoundingFactor * poly.magnitude;
            piece.whole = widen(cubic_range(poly.c, 0.0, 1.0), piece.rounding);
        };
        if (n == 0) continue;  // the value 0 everywhere
        if (n == 1) {
            for (std::size_t i = 0; i <= n; ++i) hold(i, keys[0].value[k]);
            continue;
        }
        if (spline.kind() == SplineKind::Cubic) {
            const double average = 0.5 * (keys[0].value[k] + keys[1].value[k]);
            for (std::size_t i = 0; i <= n; ++i) {
                if (n == 2)
                    hold(i, average);
                else if (i < 2)
                    hold(i, keys[1].value[k]);
                else if (i >= n - 1)
                    hold(i, keys[n - 2].value[k]);
                else
                    set(i, catmull_rom(keys, i - 1, k));
            }
            continue;
        }
        hold(0, keys.front().value[k]);
        hold(n, keys.back().value[k]);
        for (std::size_t i = 1; i < n; ++i) {
            const Spline::Key& a = keys[i - 1];
            const Spline::Key& b = keys[i];
            switch (spline.kind()) {
                case SplineKind::Linear:
                    set(i, linear(a.value[k], b.value[k]));
                    break;
                case SplineKind::Quadratic:
                    if (n == 2)
                        set(i, linear(a.value[k], b.value[k]));
                    else if (i > 1)
                        set(i, parabola(keys[i - 2], a, b, k, a.t, b.t));
                    else
                        set(i, parabola(keys[0], keys[1], keys[2], k, a.t, b.t));
                    break;
                case SplineKind::Natural:
                    set(i, natural(a, b, k, second[i - 1][k], second[i][k]));
                    break;
                case SplineKind::Cubic:
                    break;
            }
        }
    }
}

Interval SplineBounds::range(int component, const Interval& parameter) const {
    const std::vector<Piece>& pieces = pieces_[component];
    const std::size_t first = segment_end(t_, parameter.lo);
    const std::size_t last = segment_end(t_, parameter.hi);
    Interval range = pieces[first].whole;
    for (std::size_t i = first; i <= last; ++i) {
        const Piece& piece = pieces[i];
        if (piece.held || (first < i && i < last)) {
            range = hull(range, piece.whole);
            continue;
        }
        // Part of segment (t[i-1], t[i]); u = (p - t[i-1]) / h.
        const double t0 = t_[i - 1], t1 = t_[i];
        const Interval p{std::max(parameter.lo, t0), std::min(parameter.hi, t1)};
        const Interval u = (p - I(t0)) / (I(t1) - I(t0));
        const double u0 = std::max(u.lo, 0.0), u1 = std::min(u.hi, 1.0);
        if (u0 <= 0.0 && u1 >= 1.0) {
            range = hull(range, piece.whole);
            continue;
        }
        const Interval part = widen(cubic_range(piece.c, u0, std::max(u0, u1)), piece.rounding);
        range = i == first ? part : hull(range, part);
    }
    return range;
}

double SplineBounds::derivative(int component, double parameter) const {
    const std::size_t i = segment_end(t_, parameter);
    const Piece& piece = pieces_[component][i];
    if (piece.held) return 0.0;
    const double h = t_[i] - t_[i - 1];
    const double u = (parameter - t_[i - 1]) / h;
    const double c1 = piece.c[1].mid(), c2 = piece.c[2].mid(), c3 = piece.c[3].mid();
    return (c1 + u * (2.0 * c2 + 3.0 * c3 * u)) / h;
}

}  // namespace hexant::runtime
