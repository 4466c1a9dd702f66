#include "language/timed_string.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "language/value.hpp"
#include "language/value_ops.hpp"

namespace hexant::language {

std::size_t TimedString::longest() const {
    std::size_t n = 0;
    for (const auto& piece : pieces) n = std::max(n, piece.text.size());
    return n;
}

std::vector<std::pair<std::string, runtime::Lifetime>> TimedString::by_text() const {
    std::vector<std::pair<std::string, std::vector<runtime::Interval>>> groups;
    std::map<std::string, std::size_t> index;
    for (const auto& piece : pieces) {
        auto [it, added] = index.try_emplace(piece.text, groups.size());
        if (added) groups.push_back({piece.text, {}});
        groups[it->second].second.push_back(piece.time);
    }
    std::vector<std::pair<std::string, runtime::Lifetime>> out;
    for (auto& [text, times] : groups)
        out.push_back({text, runtime::Lifetime::of(std::move(times))});
    return out;
}

std::string TimedString::describe() const {
    constexpr std::size_t kShown = 4;
    std::string out;
    char at[64];
    for (std::size_t i = 0; i < pieces.size() && i < kShown; ++i) {
        if (i > 0) {
            std::snprintf(at, sizeof at, "%.17g", pieces[i].time.lo);
            out += std::string(i == 1 ? "" : ",") + " from clock " + at + " ";
        }
        out += "\"" + pieces[i].text + "\"";
    }
    if (pieces.size() > kShown) out += " ... (" + std::to_string(pieces.size()) + " pieces)";
    return out;
}

bool TimedString::operator==(const TimedString& other) const {
    if (pieces.size() != other.pieces.size()) return false;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const Piece &a = pieces[i], &b = other.pieces[i];
        if (a.time.lo != b.time.lo || a.time.hi != b.time.hi || a.text != b.text) return false;
    }
    return true;
}

Value timed_string(std::vector<TimedString::Piece> pieces) {
    TimedString s;
    for (auto& piece : pieces) {
        if (piece.time.is_empty()) continue;
        if (!s.pieces.empty()) {
            auto& last = s.pieces.back();
            const bool meet = piece.time.lo <= std::nextafter(last.time.hi, INFINITY);
            if (meet && last.text == piece.text) {
                last.time.hi = std::max(last.time.hi, piece.time.hi);
                continue;
            }
        }
        s.pieces.push_back(std::move(piece));
    }
    if (s.pieces.empty()) return Value{std::string()};
    const std::string& first = s.pieces.front().text;
    const bool one = std::all_of(s.pieces.begin(), s.pieces.end(),
                                 [&](const TimedString::Piece& p) { return p.text == first; });
    if (one) return Value{first};
    return Value{std::move(s)};
}

std::vector<TimedString::Piece> string_pieces(const Value& value, const runtime::Lifetime& when,
                                              const runtime::Interval& animation) {
    std::vector<TimedString::Piece> out;
    const std::vector<runtime::Interval> times = when.within(animation);
    if (value.is<std::string>()) {
        for (const auto& t : times) out.push_back({t, value.as<std::string>()});
        return out;
    }
    if (!value.is<TimedString>()) throw ValueError("a string is needed, not a " + type_name(value));
    // Both lists are sorted and disjoint: one pass.
    const auto& pieces = value.as<TimedString>().pieces;
    std::size_t i = 0, j = 0;
    while (i < pieces.size() && j < times.size()) {
        const runtime::Interval both(std::max(pieces[i].time.lo, times[j].lo),
                                     std::min(pieces[i].time.hi, times[j].hi));
        if (both.lo <= both.hi) out.push_back({both, pieces[i].text});
        if (pieces[i].time.hi < times[j].hi)
            ++i;
        else
            ++j;
    }
    return out;
}

}  // namespace hexant::language
