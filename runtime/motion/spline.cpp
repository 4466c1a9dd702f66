// POV-Ray 3.7's spline rules, written from its documented and observed
// behaviour (checked against `povray` 3.7.0.10, see
// tests/runtime/spline_test.cpp for the recorded values).
//
// Keys. Keys are inserted one at a time in the order written and kept sorted
// by t. A key whose t equals an existing key's t replaces that key's value,
// except when it equals the largest t so far: then POV-Ray 3.7 drops the new
// key (a quirk of its insertion code), so the first value given stays.
//
// Segment search. For a parameter p, let i be:
//   0            if p <= t[0],
//   n            if p >= t[n-1],
//   otherwise the first index with t[i] >= p (so 1 <= i <= n-1).
// Segment i runs from key i-1 to key i.
//
// linear_spline:    one key: that key everywhere. i == 0: first key; i == n:
//                   last key; otherwise the straight line through keys i-1, i.
// quadratic_spline: as linear at the ends and with two keys; otherwise the
//                   parabola through keys i-2, i-1, i (keys 0, 1, 2 for the
//                   first segment).
// natural_spline:   as linear at the ends; otherwise the natural cubic spline
//                   (second derivative 0 at both end keys) through all keys;
//                   with two keys this is the straight line.
// cubic_spline:     Catmull-Rom, which needs a key on each side of a segment:
//                   one key: that key; two keys: their average, for every p;
//                   p <= t[1]: key 1; p > t[n-2]: key n-2; otherwise the
//                   Hermite cubic on segment (i-1, i) whose end tangents are
//                   the averages of the neighbouring chord slopes.
// Outside the keys the value is held constant (no extrapolation).
#include "runtime/motion/spline.hpp"

#include <stdexcept>

namespace hexant::runtime {

namespace {

// POV-Ray's segment index (see the header comment).
std::size_t segment_end(const std::vector<Spline::Key>& keys, double p) {
    const std::size_t n = keys.size();
    if (n == 0 || p <= keys.front().t) return 0;
    if (p >= keys.back().t) return n;
    std::size_t lo = 0, hi = n - 1;  // keys[lo].t < p <= keys[hi].t
    while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (p > keys[mid].t)
            lo = mid;
        else
            hi = mid;
    }
    return hi;
}

double linear(const Spline::Key& a, const Spline::Key& b, int k, double p) {
    return a.value[k] + (p - a.t) * (b.value[k] - a.value[k]) / (b.t - a.t);
}

// The parabola through three keys, in Lagrange form.
double parabola(const Spline::Key& a, const Spline::Key& b, const Spline::Key& c, int k, double p) {
    const double la = (p - b.t) * (p - c.t) / ((a.t - b.t) * (a.t - c.t));
    const double lb = (p - a.t) * (p - c.t) / ((b.t - a.t) * (b.t - c.t));
    const double lc = (p - a.t) * (p - b.t) / ((c.t - a.t) * (c.t - b.t));
    return la * a.value[k] + lb * b.value[k] + lc * c.value[k];
}

// Catmull-Rom on the segment from keys[j] to keys[j+1] (needs j-1 and j+2).
double catmull_rom(const std::vector<Spline::Key>& keys, std::size_t j, int k, double p) {
    const Spline::Key& k0 = keys[j - 1];
    const Spline::Key& k1 = keys[j];
    const Spline::Key& k2 = keys[j + 1];
    const Spline::Key& k3 = keys[j + 2];
    const double dt = k2.t - k1.t;
    const double u = (p - k1.t) / dt;
    const double slope01 = (k1.value[k] - k0.value[k]) / (k1.t - k0.t);
    const double slope12 = (k2.value[k] - k1.value[k]) / dt;
    const double slope23 = (k3.value[k] - k2.value[k]) / (k3.t - k2.t);
    const double m1 = 0.5 * (slope01 + slope12) * dt;
    const double m2 = 0.5 * (slope12 + slope23) * dt;
    const double u2 = u * u, u3 = u2 * u;
    return k1.value[k] * (2 * u3 - 3 * u2 + 1) + k2.value[k] * (3 * u2 - 2 * u3) +
           m1 * (u3 - 2 * u2 + u) + m2 * (u3 - u2);
}

}  // namespace

