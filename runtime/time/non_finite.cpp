#include "runtime/time/non_finite.hpp"

#include <cmath>
#include <vector>

#include "runtime/time/interval.hpp"
#include "runtime/time/time_tape.hpp"

namespace hexant::runtime {

namespace {

// Interval evaluations one search may spend: each suspect branch goes ~60
// halvings deep before its interval is a few doubles wide.
constexpr int kBudget = 4000;
// Doubles tried one by one in an interval this narrow.
constexpr int kLastDoubles = 16;

bool finite(const Interval& v) {
    return std::isfinite(v.lo) && std::isfinite(v.hi);
}
bool contains_zero(const Interval& v) {
    return v.lo <= 0.0 && v.hi >= 0.0;
}

// Whether an operation may leave its domain (or meet 0 times infinity)
// somewhere in its arguments' intervals, where the interval evaluator
// clamps instead of giving NaN.
bool may_leave_domain(TimeOp op, const Interval& a, const Interval& b) {
    switch (op) {
        case TimeOp::Sqrt:
            return a.lo < 0.0;
        case TimeOp::Ln:
        case TimeOp::Log10:
            return a.lo <= 0.0;
        case TimeOp::Asin:
        case TimeOp::Acos:
            return a.lo < -1.0 || a.hi > 1.0;
        case TimeOp::Pow:
            return (a.lo < 0.0 && !(b.is_point() && std::floor(b.lo) == b.lo)) ||
                   (contains_zero(a) && b.lo < 0.0);
        case TimeOp::Mod:
        case TimeOp::IntDiv:
        case TimeOp::Divide:
            return contains_zero(b);
        case TimeOp::Multiply:
            return (contains_zero(a) && !finite(b)) || (contains_zero(b) && !finite(a));
        default:
            return false;
    }
}

class Search {
  public:
    explicit Search(const TimeFunction& f)
        : tape_(TimeTape::compile({f})), slots_(tape_.size()), suspect_(tape_.size()) {}

    std::optional<double> first(double begin, double end) {
        if (const auto t = point(begin)) return t;
        return search(begin, end);
    }

  private:
    std::optional<double> point(double t) const {
        double out = 0.0;
        tape_.evaluate<double>(t, &out);
        if (std::isfinite(out)) return std::nullopt;
        return t;
    }

    // Whether [begin, end] may hold an instant: the output unbounded, or an
    // operation on the way out of its domain.
    bool suspect(double begin, double end) {
        Interval out(0.0);
        tape_.evaluate<Interval>(Interval(begin, end), &out, slots_.data());
        if (!finite(out)) return true;
        const auto& code = tape_.instructions();
        for (std::size_t i = 0; i < code.size(); ++i) {
            const auto& in = code[i];
            const int n = in.op == TimeOp::SplineComponent ? 1 : arity(in.op);
            bool s = false;
            if (n >= 1) s = s || suspect_[in.a];
            if (n >= 2) s = s || suspect_[in.b];
            if (n >= 3) s = s || suspect_[in.c];
            if (!s && n >= 1)
                s = may_leave_domain(in.op, slots_[in.a], n >= 2 ? slots_[in.b] : Interval(0.0));
            suspect_[i] = s;
        }
        return suspect_.back();
    }

    std::optional<double> search(double begin, double end) {
        if (++spent_ > kBudget || !suspect(begin, end)) return std::nullopt;
        const double middle = begin + (end - begin) / 2;
        if (middle <= begin || middle >= end || narrow(begin, end)) {
            double t = begin;
            for (int i = 0; i < kLastDoubles && t <= end; ++i, t = std::nextafter(t, end + 1.0))
                if (const auto found = point(t)) return found;
            return point(end);
        }
        if (const auto found = search(begin, middle)) return found;
        if (const auto found = point(middle)) return found;
        return search(middle, end);
    }

    static bool narrow(double begin, double end) {
        double t = begin;
        for (int i = 0; i < kLastDoubles; ++i) t = std::nextafter(t, end + 1.0);
        return t >= end;
    }

    TimeTape tape_;
    std::vector<Interval> slots_;
    std::vector<bool> suspect_;
    int spent_ = 0;
};

}  // namespace

std::optional<double> first_non_finite(const TimeFunction& f, double begin, double end) {
    if (f.is_constant()) {
        if (std::isfinite(f.constant())) return std::nullopt;
        return begin;
    }
    if (end < begin) std::swap(begin, end);
    return Search(f).first(begin, end);
}

}  // namespace hexant::runtime
