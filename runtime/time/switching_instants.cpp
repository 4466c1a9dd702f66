#include "runtime/time/switching_instants.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include "runtime/time/time_ops.hpp"
#include "runtime/time/time_tape.hpp"

namespace hexant::runtime {

namespace {

// Splits time into pieces where a label is constant: the condition's truth
// (TruthLabel), a step function's value (ValueLabel), or keys of several
// functions' values (KeyLabel). A labeller gives the label of a piece from
// the functions' interval ranges over it (none: undecided) and the label at
// one instant from their values there.
template <typename Labeller>
class Splitter {
  public:
    using Label = typename Labeller::Label;

    Splitter(const std::vector<TimeFunction>& functions, std::size_t max_pieces, Labeller labeller)
        : labeller_(std::move(labeller)),
          tape_(TimeTape::compile(functions)),
          ranges_scratch_(tape_.size()),
          points_(tape_.size()),
          point_ranges_(functions.size()),
          ranges_(functions.size()),
          values_(functions.size()),
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
            throw TimePiecesLimit(std::string(Labeller::kWhat) +
                                  " that depends on clock could not be split into pieces of "
                                  "constant value within " +
                                  std::to_string(max_evaluations_) + " evaluations: near clock " +
                                  where +
                                  " it changes without end, or stays within rounding of changing "
                                  "(write it so that it is clearly one side there)");
        }
        // The point evaluation's possible values over t (point_range.hpp).
        tape_.evaluate(PointRange(t), point_ranges_.data(), ranges_scratch_.data());
        for (std::size_t i = 0; i < ranges_.size(); ++i) ranges_[i] = point_ranges_[i].v;
        if (auto label = labeller_.decide(ranges_)) return push(t, std::move(*label));
        using interval_detail::next_up;
        // Three doubles or fewer: each decided by itself.
        if (next_up(next_up(t.lo)) >= t.hi) {
            for (double v = t.lo; v <= t.hi; v = next_up(v)) {
                tape_.evaluate(v, values_.data(), points_.data());
                push(Interval(v, v), labeller_.at(values_));
            }
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

    std::vector<std::pair<Interval, Label>>& pieces() { return pieces_; }
    std::vector<double>& instants() { return instants_; }

  private:
    void push(const Interval& t, Label label) {
        if (open_ && !pieces_.empty() && pieces_.back().second == label) {
            pieces_.back().first.hi = t.hi;
            return;
        }
        if (open_ && !pieces_.empty()) instants_.push_back(t.lo);
        open_ = true;
        pieces_.push_back({t, std::move(label)});
        if (instants_.size() > max_pieces_)
            throw TimePiecesLimit(
                std::string(Labeller::kWhat) + " that depends on clock changes more than " +
                std::to_string(max_pieces_) +
                " times over the animation (--max-time-pieces N raises the limit)");
    }

    Labeller labeller_;
    TimeTape tape_;
    std::vector<PointRange> ranges_scratch_;
    std::vector<double> points_;
    std::vector<PointRange> point_ranges_;
    std::vector<Interval> ranges_;
    std::vector<double> values_;
    std::size_t max_pieces_;
    std::size_t max_evaluations_;
    std::size_t evaluations_ = 0;
    bool open_ = false;
    std::vector<std::pair<Interval, Label>> pieces_;
    std::vector<double> instants_;
};

// POV-Ray's truth: |c| > 1e-10, decided where the whole range is one side.
struct TruthLabel {
    using Label = bool;
    static constexpr const char* kWhat = "a condition";
    std::optional<bool> decide(const std::vector<Interval>& r) const {
        if (r[0].lo > kPovEpsilon || r[0].hi < -kPovEpsilon) return true;
        if (-kPovEpsilon <= r[0].lo && r[0].hi <= kPovEpsilon) return false;
        return std::nullopt;
    }
    bool at(const std::vector<double>& v) const { return pov_true(v[0]); }
};

// A step function's value, decided where the range is one number.
struct ValueLabel {
    using Label = double;
    static constexpr const char* kWhat = "a value";
    std::optional<double> decide(const std::vector<Interval>& r) const {
        return r[0].is_point() ? std::optional<double>(r[0].lo) : std::nullopt;
    }
    double at(const std::vector<double>& v) const { return v[0]; }
};

// The keys of each function's value, joined; decided where each range's
// two ends have the same key (the keys are monotone: every value between
// has it too).
struct KeyLabel {
    using Label = std::string;
    static constexpr const char* kWhat = "a value";
    const KeyOf* key;
    std::optional<std::string> decide(const std::vector<Interval>& r) const {
        std::string joined;
        for (std::size_t i = 0; i < r.size(); ++i) {
            std::string k = (*key)(i, r[i].lo);
            if (!r[i].is_point() && (*key)(i, r[i].hi) != k) return std::nullopt;
            joined += k;
            joined += '\0';
        }
        return joined;
    }
    std::string at(const std::vector<double>& v) const {
        std::string joined;
        for (std::size_t i = 0; i < v.size(); ++i) {
            joined += (*key)(i, v[i]);
            joined += '\0';
        }
        return joined;
    }
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
    Splitter<TruthLabel> splitter({condition}, max_pieces, TruthLabel{});
    splitter.split_all(domain);
    TruthPieces r;
    std::vector<Interval> yes, no;
    for (const auto& [piece, truth] : splitter.pieces()) (truth ? yes : no).push_back(piece);
    r.when_true = Lifetime::of(std::move(yes));
    r.when_false = Lifetime::of(std::move(no));
    r.instants = std::move(splitter.instants());
    return r;
}

std::vector<ValuePiece> split_by_value(const TimeFunction& f, const std::vector<Interval>& domain,
                                       std::size_t max_pieces) {
    std::vector<ValuePiece> r;
    if (f.is_constant()) {
        for (const Interval& t : domain)
            if (!t.is_empty()) r.push_back({t, f.constant()});
        return r;
    }
    Splitter<ValueLabel> splitter({f}, max_pieces, ValueLabel{});
    splitter.split_all(domain);
    for (const auto& [piece, value] : splitter.pieces()) r.push_back({piece, value});
    return r;
}

std::vector<KeyPiece> split_by_key(const std::vector<TimeFunction>& functions,
                                   const std::vector<Interval>& domain, std::size_t max_pieces,
                                   const KeyOf& key) {
    std::vector<KeyPiece> r;
    if (functions.empty()) {
        for (const Interval& t : domain)
            if (!t.is_empty()) r.push_back({t});
        return r;
    }
    Splitter<KeyLabel> splitter(functions, max_pieces, KeyLabel{&key});
    splitter.split_all(domain);
    for (auto& [piece, label] : splitter.pieces()) r.push_back({piece});
    return r;
}

}  // namespace hexant::runtime
