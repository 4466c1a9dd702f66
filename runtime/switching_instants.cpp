#include "runtime/switching_instants.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include "runtime/time_ops.hpp"
#include "runtime/time_tape.hpp"

namespace hexant::runtime {

namespace {

// Splits time into pieces where a label is constant: the condition's truth
// (truth mode), or the function's value (a step function).
class Splitter {
public:
    Splitter(const TimeFunction& condition, std::size_t max_pieces, bool truth)
        : truth_(truth),
          tape_(TimeTape::compile({condition})),
          intervals_(tape_.size()),
          points_(tape_.size()),
          max_pieces_(max_pieces),
          // About 2 x 64 halvings isolate one switch to neighbouring doubles
          // (a piece undecided on both sides of it costs twice); a margin of
          // two over that, for a condition of up to 16 operations; a longer
          // one gets fewer evaluations, so that the work (evaluations times
          // operations) is bounded: a condition that stays undecided spends
          // it all, about 0.5 s at the default 10^4 pieces in the release
          // build (a mutated condition of 256 operations took 9 s when the
          // budget counted evaluations only).
          max_evaluations_(256 * (max_pieces + 1) * 16 / std::max<std::size_t>(16, tape_.size())) {}

    void split(Interval t) {
        if (++evaluations_ > max_evaluations_) {
            // Where it was still undecided: the interval evaluation could
            // not tell the value there from the threshold (it changes
            // without end there, or stays within rounding of changing:
            // clock * clock > 0 near 0, where the square underflows).
            char where[64];
            std::snprintf(where, sizeof where, "%.17g", t.lo);
            throw LimitError(std::string(truth_ ? "a condition" : "a value") +
                             " that depends on clock could not be split into pieces of "
                             "constant value within " + std::to_string(max_evaluations_) +
                             " evaluations: near clock " + where +
                             " it changes without end, or stays within rounding of changing "
                             "(write it so that it is clearly one side there)");
        }
        if (const auto label = decide(t)) return push(t, *label);
        using interval_detail::next_up;
        // Three doubles or fewer: each decided by itself.
        if (next_up(next_up(t.lo)) >= t.hi) {
            for (double v = t.lo; v <= t.hi; v = next_up(v)) push(Interval(v, v), label_at(v));
            return;
        }
        const double m = t.mid();
        split({t.lo, m});
        split({next_up(m), t.hi});
    }

    // Each interval of the domain in turn (one does not continue the last).
    void split_all(const std::vector<Interval>& domain) {
        for (const Interval& t : domain) {
            if (t.is_empty()) continue;
            split(t);
            open_ = false;
        }
    }

    TruthPieces truth_result() {
        TruthPieces r;
        std::vector<Interval> yes, no;
        for (const auto& [piece, truth] : pieces_) (truth != 0.0 ? yes : no).push_back(piece);
        r.when_true = Lifetime::of(std::move(yes));
        r.when_false = Lifetime::of(std::move(no));
        r.instants = std::move(instants_);
        return r;
    }
    std::vector<ValuePiece> value_result() {
        std::vector<ValuePiece> r;
        for (const auto& [piece, value] : pieces_) r.push_back({piece, value});
        return r;
    }

private:
    // The label over all of t (truth: 1 or 0), or none: undecided.
    std::optional<double> decide(const Interval& t) {
        Interval v;
        tape_.evaluate(t, &v, intervals_.data());
        if (!truth_) return v.is_point() ? std::optional<double>(v.lo) : std::nullopt;
        if (v.lo > kPovEpsilon || v.hi < -kPovEpsilon) return 1.0;
        if (-kPovEpsilon <= v.lo && v.hi <= kPovEpsilon) return 0.0;
        return std::nullopt;
    }
    double label_at(double t) {
        double v;
        tape_.evaluate(t, &v, points_.data());
        return truth_ ? (pov_true(v) ? 1.0 : 0.0) : v;
    }
    void push(const Interval& t, double label) {
        if (open_ && !pieces_.empty() && pieces_.back().second == label) {
            pieces_.back().first.hi = t.hi;
            return;
        }
        if (open_ && !pieces_.empty()) instants_.push_back(t.lo);
        open_ = true;
        pieces_.push_back({t, label});
        if (instants_.size() > max_pieces_)
            throw LimitError(std::string(truth_ ? "a condition" : "a value") +
                             " that depends on clock changes more than " +
                             std::to_string(max_pieces_) +
                             " times over the animation (--max-time-pieces N raises the limit)");
    }

    bool truth_;
    TimeTape tape_;
    std::vector<Interval> intervals_;
    std::vector<double> points_;
    std::size_t max_pieces_;
    std::size_t max_evaluations_;
    std::size_t evaluations_ = 0;
    bool open_ = false;
    std::vector<std::pair<Interval, double>> pieces_;
    std::vector<double> instants_;
};

}  // namespace

TruthPieces split_by_truth(const TimeFunction& condition, const std::vector<Interval>& domain,
                           std::size_t max_pieces) {
    if (condition.is_constant()) {
        TruthPieces r;
        (pov_true(condition.constant()) ? r.when_true : r.when_false) = Lifetime::of(domain);
        (pov_true(condition.constant()) ? r.when_false : r.when_true) = Lifetime::never();
        return r;
    }
    Splitter splitter(condition, max_pieces, true);
    splitter.split_all(domain);
    return splitter.truth_result();
}

std::vector<ValuePiece> split_by_value(const TimeFunction& f, const std::vector<Interval>& domain,
                                       std::size_t max_pieces) {
    if (f.is_constant()) {
        std::vector<ValuePiece> r;
        for (const Interval& t : domain)
            if (!t.is_empty()) r.push_back({t, f.constant()});
        return r;
    }
    Splitter splitter(f, max_pieces, false);
    splitter.split_all(domain);
    return splitter.value_result();
}

}  // namespace hexant::runtime
