// The Interpreter's #declare of a value, #include (also by clock) and reading a whole file.
// Part of the Interpreter (language/interpreter_state.hpp), whose end includes it.
#pragma once

#include "language/interpreter/reading.hpp"
#include "language/interpreter_state.hpp"

namespace hexant::language {

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::declare_value(ParseInput& in) {
    const auto start = in.iterator();
    const ValueStack::Mark mark = values.mark();
    const std::size_t block_count = blocks.depth();
    const std::size_t functions_count = functions_open.size();
    // `#declare X = #if (..) A #else B #end`: POV-Ray's directives act on
    // the token stream, so a branch may choose the value itself. The taken
    // branch must leave exactly one value.
    using branch_opening =
        p::seq<grammar::hash, p::sor<TAO_PEGTL_KEYWORD("if"), TAO_PEGTL_KEYWORD("ifdef"),
                                     TAO_PEGTL_KEYWORD("ifndef"), TAO_PEGTL_KEYWORD("switch")>>;
    if (p::match<p::at<branch_opening>, p::apply_mode::nothing, p::rewind_mode::required,
                 p::nothing, Control>(in, *this)) {
        const auto where = in.position();
        const std::size_t depth = values.depth();
        (void)p::match<grammar::directive<grammar::value_item>, p::apply_mode::action,
                       p::rewind_mode::required, Action, Control>(in, *this);
        if (values.depth() != depth + 1)
            fail(where, "the branch taken here gives " +
                            std::to_string(values.depth() - std::min(values.depth(), depth)) +
                            " values; a #declare's value chosen by a directive must be one");
        return true;
    }
    try {
        return p::match<grammar::value, p::apply_mode::action, p::rewind_mode::required, Action,
                        Control>(in, *this);
    } catch (const unsupported_use& e) {
        // Keep the declaration as source: an error only where it is used.
        in.iterator() = start;
        values.rewind(mark);
        blocks.rewind(block_count);
        functions_open.resize(functions_count);
        function_parameter_names.clear();
        function_parameters_given = false;
        const auto where = in.position();
        (void)p::match<grammar::skip::declaration, p::apply_mode::nothing, p::rewind_mode::dontcare,
                       p::nothing, Control>(in, *this);
        values.push(Value{Unevaluated{
            "declaration that hexant cannot evaluate (" + std::string(e.message()) + ")", where}});
        return true;
    }
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
bool Interpreter::run_include(ParseInput& in) {
    const auto opened = directive_position(in);
    if (!keyword(in, "include")) return false;
    read<grammar::include_name, Action, Control>(in);
    const Value name = values.pop();
    if (name.is<TimedString>()) {
        include_by_clock<Item, Action, Control>(in, opened, name.as<TimedString>());
        return true;
    }
    std::string file;
    try {
        file = to_string_value(name, "the name after #include");
    } catch (const ValueError& e) {
        fail(opened, e);
    }
    include_file<Item, Action, Control>(opened, file);
    return true;
}

template <typename Item, template <typename...> class Action, template <typename...> class Control,
          typename ParseInput>
void Interpreter::include_by_clock(ParseInput& in, const p::position& opened,
                                   const TimedString& name) {
    // Each file read for the time its name holds, as the sides of a branch
    // on clock: the first name against the rest, then the rest in turn.
    std::vector<double> instants;  // for `hexant check`, as split_domain records them
    for (std::size_t i = 1; i < name.pieces.size(); ++i)
        if (domain.contains(name.pieces[i].time.lo)) instants.push_back(name.pieces[i].time.lo);
    if (!instants.empty())
        scene.time_splits.push_back({{opened.source, opened.line, opened.column}, instants});
    std::vector<std::pair<std::string, runtime::Lifetime>> files;
    for (auto& [file, when] : name.by_text()) {
        runtime::Lifetime here =
            runtime::Lifetime::of(when.within(animation_time())).intersect(domain);
        if (!here.is_never()) files.push_back({file, std::move(here)});
    }
    const auto from = [&](const auto& self, std::size_t k) -> void {
        if (k + 1 >= files.size()) {
            if (k < files.size()) include_file<Item, Action, Control>(opened, files[k].first);
            return;
        }
        runtime::TruthPieces pieces;
        pieces.when_true = files[k].second;
        std::vector<runtime::Interval> rest;
        for (std::size_t j = k + 1; j < files.size(); ++j)
            rest.insert(rest.end(), files[j].second.pieces().begin(),
                        files[j].second.pieces().end());
        pieces.when_false = runtime::Lifetime::of(std::move(rest));
        split_time(in, opened, indicator(pieces.when_true), pieces, [&](bool first) {
            if (first)
                include_file<Item, Action, Control>(opened, files[k].first);
            else
                self(self, k + 1);
        });
    };
    from(from, 0);
}

template <typename Item, template <typename...> class Action, template <typename...> class Control>
void Interpreter::include_file(const p::position& opened, const std::string& file) {
    if (include_depth_ >= options.limits.include_depth)
        fail(opened, "#include nested more than " + std::to_string(options.limits.include_depth) +
                         " deep; stopping (does a file include itself? --max-include-depth N "
                         "raises the limit)");
    const std::filesystem::path path = resolve_include(file, opened);
    const std::string text = read_include(path, opened);
    ++include_depth_;
    symbols.open_scope();
    try {
        read_file<Item, Action, Control>(path.string(), text);
    } catch (SceneError& scene_error) {
        scene_error.add_context(place(opened, "included from here"));
        throw;
    }
    symbols.close_scope();
    --include_depth_;
}

template <typename Items, template <typename...> class Action, template <typename...> class Control>
void Interpreter::read_file(const std::string& name, const std::string& text) {
    const std::string& stored = add_source(name, text);
    Input in(stored.data(), stored.data() + stored.size(), name, 0, 1, 1);
    try {
        if constexpr (std::is_same_v<Items, grammar::scene_item>)
            (void)p::match<grammar::scene_file, p::apply_mode::action, p::rewind_mode::dontcare,
                           Action, Control>(in, *this);
        else
            (void)p::match<p::seq<grammar::ws, p::star<Items>, p::must<grammar::include_end>>,
                           p::apply_mode::action, p::rewind_mode::dontcare, Action, Control>(in,
                                                                                             *this);
    } catch (const p::parse_error& error) {
        throw to_scene_error(error);
    } catch (const std::bad_alloc&) {
        // An allocation outside any action (a directive's own work): the
        // place is where the reading of this file had got to.
        throw to_scene_error(p::parse_error(kOutOfMemory, in.position()));
    }
}

}  // namespace hexant::language
