// What each grammar rule does when it matches: the actions' common part (the
// action template, the words a rule matched, and the control that turns an
// action's failure into an error at its place). Part of the actions
// (language/actions.hpp).
#pragma once

#include <algorithm>
#include <bit>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <tao/pegtl.hpp>

#include "language/checked_integer.hpp"
#include "language/grammar.hpp"
#include "language/interpreter_state.hpp"
#include "language/keyword_rules.hpp"
#include "language/mesh_reading.hpp"
#include "language/object_extent.hpp"
#include "language/timed_call.hpp"
#include "language/value_ops.hpp"
#include "runtime/objects/parameter_check.hpp"

namespace hexant::language {

namespace g = grammar;
using runtime::TimeOp;
using runtime::TransformKind;

template <typename Rule>
struct action : p::nothing<Rule> {};

// The word a rule matched, without the blanks after it.
template <typename ActionInput>
std::string word(const ActionInput& in) {
    const std::string s = in.string();
    std::size_t n = 0;
    while (n < s.size() && (std::isalnum(static_cast<unsigned char>(s[n])) || s[n] == '_')) ++n;
    return s.substr(0, n);
}

// A word hexant reads but does not render as POV-Ray does (its keyword
// rule Warned), kept with the block it belongs to (a finish, an interior,
// an object) and warned where an object uses it
// (Interpreter::report_unrendered).
template <class Record>
struct unrendered_action {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const std::string w = word(in);
        st.blocks.edit<Record>(in.position(), w.c_str())
            .unrendered.push_back(st.unrendered(in.position(), w));
    }
};

// Rules whose action is to remember the word they matched.
struct name_action {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.values.push_name(word(in));
    }
};
template <>
struct action<g::function_name> : name_action {};
template <>
struct action<g::defined_name> : name_action {};
template <>
struct action<g::colour_model> : name_action {};
template <>
struct action<g::colour_component_name> : name_action {};
template <>
struct action<g::component_name> : name_action {};
template <>
struct action<g::declare_kind> : name_action {};
template <>
struct action<g::declare_name> : name_action {};
template <>
struct action<g::for_variable> : name_action {};
template <>
struct action<g::deformation_name> : name_action {};
template <>
struct action<g::unsupported_pattern_name> : name_action {};
template <>
struct action<g::pattern_name> : name_action {};
template <>
struct action<g::pattern_setting_name> : name_action {};
template <>
struct action<g::pattern_pair_name> : name_action {};
template <>
struct action<g::pattern_wave_name> : name_action {};
template <>
struct action<g::warp_setting_name> : name_action {};
template <>
struct action<g::normal_setting_name> : name_action {};
template <>
struct action<g::fog_setting_name> : name_action {};
template <>
struct action<g::rainbow_setting_name> : name_action {};
template <>
struct action<g::finish_setting_name> : name_action {};
template <>
struct action<g::csg_kind> : name_action {};
template <>
struct action<g::object_flag_name> : name_action {};
template <>
struct action<g::object_bare_flag_name> : name_action {};
template <>
struct action<g::shape_setting_name> : name_action {};
template <>
struct action<g::shape_vectors_setting_name> : name_action {};
template <>
struct action<g::light_setting_name> : name_action {};
template <>
struct action<g::camera_vector_name> : name_action {};
template <>
struct action<g::camera_blur_name> : name_action {};
template <>
struct action<g::global_setting_name> : name_action {};
template <>
struct action<g::radiosity_setting_name> : name_action {};
template <>
struct action<g::photons_setting_name> : name_action {};
template <>
struct action<g::global_ignored_name> : name_action {};
template <>
struct action<g::unsupported_kind> : name_action {};
template <>
struct action<g::image_map_setting_name> : name_action {};
template <>
struct action<g::image_map_filter_name> : name_action {};

// A shape's keyword (one of runtime::ShapeKinds', the rule's words): opens
// the shape, its kind as its index in the list, and where it was written.
template <>
struct action<g::shape_keyword> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const std::size_t kind = runtime::objects::kind_index(runtime::ShapeKinds{}, word(in));
        if (kind == runtime::objects::kind_count(runtime::ShapeKinds{}))
            throw std::logic_error("hexant: shape_keyword matched '" + word(in) + "', no kind");
        const auto p = in.position();
        st.shapes_open.push_back({kind, {}, {p.source, p.line, p.column}});
    }
};
template <>
struct action<g::shape_option> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.shapes_open.back().options.push_back(word(in));
    }
};

template <class State>
void mark_piecewise_refusal(State& st) {
    if constexpr (std::is_same_v<std::decay_t<State>, Interpreter>) st.split_refused = true;
}

// The control of a reading with these actions: errors.hpp's, and every
// action's failure becomes an error at the place its rule matched, written
// once here rather than in each action: a ValueError from the value
// operations, a runtime::LimitError or running out of memory as an error
// there, an UnsupportedError as a use of what hexant lacks there.
template <typename Rule>
struct action_control : control<Rule> {
    template <template <typename...> class Action, typename Iterator, typename ParseInput,
              typename... States>
    static auto apply(const Iterator& begin, const ParseInput& in, States&&... st)
        -> decltype(control<Rule>::template apply<Action>(begin, in, st...)) {
        const auto place = [&] { return typename ParseInput::action_t(begin, in).position(); };
        try {
            return control<Rule>::template apply<Action>(begin, in, st...);
        } catch (const UnsupportedError& e) {
            throw unsupported_use(e.what(), place());
        } catch (const ValueError& e) {
            // (What cannot yet be piecewise in time marks the reading.)
            if (dynamic_cast<const PiecewiseError*>(&e) != nullptr)
                ((void)mark_piecewise_refusal(st), ...);
            Interpreter::fail(place(), e.what());
        } catch (const runtime::LimitError& e) {
            if (dynamic_cast<const runtime::TimePiecesLimit*>(&e) != nullptr)
                ((void)mark_piecewise_refusal(st), ...);
            Interpreter::fail(place(), e.what());
        } catch (const std::bad_alloc&) {
            Interpreter::fail(place(), kOutOfMemory);
        }
    }
};

}  // namespace hexant::language
