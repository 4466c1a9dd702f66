// Ranges and derivatives of splines (SplineBounds) against Spline::evaluate
// itself: ranges hold dense samples and random points and are barely wider
// than what sampling finds; derivatives match finite differences.
#include "runtime/motion/spline_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "runtime/motion/spline.hpp"
#include "runtime/time/interval.hpp"

using hexant::runtime::Interval;
using hexant::runtime::Spline;
using hexant::runtime::SplineBounds;
using hexant::runtime::SplineKind;

namespace {

const SplineKind kKinds[] = {SplineKind::Linear, SplineKind::Quadratic, SplineKind::Cubic,
                             SplineKind::Natural};

const char* kind_name(SplineKind kind) {
    switch (kind) {
        case SplineKind::Linear:
            return "linear";
        case SplineKind::Quadratic:
            return "quadratic";
        case SplineKind::Cubic:
            return "cubic";
        case SplineKind::Natural:
            return "natural";
    }
    return "?";
}

// Random keys: 1 to 9 of them, spacing even or very uneven, values of a
// random scale, sometimes repeated parameters (POV-Ray replaces or drops).
Spline random_spline(SplineKind kind, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int n = std::uniform_int_distribution<int>(1, 9)(rng);
    const double scale = std::pow(10.0, 6.0 * unit(rng) - 3.0);
    const double offset = unit(rng) < 0.3 ? 1e3 * scale : 0.0;  // far from zero
    const bool uneven = unit(rng) < 0.4;
    std::vector<Spline::Key> keys;
    double t = 4.0 * unit(rng) - 2.0;
    for (int i = 0; i < n; ++i) {
        Spline::Key key{t, {}};
        for (double& v : key.value) v = offset + scale * (2.0 * unit(rng) - 1.0);
        keys.push_back(key);
        t += uneven ? std::pow(10.0, -3.0 * unit(rng)) : 0.2 + unit(rng);
        if (unit(rng) < 0.05) t = keys.back().t;  // a repeated parameter
    }
    std::shuffle(keys.begin(), keys.end(), rng);
    return Spline(kind, keys, 5);
}

// The parameters worth sampling near: the keys and a margin outside them.
std::pair<double, double> parameter_span(const Spline& spline) {
    if (spline.keys().empty()) return {-1.0, 1.0};
    return {spline.keys().front().t - 1.0, spline.keys().back().t + 1.0};
}

}  // namespace

TEST_CASE("spline ranges hold dense samples and are tight", "[runtime][spline]") {
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    long samples = 0, outside = 0, loose = 0;
    for (SplineKind kind : kKinds) {
        INFO(kind_name(kind));
        for (int s = 0; s < 50; ++s) {
            const Spline spline = random_spline(kind, rng);
            const SplineBounds bounds(spline);
            const auto [first, last] = parameter_span(spline);
            // The rounding scale: the largest key value.
            double largest = 0.0;
            for (const auto& key : spline.keys())
                for (double v : key.value) largest = std::max(largest, std::fabs(v));
            for (int trial = 0; trial < 12; ++trial) {
                double a = first + (last - first) * unit(rng);
                double b = first + (last - first) * unit(rng);
                if (trial % 4 == 0) b = a + (last - first) * 1e-4 * unit(rng);  // short
                if (trial % 6 == 1) b = a;                                      // a point
                if (a > b) std::swap(a, b);
                const Interval p{a, b};
                // Dense samples, the ends, every key inside, random points.
                std::vector<double> at{a, b};
                for (int i = 0; i <= 300; ++i) at.push_back(a + (b - a) * i / 300.0);
                for (int i = 0; i < 50; ++i) at.push_back(a + (b - a) * unit(rng));
                for (const auto& key : spline.keys())
                    if (p.contains(key.t)) at.push_back(key.t);
                // Dense in every segment too: segments may be much shorter
                // than the sampling step.
                const auto& keys = spline.keys();
                for (std::size_t i = 1; i < keys.size(); ++i) {
                    const double s0 = std::max(a, keys[i - 1].t), s1 = std::min(b, keys[i].t);
                    for (int j = 0; s0 < s1 && j <= 60; ++j)
                        at.push_back(s0 + (s1 - s0) * j / 60.0);
                }
                std::array<Interval, 5> range;
                std::array<double, 5> lo, hi;
                for (int k = 0; k < 5; ++k) {
                    range[k] = bounds.range(k, p);
                    lo[k] = INFINITY;
                    hi[k] = -INFINITY;
                }
                for (double x : at) {
                    const auto v = spline.evaluate(x);
                    for (int k = 0; k < 5; ++k) {
                        lo[k] = std::min(lo[k], v[k]);
                        hi[k] = std::max(hi[k], v[k]);
                        if (!range[k].contains(v[k])) {  // report failures only
                            ++outside;
                            INFO("p " << p << " component " << k << " at " << x << " value " << v[k]
                                      << " range " << range[k]);
                            CHECK(range[k].contains(v[k]));
                        }
                        ++samples;
                    }
                }
                for (int k = 0; k < 5; ++k) {
                    // Tight: beyond the sampled range by at most what the
                    // sampling step can miss, plus rounding.
                    const double slack = 0.01 * (hi[k] - lo[k]) + 1e-9 * largest;
                    const bool tight = range[k].lo >= lo[k] - slack && range[k].hi <= hi[k] + slack;
                    if (!tight) {
                        ++loose;
                        INFO("p " << p << " component " << k << " sampled [" << lo[k] << ", "
                                  << hi[k] << "] range " << range[k] << " keys "
                                  << spline.keys().size());
                        CHECK(tight);
                    }
                }
            }
        }
    }
    CHECK(outside == 0);
    CHECK(loose == 0);
    CHECK(samples > 1000000);
}

