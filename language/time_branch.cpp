#include "language/time_branch.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <vector>

#include "language/value_ops.hpp"

namespace hexant::language {

using runtime::TimeOp;

namespace {

bool same_function(const TimeFunction& a, const TimeFunction& b) {
    if (a.is_constant() != b.is_constant()) return false;
    if (a.is_constant()) {
        const double x = a.constant(), y = b.constant();
        return x == y || (x != x && y != y);
    }
    return a.node() == b.node();
}

}  // namespace

namespace {

TimeFunction any_of(const std::vector<runtime::Interval>& pieces, std::size_t first,
                    std::size_t last) {
    if (last - first == 1) {
        const TimeFunction t = TimeFunction::clock();
        return TimeFunction::apply(TimeOp::And,
                                   TimeFunction::apply(TimeOp::GreaterEqual, t, pieces[first].lo),
                                   TimeFunction::apply(TimeOp::LessEqual, t, pieces[first].hi));
    }
    const std::size_t middle = first + (last - first) / 2;
    return TimeFunction::apply(TimeOp::Or, any_of(pieces, first, middle),
                               any_of(pieces, middle, last));
}

}  // namespace

TimeFunction indicator(const runtime::Lifetime& when) {
    if (when.is_always()) return 1.0;
    if (when.is_never()) return 0.0;
    return any_of(when.pieces(), 0, when.pieces().size());
}

bool same_value(const Value& a, const Value& b) {
    if (a.v.index() != b.v.index()) return false;
    if (a.is<TimeFunction>()) return same_function(a.as<TimeFunction>(), b.as<TimeFunction>());
    if (a.is<Vector>()) {
        const Vector &x = a.as<Vector>(), &y = b.as<Vector>();
        if (x.size != y.size) return false;
        for (int i = 0; i < x.size; ++i)
            if (!same_function(x.c[i], y.c[i])) return false;
        return true;
    }
    if (a.is<std::string>()) return a.as<std::string>() == b.as<std::string>();
    if (a.is<TimedString>()) return a.as<TimedString>() == b.as<TimedString>();
    if (a.is<runtime::ObjectPtr>()) return a.as<runtime::ObjectPtr>() == b.as<runtime::ObjectPtr>();
    if (a.is<std::shared_ptr<Array>>())
        return a.as<std::shared_ptr<Array>>() == b.as<std::shared_ptr<Array>>();
    if (a.is<std::shared_ptr<const runtime::Spline>>())
        return a.as<std::shared_ptr<const runtime::Spline>>() ==
               b.as<std::shared_ptr<const runtime::Spline>>();
    if (a.is<std::shared_ptr<const Macro>>())
        return a.as<std::shared_ptr<const Macro>>() == b.as<std::shared_ptr<const Macro>>();
    if (a.is<std::shared_ptr<const runtime::UserFunction>>())
        return a.as<std::shared_ptr<const runtime::UserFunction>>() ==
               b.as<std::shared_ptr<const runtime::UserFunction>>();
    return false;
}

Value during(const Value& value, const runtime::Lifetime& when) {
    if (when.is_always()) return value;
    if (value.is<runtime::ObjectPtr>()) {
        const runtime::ObjectPtr& object = value.as<runtime::ObjectPtr>();
        if (object->lifetime.intersect(when) == object->lifetime) return value;
        auto copy = std::make_shared<runtime::ObjectRecord>(*object);
        copy->lifetime = copy->lifetime.intersect(when);
        return Value{runtime::ObjectPtr(std::move(copy))};
    }
    if (value.is<runtime::LightRecord>()) {
        runtime::LightRecord light = value.as<runtime::LightRecord>();
        light.lifetime = light.lifetime.intersect(when);
        return Value{std::move(light)};
    }
    return value;
}

std::optional<Value> merge_sides(const std::string& name, const TimeFunction& condition,
                                 const std::optional<Value>& when_true,
                                 const runtime::Lifetime& true_pieces,
                                 const std::optional<Value>& when_false,
                                 const runtime::Lifetime& false_pieces) {
    // Undefined on one side: what the other side holds, there only (using
    // it on the other side is the scene's error, as in POV-Ray at that clock).
    if (!when_true && !when_false) return std::nullopt;
    if (!when_false) return during(*when_true, true_pieces);
    if (!when_true) return during(*when_false, false_pieces);
    const Value& a = *when_true;
    const Value& b = *when_false;
    if (same_value(a, b)) return a;
    const bool numbers =
        (a.is<TimeFunction>() || a.is<Vector>()) && (b.is<TimeFunction>() || b.is<Vector>());
    if (numbers) return conditional(Value{condition}, a, b);
    const auto is_string = [](const Value& v) {
        return v.is<std::string>() || v.is<TimedString>();
    };
    if (is_string(a) && is_string(b)) {
        // Each side's text on its own pieces (the sides' pieces are
        // disjoint, both within the time being read).
        const runtime::Interval any(-std::numeric_limits<double>::max(),
                                    std::numeric_limits<double>::max());
        std::vector<TimedString::Piece> pieces = string_pieces(a, true_pieces, any);
        for (auto& piece : string_pieces(b, false_pieces, any)) pieces.push_back(std::move(piece));
        std::sort(pieces.begin(), pieces.end(),
                  [](const TimedString::Piece& x, const TimedString::Piece& y) {
                      return x.time.lo < y.time.lo;
                  });
        return timed_string(std::move(pieces));
    }
    if (a.is<runtime::ObjectPtr>() && b.is<runtime::ObjectPtr>()) {
        // Both, each while its side holds: one of them at any instant.
        runtime::ObjectRecord both;
        runtime::Csg csg;
        csg.kind = runtime::Csg::Kind::Union;
        const runtime::ObjectPtr first = during(a, true_pieces).as<runtime::ObjectPtr>();
        const runtime::ObjectPtr second = during(b, false_pieces).as<runtime::ObjectPtr>();
        both.depth = std::max(first->depth, second->depth) + 1;
        both.objects = runtime::add_objects(first->objects, second->objects);
        both.place = first->place;
        csg.children = {first, second};
        both.shape = std::move(csg);
        return Value{runtime::ObjectPtr(std::make_shared<runtime::ObjectRecord>(std::move(both)))};
    }
    const auto a_or_an = [](const std::string& kind) {
        return (std::string("aeiou").find(kind.front()) != std::string::npos ? "an " : "a ") + kind;
    };
    if (a.v.index() != b.v.index() && !(is_string(a) && is_string(b)))
        throw ValueError(name + " is " + a_or_an(type_name(a)) +
                         " on one side of this clock-dependent "
                         "branch and " +
                         a_or_an(type_name(b)) +
                         " on the other; a name keeps one kind "
                         "of value across a branch on clock");
    throw PiecewiseError(
        name + " is a different " + type_name(a) +
        " on each side of this clock-dependent "
        "branch; hexant makes floats, vectors, strings and objects piecewise in time, not "
        "yet " +
        type_name(a) + "s");
}

}  // namespace hexant::language
