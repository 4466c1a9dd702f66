#include "runtime/time/lifetime.hpp"

#include <algorithm>
#include <sstream>

namespace hexant::runtime {

Lifetime Lifetime::of(std::vector<Interval> pieces) {
    Lifetime l;
    l.always_ = false;
    std::erase_if(pieces, [](const Interval& p) { return p.is_empty(); });
    std::sort(pieces.begin(), pieces.end(),
              [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
    for (const Interval& p : pieces) {
        // Overlapping, or touching with no double between them.
        if (!l.pieces_.empty() && p.lo <= interval_detail::next_up(l.pieces_.back().hi))
            l.pieces_.back().hi = std::max(l.pieces_.back().hi, p.hi);
        else
            l.pieces_.push_back(p);
    }
    return l;
}

bool Lifetime::contains(double t) const {
    if (always_) return true;
    // The first piece ending at or after t.
    const auto it = std::lower_bound(pieces_.begin(), pieces_.end(), t,
                                     [](const Interval& p, double v) { return p.hi < v; });
    return it != pieces_.end() && it->lo <= t;
}

bool Lifetime::holds_all(const Interval& t) const {
    if (always_) return true;
    const auto it = std::lower_bound(pieces_.begin(), pieces_.end(), t.lo,
                                     [](const Interval& p, double v) { return p.hi < v; });
    return it != pieces_.end() && it->lo <= t.lo && t.hi <= it->hi;
}

bool Lifetime::meets(const Interval& t) const {
    if (always_) return !t.is_empty();
    const auto it = std::lower_bound(pieces_.begin(), pieces_.end(), t.lo,
                                     [](const Interval& p, double v) { return p.hi < v; });
    return it != pieces_.end() && it->lo <= t.hi;
}

Lifetime Lifetime::intersect(const Lifetime& other) const {
    if (always_) return other;
    if (other.always_) return *this;
    std::vector<Interval> out;
    for (const Interval& a : pieces_)
        for (const Interval& b : other.pieces_) {
            const Interval c = runtime::intersect(a, b);
            if (!c.is_empty()) out.push_back(c);
        }
    return of(std::move(out));
}

std::vector<Interval> Lifetime::within(const Interval& range) const {
    if (always_) return {range};
    std::vector<Interval> out;
    for (const Interval& p : pieces_) {
        const Interval c = runtime::intersect(p, range);
        if (!c.is_empty()) out.push_back(c);
    }
    return out;
}

Lifetime Lifetime::complement_within(const Interval& range) const {
    if (always_) return never();
    std::vector<Interval> out;
    double from = range.lo;
    for (const Interval& p : pieces_) {
        if (p.hi < range.lo || p.lo > range.hi) continue;
        if (p.lo > from) out.push_back({from, interval_detail::next_down(p.lo)});
        from = interval_detail::next_up(p.hi);
    }
    if (from <= range.hi) out.push_back({from, range.hi});
    return of(std::move(out));
}

bool Lifetime::operator==(const Lifetime& other) const {
    if (always_ != other.always_) return false;
    if (pieces_.size() != other.pieces_.size()) return false;
    for (std::size_t i = 0; i < pieces_.size(); ++i)
        if (pieces_[i].lo != other.pieces_[i].lo || pieces_[i].hi != other.pieces_[i].hi)
            return false;
    return true;
}

std::string Lifetime::to_string() const {
    if (always_) return "always";
    if (pieces_.empty()) return "never";
    std::ostringstream out;
    out.precision(17);
    for (std::size_t i = 0; i < pieces_.size(); ++i)
        out << (i ? " u " : "") << '[' << pieces_[i].lo << ", " << pieces_[i].hi << ']';
    return out.str();
}

}  // namespace hexant::runtime
