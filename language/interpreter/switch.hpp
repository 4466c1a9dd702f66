// The Interpreter's #switch, #case, #range and #break.
// Part of the Interpreter (language/interpreter_state.hpp), whose end includes it.
#pragma once

#include "language/interpreter/reading.hpp"
#include "language/interpreter_state.hpp"

namespace hexant::language {

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::run_switch(ParseInput& in) {
    const auto opened = directive_position(in);
    if (!keyword(in, "switch")) return false;
    const TimeFunction value = timed_condition<Action, Control>(in, "#switch");
    switch_from<Item, Action, Control>(in, opened, value, skip_body<Control>(in), false, false);
    return true;
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
void Interpreter::switch_from(ParseInput& in, const p::position& opened, const TimeFunction& value,
                              Divider d, bool matched, bool executing) {
    for (;;) {
        const auto at = in.position();
        switch (d) {
            case Divider::Case:
            case Divider::Range: {
                TimeFunction hit;
                if (d == Divider::Case) {
                    // POV-Ray's: |value - case| < epsilon.
                    hit = TimeFunction::apply(runtime::TimeOp::Equal, value,
                                              timed_condition<Action, Control>(in, "#case"));
                } else {
                    values.open_frame();
                    read<grammar::range_header, Action, Control>(in);
                    auto r = values.close_frame();
                    try {
                        const TimeFunction lo = to_float(r[0], "the low end of #range");
                        const TimeFunction hi = to_float(r[1], "the high end of #range");
                        hit = TimeFunction::apply(
                            runtime::TimeOp::And,
                            TimeFunction::apply(runtime::TimeOp::GreaterEqual, value, lo),
                            TimeFunction::apply(runtime::TimeOp::LessEqual, value, hi));
                    } catch (const ValueError& e) {
                        fail(at, e);
                    }
                }
                // A clause that matches part of the time (once none before
                // it runs): the rest of the #switch once for each side.
                std::optional<bool> decided;
                runtime::TruthPieces pieces;
                if (hit.is_constant())
                    decided = runtime::pov_true(hit.constant());
                else if (!executing)
                    decided = whole_truth(pieces = split_domain(hit, at));
                if (!executing && !decided) {
                    split_time(in, at, hit, pieces, [&](bool taken) {
                        const Divider next =
                            taken ? run_body<Item, Action, Control>(in) : skip_body<Control>(in);
                        switch_from<Item, Action, Control>(in, opened, value, next,
                                                           matched || taken, taken);
                    });
                    return;
                }
                executing = executing || decided.value_or(false);
                if (executing) matched = true;
                d = executing ? run_body<Item, Action, Control>(in) : skip_body<Control>(in);
                break;
            }
            case Divider::Else:
                executing = !matched;
                d = executing ? run_body<Item, Action, Control>(in) : skip_body<Control>(in);
                break;
            case Divider::Break:
                if (executing) {
                    // Skip the remaining clauses up to #end.
                    do {
                        d = skip_body<Control>(in);
                    } while (d != Divider::End && d != Divider::None);
                    if (d != Divider::End) unclosed(opened, "#switch", d, in);
                    return;
                }
                d = skip_body<Control>(in);
                break;
            case Divider::End:
                return;
            default:
                unclosed(opened, "#switch", d, in);
        }
    }
}

}  // namespace hexant::language
