// The Interpreter's reading helpers of the directives: words, names and the
// dividers (#else, #end, ...). Part of the Interpreter (language/interpreter_state.hpp), whose end
// includes it.
#pragma once

#include "language/interpreter_state.hpp"

namespace hexant::language {

// Where a directive starts: at its '#', just before the input's position.
template <typename ParseInput>
p::position directive_position(const ParseInput& in) {
    p::position position = in.position();
    if (position.byte > 0 && position.column > 1 && in.current()[-1] == '#') {
        --position.byte;
        --position.column;
    }
    return position;
}

template <typename ParseInput>
void Interpreter::unclosed(const p::position& opened, const char* directive, Divider found,
                           const ParseInput& in) {
    static const char* names[] = {"", "#else", "#elseif", "#end", "#case", "#range", "#break"};
    if (found == Divider::None) {
        if (in.empty()) fail(opened, std::string(directive) + " has no matching #end");
        fail(in.position(), std::string("this does not belong inside ") + directive +
                                " here: expected an item of the enclosing block, a directive "
                                "or #end" +
                                found_text(in));
    }
    fail(in.position(), std::string(names[static_cast<int>(found)]) +
                            " does not belong here, in the " + directive + " opened at line " +
                            std::to_string(opened.line));
}

template <typename ParseInput>
bool Interpreter::keyword(ParseInput& in, std::string_view word) {
    const char* b = in.current();
    const std::size_t n = word.size();
    if (static_cast<std::size_t>(in.end() - b) < n || std::string_view(b, n) != word) return false;
    if (b + n != in.end() && (std::isalnum(static_cast<unsigned char>(b[n])) || b[n] == '_'))
        return false;
    in.bump_in_this_line(n);
    (void)p::match<grammar::ws, p::apply_mode::nothing, p::rewind_mode::dontcare, p::nothing,
                   p::normal>(in);
    return true;
}

template <typename ParseInput>
std::string Interpreter::identifier(ParseInput& in, const char* what) {
    const char* b = in.current();
    const auto position = in.position();
    if (!p::match<grammar::name, p::apply_mode::nothing, p::rewind_mode::required, p::nothing,
                  p::normal>(in))
        fail(position, std::string("expected ") + what + found_text(in));
    std::string result(b, in.current());
    (void)p::match<grammar::ws, p::apply_mode::nothing, p::rewind_mode::dontcare, p::nothing,
                   p::normal>(in);
    return result;
}

template <typename ParseInput>
Divider Interpreter::next_divider(ParseInput& in) {
    const char* b = in.current();
    const char* e = in.end();
    if (b == e || *b != '#') return Divider::None;
    const char* q = b + 1;
    while (q != e && (*q == ' ' || *q == '\t')) ++q;
    const char* w = q;
    while (q != e && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
    const std::string_view word(w, static_cast<std::size_t>(q - w));
    Divider d = Divider::None;
    if (word == "else")
        d = Divider::Else;
    else if (word == "elseif")
        d = Divider::Elseif;
    else if (word == "end")
        d = Divider::End;
    else if (word == "case")
        d = Divider::Case;
    else if (word == "range")
        d = Divider::Range;
    else if (word == "break")
        d = Divider::Break;
    if (d == Divider::None) return d;
    in.bump_in_this_line(static_cast<std::size_t>(q - b));
    (void)p::match<grammar::ws, p::apply_mode::nothing, p::rewind_mode::dontcare, p::nothing,
                   p::normal>(in);
    return d;
}

}  // namespace hexant::language
