// Interval arithmetic: every operation's result holds the double result (and
// the long double one, nearer the truth) at random points of random argument
// intervals, over huge and tiny magnitudes; the trigonometric functions are
// tight over short intervals and exact at their extremes.
#include "runtime/time/interval.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

using hexant::runtime::Interval;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool has_nan(const Interval& x) {
    return std::isnan(x.lo) || std::isnan(x.hi);
}

// Random intervals of every scale: magnitudes from 1e-300 to 1e300, widths
// from a point to many times the magnitude, crossing zero or not.
class IntervalSource {
  public:
    explicit IntervalSource(std::uint64_t seed) : rng_(seed) {}

    double uniform(double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(rng_);
    }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

    // A number of magnitude 10^[lo_exp, hi_exp], either sign.
    double scaled(double lo_exp, double hi_exp) {
        const double v = std::pow(10.0, uniform(lo_exp, hi_exp));
        return integer(0, 1) ? v : -v;
    }

    Interval interval(double lo_exp, double hi_exp) {
        const double a = scaled(lo_exp, hi_exp);
        switch (integer(0, 4)) {
            case 0:
                return a;  // a point
            case 1: {      // short: a few ulps to 1e-6 relative
                const double w = std::fabs(a) * std::pow(10.0, uniform(-15, -6));
                return {a, a + w};
            }
            case 2: {  // of its own size
                const double b = a + std::fabs(a) * uniform(0.0, 3.0);
                return {a, b};
            }
            case 3: {  // crossing zero
                const double b = scaled(lo_exp, hi_exp);
                return {-std::fabs(a), std::fabs(b)};
            }
            default: {
                const double b = scaled(lo_exp, hi_exp);
                return {std::min(a, b), std::max(a, b)};
            }
        }
    }

    // Points inside x: both ends and random points between.
    std::vector<double> points(const Interval& x, int count) {
        std::vector<double> p{x.lo, x.hi};
        for (int i = 0; i < count; ++i) {
            const double u = uniform(0.0, 1.0);
            double v = x.lo + u * (x.hi - x.lo);
            if (!std::isfinite(v)) v = 0.5 * x.lo + 0.5 * x.hi;  // huge widths
            p.push_back(std::clamp(v, x.lo, x.hi));
        }
        return p;
    }

  private:
    std::mt19937_64 rng_;
};

struct Unary {
    std::string name;
    std::function<Interval(const Interval&)> bound;
    std::function<double(double)> point;
    std::function<long double(long double)> precise;
    double lo_exp, hi_exp;  // argument magnitudes
};

struct Binary {
    std::string name;
    std::function<Interval(const Interval&, const Interval&)> bound;
    std::function<double(double, double)> point;
    std::function<long double(long double, long double)> precise;
    double lo_exp, hi_exp;
};

