// The Interpreter's #while and #for: the condition read again at each turn, the body replayed from
// its stored source. Part of the Interpreter (language/interpreter_state.hpp), whose end includes
// it.
#pragma once

#include <sstream>

#include "language/interpreter/reading.hpp"
#include "language/interpreter_state.hpp"

namespace hexant::language {

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::run_while(ParseInput& in) {
    const auto opened = directive_position(in);
    if (!keyword(in, "while")) return false;
    const auto start = in.iterator();  // (a copy: the input moves on)
    while_from<Item, Action, Control>(in, opened, start, 0);
    return true;
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput, typename Iterator>
void Interpreter::while_from(ParseInput& in, const p::position& opened, const Iterator& start,
                             std::size_t count) {
    for (;; ++count) {
        in.iterator() = start;
        const auto at = in.position();
        const TimeFunction c = timed_condition<Action, Control>(in, "#while");
        // A condition on clock: the loop goes on only on the pieces where
        // it holds, turn by turn (objects that appear one by one).
        const auto turn = [&](bool go) {
            if (go && count >= options.limits.loop_iterations)
                fail(opened, "#while loop ran more than " +
                                 std::to_string(options.limits.loop_iterations) +
                                 " times; stopping (is its condition ever false? "
                                 "--max-loop-iterations N raises the limit)");
            if (go) count_step(opened);
            const Divider d = go ? run_body<Item, Action, Control>(in) : skip_body<Control>(in);
            if (d != Divider::End) unclosed(opened, "#while", d, in);
            if (go) count_text(static_cast<std::size_t>(in.current() - start.data), opened);
            return go;
        };
        bool go;
        if (c.is_constant()) {
            go = runtime::pov_true(c.constant());
        } else {
            const runtime::TruthPieces pieces = split_domain(c, at);
            if (const auto whole = whole_truth(pieces)) {
                go = *whole;  // the same all the domain's time: a plain turn
            } else {
                split_time(in, at, c, pieces, [&](bool on) {
                    if (turn(on)) while_from<Item, Action, Control>(in, opened, start, count + 1);
                });
                return;
            }
        }
        if (!turn(go)) return;
    }
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::run_for(ParseInput& in) {
    const auto opened = directive_position(in);
    if (!keyword(in, "for")) return false;
    values.open_frame();
    read<grammar::for_header, Action, Control>(in);
    std::vector<Value> bounds = values.close_frame();
    const std::string variable = values.pop_name();
    double from, step = 1.0;
    TimeFunction to;
    try {
        from = to_constant(bounds[0], "the start of #for");
        to = to_float(bounds[1], "the end of #for");
        if (bounds.size() > 2) step = to_constant(bounds[2], "the step of #for");
    } catch (const ValueError& e) {
        fail(opened, e);
    }
    if (step == 0.0) fail(opened, "#for with a step of 0 would never end");
    // A NaN bound ran no turn with no word where every other NaN is an
    // error at its place (issue 45); an infinite one would never end.
    if (!std::isfinite(from) || !std::isfinite(step) ||
        (to.is_constant() && !std::isfinite(to.constant()))) {
        std::ostringstream text;
        text << "#for needs finite bounds and step (start " << from << ", end ";
        if (to.is_constant())
            text << to.constant();
        else
            text << "on clock";
        text << ", step " << step << ")";
        fail(opened, text.str());
    }
    const auto start = in.iterator();
    for_from<Item, Action, Control>(in, opened, start, variable, from, step, to, 0);
    return true;
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput, typename Iterator>
void Interpreter::for_from(ParseInput& in, const p::position& opened, const Iterator& start,
                           const std::string& variable, double v, double step,
                           const TimeFunction& to, std::size_t count) {
    for (;; v += step) {
        // Goes on while v <= to (or >= for a negative step), within
        // POV-Ray's epsilon; an end on clock splits time turn by turn, as
        // a #while on clock does.
        const TimeFunction go =
            step > 0
                ? TimeFunction::apply(runtime::TimeOp::LessEqual, v, to + runtime::kPovEpsilon)
                : TimeFunction::apply(runtime::TimeOp::GreaterEqual, v, to - runtime::kPovEpsilon);
        const auto turn = [&](bool on) {
            // As in POV-Ray, the variable is left one step past the end.
            symbols.declare(variable, Value{TimeFunction(v)}, true);
            if (!on) {
                if (count == 0) {
                    const Divider d = skip_body<Control>(in);
                    if (d != Divider::End) unclosed(opened, "#for", d, in);
                }
                return false;
            }
            if (count + 1 > options.limits.loop_iterations)
                fail(opened, "#for loop ran more than " +
                                 std::to_string(options.limits.loop_iterations) +
                                 " times; stopping (--max-loop-iterations N raises the limit)");
            count_step(opened);
            in.iterator() = start;
            const Divider d = run_body<Item, Action, Control>(in);
            if (d != Divider::End) unclosed(opened, "#for", d, in);
            count_text(static_cast<std::size_t>(in.current() - start.data), opened);
            return true;
        };
        bool on;
        if (go.is_constant()) {
            on = runtime::pov_true(go.constant());
        } else {
            const runtime::TruthPieces pieces = split_domain(go, opened);
            if (const auto whole = whole_truth(pieces)) {
                on = *whole;
            } else {
                split_time(in, opened, go, pieces, [&](bool more) {
                    if (turn(more))
                        for_from<Item, Action, Control>(in, opened, start, variable, v + step, step,
                                                        to, count + 1);
                });
                return;
            }
        }
        if (!turn(on)) return;
        ++count;
    }
}

}  // namespace hexant::language