TEST_CASE("spline ranges over the whole line and far outside the keys", "[runtime][spline]") {
    const std::vector<Spline::Key> keys = {{0.0, {1.0}}, {1.0, {3.0}}, {2.0, {-1.0}}, {4.0, {2.0}}};
    for (SplineKind kind : kKinds) {
        INFO(kind_name(kind));
        const Spline spline(kind, keys, 1);
        const SplineBounds bounds(spline);
        // Held at the end keys (cubic: at the second and second-to-last).
        const double before = kind == SplineKind::Cubic ? 3.0 : 1.0;
        const double after = kind == SplineKind::Cubic ? -1.0 : 2.0;
        CHECK(bounds.range(0, Interval(-1e300, -5.0)).lo == before);
        CHECK(bounds.range(0, Interval(-1e300, -5.0)).hi == before);
        CHECK(bounds.range(0, Interval(7.0, INFINITY)).lo == after);
        CHECK(bounds.range(0, Interval(7.0, INFINITY)).hi == after);
        const Interval all = bounds.range(0, Interval::entire());
        for (int i = -100; i <= 600; ++i) CHECK(all.contains(spline.evaluate(i * 0.01)[0]));
        CHECK(all.width() < 10.0);
    }
    // No keys: zero; one key: that key.
    const Spline none(SplineKind::Cubic, {}, 1);
    CHECK(SplineBounds(none).range(0, Interval(-1, 1)).hi == 0.0);
    const Spline one(SplineKind::Natural, {{0.5, {7.0}}}, 1);
    CHECK(SplineBounds(one).range(0, Interval(-1, 1)).lo == 7.0);
    CHECK(SplineBounds(one).derivative(0, 0.3) == 0.0);
}

TEST_CASE("spline derivatives match finite differences", "[runtime][spline]") {
    std::mt19937_64 rng(22);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    long checked = 0;
    for (SplineKind kind : kKinds) {
        INFO(kind_name(kind));
        for (int s = 0; s < 80; ++s) {
            const Spline spline = random_spline(kind, rng);
            const SplineBounds bounds(spline);
            const auto [first, last] = parameter_span(spline);
            for (int trial = 0; trial < 40; ++trial) {
                const double p = first + (last - first) * unit(rng);
                // Keep the difference inside one piece: the pieces meet at
                // keys with only a continuous value (linear, quadratic).
                double gap = INFINITY;
                for (const auto& key : spline.keys()) gap = std::min(gap, std::fabs(key.t - p));
                // Small against the piece (truncation error ~ (h / gap)^2),
                // large against rounding (~ eps |value| / h).
                const double h = 1e-4 * std::min(gap, 1.0);
                if (h < 1e-10) continue;
                for (int k = 0; k < 5; ++k) {
                    const double fd =
                        (spline.evaluate(p + h)[k] - spline.evaluate(p - h)[k]) / (2.0 * h);
                    const double d = bounds.derivative(k, p);
                    const double scale = std::fabs(spline.evaluate(p)[k]);
                    INFO("p " << p << " component " << k << " h " << h);
                    CHECK(d == Approx(fd).epsilon(1e-6).margin(1e-13 * scale / h + 1e-12));
                    ++checked;
                }
            }
        }
    }
    CHECK(checked > 5000);
}

TEST_CASE("cubic ranges are exact up to rounding", "[runtime][spline]") {
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> coefficient(-10.0, 10.0), unit(0.0, 1.0);
    for (int trial = 0; trial < 3000; ++trial) {
        std::array<Interval, 4> c;
        for (Interval& x : c) x = coefficient(rng);
        if (trial % 5 == 0) c[3] = 0.0;  // quadratics
        double u0 = unit(rng), u1 = unit(rng);
        if (u0 > u1) std::swap(u0, u1);
        const Interval r = SplineBounds::cubic_range(c, u0, u1);
        // The true extremes: the ends and the derivative's real roots.
        std::vector<double> at{u0, u1};
        const double a = 3 * c[3].lo, b = 2 * c[2].lo, e = c[1].lo;
        const long double disc = (long double)b * b - 4.0L * a * e;
        if (a != 0 && disc >= 0) {
            for (int sign : {-1, 1}) {
                const double root = double((-b + sign * std::sqrt(disc)) / (2.0L * a));
                if (root > u0 && root < u1) at.push_back(root);
            }
        } else if (a == 0 && b != 0 && -e / b > u0 && -e / b < u1) {
            at.push_back(-e / b);
        }
        double lo = INFINITY, hi = -INFINITY;
        for (double u : at) {
            const long double v =
                c[0].lo + u * (c[1].lo + u * ((long double)c[2].lo + u * c[3].lo));
            lo = std::min(lo, double(v));
            hi = std::max(hi, double(v));
        }
        INFO("trial " << trial << " [" << u0 << ", " << u1 << "] sampled [" << lo << ", " << hi
                      << "] range " << r);
        const double tolerance = 1e-13 * (1.0 + std::max(std::fabs(lo), std::fabs(hi)));
        CHECK(r.lo <= lo + tolerance);
        CHECK(r.hi >= hi - tolerance);
        CHECK(r.lo >= lo - tolerance);
        CHECK(r.hi <= hi + tolerance);
    }
}