std::vector<Unary> unary_operations() {
    using namespace hexant::runtime;
    return {
        {"-", [](auto& x) { return -x; }, [](double v) { return -v; },
         [](long double v) { return -v; }, -300, 300},
        {"abs", [](auto& x) { return abs(x); }, [](double v) { return std::fabs(v); },
         [](long double v) { return std::fabs(v); }, -300, 300},
        {"sqr", [](auto& x) { return sqr(x); }, [](double v) { return v * v; },
         [](long double v) { return v * v; }, -160, 160},
        {"sqrt", [](auto& x) { return sqrt(x); }, [](double v) { return std::sqrt(v); },
         [](long double v) { return std::sqrt(v); }, -300, 300},
        {"exp", [](auto& x) { return exp(x); }, [](double v) { return std::exp(v); },
         [](long double v) { return std::exp(v); }, -5, 2.9},
        {"log", [](auto& x) { return log(x); }, [](double v) { return std::log(v); },
         [](long double v) { return std::log(v); }, -300, 300},
        {"log10", [](auto& x) { return log10(x); }, [](double v) { return std::log10(v); },
         [](long double v) { return std::log10(v); }, -300, 300},
        {"sin", [](auto& x) { return sin(x); }, [](double v) { return std::sin(v); },
         [](long double v) { return std::sin(v); }, -10, 6},
        {"cos", [](auto& x) { return cos(x); }, [](double v) { return std::cos(v); },
         [](long double v) { return std::cos(v); }, -10, 6},
        {"tan", [](auto& x) { return tan(x); }, [](double v) { return std::tan(v); },
         [](long double v) { return std::tan(v); }, -10, 6},
        {"asin", [](auto& x) { return asin(x); }, [](double v) { return std::asin(v); },
         [](long double v) { return std::asin(v); }, -20, 0.1},
        {"acos", [](auto& x) { return acos(x); }, [](double v) { return std::acos(v); },
         [](long double v) { return std::acos(v); }, -20, 0.1},
        {"atan", [](auto& x) { return atan(x); }, [](double v) { return std::atan(v); },
         [](long double v) { return std::atan(v); }, -300, 300},
        {"floor", [](auto& x) { return floor(x); }, [](double v) { return std::floor(v); },
         [](long double v) { return std::floor(v); }, -5, 20},
        {"ceil", [](auto& x) { return ceil(x); }, [](double v) { return std::ceil(v); },
         [](long double v) { return std::ceil(v); }, -5, 20},
        {"trunc", [](auto& x) { return trunc(x); }, [](double v) { return std::trunc(v); },
         [](long double v) { return std::trunc(v); }, -5, 20},
    };
}

std::vector<Binary> binary_operations() {
    using namespace hexant::runtime;
    return {
        {"+", [](auto& a, auto& b) { return a + b; }, [](double a, double b) { return a + b; },
         [](long double a, long double b) { return a + b; }, -300, 300},
        {"-", [](auto& a, auto& b) { return a - b; }, [](double a, double b) { return a - b; },
         [](long double a, long double b) { return a - b; }, -300, 300},
        {"*", [](auto& a, auto& b) { return a * b; }, [](double a, double b) { return a * b; },
         [](long double a, long double b) { return a * b; }, -160, 160},
        {"/", [](auto& a, auto& b) { return a / b; }, [](double a, double b) { return a / b; },
         [](long double a, long double b) { return a / b; }, -150, 150},
        {"min", [](auto& a, auto& b) { return min(a, b); },
         [](double a, double b) { return a < b ? a : b; },
         [](long double a, long double b) { return a < b ? a : b; }, -300, 300},
        {"max", [](auto& a, auto& b) { return max(a, b); },
         [](double a, double b) { return a > b ? a : b; },
         [](long double a, long double b) { return a > b ? a : b; }, -300, 300},
        {"atan2", [](auto& a, auto& b) { return atan2(a, b); },
         [](double a, double b) { return std::atan2(a, b); },
         [](long double a, long double b) { return std::atan2(a, b); }, -300, 300},
        {"pow", [](auto& a, auto& b) { return pow(a, b); },
         [](double a, double b) { return std::pow(a, b); },
         [](long double a, long double b) { return std::pow(a, b); }, -3, 1.3},
    };
}