Spline::Spline(SplineKind kind, std::vector<Key> keys, int dimensions)
    : kind_(kind), dimensions_(dimensions) {
    if (dimensions < 1 || dimensions > 5)
        throw std::invalid_argument("spline dimensions must be 1..5");
    // Insert in the order given, as POV-Ray's parser does.
    for (const Key& key : keys) {
        const std::size_t i = segment_end(keys_, key.t);
        if (i == keys_.size()) {
            if (!keys_.empty() && keys_.back().t == key.t) continue;  // POV-Ray drops it
            keys_.push_back(key);
        } else if (keys_[i].t == key.t) {
            keys_[i].value = key.value;
        } else {
            keys_.insert(keys_.begin() + static_cast<std::ptrdiff_t>(i), key);
        }
    }

    if (kind_ == SplineKind::Natural && keys_.size() >= 2) {
        // Second derivatives M with M[0] = M[n-1] = 0, from the tridiagonal
        // system h[i-1] M[i-1] + 2 (h[i-1] + h[i]) M[i] + h[i] M[i+1]
        //   = 6 (slope[i] - slope[i-1]),  i = 1 .. n-2.
        const std::size_t n = keys_.size();
        natural_second_derivatives_.assign(n, Vector5{});
        if (n >= 3) {
            std::vector<double> h(n - 1), diag(n), rhs(n);
            for (std::size_t i = 0; i + 1 < n; ++i) h[i] = keys_[i + 1].t - keys_[i].t;
            for (int k = 0; k < 5; ++k) {
                // Forward elimination.
                for (std::size_t i = 1; i + 1 < n; ++i) {
                    const double s0 = (keys_[i].value[k] - keys_[i - 1].value[k]) / h[i - 1];
                    const double s1 = (keys_[i + 1].value[k] - keys_[i].value[k]) / h[i];
                    diag[i] = 2 * (h[i - 1] + h[i]);
                    rhs[i] = 6 * (s1 - s0);
                    if (i > 1) {
                        const double f = h[i - 1] / diag[i - 1];
                        diag[i] -= f * h[i - 1];
                        rhs[i] -= f * rhs[i - 1];
                    }
                }
                // Back substitution.
                for (std::size_t i = n - 2; i >= 1; --i) {
                    natural_second_derivatives_[i][k] =
                        (rhs[i] - h[i] * natural_second_derivatives_[i + 1][k]) / diag[i];
                }
            }
        }
    }
}

Vector5 Spline::evaluate(double p) const {
    Vector5 v{};
    const std::size_t n = keys_.size();
    if (n == 0) return v;
    if (n == 1) return keys_.front().value;
    const std::size_t i = segment_end(keys_, p);

    if (kind_ == SplineKind::Cubic) {
        for (int k = 0; k < 5; ++k) {
            if (n == 2)
                v[k] = 0.5 * (keys_[0].value[k] + keys_[1].value[k]);
            else if (i < 2)
                v[k] = keys_[1].value[k];
            else if (i >= n - 1)
                v[k] = keys_[n - 2].value[k];
            else
                v[k] = catmull_rom(keys_, i - 1, k, p);
        }
        return v;
    }

    if (i == 0) return keys_.front().value;
    if (i >= n) return keys_.back().value;

    for (int k = 0; k < 5; ++k) {
        switch (kind_) {
            case SplineKind::Linear:
                v[k] = linear(keys_[i - 1], keys_[i], k, p);
                break;
            case SplineKind::Quadratic:
                if (n == 2)
                    v[k] = linear(keys_[0], keys_[1], k, p);
                else if (i > 1)
                    v[k] = parabola(keys_[i - 2], keys_[i - 1], keys_[i], k, p);
                else
                    v[k] = parabola(keys_[0], keys_[1], keys_[2], k, p);
                break;
            case SplineKind::Natural: {
                const Key& a = keys_[i - 1];
                const Key& b = keys_[i];
                const double h = b.t - a.t;
                const double ma = natural_second_derivatives_[i - 1][k];
                const double mb = natural_second_derivatives_[i][k];
                const double x = p - a.t;
                // Taylor form about key a: value, slope, M/2, third derivative / 6.
                const double slope = (b.value[k] - a.value[k]) / h - h * (2 * ma + mb) / 6;
                v[k] = a.value[k] + x * (slope + x * (ma / 2 + x * (mb - ma) / (6 * h)));
                break;
            }
            case SplineKind::Cubic:
                break;
        }
    }
    return v;
}

}  // namespace hexant::runtime
