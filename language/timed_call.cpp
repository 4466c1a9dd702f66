#include "language/timed_call.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "language/value_ops.hpp"
#include "runtime/time/limit_error.hpp"
#include "runtime/time/switching_instants.hpp"

namespace hexant::language {

using runtime::Interval;
using runtime::TimeOp;

namespace {

// What a function reads of an argument that is a number.
enum class Reads {
    Exact,      // the number itself (decided only where it is constant)
    Integer,    // its integer part (a length, a code, a position)
    Formatted,  // its text at the call's precision (str, vstr)
};

// The functions split here, and what each reads of argument i.
std::optional<Reads> reads(const std::string& name, std::size_t i) {
    if (name == "str") return i == 0 ? Reads::Formatted : Reads::Integer;
    if (name == "vstr") return i == 1 ? Reads::Formatted : Reads::Integer;
    if (name == "chr" || name == "substr") return Reads::Integer;
    static const std::set<std::string> strings = {"concat", "asc", "strlen", "strupr",
                                                  "strlwr", "val", "strcmp"};
    if (strings.count(name)) return Reads::Exact;
    return std::nullopt;
}

std::string exact_key(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

// One number of an argument that depends on clock: args[arg], or its
// component `component` (a vector's).
struct Leaf {
    std::size_t arg;
    int component;  // -1: a float
    Reads read;
    TimeFunction f;
};

}  // namespace

TimeFunction piecewise_constant(const std::vector<Interval>& times,
                                const std::vector<double>& values) {
    const auto build = [&](const auto& self, std::size_t first, std::size_t last) -> TimeFunction {
        if (last - first == 1) return values[first];
        const std::size_t middle = first + (last - first) / 2;
        const TimeFunction before =
            TimeFunction::apply(TimeOp::Less, TimeFunction::clock(), times[middle].lo);
        return TimeFunction::apply(TimeOp::Conditional, before, self(self, first, middle),
                                   self(self, middle, last));
    };
    if (times.empty()) return 0.0;
    return build(build, 0, times.size());
}

std::optional<Value> call_over_time(const std::string& name, const std::vector<Value>& args,
                                    const std::vector<Interval>& domain, std::size_t max_pieces,
                                    RandomStreams& random) {
    if (!reads(name, 0)) return std::nullopt;
    std::vector<Leaf> leaves;
    std::vector<std::size_t> strings;  // args that are TimedStrings
    for (std::size_t i = 0; i < args.size(); ++i) {
        const Reads read = *reads(name, i);
        if (args[i].is<TimedString>()) strings.push_back(i);
        if (args[i].is<TimeFunction>() && args[i].as<TimeFunction>().depends_on_time())
            leaves.push_back({i, -1, read, args[i].as<TimeFunction>()});
        if (args[i].is<Vector>()) {
            const Vector& v = args[i].as<Vector>();
            for (int c = 0; c < v.size; ++c)
                if (v.c[c].depends_on_time()) leaves.push_back({i, c, read, v.c[c]});
        }
    }
    if (leaves.empty() && strings.empty()) return std::nullopt;

    // The precision a formatted number is read at (str's third argument,
    // vstr's fifth), when it is one number; else the number exactly.
    std::optional<int> precision;
    const std::size_t precision_arg = name == "str" ? 2 : 4;
    if (precision_arg < args.size() && args[precision_arg].is<TimeFunction>() &&
        args[precision_arg].as<TimeFunction>().is_constant()) {
        const double p = args[precision_arg].as<TimeFunction>().constant();
        if (p >= -1.0e4 && p <= 100) precision = static_cast<int>(p);
    }
    const runtime::KeyOf key = [&](std::size_t which, double v) {
        switch (leaves[which].read) {
            case Reads::Integer:
                return exact_key(std::trunc(v));
            case Reads::Formatted:
                return precision ? format_number(v, 0, *precision) : exact_key(v);
            case Reads::Exact:
                break;
        }
        return exact_key(v);
    };
    std::vector<TimeFunction> functions;
    for (const Leaf& leaf : leaves) functions.push_back(leaf.f);

    // The domain cut where a string argument changes its text; then each
    // part cut where a number changes what is read of it.
    struct Part {
        Interval time;
        std::vector<std::string> texts;  // of the TimedString args, in order
    };
    std::vector<Part> parts;
    for (const Interval& t : domain)
        if (!t.is_empty()) parts.push_back({t, {}});
    for (const std::size_t i : strings) {
        const auto& pieces = args[i].as<TimedString>().pieces;
        std::vector<Part> cut;
        std::size_t a = 0, b = 0;
        while (a < parts.size() && b < pieces.size()) {
            const Interval both(std::max(parts[a].time.lo, pieces[b].time.lo),
                                std::min(parts[a].time.hi, pieces[b].time.hi));
            if (both.lo <= both.hi) {
                cut.push_back({both, parts[a].texts});
                cut.back().texts.push_back(pieces[b].text);
            }
            if (parts[a].time.hi < pieces[b].time.hi)
                ++a;
            else
                ++b;
        }
        parts = std::move(cut);
        if (parts.size() > max_pieces + 1)
            throw PiecewiseError(
                name + "() of strings that depend on clock changes more than " +
                std::to_string(max_pieces) +
                " times over the animation (--max-time-pieces N raises the limit)");
    }

    // The arguments each call reads, strings on clock replaced piece by
    // piece (copying them whole for every piece was quadratic).
    std::vector<Value> base = args;
    for (const std::size_t i : strings) base[i] = Value{std::string()};
    std::vector<Interval> times;
    std::vector<Value> results;
    for (const Part& part : parts) {
        std::vector<runtime::KeyPiece> pieces;
        try {
            pieces = runtime::split_by_key(functions, {part.time}, max_pieces, key);
        } catch (const runtime::TimePiecesLimit& e) {
            throw PiecewiseError("an argument of " + name + "(): " + e.what());
        } catch (const runtime::LimitError& e) {
            throw ValueError("an argument of " + name + "(): " + e.what());
        }
        for (const auto& piece : pieces) {
            // Any instant of the piece reads the same: its start.
            std::vector<Value> concrete = base;
            for (std::size_t s = 0; s < strings.size(); ++s)
                concrete[strings[s]] = Value{part.texts[s]};
            for (const Leaf& leaf : leaves) {
                const double v = leaf.f(piece.time.lo);
                if (leaf.component < 0)
                    concrete[leaf.arg] = Value{TimeFunction(v)};
                else
                    concrete[leaf.arg].as<Vector>().c[static_cast<std::size_t>(leaf.component)] = v;
            }
            times.push_back(piece.time);
            results.push_back(call_builtin(name, concrete, random));
            if (times.size() > max_pieces + 1)
                throw PiecewiseError(
                    name + "() of arguments that depend on clock changes more than " +
                    std::to_string(max_pieces) +
                    " times over the animation (--max-time-pieces N raises the limit)");
        }
    }
    if (results.empty())
        throw ValueError(name + "() of arguments that depend on clock, over no time");
    if (results.front().is<std::string>()) {
        std::vector<TimedString::Piece> pieces;
        for (std::size_t i = 0; i < results.size(); ++i)
            pieces.push_back({times[i], results[i].as<std::string>()});
        return timed_string(std::move(pieces));
    }
    std::vector<double> values;
    for (const Value& r : results) values.push_back(to_constant(r, name + "()'s result"));
    // Neighbours with one value are one piece.
    std::vector<Interval> merged_times;
    std::vector<double> merged;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!merged.empty() && merged.back() == values[i]) continue;
        merged_times.push_back(times[i]);
        merged.push_back(values[i]);
    }
    return Value{piecewise_constant(merged_times, merged)};
}

}  // namespace hexant::language