// Whether x holds the double v and the long double w (unless either is
// outside the domain, NaN).
bool holds(const Interval& x, double v, long double w) {
    if (!std::isnan(v) && !x.contains(v)) return false;
    if (!std::isnan(w) && !(x.lo <= w && w <= x.hi)) {
        // The long double result may lie beyond the double range.
        if (!(std::fabs(w) > std::numeric_limits<double>::max())) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("unary interval operations hold every point value", "[runtime][interval]") {
    IntervalSource source(11);
    long samples = 0;
    for (const Unary& op : unary_operations()) {
        INFO(op.name);
        for (int trial = 0; trial < 700; ++trial) {
            const Interval x = source.interval(op.lo_exp, op.hi_exp);
            const Interval r = op.bound(x);
            INFO(x << " -> " << r);
            REQUIRE_FALSE(has_nan(r));
            REQUIRE(r.lo <= r.hi);
            for (double v : source.points(x, 6)) {
                const double got = op.point(v);
                INFO(v << " -> " << got);
                REQUIRE(holds(r, got, op.precise(v)));
                ++samples;
            }
        }
    }
    CHECK(samples > 70000);
}

TEST_CASE("binary interval operations hold every point value", "[runtime][interval]") {
    IntervalSource source(12);
    long samples = 0;
    for (const Binary& op : binary_operations()) {
        INFO(op.name);
        for (int trial = 0; trial < 1500; ++trial) {
            const Interval a = source.interval(op.lo_exp, op.hi_exp);
            Interval b = source.interval(op.lo_exp, op.hi_exp);
            // pow: also whole exponents, the case negative bases need.
            if (op.name == "pow" && trial % 3 == 0) b = std::round(source.uniform(-6, 6));
            const Interval r = op.bound(a, b);
            INFO(a << " op " << b << " -> " << r);
            REQUIRE_FALSE(has_nan(r));
            REQUIRE(r.lo <= r.hi);
            const auto pa = source.points(a, 3), pb = source.points(b, 3);
            for (double u : pa) {
                for (double v : pb) {
                    const double got = op.point(u, v);
                    INFO(u << " op " << v << " -> " << got);
                    REQUIRE(holds(r, got, op.precise(u, v)));
                    ++samples;
                }
            }
        }
    }
    CHECK(samples > 100000);
}

TEST_CASE("infinite and indeterminate ends give no NaN", "[runtime][interval]") {
    using namespace hexant::runtime;
    const Interval all = Interval::entire();
    const Interval inf{kInf, kInf}, zero{0.0, 0.0}, nan_point{std::nan("")};
    for (const Interval& x :
         {all, inf, zero, nan_point, Interval(-kInf, 0.0), Interval(0.0, kInf)}) {
        for (const Interval& y : {all, inf, zero, -inf, Interval(1.0, kInf)}) {
            INFO(x << " " << y);
            for (const Interval& r : {x + y, x - y, x * y, x / y, pow(x, y), atan2(x, y), min(x, y),
                                      sin(x), cos(x), tan(x), exp(x), log(x), sqrt(x), asin(x),
                                      acos(x), atan(x), sqr(x), log10(x), floor(x)}) {
                CHECK_FALSE(has_nan(r));
            }
        }
    }
    CHECK(nan_point.lo == -kInf);
    CHECK(nan_point.hi == kInf);
    // An overflowing end stays an upper bound of the true, finite value.
    const Interval big = exp(Interval(710.0, 711.0));
    CHECK(big.lo > 1e308);
    CHECK(big.lo < kInf);
    CHECK(big.hi == kInf);
}

TEST_CASE("sin and cos are tight over short intervals and exact at their extremes",
          "[runtime][interval]") {
    using namespace hexant::runtime;
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> position(-100.0, 100.0), exponent(-12.0, -1.0);
    for (int i = 0; i < 2000; ++i) {
        const double x = position(rng);
        const double w = std::pow(10.0, exponent(rng));
        const Interval s = sin(Interval(x, x + w)), c = cos(Interval(x, x + w));
        // Width is about |derivative| * width (plus the curvature, w^2 / 2).
        const double ds = std::max(std::fabs(std::cos(x)), std::fabs(std::cos(x + w)));
        const double dc = std::max(std::fabs(std::sin(x)), std::fabs(std::sin(x + w)));
        CHECK(s.width() <= ds * w + 0.5 * w * w + 1e-14);  // + 4 ulps each side
        CHECK(c.width() <= dc * w + 0.5 * w * w + 1e-14);  // + 4 ulps each side
    }
    for (double w : {6.2832, 7.0, 100.0, 1e10, kInf}) {
        const Interval s = sin(Interval(-1.0, -1.0 + w)), c = cos(Interval(0.3, 0.3 + w));
        CHECK(s.lo == -1.0);
        CHECK(s.hi == 1.0);
        CHECK(c.lo == -1.0);
        CHECK(c.hi == 1.0);
    }
    // A maximum inside reaches 1, a minimum -1; none inside stays well below.
    const double pi = 3.14159265358979323846;
    CHECK(sin(Interval(1.5, 1.6)).hi == 1.0);
    CHECK(sin(Interval(1.5 + 200 * pi, 1.6 + 200 * pi)).hi == 1.0);
    CHECK(sin(Interval(4.7, 4.8)).lo == -1.0);
    CHECK(cos(Interval(-0.1, 0.1)).hi == 1.0);
    CHECK(cos(Interval(3.1, 3.2)).lo == -1.0);
    CHECK(sin(Interval(0.1, 1.5)).hi < 0.99750);
    CHECK(sin(Interval(0.1, 1.5)).lo > 0.09983);
    CHECK(cos(Interval(0.1, 3.0)).hi < 0.99501);
    CHECK(cos(Interval(0.1, 3.0)).lo > -0.9899925);
}

TEST_CASE("interval special cases", "[runtime][interval]") {
    using namespace hexant::runtime;
    // Division by an interval holding 0.
    const Interval q = Interval(1.0, 2.0) / Interval(-1.0, 1.0);
    CHECK(q.lo == -kInf);
    CHECK(q.hi == kInf);
    // Even powers are not negative; odd ones keep their sign.
    CHECK(pow(Interval(-2.0, 3.0), 2.0).lo == 0.0);
    CHECK(pow(Interval(-2.0, 3.0), 2.0).hi == Approx(9.0));
    CHECK(pow(Interval(-2.0, 3.0), 3.0).lo == Approx(-8.0));
    CHECK(pow(Interval(-3.0, -2.0), -2.0).hi == Approx(0.25));
    CHECK(pow(Interval(-1.0, 2.0), -2.0).lo == Approx(0.25));
    CHECK(pow(Interval(-1.0, 2.0), -2.0).hi == kInf);
    CHECK(sqr(Interval(-2.0, 3.0)).lo == 0.0);
    // Outside the domain the argument is clamped.
    CHECK(sqrt(Interval(-1.0, 4.0)).lo == 0.0);
    CHECK(sqrt(Interval(-1.0, 4.0)).hi == Approx(2.0));
    CHECK(log(Interval(-1.0, 1.0)).lo == -kInf);
    CHECK(asin(Interval(-3.0, 3.0)).hi == Approx(std::asin(1.0)));
    // atan2 across the negative x axis is the whole circle; elsewhere tight.
    CHECK(atan2(Interval(-0.1, 0.1), Interval(-2.0, -1.0)).hi >= 3.14159265358979);
    CHECK(atan2(Interval(-0.1, 0.1), Interval(-2.0, -1.0)).lo <= -3.14159265358979);
    const Interval right = atan2(Interval(-0.1, 0.1), Interval(1.0, 2.0));
    CHECK(right.hi == Approx(std::atan2(0.1, 1.0)));
    CHECK(right.lo == Approx(std::atan2(-0.1, 1.0)));
    // Outward rounding: 0.1 + 0.2 holds the exact sum, which no double is.
    const Interval s = Interval(0.1) + Interval(0.2);
    CHECK(s.lo < s.hi);
    CHECK(s.lo <= 0.1 + 0.2);
    CHECK(s.hi >= 0.1 + 0.2);
    // Set operations.
    CHECK(hull(Interval(1, 2), Interval(4, 5)).width() == 4.0);
    CHECK(intersect(Interval(1, 2), Interval(4, 5)).is_empty());
    CHECK(intersect(Interval(1, 4), Interval(2, 5)).lo == 2.0);
    CHECK(Interval::entire().mid() == 0.0);
    CHECK(Interval(1.0, 3.0).mid() == 2.0);
}
