// The Interpreter's #if, #ifdef and #ifndef, and the split of the animation's time where a
// condition depends on clock. Part of the Interpreter (language/interpreter_state.hpp), whose end
// includes it.
#pragma once

#include <algorithm>
#include <cctype>
#include <string_view>

#include "language/array_index.hpp"
#include "language/interpreter/reading.hpp"
#include "language/interpreter_state.hpp"

namespace hexant::language {

template <template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
double Interpreter::condition(ParseInput& in, const char* directive) {
    const auto position = in.position();
    read<grammar::condition, Action, Control>(in);
    try {
        return to_constant(values.pop(), std::string("the condition of ") + directive);
    } catch (const ValueError& e) {
        fail(position, e);
    }
}

template <template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
TimeFunction Interpreter::timed_condition(ParseInput& in, const char* directive) {
    const auto position = in.position();
    read<grammar::condition, Action, Control>(in);
    try {
        return to_float(values.pop(), std::string("the condition of ") + directive);
    } catch (const ValueError& e) {
        fail(position, e);
    }
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::run_if(ParseInput& in) {
    const auto opened = directive_position(in);
    if (!keyword(in, "if")) return false;
    const auto at = in.position();
    if_chain<Item, Action, Control>(in, opened, at, timed_condition<Action, Control>(in, "#if"));
    return true;
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
void Interpreter::if_chain(ParseInput& in, const p::position& opened, const p::position& at,
                           const TimeFunction& c) {
    if (c.is_constant())
        return if_rest<Item, Action, Control>(in, opened, runtime::pov_true(c.constant()));
    const runtime::TruthPieces pieces = split_domain(c, at);
    if (const auto whole = whole_truth(pieces))
        return if_rest<Item, Action, Control>(in, opened, *whole);
    split_time(in, at, c, pieces,
               [&](bool taken) { if_rest<Item, Action, Control>(in, opened, taken); });
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
void Interpreter::if_rest(ParseInput& in, const p::position& opened, bool taken) {
    bool seen_else = false;
    for (;;) {
        if (taken && read_opening_branch<Item, Action, Control>(in, opened, "#if")) return;
        const Divider d = taken ? run_body<Item, Action, Control>(in) : skip_body<Control>(in);
        if (d == Divider::End) return;
        if (taken) {
            // The rest, up to #end, is skipped whatever it holds.
            if (d != Divider::Else && d != Divider::Elseif) unclosed(opened, "#if", d, in);
            if (d == Divider::Else && seen_else) unclosed(opened, "#if", d, in);
            Divider rest;
            do {
                rest = skip_body<Control>(in);
            } while (rest == Divider::Else || rest == Divider::Elseif);
            if (rest != Divider::End) unclosed(opened, "#if", rest, in);
            return;
        }
        if (d == Divider::Else) {
            if (seen_else) unclosed(opened, "#if", d, in);
            seen_else = true;
            taken = true;
            if (read_opening_branch<Item, Action, Control>(in, opened, "#if")) return;
            // After #else only #end may follow.
            const Divider last = run_body<Item, Action, Control>(in);
            if (last != Divider::End) unclosed(opened, "#if", last, in);
            return;
        }
        if (d == Divider::Elseif) {
            const auto at = in.position();
            const TimeFunction c = timed_condition<Action, Control>(in, "#elseif");
            // The rest of the chain splits the time this side holds.
            if (!c.is_constant()) return if_chain<Item, Action, Control>(in, opened, at, c);
            taken = runtime::pov_true(c.constant());
            continue;
        }
        unclosed(opened, "#if", d, in);
    }
}

template <typename ParseInput, typename Read>
void Interpreter::split_time(ParseInput& in, const p::position& at, const TimeFunction& c,
                             const runtime::TruthPieces& pieces, Read read) {
    // Each split re-reads its text once a side and nests the next inside
    // it: bounded like macro calls (a chain of #elseif each on clock).
    if (symbols.sides_open() >= static_cast<std::size_t>(options.limits.macro_depth))
        fail(at, "clock-dependent branches nested more than " +
                     std::to_string(options.limits.macro_depth) +
                     " deep (--max-macro-depth N raises the limit)");
    const auto start = in.iterator();
    const runtime::Lifetime outer = domain;
    // What a side may change besides variables: values it leaves on the
    // stack (an #if inside a macro that returns a value), and the object
    // being built around it (CSG members it adds).
    const std::size_t stack_base = values.depth();
    const runtime::CameraRecord camera_before = scene.camera;
    const runtime::ColourFunction background_before = scene.background;
    const std::size_t camera_count = camera_sets, background_count = background_sets;
    const std::size_t block_count = blocks.depth();
    std::optional<runtime::ObjectRecord> top_before;
    if (!blocks.empty()) {
        if (!std::holds_alternative<runtime::ObjectRecord>(blocks.top()))
            fail_piecewise(
                at,
                "a branch whose condition depends on clock inside this block; hexant makes "
                "objects, their CSG members, floats and vectors piecewise in time, not yet "
                "what this block holds");
        top_before = std::get<runtime::ObjectRecord>(blocks.top());
    }
    std::optional<TimeSide> sides[2];  // [0]: where c holds
    auto end = start;
    // Whether each side closed the block around the split (and where its
    // branch ends), read_closing_branch.
    const std::optional<std::size_t> outer_split_depth = split_block_depth_;
    const char* const outer_escape = side_escape_;
    split_block_depth_ =
        top_before ? std::optional<std::size_t>(block_count) : std::optional<std::size_t>();
    const char* escapes[2] = {nullptr, nullptr};
    const auto restore_split = [&] {
        split_block_depth_ = outer_split_depth;
        side_escape_ = outer_escape;
    };
    const auto restore = [&] {
        TimeSide side;
        side.after = symbols.end_side();
        if (camera_sets != camera_count) side.camera = std::exchange(scene.camera, camera_before);
        if (background_sets != background_count)
            side.background = std::exchange(scene.background, background_before);
        camera_sets = camera_count;
        background_sets = background_count;
        const bool balanced = values.depth() >= stack_base && blocks.depth() == block_count;
        side.pushed = values.take_above(stack_base);
        if (blocks.depth() == block_count && top_before) {
            side.top = std::move(std::get<runtime::ObjectRecord>(blocks.top()));
            blocks.top() = *top_before;
        }
        return std::pair{std::move(side), balanced};
    };
    for (int side = 0; side < 2; ++side) {
        const runtime::Lifetime& when = side == 0 ? pieces.when_true : pieces.when_false;
        if (when.is_never()) continue;
        in.iterator() = start;
        // (A condition true, or false, over all of the domain: no split.)
        const bool whole = (side == 0 ? pieces.when_false : pieces.when_true).is_never();
        domain = whole ? outer : when;
        side_escape_ = nullptr;
        symbols.begin_side();
        const BlockStack::Watch watch = blocks.watch(top_before ? block_count : 0);
        try {
            read(side == 0);
        } catch (const p::parse_error& e) {
            // Where in time the error is: from this side's first instant
            // (POV-Ray stops at that clock's frame).
            std::ostringstream note;
            note << std::setprecision(17) << e.message() << " (at clock "
                 << when.pieces().front().lo << ", on a side of the branch on clock at line "
                 << at.line << ")";
            domain = outer;
            blocks.abandon_watch(watch);
            (void)restore();
            restore_split();
            if (e.message().find(" (at clock ") != std::string_view::npos)
                throw;  // said once, innermost
            p::parse_error amended(note.str(), e.positions().front());
            for (std::size_t i = 1; i < e.positions().size(); ++i)
                amended.add_position(p::position(e.positions()[i]));
            throw amended;
        } catch (...) {
            domain = outer;
            blocks.abandon_watch(watch);
            (void)restore();
            restore_split();
            throw;
        }
        escapes[side] = side_escape_;
        const BlockStack::Edited edited = blocks.end_watch(watch);
        auto [done, balanced] = restore();
        done.top_edited = edited;
        if (!balanced) {
            domain = outer;
            restore_split();
            fail_piecewise(
                at,
                "a branch whose condition depends on clock that uses values from before it "
                "or leaves a block open; hexant cannot yet make that piecewise in time");
        }
        done.when = when;
        sides[side] = std::move(done);
        end = in.iterator();
    }
    domain = outer;
    restore_split();
    // Both sides close the block around the split, or neither: the input
    // is then at the last side's '}', and its branch's end is stepped over
    // when the reading reaches it.
    if (sides[0] && sides[1] && (escapes[0] != nullptr) != (escapes[1] != nullptr))
        fail_piecewise(
            at,
            "one side of this branch on clock closes the block around it and the other does "
            "not; hexant cannot make that piecewise in time");
    if (const char* last = sides[1] ? escapes[1] : escapes[0]) escaped_ends_.push_back(last);
    in.iterator() = end;
    merge_time_sides(at, c, sides, top_before, camera_before, background_before);
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::run_ifdef(ParseInput& in) {
    const auto opened = directive_position(in);
    bool negate = false;
    if (keyword(in, "ifndef"))
        negate = true;
    else if (!keyword(in, "ifdef"))
        return false;
    const char* name = negate ? "#ifndef" : "#ifdef";
    read<grammar::lparen, Action, Control>(in);
    const std::string id = identifier(in, "a name in #ifdef ( )");
    // #ifdef (A[i][j]): whether that element of an array is set.
    std::vector<double> indices;
    while (!in.empty() && in.peek_char() == '[') {
        const auto where = in.position();
        read<grammar::declare_index, Action, Control>(in);
        try {
            indices.push_back(to_constant(values.pop(), "an array index in #ifdef ( )"));
        } catch (const ValueError& e) {
            fail(where, e);
        }
    }
    read<grammar::condition_close, Action, Control>(in);
    const auto rest = [&](bool taken) {
        if (taken && read_opening_branch<Item, Action, Control>(in, opened, name)) return;
        Divider d = taken ? run_body<Item, Action, Control>(in) : skip_body<Control>(in);
        if (d == Divider::Else) {
            if (!taken && read_opening_branch<Item, Action, Control>(in, opened, name)) return;
            d = taken ? skip_body<Control>(in) : run_body<Item, Action, Control>(in);
        }
        if (d != Divider::End) unclosed(opened, name, d, in);
    };
    if (!indices.empty()) {
        const Value* v = symbols.lookup(id);
        if (v == nullptr) {
            rest(negate);
            return true;
        }
        if (!v->is<std::shared_ptr<Array>>())
            fail(opened, std::string(name) + " (" + id + "[...]): '" + id + "' is not an array");
        const Array& array = *v->as<std::shared_ptr<Array>>();
        bool set = false;
        try {
            set = array.elements[element_index(array, indices)].has_value();
        } catch (const ValueError& e) {
            fail(opened, e, std::string(name) + ": ");
        }
        rest(set != negate);
        return true;
    }
    const runtime::Lifetime* when = symbols.declared_when(id);
    if (when == nullptr || when->is_always()) {
        rest((when != nullptr) != negate);
        return true;
    }
    // Declared part of the time: a branch on the time it is declared.
    TimeFunction c = indicator(*when);
    if (negate) c = TimeFunction::apply(runtime::TimeOp::Not, c);
    // (The split is the directive's, as an #if's is.)
    const runtime::TruthPieces pieces = split_domain(c, opened);
    if (const auto whole = whole_truth(pieces))
        rest(*whole);
    else
        split_time(in, opened, c, pieces, rest);
    return true;
}

// How many more '{' than '}' the text [b, e) holds, outside strings,
// comments and the directives nested in it (#if, #ifdef, #ifndef, #while,
// #for, #switch, #macro to their #end: their braces are their own).
inline long brace_balance(const char* b, const char* e) {
    long balance = 0;
    int nested = 0;
    for (const char* c = b; c < e; ++c) {
        if (*c == '"') {
            for (++c; c < e && *c != '"'; ++c)
                if (*c == '\\') ++c;
        } else if (*c == '/' && c + 1 < e && c[1] == '/') {
            while (c < e && *c != '\n') ++c;
        } else if (*c == '/' && c + 1 < e && c[1] == '*') {
            for (c += 2; c + 1 < e && !(c[0] == '*' && c[1] == '/'); ++c) {
            }
            ++c;
        } else if (*c == '#') {
            const char* w = c + 1;
            while (w < e && (*w == ' ' || *w == '\t')) ++w;
            const char* w_end = w;
            while (w_end < e && (std::isalnum(static_cast<unsigned char>(*w_end)) || *w_end == '_'))
                ++w_end;
            const std::string_view word(w, static_cast<std::size_t>(w_end - w));
            if (word == "if" || word == "ifdef" || word == "ifndef" || word == "while" ||
                word == "for" || word == "switch" || word == "macro")
                ++nested;
            else if (word == "end" && nested > 0)
                --nested;
            c = w_end - 1;
        } else if (nested == 0 && *c == '{') {
            ++balance;
        } else if (nested == 0 && *c == '}') {
            --balance;
        }
    }
    return balance;
}

// POV-Ray's directives act on its token stream, so a taken branch may open
// a block that the text after #end goes on to fill and close (shapes.inc's
// `#if (UseMerge) merge { #else union { #end ... }`). When the braces of
// the branch starting here open more than they close, the item it begins
// is read from a copy of the input in which the directive's other parts
// (from the branch's end through #end) are blanks, lines kept, so that
// places stay the same; the input then resumes after that item. Returns
// false, reading nothing, for a branch whose braces balance.
template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::read_opening_branch(ParseInput& in, const p::position& opened,
                                      const char* directive) {
    const auto start = in.iterator();
    const char* body = in.current();
    skip_text<Control>(in);
    const char* body_end = in.current();
    const long balance = brace_balance(body, body_end);
    if (balance <= 0) {
        in.iterator() = start;
        // (One that closes more than it opens: the scan is not repeated.)
        return balance < 0 &&
               read_closing_branch<Item, Action, Control>(in, opened, directive, body_end);
    }
    // Through the directive's #end.
    Divider d = next_divider(in);
    while (d == Divider::Else || d == Divider::Elseif) d = skip_body<Control>(in);
    if (d != Divider::End) unclosed(opened, directive, d, in);
    const char* after_end = in.current();
    std::string& copy = spliced_texts_.emplace_back(in.begin(), in.end());
    for (const char* c = body_end; c < after_end; ++c)
        if (*c != '\n' && *c != '\r') copy[static_cast<std::size_t>(c - in.begin())] = ' ';
    const std::size_t offset = static_cast<std::size_t>(body - in.begin());
    Input rest(copy.data() + offset, copy.data() + copy.size(), in.source(), start.byte, start.line,
               start.column);
    (void)p::match<Item, p::apply_mode::action, p::rewind_mode::dontcare, Action, Control>(rest,
                                                                                           *this);
    const std::size_t consumed = static_cast<std::size_t>(rest.current() - (copy.data() + offset));
    if (consumed < static_cast<std::size_t>(body_end - body))
        fail(opened, std::string("the branch taken here opens a block that the item it begins "
                                 "does not close after ") +
                         directive + "'s #end");
    in.iterator() = start;
    in.bump(consumed);
    return true;
}

// The other side of the same rule: a taken branch that closes more blocks
// than it opens (`#if (C) cone { } } #else cone { } } #end`, each branch
// ending the union around it). Its items are read up to the '}' that
// closes the block around the directive, and the input is left there for
// that block's reader; the place where the branch's text ends is kept in
// escaped_ends_, and when the reading after the block reaches it
// (skip_escaped_rest, the first alternative of every directive) the
// directive's other branches through #end are stepped over. Called by
// read_opening_branch, which found the branch's end `body_end` and its
// braces closing more than they open.
template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::read_closing_branch(ParseInput& in, const p::position& opened,
                                      const char* directive, const char* body_end) {
    const bool in_side = symbols.sides_open() > 0;
    if (in_side && !split_block_depth_)
        fail_piecewise(opened,
                       std::string("the branch taken here closes a block it did not open, inside "
                                   "a branch whose condition depends on clock; hexant cannot yet "
                                   "make that piecewise in time (close the block after ") +
                           directive + "'s #end)");
    (void)p::match<p::star<Item>, p::apply_mode::action, p::rewind_mode::dontcare, Action, Control>(
        in, *this);
    if (in.current() >= body_end || *in.current() != '}')
        fail(opened, std::string("the branch taken here closes a block, but its items stop "
                                 "before the '}' that would close it (") +
                         directive + ")");
    if (in_side && blocks.depth() <= *split_block_depth_) {
        // The block around a split on clock: each side stops at its '}'
        // and split_time leaves the last side's for that block's reader.
        // What follows the '}' in the branch would be read for one side
        // only: it may be blanks and comments.
        const char* c = in.current() + 1;
        while (c < body_end) {
            if (std::isspace(static_cast<unsigned char>(*c))) {
                ++c;
            } else if (*c == '/' && c + 1 < body_end && c[1] == '/') {
                while (c < body_end && *c != '\n') ++c;
            } else if (*c == '/' && c + 1 < body_end && c[1] == '*') {
                c += 2;
                while (c + 1 < body_end && !(c[0] == '*' && c[1] == '/')) ++c;
                c += 2;
            } else {
                fail_piecewise(opened,
                               std::string("the branch taken here closes the block around a "
                                           "branch on clock and goes on after it; hexant cannot "
                                           "yet make that piecewise in time (") +
                                   directive + ")");
            }
        }
        side_escape_ = body_end;
        return true;
    }
    escaped_ends_.push_back(body_end);
    return true;
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::skip_escaped_rest(ParseInput& in) {
    if (escaped_ends_.empty()) return false;
    const auto found = std::find(escaped_ends_.begin(), escaped_ends_.end(), in.current());
    if (found == escaped_ends_.end()) return false;
    escaped_ends_.erase(found);
    const auto at = in.position();
    Divider d = next_divider(in);
    while (d == Divider::Else || d == Divider::Elseif) d = skip_body<Control>(in);
    if (d != Divider::End) unclosed(at, "#if", d, in);
    return true;
}

}  // namespace hexant::language
