// The Interpreter's #macro: definitions and calls, the body read from its stored source with its
// own positions. Part of the Interpreter (language/interpreter_state.hpp), whose end includes it.
#pragma once

#include "language/interpreter/reading.hpp"
#include "language/interpreter_state.hpp"

namespace hexant::language {

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::define_macro(ParseInput& in) {
    const auto opened = directive_position(in);
    if (!keyword(in, "macro")) return false;
    std::string name = identifier(in, "the macro's name after #macro");
    std::vector<std::string> parameters;
    read<grammar::lparen, Action, Control>(in);
    while (in.current() != in.end() && *in.current() != ')') {
        if (!parameters.empty()) {
            // POV-Ray lets one leave out the ',' and allows a trailing one.
            (void)p::match<grammar::comma, p::apply_mode::nothing, p::rewind_mode::required,
                           p::nothing, p::normal>(in);
            if (in.current() != in.end() && *in.current() == ')') break;
        }
        parameters.push_back(identifier(in, "a parameter name in #macro ( )"));
    }
    read<grammar::rparen, Action, Control>(in);
    const char* body_begin = in.current();
    const auto body_position = in.position();
    skip_text<Control>(in);
    const char* body_end = in.current();
    const Divider d = next_divider(in);
    if (d != Divider::End) unclosed(opened, "#macro", d, in);
    auto macro = std::make_shared<Macro>(
        Macro{std::move(name), std::move(parameters), body_begin, body_end, body_position, opened});
    symbols.declare(macro->name, Value{std::shared_ptr<const Macro>(macro)}, false);
    return true;
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::call_macro(ParseInput& in) {
    const char* b = in.current();
    const char* end = in.end();
    const char* q = b;
    while (q != end && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
    if (q == b || std::isdigit(static_cast<unsigned char>(*b))) return false;
    const std::string name(b, q);
    const Value* v = symbols.lookup(name);
    if (v == nullptr || !v->is<std::shared_ptr<const Macro>>()) return false;
    const auto macro = v->as<std::shared_ptr<const Macro>>();
    const auto call_place = in.position();
    in.bump_in_this_line(static_cast<std::size_t>(q - b));
    (void)p::match<grammar::ws, p::apply_mode::nothing, p::rewind_mode::dontcare, p::nothing,
                   p::normal>(in);
    read<grammar::call_open, Action, Control>(in);
    values.open_frame();
    // An argument that is just a declared name is passed by reference, as in
    // POV-Ray: what the macro #declares to its parameter goes back to it.
    std::vector<std::string> references;
    if (in.current() != in.end() && *in.current() != ')') {
        do {
            const char* start = in.current();
            read<grammar::call_argument, Action, Control>(in);
            std::string text(start, in.current());
            while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
                text.pop_back();
            const bool is_name = !text.empty() &&
                                 !std::isdigit(static_cast<unsigned char>(text[0])) &&
                                 std::all_of(text.begin(), text.end(), [](char c) {
                                     return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                                 });
            references.push_back(is_name && symbols.lookup(text) ? text : std::string());
            // The comma between arguments may be left out, as POV-Ray's
            // Parse_Comma allows: Align_Object(Center_Object(O, x) -y, 0),
            // an object's value ending before the -y.
        } while (p::match<grammar::comma, p::apply_mode::nothing, p::rewind_mode::required,
                          p::nothing, p::normal>(in) ||
                 (references.size() < macro->parameters.size() && in.current() != in.end() &&
                  *in.current() != ')'));
    }
    read<grammar::call_close, Action, Control>(in);
    std::vector<Value> args = values.close_frame();
    if (args.size() != macro->parameters.size())
        fail(call_place, "macro '" + name + "' takes " + std::to_string(macro->parameters.size()) +
                             " argument" + (macro->parameters.size() == 1 ? "" : "s") + ", not " +
                             std::to_string(args.size()));
    if (macro_depth_ >= options.limits.macro_depth)
        fail(call_place, "macro calls nested more than " +
                             std::to_string(options.limits.macro_depth) +
                             " deep; stopping (runaway recursion? --max-macro-depth N raises the "
                             "limit)");
    count_step(call_place);
    count_text(static_cast<std::size_t>(macro->body_end - macro->body_begin), call_place);
    symbols.open_scope();
    try {
        for (std::size_t i = 0; i < args.size(); ++i)
            symbols.declare(macro->parameters[i], std::move(args[i]), true);
    } catch (const ValueError& e) {
        symbols.close_scope();
        fail(call_place, e);
    }
    ++macro_depth_;
    const std::size_t before = values.depth();
    const auto& at = macro->body_position;
    Input body(macro->body_begin, macro->body_end, at.source, at.byte, at.line, at.column);
    try {
        (void)p::match<p::seq<grammar::ws, p::star<Item>, p::must<grammar::macro_body_end>>,
                       p::apply_mode::action, p::rewind_mode::dontcare, Action, Control>(body,
                                                                                         *this);
    } catch (const unsupported_use&) {
        // A #declare around the call may keep it as source and read on.
        --macro_depth_;
        symbols.close_scope();
        throw;
    } catch (const p::parse_error& error) {
        SceneError scene_error = to_scene_error(error);
        scene_error.add_context(place(call_place, "in macro '" + name + "' called here"));
        throw scene_error;
    } catch (SceneError& scene_error) {
        scene_error.add_context(place(call_place, "in macro '" + name + "' called here"));
        throw;
    }
    --macro_depth_;
    for (std::size_t i = 0; i < references.size(); ++i) {
        if (references[i].empty()) continue;
        const Value* value = symbols.innermost(macro->parameters[i]);
        if (value == nullptr) continue;
        try {
            symbols.set_outer(references[i], *value);
        } catch (const ValueError& e) {
            symbols.close_scope();
            fail(call_place, e);
        }
    }
    symbols.close_scope();
    if constexpr (std::is_same_v<Item, grammar::value_item>) {
        if (values.depth() != before + 1)
            fail(call_place, "macro '" + name + "' is used as a value but gives " +
                                 std::to_string(values.depth() - before) + " values");
    }
    return true;
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::call_object_macro(ParseInput& in) {
    const auto at = in.position();
    const std::size_t depth = blocks.depth();
    object_macro_depths_.push_back(depth);
    bool called = false;
    try {
        called = call_macro<Item, Action, Control>(in);
    } catch (...) {
        object_macro_depths_.pop_back();
        throw;
    }
    object_macro_depths_.pop_back();
    if (called && blocks.depth() != depth + 1)
        fail(at, "this macro gives no object for object { } to hold");
    return called;
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::object_macro_first(ParseInput& in) {
    if (object_macro_depths_.empty() || blocks.depth() != object_macro_depths_.back()) return false;
    // (Only where an object starts: a divider or a modifier is another
    // item's, as in a branch of the body before its object.)
    return p::match<grammar::object_base, p::apply_mode::action, p::rewind_mode::required, Action,
                    Control>(in, *this);
}

}  // namespace hexant::language
