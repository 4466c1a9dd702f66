// What each grammar rule does when it matches: PEGTL actions, kept apart from
// the grammar. They work on the Interpreter's value stack and block stack.
#pragma once

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <tao/pegtl.hpp>

#include "language/grammar.hpp"
#include "language/interpreter_state.hpp"
#include "language/mesh_reading.hpp"
#include "language/object_extent.hpp"
#include "language/checked_integer.hpp"
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

// Rules whose action is to remember the word they matched.
#define HEXANT_NAME_ACTION(rule)                                        \
    template <>                                                         \
    struct action<g::rule> {                                            \
        template <typename ActionInput>                                 \
        static void apply(const ActionInput& in, Interpreter& st) {     \
            st.push_name(word(in));                                     \
        }                                                               \
    }
HEXANT_NAME_ACTION(function_name);
HEXANT_NAME_ACTION(defined_name);
HEXANT_NAME_ACTION(colour_model);
HEXANT_NAME_ACTION(colour_component_name);
HEXANT_NAME_ACTION(component_name);
HEXANT_NAME_ACTION(declare_kind);
HEXANT_NAME_ACTION(declare_name);
HEXANT_NAME_ACTION(for_variable);
HEXANT_NAME_ACTION(deformation_name);
HEXANT_NAME_ACTION(unsupported_pattern_name);
HEXANT_NAME_ACTION(pattern_name);
HEXANT_NAME_ACTION(pattern_setting_name);
HEXANT_NAME_ACTION(pattern_wave_name);
HEXANT_NAME_ACTION(warp_setting_name);
HEXANT_NAME_ACTION(normal_setting_name);
HEXANT_NAME_ACTION(fog_setting_name);
HEXANT_NAME_ACTION(finish_setting_name);
HEXANT_NAME_ACTION(csg_kind);
HEXANT_NAME_ACTION(object_flag_name);
HEXANT_NAME_ACTION(shape_setting_name);
HEXANT_NAME_ACTION(shape_vectors_setting_name);
HEXANT_NAME_ACTION(light_setting_name);
HEXANT_NAME_ACTION(camera_vector_name);
HEXANT_NAME_ACTION(camera_blur_name);
HEXANT_NAME_ACTION(global_setting_name);
HEXANT_NAME_ACTION(global_ignored_name);
HEXANT_NAME_ACTION(unsupported_kind);
HEXANT_NAME_ACTION(image_map_setting_name);
HEXANT_NAME_ACTION(image_map_filter_name);
#undef HEXANT_NAME_ACTION

// A shape's keyword: remembers which shape and where it was written.
template <typename ActionInput>
void shape_keyword(const ActionInput& in, Interpreter& st) {
    st.push_name(word(in));
    const auto p = in.position();
    st.shape_place = {p.source, p.line, p.column};
}
template <>
struct action<g::shape_keyword> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        shape_keyword(in, st);
        st.shape_options.emplace_back();
    }
};
template <>
struct action<g::shape_option> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.shape_options.back().push_back(word(in));
    }
};

// A ValueError from the value operations, or a runtime::LimitError,
// becomes an error at the rule's place.
#define HEXANT_ACTION(rule) \
    template <>             \
    struct action<g::rule>
#define HEXANT_APPLY                                              \
    template <typename ActionInput>                               \
    static void apply(const ActionInput& in, Interpreter& st) {   \
        try {                                                     \
            run(in, st);                                          \
        } catch (const UnsupportedError& e) {                     \
            throw unsupported_use(e.what(), in.position());       \
        } catch (const ValueError& e) {                           \
            Interpreter::fail(in.position(), e.what());           \
        } catch (const runtime::LimitError& e) {                  \
            Interpreter::fail(in.position(), e.what());           \
        } catch (const std::bad_alloc&) {                         \
            Interpreter::fail(in.position(), kOutOfMemory);       \
        }                                                         \
    }                                                             \
    template <typename ActionInput>                               \
    static void run([[maybe_unused]] const ActionInput& in,      \
                    [[maybe_unused]] Interpreter& st)

// ------------------------------------------------------------ literals

HEXANT_ACTION(number_text) {
    HEXANT_APPLY { (void)in; st.push(Value{TimeFunction(std::strtod(in.string().c_str(), nullptr))}); }
};

HEXANT_ACTION(string_content) {
    HEXANT_APPLY {
        const std::string raw = in.string();
        std::string out;
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (raw[i] != '\\' || i + 1 == raw.size()) {
                out += raw[i];
                continue;
            }
            const char c = raw[++i];
            switch (c) {
                case 'n': out += '\n'; break;
                case 't': out += '\t'; break;
                case 'r': out += '\r'; break;
                case 'a': out += '\a'; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'v': out += '\v'; break;
                case '0': out += '\0'; break;
                default: out += c; break;
            }
        }
        st.push(Value{out});
    }
};

HEXANT_ACTION(frame_open) {
    HEXANT_APPLY { (void)in; st.open_frame(); }
};

HEXANT_ACTION(vector_literal) {
    HEXANT_APPLY {
        std::vector<Value> items = st.close_frame();
        if (items.size() < 2 || items.size() > 5)
            throw ValueError("a vector has 2 to 5 components, not " + std::to_string(items.size()));
        Vector v;
        v.size = static_cast<int>(items.size());
        for (std::size_t i = 0; i < items.size(); ++i)
            v.c[i] = to_float(items[i], "a vector component");
        st.push(Value{v});
    }
};

HEXANT_ACTION(function_call) {
    HEXANT_APPLY {
        (void)in;
        std::vector<Value> args = st.close_frame();
        const std::string name = st.pop_name();
        // concat() is checked before it is built: a string doubled each time
        // would otherwise reach the allocator's limit first.
        if (name == "concat") {
            std::size_t length = 0;
            for (const auto& a : args) {
                if (a.is<std::string>()) length += a.as<std::string>().size();
                if (a.is<TimedString>()) length += a.as<TimedString>().longest();
            }
            st.check_string_length(length, "concat()'s result");
        }
        // The box of an object (language/object_extent.hpp).
        if (name == "min_extent" || name == "max_extent") {
            if (args.size() != 1 || !args[0].is<runtime::ObjectPtr>())
                throw ValueError(name + "() takes one object, as in POV-Ray");
            st.push(object_extent(*args[0].as<runtime::ObjectPtr>(), name == "max_extent", st.animation_time(),
                                  st.options.limits.time_pieces));
            return;
        }
        // (A string function of arguments that depend on clock: once a
        // piece of time, language/timed_call.hpp.)
        std::optional<Value> timed = call_over_time(name, args, st.domain.within(st.animation_time()),
                                                    st.options.limits.time_pieces, st.random);
        Value result = timed ? std::move(*timed) : call_builtin(name, args, st.random);
        if (name == "vnormalize")
            if (const auto zero = vnormalize_zero_at(args, st.animation_time())) {
                std::ostringstream note;
                note << "vnormalize() of a zero-length vector gives <0, 0, 0>, as in POV-Ray";
                bool timed = false;
                const Vector v = to_vector(args.at(0), "the argument of vnormalize()");
                for (int i = 0; i < v.size; ++i) timed = timed || v.c[i].depends_on_time();
                if (timed)
                    note << " (at clock " << std::setprecision(17) << *zero << " and wherever else it is zero)";
                st.warn(in.position(), note.str());
            }
        if (result.is<std::string>())
            st.check_string_length(result.as<std::string>().size(), name + "()'s result");
        if (result.is<TimedString>())
            st.check_string_length(result.as<TimedString>().longest(), name + "()'s result");
        st.push(std::move(result));
    }
};

HEXANT_ACTION(defined_call) {
    HEXANT_APPLY {
        (void)in;
        // (Declared part of the time: 1 on those pieces, language/time_branch.hpp.)
        const runtime::Lifetime* when = st.declared_when(st.pop_name());
        st.push(Value{when ? indicator(*when) : TimeFunction(0.0)});
    }
};

HEXANT_ACTION(builtin_constant_name) {
    HEXANT_APPLY {
        const std::string w = in.string();
        const auto& a = st.options.animation;
        auto f = [&](double v) { st.push(Value{TimeFunction(v)}); };
        if (w == "pi") f(3.14159265358979323846);
        else if (w == "tau") f(2 * 3.14159265358979323846);
        else if (w == "true" || w == "yes" || w == "on") f(1.0);
        else if (w == "false" || w == "no" || w == "off") f(0.0);
        else if (w == "x") st.push(make_vector({1.0, 0.0, 0.0}));
        else if (w == "y") st.push(make_vector({0.0, 1.0, 0.0}));
        else if (w == "z") st.push(make_vector({0.0, 0.0, 1.0}));
        else if (w == "t") st.push(make_vector({0.0, 0.0, 0.0, 1.0}));
        else if (w == "u") st.push(make_vector({1.0, 0.0}));
        else if (w == "v") st.push(make_vector({0.0, 1.0}));
        else if (w == "image_width") f(a.width);
        else if (w == "image_height") f(a.height);
        else if (w == "clock") st.push(Value{a.clock_runs() ? TimeFunction::clock() : TimeFunction(a.initial_clock)});
        else if (w == "clock_delta") f(a.clock_delta());
        else if (w == "clock_on") f(a.clock_runs() ? 1.0 : 0.0);
        // In a still, POV-Ray reads these four (and frame_number) as 0.
        else if (w == "initial_clock") f(a.clock_runs() ? a.initial_clock : 0.0);
        else if (w == "final_clock") f(a.clock_runs() ? a.final_clock : 0.0);
        else if (w == "initial_frame") f(a.is_animation() ? a.initial_frame : 0.0);
        else if (w == "final_frame") f(a.is_animation() ? a.final_frame : 0.0);
        else if (w == "version") f(st.version);
        else if (w == "frame_number") {
            // The frame whose shutter holds the time: constant within a
            // frame, and switching exactly at each frame's clock as the
            // renderer computes it (Animation::clock_of_frame: c0 + n *
            // delta, the same operations here), so that a branch on it
            // splits time at the frames' first instants. The quotient may
            // be a frame off next to a boundary; the comparisons with the
            // frame's own clock and the next one's correct it.
            if (!a.is_animation() || a.clock_delta() == 0.0) {
                f(a.is_animation() ? a.initial_frame : 0.0);
            } else {
                const TimeFunction t = TimeFunction::clock();
                const double delta = a.clock_delta();
                const TimeFunction n = TimeFunction::apply(TimeOp::Floor, (t - a.initial_clock) / delta);
                const TimeFunction start = a.initial_clock + n * delta;
                const TimeFunction next = a.initial_clock + (n + 1.0) * delta;
                // (A clock running backwards, delta < 0: a frame holds the
                // times from its clock down to the next one's.)
                const bool forward = delta > 0.0;
                const TimeFunction past_next =
                    TimeFunction::apply(forward ? TimeOp::GreaterEqual : TimeOp::LessEqual, t, next);
                const TimeFunction before_start =
                    TimeFunction::apply(forward ? TimeOp::Less : TimeOp::Greater, t, start);
                const TimeFunction exact = n + past_next - before_start;
                st.push(Value{TimeFunction::apply(TimeOp::Min, exact + double(a.initial_frame),
                                                  double(a.final_frame))});
            }
        }
    }
};

HEXANT_ACTION(colour_model_literal) {
    HEXANT_APPLY {
        (void)in;
        Value v = st.pop();
        st.push(colour_model(st.pop_name(), v));
    }
};

HEXANT_ACTION(colour_keyword) {
    HEXANT_APPLY {
        (void)in;
        Vector black;
        black.size = 5;
        st.push(Value{black});
    }
};

HEXANT_ACTION(colour_base) {
    HEXANT_APPLY {
        (void)in;
        Value v = st.pop();
        const runtime::ColourFunction c = to_colour(v, "the colour after 'color'");
        Vector r;
        r.size = 5;
        for (int i = 0; i < 5; ++i) r.c[i] = c.c[i];
        st.top() = Value{r};
    }
};

HEXANT_ACTION(colour_component_setting) {
    HEXANT_APPLY {
        (void)in;
        const TimeFunction v = to_float(st.pop(), "a colour component");
        const std::string name = st.pop_name();
        Vector& c = st.top().as<Vector>();
        const int i = name == "red" ? 0 : name == "green" ? 1 : name == "blue" ? 2 : name == "filter" ? 3 : 4;
        c.c[i] = v;
    }
};

HEXANT_ACTION(reference) {
    HEXANT_APPLY {
        const std::string name = word(in);
        const Value* v = st.lookup(name);
        if (v == nullptr) throw ValueError("undeclared identifier '" + name + "'");
        st.check_declared(name);
        if (v->is<Unevaluated>()) {
            const auto& u = v->as<Unevaluated>();
            throw UnsupportedError("'" + name + "' is a " + u.what + " (declared at " + u.where.source + ":" +
                             std::to_string(u.where.line) + ":" + std::to_string(u.where.column) +
                             "), which hexant does not support");
        }
        if (v->is<std::shared_ptr<Array>>()) {
            // Arrays are values: a copy, so that changing it leaves the original alone.
            st.push(Value{std::make_shared<Array>(*v->as<std::shared_ptr<Array>>())});
            return;
        }
        st.push(*v);
    }
};

HEXANT_ACTION(component_access) {
    HEXANT_APPLY {
        (void)in;
        Value v = st.pop();
        st.push(component(v, st.pop_name()));
    }
};

// The element of an array; `indices` already constant.
inline std::size_t element_index(const Array& array, const std::vector<double>& indices) {
    if (indices.size() != array.dimensions.size())
        throw ValueError("this array has " + std::to_string(array.dimensions.size()) +
                         " dimension(s) but " + std::to_string(indices.size()) + " index(es) were given");
    std::size_t flat = 0;
    for (std::size_t d = 0; d < indices.size(); ++d) {
        const long long i = checked_integer(std::floor(indices[d]), "an array index", 0,
                                            array.dimensions[d] - 1);
        flat = flat * static_cast<std::size_t>(array.dimensions[d]) + static_cast<std::size_t>(i);
    }
    return flat;
}

// A[index] where the index depends on clock: the element of each piece of
// time where floor(index) is one number (runtime::split_by_value), made
// piecewise as a branch's sides are (time_branch.hpp: floats and vectors
// as `floor(index) = k ? A[k] : ...`, objects each living on its pieces).
inline Value element_by_clock(const Array& array, const TimeFunction& index, Interpreter& st) {
    if (array.dimensions.size() != 1)
        throw ValueError("an index that depends on clock into an array of " +
                         std::to_string(array.dimensions.size()) +
                         " dimensions; hexant picks elements by clock from one-dimensional arrays only");
    const TimeFunction step = TimeFunction::apply(TimeOp::Floor, index);
    std::vector<runtime::ValuePiece> pieces;
    try {
        pieces = runtime::split_by_value(step, st.domain.within(st.animation_time()),
                                         st.options.limits.time_pieces);
    } catch (const runtime::LimitError& e) {
        throw ValueError(std::string("an array index: ") + e.what());
    }
    std::map<double, std::vector<runtime::Interval>> by_value;
    for (const auto& piece : pieces) by_value[piece.value].push_back(piece.time);
    std::optional<Value> result;
    std::vector<runtime::Interval> result_times;
    for (const auto& [k, times] : by_value) {
        const std::size_t i = element_index(array, {k});
        if (!array.elements[i])
            throw ValueError("array element " + std::to_string(i) + " is used (by clock) before it is set");
        const Value& element = **array.elements[i];
        const runtime::Lifetime when = runtime::Lifetime::of(times);
        if (!result) {
            result = by_value.size() == 1 ? element : during(element, when);
        } else {
            result = merge_sides("the element picked by clock",
                                 TimeFunction::apply(TimeOp::Equal, step, k), element, when, result,
                                 runtime::Lifetime::of(result_times));
        }
        result_times.insert(result_times.end(), times.begin(), times.end());
    }
    if (!result) throw ValueError("an array index that depends on clock, over no time");
    return *result;
}

HEXANT_ACTION(index_suffix) {
    HEXANT_APPLY {
        (void)in;
        const TimeFunction index_f = to_float(st.pop(), "an array index");
        Value a = st.pop();
        if (!a.is<std::shared_ptr<Array>>()) throw ValueError("'[ ]' needs an array, not a " + type_name(a));
        auto array = a.as<std::shared_ptr<Array>>();
        if (index_f.depends_on_time()) {
            st.push(element_by_clock(*array, index_f, st));
            return;
        }
        const double index = index_f.constant();
        if (array->dimensions.size() > 1) {
            // A[i] of a many-dimensional array: the sub-array.
            const int rows = array->dimensions[0];
            const long long row = checked_integer(std::floor(index), "an array index", 0, rows - 1);
            auto sub = std::make_shared<Array>();
            sub->charge.attach(st.array_memory());
            sub->dimensions.assign(array->dimensions.begin() + 1, array->dimensions.end());
            const std::size_t stride = array->elements.size() / static_cast<std::size_t>(rows);
            sub->charge.add(stride * kArraySlotBytes);
            const std::size_t start = static_cast<std::size_t>(row) * stride;
            sub->elements.assign(array->elements.begin() + static_cast<std::ptrdiff_t>(start),
                                 array->elements.begin() + static_cast<std::ptrdiff_t>(start + stride));
            st.push(Value{sub});
            return;
        }
        const std::size_t i = element_index(*array, {index});
        if (!array->elements[i]) throw ValueError("array element " + std::to_string(i) + " is used before it is set");
        st.push(**array->elements[i]);
    }
};

HEXANT_ACTION(spline_call) {
    HEXANT_APPLY {
        (void)in;
        std::vector<Value> args = st.close_frame();
        Value s = st.pop();
        if (!s.is<std::shared_ptr<const runtime::Spline>>())
            throw ValueError("only a spline can be called like this, not a " + type_name(s));
        if (args.empty() || args.size() > 2) throw ValueError("a spline takes one argument, the time");
        const auto spline = s.as<std::shared_ptr<const runtime::Spline>>();
        const TimeFunction t = to_float(args[0], "the spline's argument");
        // POV-Ray's S(t) is a vector even for a spline of floats (the value in .x).
        Vector v;
        v.size = std::max(spline->dimensions(), 2);
        for (int i = 0; i < v.size; ++i) v.c[i] = TimeFunction::spline_component(spline, i, t);
        st.push(Value{v});
    }
};

// ------------------------------------------------------------ operators

template <TimeOp Op>
struct unary_action {
    HEXANT_APPLY { (void)in; st.push(unary_op(Op, st.pop())); }
};
template <> struct action<g::negation> : unary_action<TimeOp::Negate> {};
template <> struct action<g::logical_not> : unary_action<TimeOp::Not> {};

template <TimeOp Op>
struct binary_action {
    HEXANT_APPLY {
        (void)in;
        Value b = st.pop();
        Value a = st.pop();
        st.push(binary_op(Op, a, b));
    }
};
template <> struct action<g::multiplication> : binary_action<TimeOp::Multiply> {};
template <> struct action<g::division> : binary_action<TimeOp::Divide> {};
template <> struct action<g::addition> : binary_action<TimeOp::Add> {};
template <> struct action<g::subtraction> : binary_action<TimeOp::Subtract> {};
template <> struct action<g::less_equal> : binary_action<TimeOp::LessEqual> {};
template <> struct action<g::greater_equal> : binary_action<TimeOp::GreaterEqual> {};
template <> struct action<g::not_equal> : binary_action<TimeOp::NotEqual> {};
template <> struct action<g::less> : binary_action<TimeOp::Less> {};
template <> struct action<g::greater> : binary_action<TimeOp::Greater> {};
template <> struct action<g::equal> : binary_action<TimeOp::Equal> {};
template <> struct action<g::logical_and> : binary_action<TimeOp::And> {};
template <> struct action<g::logical_or> : binary_action<TimeOp::Or> {};

HEXANT_ACTION(conditional_tail) {
    HEXANT_APPLY {
        (void)in;
        Value c = st.pop();
        Value b = st.pop();
        Value a = st.pop();
        st.push(conditional(a, b, c));
    }
};

// ------------------------------------------------------------ directives

HEXANT_ACTION(declare_directive) {
    HEXANT_APPLY {
        std::vector<Value> frame = st.close_frame();  // indices..., value
        Value value = std::move(frame.back());
        frame.pop_back();
        const std::string name = st.pop_name();
        const bool local = st.pop_name() == "local";
        if (value.is<std::shared_ptr<Array>>())
            value = Value{std::make_shared<Array>(*value.as<std::shared_ptr<Array>>())};
        if (frame.empty()) {
            st.declare(name, std::move(value), local);
        } else {
            st.assign_element(name, frame, std::move(value), in.position());
        }
    }
};

HEXANT_ACTION(undef_name) {
    HEXANT_APPLY { st.undefine(word(in)); }
};

HEXANT_ACTION(version_value) {
    HEXANT_APPLY { (void)in; st.version = to_constant(st.pop(), "#version"); }
};

// A message's text that depends on clock: each piece's text, after the
// time it is said for (POV-Ray says it once a frame, at that frame's clock).
inline std::string message_text(const Value& value, const char* what) {
    if (!value.is<TimedString>()) return to_string_value(value, what);
    std::ostringstream out;
    out << std::setprecision(17);
    for (const auto& piece : value.as<TimedString>().pieces) {
        out << "[clock " << piece.time.lo << " to " << piece.time.hi << "] " << piece.text;
        // (One line a piece, whether or not the text ends its line.)
        if (piece.text.empty() || piece.text.back() != '\n') out << '\n';
    }
    return out.str();
}

HEXANT_ACTION(debug_directive) {
    HEXANT_APPLY { (void)in; st.messages() << message_text(st.pop(), "#debug's text"); }
};

HEXANT_ACTION(warning_directive) {
    HEXANT_APPLY { st.warn(in.position(), message_text(st.pop(), "#warning's text")); }
};

HEXANT_ACTION(error_directive) {
    HEXANT_APPLY { Interpreter::fail(in.position(), "#error: " + message_text(st.pop(), "#error's text")); }
};

HEXANT_ACTION(unsupported_directive) {
    HEXANT_APPLY { Interpreter::fail(in.position(), "#" + word(in) + " is not supported by hexant"); }
};

HEXANT_ACTION(unknown_directive) {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter&) {
        const char* b = in.begin();
        const char* e = in.input().end();
        const char* q = b;
        while (q != e && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
        Interpreter::fail(in.position(), "unknown directive '#" + std::string(b, q) + "'");
    }
};

HEXANT_ACTION(default_item) {
    HEXANT_APPLY {
        st.require_whole_time(in.position(), "#default");
        Value v = st.pop();
        auto& texture = st.scene.default_texture;
        if (v.is<runtime::Texture>()) texture = v.as<runtime::Texture>();
        else if (v.is<runtime::Pigment>()) texture.pigment = v.as<runtime::Pigment>();
        else if (v.is<runtime::Finish>()) texture.finish = v.as<runtime::Finish>();
        // Checked here, at the #default: the objects that take it are
        // checked for their own parameters only.
        if (auto problem = runtime::bad_parameter(texture, "the #default", st.scene.animation))
            Interpreter::fail(in.position(), *problem);
    }
};

// ------------------------------------------------------------ transformations

inline runtime::TransformStep make_step(TransformKind kind, const runtime::Vector3Function& v) {
    runtime::TransformStep step;
    step.kind = kind;
    step.vector = v;
    return step;
}

HEXANT_ACTION(translate_step) {
    HEXANT_APPLY { st.apply_transform(make_step(TransformKind::Translate, to_vector3(st.pop(), "translate's amount")), in.position()); }
};
HEXANT_ACTION(rotate_step) {
    HEXANT_APPLY { st.apply_transform(make_step(TransformKind::Rotate, to_vector3(st.pop(), "rotate's angles")), in.position()); }
};
HEXANT_ACTION(scale_step) {
    HEXANT_APPLY {
        auto v = to_vector3(st.pop(), "scale's factors");
        // POV-Ray 3.7 warns and scales by 1 instead (parser_expressions.cpp);
        // a factor that only passes through 0 is handled where it is
        // evaluated (runtime/motion/motion.cpp, scale_factor).
        static const char* const kAxis[] = {"X", "Y", "Z"};
        for (int i = 0; i < 3; ++i)
            if (v.c[i].is_constant() && v.c[i].constant() == 0.0) {
                st.warn(in.position(), std::string("scale ") + kAxis[i] + " by 0.0: changed to 1.0, as POV-Ray does");
                v.c[i] = runtime::TimeFunction(1.0);
            }
        st.apply_transform(make_step(TransformKind::Scale, v), in.position());
    }
};
HEXANT_ACTION(matrix_step) {
    HEXANT_APPLY {
        std::vector<Value> entries = st.close_frame();
        if (entries.size() != 12)
            throw ValueError("matrix needs 12 numbers, not " + std::to_string(entries.size()));
        runtime::TransformStep step;
        step.kind = TransformKind::Matrix;
        for (int i = 0; i < 12; ++i) step.matrix[i] = to_float(entries[i], "a matrix entry");
        st.apply_transform(step, in.position());
    }
};
HEXANT_ACTION(transform_step) {
    HEXANT_APPLY {
        Value v = st.pop();
        if (!v.is<runtime::Transform>()) throw ValueError("transform needs a transform, not a " + type_name(v));
        for (const auto& step : v.as<runtime::Transform>().steps()) st.apply_transform(step, in.position());
    }
};
HEXANT_ACTION(transform_open) {
    HEXANT_APPLY { (void)in; st.blocks.emplace_back(std::in_place_type<runtime::Transform>); }
};
HEXANT_ACTION(transform_base) {
    HEXANT_APPLY {
        Value v = st.pop();
        if (!v.is<runtime::Transform>()) throw ValueError("transform { } starts with a transform, not a " + type_name(v));
        st.block<runtime::Transform>(in.position(), "a transform") = v.as<runtime::Transform>();
    }
};
HEXANT_ACTION(transform_inverse) {
    HEXANT_APPLY {
        auto& t = st.block<runtime::Transform>(in.position(), "inverse");
        t = t.inverse();
    }
};
HEXANT_ACTION(transform_block) {
    HEXANT_APPLY {
        (void)in;
        Value v{std::get<runtime::Transform>(st.blocks.back())};
        st.blocks.pop_back();
        st.push(std::move(v));
    }
};
HEXANT_ACTION(deformation) {
    HEXANT_APPLY {
        const TimeFunction amount = to_float(st.pop(), "the deformation's amount");
        const auto axis = to_vector3(st.pop(), "the deformation's axis");
        const std::string name = st.pop_name();
        runtime::TransformStep step;
        step.kind = name == "twist" ? TransformKind::Twist : name == "taper" ? TransformKind::Taper : TransformKind::Bend;
        step.vector = axis;
        step.amount = amount;
        st.apply_deformation(step, in.position());
    }
};

// ------------------------------------------------------------ textures

// The pigment or normal an object, a texture or the camera already has:
// a second pigment { } there modifies it (POV-Ray parses into the one it
// has), it does not start over.
inline const runtime::Texture* texture_being_written(const Interpreter& st) {
    if (st.blocks.empty()) return nullptr;
    if (const auto* t = std::get_if<runtime::Texture>(&st.blocks.back())) return t;
    if (const auto* o = std::get_if<runtime::ObjectRecord>(&st.blocks.back()))
        return o->texture ? &*o->texture : nullptr;
    return nullptr;
}

HEXANT_ACTION(pigment_open) {
    HEXANT_APPLY {
        (void)in;
        const runtime::Texture* texture = texture_being_written(st);
        runtime::Pigment start = texture ? texture->pigment : runtime::Pigment();
        st.blocks.emplace_back(std::move(start));
    }
};
HEXANT_ACTION(pigment_base) {
    HEXANT_APPLY {
        Value v = st.pop();
        auto& pigment = st.block<runtime::Pigment>(in.position(), "a pigment");
        if (v.is<runtime::Pigment>()) {
            pigment = v.as<runtime::Pigment>();
        } else {
            pigment = runtime::Pigment();
            pigment.colours = {to_colour(v, "a pigment")};
        }
    }
};
// ---- patterns (runtime/texture/pattern/pattern.hpp), in a pigment or a normal

// The pattern being written: a pigment's, a normal's or a texture's.
struct PatternSlot {
    runtime::pattern::Pattern& pattern;
    runtime::Transform& transform;
    runtime::Pigment* pigment = nullptr;  // (one of the three)
    runtime::Normal* normal = nullptr;
    runtime::Texture* texture = nullptr;
};
// (`starts` for the pattern's name itself: in a texture, a modifier comes
// after it.)
// A uv-mapped block, once written, takes no transforms from outside it.
inline void close_uv_mapping(runtime::UvMapping& m) {
    if (m == runtime::UvMapping::Open) m = runtime::UvMapping::Closed;
}
// A new pattern written over a uv-mapped pigment or normal of an earlier
// block (a second pigment { } on the object): POV-Ray's Parse_Pattern
// replaces the uv map, and the transforms that lived inside it go with it.
template <class Record>
void replace_uv_mapping(Record& r) {
    if (r.uv_mapping != runtime::UvMapping::Closed) return;
    r.uv_mapping = runtime::UvMapping::Off;
    r.transform = {};
}

inline PatternSlot pattern_slot(Interpreter& st, const p::position& at, const char* what, bool starts = false) {
    if (!st.blocks.empty()) {
        if (auto* n = std::get_if<runtime::Normal>(&st.blocks.back())) return {n->patterned, n->transform, nullptr, n};
        if (auto* t = std::get_if<runtime::Texture>(&st.blocks.back())) {
            if (t->patterned.kind == nullptr && !starts)
                throw ValueError(std::string(what) + " in a texture follows a pattern (texture { PATTERN texture_map { } })");
            return {t->patterned, t->transform, nullptr, nullptr, t};
        }
    }
    auto& pigment = st.block<runtime::Pigment>(at, what);
    return {pigment.patterned, pigment.transform, &pigment};
}

HEXANT_ACTION(pattern_kind) {
    HEXANT_APPLY {
        std::vector<Value> args = st.close_frame();
        const std::string name = st.pop_name();
        const PatternSlot slot = pattern_slot(st, in.position(), "a pattern", true);
        const runtime::pattern::Kind* kind = runtime::pattern::find_kind(name);
        if (kind == nullptr) throw ValueError("no pattern " + name);
        if (slot.pigment) replace_uv_mapping(*slot.pigment);
        if (slot.normal) replace_uv_mapping(*slot.normal);
        slot.pattern = runtime::pattern::Pattern::of(*kind);
        // (The scene's noise generator, global_settings { noise_generator }.)
        slot.pattern.noise_generator = st.scene.global.noise_generator;
        ++st.patterns_written;
        if (slot.pigment) {
            slot.pigment->pattern = runtime::Pigment::Pattern::Patterned;
            slot.pigment->colour_map = {};
        }
        if (slot.texture) {
            // (POV-Ray: a texture is plain or patterned; a pattern after
            // its layers or in a declared plain one starts it over.)
            if (!slot.texture->below.empty())
                throw ValueError("a layered texture cannot take a pattern (" + name + ")");
            slot.texture->texture_map.clear();
        }
        using A = runtime::pattern::Kind::Argument;
        // In a normal, one more number may follow: the amount (bump_size).
        const std::size_t own = kind->argument == A::Vector || kind->argument == A::Number ? 1 : 0;
        if (slot.normal && args.size() == own + 1) {
            slot.normal->amount = to_float(args.back(), name + "'s amount");
            args.pop_back();
        }
        const auto count = [&](std::size_t lo, std::size_t hi, const char* what) {
            if (args.size() < lo || args.size() > hi)
                throw ValueError(name + " takes " + what + ", not " + std::to_string(args.size()) + " values");
        };
        switch (kind->argument) {
            case A::None: count(0, 0, slot.normal ? "at most an amount" : "no value after it"); break;
            case A::Vector: {
                count(1, 1, "one vector (its direction)");
                // POV-Ray normalizes the direction.
                const runtime::Vector3Function v = to_vector3(args[0], name + "'s direction");
                const TimeFunction length = TimeFunction::apply(
                    TimeOp::Sqrt, v.c[0] * v.c[0] + v.c[1] * v.c[1] + v.c[2] * v.c[2]);
                if (length.is_constant() && length.constant() == 0.0)
                    throw ValueError(name + "'s direction is the zero vector");
                for (int i = 0; i < 3; ++i) slot.pattern.vector.c[i] = v.c[i] / length;
                break;
            }
            case A::Number:
                count(1, 1, "one number");
                // (POV-Ray keeps the arms and the iterations as integers.)
                slot.pattern.number[0] = TimeFunction::apply(TimeOp::Int, to_float(args[0], name + "'s number"));
                break;
            case A::Colours: {
                // (In a normal or a texture, the normals or textures follow
                // as blocks.)
                if (slot.normal) {
                    count(0, 0, "at most an amount in a normal");
                    break;
                }
                if (slot.texture) {
                    count(0, 0, "its textures as texture { } blocks");
                    break;
                }
                count(0, static_cast<std::size_t>(kind->colours),
                      ("at most " + std::to_string(kind->colours) + " colours").c_str());
                // A blend list: colour i at value i, the kind's default
                // where none is given.
                for (std::size_t i = 0; i < static_cast<std::size_t>(kind->colours); ++i) {
                    runtime::ColourMapEntry e;
                    e.value = static_cast<double>(i);
                    if (i < args.size()) {
                        e.colour = to_colour(args[i], name + "'s colour " + std::to_string(i + 1));
                    } else {
                        const auto& d = kind->default_map[i].colour;
                        e.colour = runtime::ColourFunction{{d[0], d[1], d[2], d[3], d[4]}};
                    }
                    slot.pigment->colour_map.entries.push_back(std::move(e));
                }
                break;
            }
        }
    }
};

// A kind's own modifier, as its file under runtime/texture/pattern/kinds/
// declares it (POV-Ray refuses one the pattern does not have).
inline void set_kind_setting(runtime::pattern::Pattern& pattern, const std::string& name, const Value& v) {
    namespace pt = runtime::pattern;
    const pt::Setting* setting = pattern.kind ? pt::find_setting(*pattern.kind, name) : nullptr;
    if (setting == nullptr) {
        std::string owners;
        for (const pt::Kind* k : pt::all_kinds())
            if (pt::find_setting(*k, name)) owners += (owners.empty() ? "" : " or ") + std::string(k->name);
        throw ValueError(name + " belongs to " + owners + ", not to " +
                         (pattern.kind ? std::string(pattern.kind->name) : std::string("a plain colour")));
    }
    if (setting->type == pt::Setting::Type::Vector) {
        const runtime::Vector3Function value = to_vector3(v, name);
        if (setting->constant && value.depends_on_time()) throw ValueError(name + " cannot move with clock");
        pattern.vector = value;
        return;
    }
    const TimeFunction value = to_float(v, name);
    if (setting->constant && value.depends_on_time()) throw ValueError(name + " cannot move with clock");
    pattern.number[static_cast<std::size_t>(setting->slot)] = value;
}

HEXANT_ACTION(pattern_setting) {
    HEXANT_APPLY {
        Value v = st.pop();
        const std::string name = st.pop_name();
        const PatternSlot slot = pattern_slot(st, in.position(), name.c_str());
        runtime::pattern::Pattern& pattern = slot.pattern;
        // Classic turbulence, made by the first of its settings (POV-Ray's Check_Turb).
        const auto turbulence = [&]() -> runtime::pattern::Turbulence& {
            if (!pattern.turbulence) pattern.turbulence.emplace();
            return *pattern.turbulence;
        };
        if (name == "frequency") pattern.frequency = to_float(v, "frequency");
        else if (name == "phase") pattern.phase = to_float(v, "phase");
        else if (name == "turbulence") turbulence().amount = to_vector3(v, "turbulence");
        else if (name == "octaves") turbulence().octaves = to_float(v, "octaves");
        else if (name == "omega") turbulence().omega = to_float(v, "omega");
        else if (name == "lambda") turbulence().lambda = to_float(v, "lambda");
        else if (name == "noise_generator") {
            pattern.noise_generator =
                static_cast<int>(checked_integer(to_constant(v, "noise_generator"), "noise_generator", 1, 3));
        } else {
            set_kind_setting(pattern, name, v);
        }
    }
};

HEXANT_ACTION(pattern_wave) {
    HEXANT_APPLY {
        std::vector<Value> args = st.close_frame();
        const std::string name = st.pop_name();
        runtime::pattern::Pattern& pattern = pattern_slot(st, in.position(), name.c_str()).pattern;
        using W = runtime::pattern::Wave;
        if (name != "poly_wave" && !args.empty()) throw ValueError(name + " takes no value");
        pattern.wave = name == "ramp_wave"       ? W::Ramp
                       : name == "sine_wave"     ? W::Sine
                       : name == "triangle_wave" ? W::Triangle
                       : name == "scallop_wave"  ? W::Scallop
                       : name == "cubic_wave"    ? W::Cubic
                                                 : W::Poly;
        if (name == "poly_wave") pattern.exponent = args.empty() ? TimeFunction(1.0) : to_float(args[0], "poly_wave");
    }
};

HEXANT_ACTION(warp_open) {
    HEXANT_APPLY {
        // The transforms written so far come before this warp (applied
        // after it, world to pattern): they become a step of their own.
        const PatternSlot slot = pattern_slot(st, in.position(), "warp");
        if (!slot.transform.empty()) {
            runtime::pattern::Warp step;
            step.transform = slot.transform;
            slot.pattern.warps.push_back(std::move(step));
            slot.transform = {};
        }
        slot.pattern.warps.push_back(runtime::pattern::Warp{});
    }
};
HEXANT_ACTION(warp_turbulence) {
    HEXANT_APPLY {
        Value v = st.pop();
        pattern_slot(st, in.position(), "warp").pattern.warps.back().turbulence.amount =
            to_vector3(v, "warp's turbulence");
    }
};
HEXANT_ACTION(warp_setting) {
    HEXANT_APPLY {
        Value v = st.pop();
        const std::string name = st.pop_name();
        auto& turbulence = pattern_slot(st, in.position(), "warp").pattern.warps.back().turbulence;
        if (name == "octaves") turbulence.octaves = to_float(v, "octaves");
        else if (name == "omega") turbulence.omega = to_float(v, "omega");
        else turbulence.lambda = to_float(v, "lambda");
    }
};


// ---- normal { }
HEXANT_ACTION(normal_open) {
    HEXANT_APPLY {
        (void)in;
        std::optional<runtime::Normal> start;
        if (const runtime::Texture* texture = texture_being_written(st)) start = texture->normal;
        else if (!st.blocks.empty())
            if (const auto* camera = std::get_if<runtime::CameraRecord>(&st.blocks.back())) start = camera->normal;
        st.blocks.emplace_back(start ? std::move(*start) : runtime::Normal());
    }
};
HEXANT_ACTION(normal_base) {
    HEXANT_APPLY {
        Value v = st.pop();
        if (!v.is<runtime::Normal>()) throw ValueError("normal { } starts with a normal, not a " + type_name(v));
        st.block<runtime::Normal>(in.position(), "a normal") = v.as<runtime::Normal>();
    }
};
HEXANT_ACTION(normal_setting) {
    HEXANT_APPLY {
        Value v = st.pop();
        const std::string name = st.pop_name();
        auto& normal = st.block<runtime::Normal>(in.position(), name.c_str());
        if (name == "bump_size") normal.amount = to_float(v, "bump_size");
        else normal.accuracy = to_float(v, "accuracy");
    }
};
HEXANT_ACTION(normal_no_bump_scale) {
    HEXANT_APPLY { st.block<runtime::Normal>(in.position(), "no_bump_scale").no_bump_scale = true; }
};
HEXANT_ACTION(normal_block) {
    HEXANT_APPLY {
        auto& normal = st.block<runtime::Normal>(in.position(), "a normal");
        if (normal.patterned.kind == nullptr && normal.unsupported_name.empty())
            throw ValueError("a normal needs a pattern (POV-Ray: no normal type given)");
        close_uv_mapping(normal.uv_mapping);
        Value v{std::move(normal)};
        st.blocks.pop_back();
        st.push(std::move(v));
    }
};
HEXANT_ACTION(texture_normal) {
    HEXANT_APPLY { Value v = st.pop(); st.block<runtime::Texture>(in.position(), "normal").normal = v.as<runtime::Normal>(); }
};
HEXANT_ACTION(camera_normal) {
    HEXANT_APPLY {
        Value v = st.pop();
        check_normal(v.as<runtime::Normal>());
        // (POV-Ray: "The 'uv_mapping' pattern cannot be used" without a surface.)
        if (v.as<runtime::Normal>().uv_mapping != runtime::UvMapping::Off)
            throw ValueError("uv_mapping needs a surface's (u, v): not in the camera's normal");
        st.block<runtime::CameraRecord>(in.position(), "normal").normal = v.as<runtime::Normal>();
    }
};

// A texture's pattern has its map (POV-Ray: "Patterned texture must have
// texture_map"), a block pattern all its textures.
inline void check_patterned_texture(const runtime::Texture& t) {
    if (t.patterned.kind == nullptr) return;
    if (t.texture_map.empty())
        throw ValueError("a texture with a pattern (" + std::string(t.patterned.kind->name) +
                         ") needs a texture_map, as in POV-Ray");
    using A = runtime::pattern::Kind::Argument;
    if (t.patterned.kind->argument == A::Colours &&
        t.texture_map.size() < static_cast<std::size_t>(t.patterned.kind->colours))
        throw ValueError(std::string(t.patterned.kind->name) + " in a texture needs " +
                         std::to_string(t.patterned.kind->colours) + " textures, not " +
                         std::to_string(t.texture_map.size()));
}

// `top` layered over `under` (POV-Ray's Link_Textures): top's layers, then
// under's. Nothing is layered over or under a patterned texture.
inline runtime::Texture layered(runtime::Texture top, runtime::Texture under) {
    if (under.is_patterned())
        throw ValueError("a texture cannot be layered over a patterned one (texture_map), as in POV-Ray");
    if (top.is_patterned())
        throw ValueError("a patterned texture (texture_map) cannot be layered over another, as in POV-Ray");
    std::vector<runtime::Texture> lower = std::move(under.below);
    under.below.clear();
    top.below.push_back(std::move(under));
    for (auto& layer : lower) top.below.push_back(std::move(layer));
    return top;
}

// ---- maps of pigments, normals and textures, and block patterns' lists

// A map entry's block closed (a pigment, normal or texture): it and the
// value written before it become an entry of the map of the block around
// it, at most 256 as in POV-Ray.
template <class Record, class Entry>
void close_map_entry(Interpreter& st, const p::position& at, const std::string& map,
                     std::vector<Entry> Record::*entries) {
    const std::string what = "a " + map + " entry";
    auto entry = std::make_shared<Record>(std::move(st.block<Record>(at, what.c_str())));
    st.blocks.pop_back();
    const TimeFunction value = to_float(st.pop(), what + "'s value");
    auto& outer = st.block<Record>(at, what.c_str());
    (outer.*entries).push_back({value, std::move(entry)});
    if ((outer.*entries).size() > 256) throw ValueError("a " + map + " has at most 256 entries, as in POV-Ray");
}

// A normal or texture for a block pattern (checker normal { } normal { }):
// its map's entries at 0, 1, 2 (POV-Ray's Parse_Blend_List).
template <class Entry, class Item>
void add_to_block_list(std::vector<Entry>& map, const runtime::pattern::Pattern& pattern, Item item,
                       const char* what) {
    using A = runtime::pattern::Kind::Argument;
    if (pattern.kind == nullptr || pattern.kind->argument != A::Colours)
        throw ValueError(std::string("a ") + what + " inside a " + what +
                         " follows a block pattern (checker, brick, hexagon) as one of its " + what + "s");
    if (map.size() >= static_cast<std::size_t>(pattern.kind->colours))
        throw ValueError(std::string(pattern.kind->name) + " takes at most " + std::to_string(pattern.kind->colours) +
                         " " + what + "s");
    map.push_back({static_cast<double>(map.size()), std::move(item)});
}
// A map's pattern must be one that gives values (POV-Ray refuses the block
// patterns with a map).
inline void check_map_pattern(const runtime::pattern::Pattern& pattern, const char* map) {
    if (pattern.kind && pattern.kind->argument == runtime::pattern::Kind::Argument::Colours)
        throw ValueError(std::string("a ") + map + " cannot go with " + std::string(pattern.kind->name) +
                         ", as in POV-Ray");
}

HEXANT_ACTION(pigment_list_pigment) {
    HEXANT_APPLY {
        auto entry = std::make_shared<runtime::Pigment>(st.pop().as<runtime::Pigment>());
        auto& outer = st.block<runtime::Pigment>(in.position(), "a pigment");
        add_to_block_list(outer.pigment_map, outer.patterned,
                          std::shared_ptr<const runtime::Pigment>(std::move(entry)), "pigment");
    }
};
HEXANT_ACTION(normal_map_open) {
    HEXANT_APPLY {
        auto& normal = st.block<runtime::Normal>(in.position(), "normal_map");
        check_map_pattern(normal.patterned, "normal_map");
        normal.normal_map.clear();
    }
};
HEXANT_ACTION(normal_map_normal_open) {
    HEXANT_APPLY { (void)in; st.blocks.emplace_back(std::in_place_type<runtime::Normal>); }
};
HEXANT_ACTION(normal_map_entry) {
    HEXANT_APPLY {
        auto& written = st.block<runtime::Normal>(in.position(), "a normal_map entry");
        if (written.patterned.kind == nullptr && written.unsupported_name.empty())
            throw ValueError("a normal_map entry needs a pattern (POV-Ray: no normal type given)");
        close_map_entry(st, in.position(), "normal_map", &runtime::Normal::normal_map);
    }
};
HEXANT_ACTION(normal_list_normal) {
    HEXANT_APPLY {
        auto entry = std::make_shared<runtime::Normal>(st.pop().as<runtime::Normal>());
        auto& outer = st.block<runtime::Normal>(in.position(), "a normal");
        add_to_block_list(outer.normal_map, outer.patterned, std::shared_ptr<const runtime::Normal>(std::move(entry)),
                          "normal");
    }
};
HEXANT_ACTION(slope_map_open) {
    HEXANT_APPLY {
        auto& normal = st.block<runtime::Normal>(in.position(), "slope_map");
        check_map_pattern(normal.patterned, "slope_map");
        normal.slope_map.clear();
    }
};
HEXANT_ACTION(slope_map_entry) {
    HEXANT_APPLY {
        std::vector<Value> items = st.close_frame();
        // [value <height, slope>] (a 2-vector; a bare pair of numbers too).
        runtime::SlopeMapEntry e;
        if (items.size() == 2) {
            e.value = to_float(items[0], "a slope_map entry's value");
            const runtime::Vector3Function hs = to_vector3(items[1], "a slope_map entry's <height, slope>");
            e.height = hs.c[0];
            e.slope = hs.c[1];
        } else {
            throw ValueError("a slope_map entry is [value <height, slope>], not " + std::to_string(items.size()) +
                             " values");
        }
        auto& normal = st.block<runtime::Normal>(in.position(), "a slope_map entry");
        normal.slope_map.push_back(std::move(e));
        if (normal.slope_map.size() > 256) throw ValueError("a slope_map has at most 256 entries, as in POV-Ray");
    }
};

HEXANT_ACTION(texture_map_open) {
    HEXANT_APPLY {
        auto& texture = st.block<runtime::Texture>(in.position(), "texture_map");
        if (texture.patterned.kind == nullptr)
            throw ValueError("a texture_map follows its pattern (texture { PATTERN texture_map { } })");
        check_map_pattern(texture.patterned, "texture_map");
        texture.texture_map.clear();
    }
};
HEXANT_ACTION(texture_map_texture_open) {
    HEXANT_APPLY { (void)in; st.blocks.emplace_back(std::in_place_type<runtime::Texture>); }
};
HEXANT_ACTION(texture_map_entry) {
    HEXANT_APPLY {
        auto& written = st.block<runtime::Texture>(in.position(), "a texture_map entry");
        check_patterned_texture(written);
        close_map_entry(st, in.position(), "texture_map", &runtime::Texture::texture_map);
    }
};
HEXANT_ACTION(texture_list_texture) {
    HEXANT_APPLY {
        auto entry = std::make_shared<runtime::Texture>(st.pop().as<runtime::Texture>());
        auto& outer = st.block<runtime::Texture>(in.position(), "a texture");
        add_to_block_list(outer.texture_map, outer.patterned,
                          std::shared_ptr<const runtime::Texture>(std::move(entry)), "texture");
    }
};

HEXANT_ACTION(pigment_map_open) {
    HEXANT_APPLY {
        auto& pigment = st.block<runtime::Pigment>(in.position(), "pigment_map");
        if (pigment.patterned.kind && pigment.patterned.kind->argument == runtime::pattern::Kind::Argument::Colours)
            throw ValueError(std::string("a pigment_map cannot go with ") + std::string(pigment.patterned.kind->name) +
                             ", as in POV-Ray");
        pigment.pigment_map.clear();
    }
};
HEXANT_ACTION(pigment_map_pigment_open) {
    HEXANT_APPLY { (void)in; st.blocks.emplace_back(std::in_place_type<runtime::Pigment>); }
};
HEXANT_ACTION(pigment_map_entry) {
    HEXANT_APPLY {
        close_map_entry(st, in.position(), "pigment_map", &runtime::Pigment::pigment_map);
    }
};

// ---- image_map { } (POV-Ray's Parse_Image, Parse_Image_Map)
HEXANT_ACTION(image_map_open) {
    HEXANT_APPLY {
        st.block<runtime::Pigment>(in.position(), "image_map");
        st.blocks.emplace_back(std::in_place_type<ImageMapBuilder>);
    }
};
HEXANT_ACTION(image_file_type) {
    HEXANT_APPLY {
        (void)st;
        // hexant reads PNG and OpenEXR (the file's own bytes say which).
        std::string type = in.string();
        while (!type.empty() && std::isspace(static_cast<unsigned char>(type.back()))) type.pop_back();
        if (type != "png" && type != "exr")
            throw UnsupportedError("image_map: " + type + " images are not supported by hexant (PNG and OpenEXR are)");
    }
};
HEXANT_ACTION(image_map_file) {
    HEXANT_APPLY {
        Value v = st.pop();
        auto& b = st.block<ImageMapBuilder>(in.position(), "image_map's file");
        const auto read = [&](const std::string& name) {
            const std::filesystem::path path = st.resolve_include(name, in.position(), "image file");
            try {
                return std::make_shared<const image::StoredImage>(image::read_stored_image(path));
            } catch (const std::runtime_error& e) {
                throw ValueError(std::string("image_map: ") + e.what());
            }
        };
        const runtime::Interval always(-std::numeric_limits<double>::infinity(),
                                       std::numeric_limits<double>::infinity());
        if (v.is<std::string>()) {
            b.map.file = v.as<std::string>();
            b.stored.push_back({always, read(b.map.file)});
        } else if (v.is<TimedString>()) {
            // An image sequence: each file read once, each piece of time
            // showing its own (the clock named where one fails).
            const TimedString& names = v.as<TimedString>();
            std::map<std::string, std::shared_ptr<const image::StoredImage>> files;
            for (const auto& piece : names.pieces) {
                auto& file = files[piece.text];
                if (!file) {
                    try {
                        file = read(piece.text);
                    } catch (const ValueError& e) {
                        throw ValueError(std::string(e.what()) + " [clock " + std::to_string(piece.time.lo) + " to " +
                                         std::to_string(piece.time.hi) + "]");
                    }
                }
                b.stored.push_back({piece.time, file});
            }
            b.map.file = names.describe();
        } else {
            throw ValueError("image_map's file is a string, not a " + type_name(v));
        }
    }
};
HEXANT_ACTION(image_map_gamma_srgb) {
    HEXANT_APPLY { st.block<ImageMapBuilder>(in.position(), "gamma").gamma_srgb_next = true; }
};
HEXANT_ACTION(image_map_gamma) {
    HEXANT_APPLY {
        auto& b = st.block<ImageMapBuilder>(in.position(), "gamma");
        if (b.gamma_srgb_next) {
            b.gamma = ImageGamma{std::nullopt, true};
            b.gamma_srgb_next = false;
            return;
        }
        const double g = to_constant(st.pop(), "gamma");
        if (!(g > 0.0) || !std::isfinite(g)) throw ValueError("an image's gamma must be positive, as in POV-Ray");
        b.gamma = ImageGamma{g, false};
    }
};
HEXANT_ACTION(image_map_setting) {
    HEXANT_APPLY {
        Value v = st.pop();
        const std::string name = st.pop_name();
        auto& b = st.block<ImageMapBuilder>(in.position(), name.c_str());
        using M = runtime::pattern::ImageMap;
        if (name == "map_type") {
            // (POV-Ray takes the integer part.)
            const double t = std::trunc(to_constant(v, "map_type"));
            if (t != 0.0 && t != 1.0 && t != 2.0 && t != 5.0)
                throw ValueError("map_type is 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus), as in POV-Ray");
            b.map.map_type = static_cast<M::MapType>(static_cast<int>(t));
        } else if (name == "interpolate") {
            const double t = std::trunc(to_constant(v, "interpolate"));
            if (t != 2.0 && t != 3.0 && t != 4.0)
                throw ValueError("interpolate is 2 (bilinear), 3 (bicubic) or 4 (normalized distance), as in POV-Ray");
            b.map.interpolate = static_cast<M::Interpolate>(static_cast<int>(t));
        } else if (name == "premultiplied") {
            // (PNG's alpha is not premultiplied; OpenEXR's is read as it is.)
            if (to_constant(v, "premultiplied") != 0.0)
                throw UnsupportedError("premultiplied alpha in an image_map is not supported by hexant");
        } else {
            const runtime::Vector3Function uv = to_vector3(v, name);
            const double u = to_constant(Value{uv.c[0]}, name), w = to_constant(Value{uv.c[1]}, name);
            if (name == "repeat") {
                if (!(u > 0.0) || !(w > 0.0)) throw ValueError("an image_map's repeat must be positive, as in POV-Ray");
                b.map.repeat_u = u;
                b.map.repeat_v = w;
            } else {
                b.map.offset_u = u;
                b.map.offset_v = w;
            }
        }
    }
};
HEXANT_ACTION(image_map_flag) {
    HEXANT_APPLY {
        std::string flag = in.string();
        while (!flag.empty() && std::isspace(static_cast<unsigned char>(flag.back()))) flag.pop_back();
        auto& b = st.block<ImageMapBuilder>(in.position(), flag.c_str());
        if (flag == "once") b.map.once = true;
        else if (flag == "use_index")
            throw UnsupportedError("use_index in an image_map is not supported by hexant (it reads colours)");
    }
};
HEXANT_ACTION(image_map_all) {
    HEXANT_APPLY { st.block<ImageMapBuilder>(in.position(), "all").all_next = true; }
};
HEXANT_ACTION(image_map_filter) {
    HEXANT_APPLY {
        std::vector<Value> args = st.close_frame();
        const std::string name = st.pop_name();
        auto& b = st.block<ImageMapBuilder>(in.position(), name.c_str());
        const bool all = b.all_next;
        b.all_next = false;
        if (!all || args.size() != 1)
            throw UnsupportedError(name + " of one palette entry is not supported by hexant (it reads a palette "
                                   "image's colours); " + name + " all AMOUNT is");
        (name == "filter" ? b.map.filter_all : b.map.transmit_all) = to_float(args[0], name + " all");
        if (name == "transmit") b.map.transmit_all_written = true;
    }
};
HEXANT_ACTION(image_map_block) {
    HEXANT_APPLY {
        ImageMapBuilder b = std::move(std::get<ImageMapBuilder>(st.blocks.back()));
        st.blocks.pop_back();
        auto map = std::make_shared<runtime::pattern::ImageMap>(std::move(b.map));
        // (Each distinct file decoded once.)
        std::map<const image::StoredImage*, std::shared_ptr<const runtime::pattern::ImagePixels>> decoded;
        for (const auto& [time, stored] : b.stored) {
            auto& pixels = decoded[stored.get()];
            if (!pixels)
                pixels = std::make_shared<const runtime::pattern::ImagePixels>(
                    image_pixels(*stored, b.gamma, st.scene.global.assumed_gamma));
            map->images.push_back({time, pixels});
        }
        auto& pigment = st.block<runtime::Pigment>(in.position(), "image_map");
        replace_uv_mapping(pigment);
        // (The pigment's modifiers, turbulence and warps, place the image.)
        pigment.pattern = runtime::Pigment::Pattern::Image;
        pigment.patterned.kind = nullptr;
        pigment.colour_map = {};
        pigment.pigment_map.clear();
        pigment.image_map = std::move(map);
    }
};

HEXANT_ACTION(colour_map_open) {
    HEXANT_APPLY { (void)in; st.blocks.emplace_back(std::in_place_type<runtime::ColourMap>); }
};
HEXANT_ACTION(colour_map_base) {
    HEXANT_APPLY {
        Value v = st.pop();
        if (!v.is<runtime::ColourMap>()) throw ValueError("color_map { } starts with a color_map, not a " + type_name(v));
        st.block<runtime::ColourMap>(in.position(), "a color_map") = v.as<runtime::ColourMap>();
    }
};
HEXANT_ACTION(colour_map_entry) {
    HEXANT_APPLY {
        std::vector<Value> items = st.close_frame();
        auto& map = st.block<runtime::ColourMap>(in.position(), "a color_map entry");
        // [value colour], or POV-Ray's older [value1, value2 colour1 colour2].
        if (items.size() == 2) {
            map.entries.push_back({to_float(items[0], "a color_map entry's value"),
                                   to_colour(items[1], "a color_map entry's colour")});
        } else if (items.size() == 4) {
            map.entries.push_back({to_float(items[0], "a color_map entry's first value"),
                                   to_colour(items[2], "a color_map entry's first colour")});
            map.entries.push_back({to_float(items[1], "a color_map entry's second value"),
                                   to_colour(items[3], "a color_map entry's second colour")});
        } else {
            throw ValueError("a color_map entry is [value colour] (or [value1, value2 colour1 colour2]), not " +
                             std::to_string(items.size()) + " values");
        }
        if (map.entries.size() > 256) throw ValueError("a color_map has at most 256 entries, as in POV-Ray");
    }
};
HEXANT_ACTION(colour_map_block) {
    HEXANT_APPLY {
        auto& map = st.block<runtime::ColourMap>(in.position(), "a color_map");
        if (map.entries.empty()) throw ValueError("a color_map needs at least one entry");
        Value v{std::move(map)};
        st.blocks.pop_back();
        st.push(std::move(v));
    }
};
HEXANT_ACTION(pigment_colour_map) {
    HEXANT_APPLY {
        Value v = st.pop();
        auto& pigment = st.block<runtime::Pigment>(in.position(), "color_map");
        if (pigment.patterned.kind && pigment.patterned.kind->argument == runtime::pattern::Kind::Argument::Colours)
            throw ValueError(std::string("a color_map cannot go with ") + std::string(pigment.patterned.kind->name) +
                             " (its colours follow its name), as in POV-Ray");
        pigment.colour_map = v.as<runtime::ColourMap>();
    }
};
HEXANT_ACTION(unsupported_pattern) {
    HEXANT_APPLY {
        if (!st.blocks.empty() && std::holds_alternative<runtime::Normal>(st.blocks.back())) {
            auto& normal = st.block<runtime::Normal>(in.position(), "a pattern");
            normal.unsupported_name = st.pop_name();
            normal.unsupported_place = {in.position().source, in.position().line, in.position().column};
            return;
        }
        auto& pigment = st.block<runtime::Pigment>(in.position(), "a pattern");
        pigment.pattern = runtime::Pigment::Pattern::Unsupported;
        pigment.unsupported_name = st.pop_name();
        pigment.unsupported_place = {in.position().source, in.position().line, in.position().column};
    }
};
HEXANT_ACTION(pigment_block) {
    HEXANT_APPLY {
        (void)in;
        auto& pigment = std::get<runtime::Pigment>(st.blocks.back());
        // A block pattern given fewer pigments than it takes: the rest are
        // its default colours (POV-Ray's Parse_Blend_List).
        const auto* kind = pigment.patterned.kind;
        if (kind && kind->argument == runtime::pattern::Kind::Argument::Colours && !pigment.pigment_map.empty())
            for (std::size_t i = pigment.pigment_map.size(); i < pigment.colour_map.entries.size(); ++i) {
                auto solid = std::make_shared<runtime::Pigment>();
                solid->colours = {pigment.colour_map.entries[i].colour};
                pigment.pigment_map.push_back({static_cast<double>(i), std::move(solid)});
            }
        close_uv_mapping(pigment.uv_mapping);
        Value v{pigment};
        st.blocks.pop_back();
        st.push(std::move(v));
    }
};

HEXANT_ACTION(finish_open) {
    HEXANT_APPLY { (void)in; st.blocks.emplace_back(std::in_place_type<runtime::Finish>); }
};
HEXANT_ACTION(finish_base) {
    HEXANT_APPLY {
        Value v = st.pop();
        if (!v.is<runtime::Finish>()) throw ValueError("finish { } starts with a finish, not a " + type_name(v));
        st.block<runtime::Finish>(in.position(), "a finish") = v.as<runtime::Finish>();
    }
};
HEXANT_ACTION(finish_setting) {
    HEXANT_APPLY {
        Value v = st.pop();
        const std::string name = st.pop_name();
        auto& f = st.block<runtime::Finish>(in.position(), name.c_str());
        TimeFunction x;
        if (v.is<Vector>()) {
            // A colour amount (ambient rgb <..>): hexant keeps its mean.
            const auto c = to_colour(v, name);
            x = (c.c[0] + c.c[1] + c.c[2]) / 3.0;
        } else {
            x = to_float(v, name);
        }
        if (name == "ambient") f.ambient = x;
        else if (name == "diffuse") f.diffuse = x;
        else if (name == "brilliance") f.brilliance = x;
        else if (name == "phong") f.phong = x;
        else if (name == "phong_size") f.phong_size = x;
        else if (name == "specular") f.specular = x;
        else if (name == "roughness") f.roughness = x;
        else if (name == "emission") f.emission = x;
        // crand and metallic are read and ignored.
    }
};
HEXANT_ACTION(reflection_value) {
    HEXANT_APPLY {
        Value v = st.pop();
        auto& f = st.block<runtime::Finish>(in.position(), "reflection");
        if (v.is<TimeFunction>()) {
            const TimeFunction x = v.as<TimeFunction>();
            f.reflection = runtime::ColourFunction{{x, x, x, 0.0, 0.0}};
        } else {
            f.reflection = to_colour(v, "reflection");
            f.reflection.c[3] = f.reflection.c[4] = 0.0;
        }
    }
};
HEXANT_ACTION(ignored_value) {
    HEXANT_APPLY { (void)in; st.pop(); }
};
HEXANT_ACTION(finish_block) {
    HEXANT_APPLY {
        (void)in;
        Value v{std::get<runtime::Finish>(st.blocks.back())};
        st.blocks.pop_back();
        st.push(std::move(v));
    }
};

HEXANT_ACTION(interior_open) {
    HEXANT_APPLY { (void)in; st.blocks.emplace_back(std::in_place_type<runtime::Interior>); }
};
HEXANT_ACTION(interior_base) {
    HEXANT_APPLY {
        Value v = st.pop();
        if (!v.is<runtime::Interior>()) throw ValueError("interior { } starts with an interior, not a " + type_name(v));
        st.block<runtime::Interior>(in.position(), "an interior") = v.as<runtime::Interior>();
    }
};
HEXANT_ACTION(ior_setting) {
    HEXANT_APPLY { st.block<runtime::Interior>(in.position(), "ior").ior = to_float(st.pop(), "ior"); }
};
HEXANT_ACTION(interior_block) {
    HEXANT_APPLY {
        (void)in;
        Value v{std::get<runtime::Interior>(st.blocks.back())};
        st.blocks.pop_back();
        st.push(std::move(v));
    }
};

// uv_mapping: the pigment, normal or texture being written reads (u, v, 0).
HEXANT_ACTION(uv_mapping) {
    HEXANT_APPLY {
        if (st.blocks.empty()) throw ValueError("uv_mapping belongs in a pigment, a normal or a texture");
        auto& b = st.blocks.back();
        // (What follows is a pigment or normal of its own, POV-Ray's
        // Parse_Item_Into_Blend_List from the default: nothing written
        // before in this block, or in one it modifies, carries over.)
        if (auto* pigment = std::get_if<runtime::Pigment>(&b)) {
            *pigment = runtime::Pigment();
            pigment->uv_mapping = runtime::UvMapping::Open;
        } else if (auto* normal = std::get_if<runtime::Normal>(&b)) {
            *normal = runtime::Normal();
            normal->uv_mapping = runtime::UvMapping::Open;
        }
        else if (auto* texture = std::get_if<runtime::Texture>(&b)) texture->uv_mapping = runtime::UvMapping::Open;
        else throw ValueError("uv_mapping belongs in a pigment, a normal or a texture");
        (void)in;
    }
};
HEXANT_ACTION(texture_open) {
    HEXANT_APPLY { (void)in; st.blocks.emplace_back(std::in_place_type<runtime::Texture>); }
};
HEXANT_ACTION(texture_base) {
    HEXANT_APPLY {
        Value v = st.pop();
        auto& t = st.block<runtime::Texture>(in.position(), "a texture");
        if (v.is<runtime::Texture>()) t = v.as<runtime::Texture>();
        else if (v.is<runtime::Pigment>()) t.pigment = v.as<runtime::Pigment>();
        else throw ValueError("texture { } starts with a texture, not a " + type_name(v));
    }
};
HEXANT_ACTION(texture_pigment) {
    HEXANT_APPLY { Value v = st.pop(); st.block<runtime::Texture>(in.position(), "pigment").pigment = v.as<runtime::Pigment>(); }
};
HEXANT_ACTION(texture_finish) {
    HEXANT_APPLY { Value v = st.pop(); st.block<runtime::Texture>(in.position(), "finish").finish = v.as<runtime::Finish>(); }
};
HEXANT_ACTION(texture_block) {
    HEXANT_APPLY {
        (void)in;
        check_patterned_texture(std::get<runtime::Texture>(st.blocks.back()));
        close_uv_mapping(std::get<runtime::Texture>(st.blocks.back()).uv_mapping);
        Value v{std::get<runtime::Texture>(st.blocks.back())};
        st.blocks.pop_back();
        st.push(std::move(v));
    }
};
HEXANT_ACTION(texture_layer) {
    HEXANT_APPLY {
        // texture { A } texture { B }: B on top of A.
        (void)in;
        runtime::Texture top = st.pop().as<runtime::Texture>();
        if (st.top().is<Unevaluated>()) return;
        st.top() = Value{layered(std::move(top), st.top().as<runtime::Texture>())};
    }
};
HEXANT_ACTION(material_value) {
    HEXANT_APPLY {
        st.blocks.pop_back();
        st.push(Value{Unevaluated{"material", in.position()}});
    }
};
HEXANT_ACTION(material_open) {
    HEXANT_APPLY { (void)in; st.blocks.emplace_back(std::in_place_type<MaterialBuilder>); }
};
HEXANT_ACTION(material_base) {
    HEXANT_APPLY { (void)st; throw ValueError("declared materials are not supported; declare its texture and interior"); (void)in; }
};
HEXANT_ACTION(material_texture) {
    HEXANT_APPLY {
        Value v = st.pop();
        auto& material = st.block<MaterialBuilder>(in.position(), "texture");
        auto texture = v.as<runtime::Texture>();
        material.texture = material.texture ? layered(std::move(texture), std::move(*material.texture)) : std::move(texture);
    }
};
HEXANT_ACTION(material_interior) {
    HEXANT_APPLY { Value v = st.pop(); st.block<MaterialBuilder>(in.position(), "interior").interior = v.as<runtime::Interior>(); }
};

// ------------------------------------------------------------ objects

// Where an object was written.
template <typename ActionInput>
runtime::SourcePlace source_place(const ActionInput& in) {
    const auto p = in.position();
    return {p.source, p.line, p.column};
}

runtime::ObjectRecord make_shape(const std::string& kind, std::vector<std::string> options,
                                 std::vector<Value>& args, Interpreter& st, const p::position& where);
void set_shape_setting(runtime::ObjectRecord& record, const std::string& name,
                       std::vector<Value>& values, Interpreter& st, const p::position& where);
void add_blob_component(runtime::ObjectRecord& record, const std::string& kind,
                        std::vector<Value>& values, Interpreter& st, const p::position& where);

HEXANT_ACTION(shape_arguments) {
    HEXANT_APPLY {
        std::vector<Value> args = st.close_frame();
        const std::string kind = st.pop_name();
        std::vector<std::string> options = std::move(st.shape_options.back());
        st.shape_options.pop_back();
        runtime::ObjectRecord record = make_shape(kind, std::move(options), args, st, in.position());
        record.place = st.shape_place;
        st.blocks.emplace_back(std::move(record));
    }
};

// Finishes the object on top of the block stack and pushes it as a value.
struct finish_object {
    HEXANT_APPLY {
        Block b = std::move(st.blocks.back());
        st.blocks.pop_back();
        // Made under clock-dependent branches: it exists while they hold.
        if (auto* light = std::get_if<runtime::LightRecord>(&b)) {
            light->lifetime = light->lifetime.intersect(st.domain);
            st.push(Value{std::move(*light)});
            return;
        }
        auto& record = std::get<runtime::ObjectRecord>(b);
        record.lifetime = record.lifetime.intersect(st.domain);
        // A variant of its kind that hexant lacks: usable only where nothing uses it.
        const auto lacking = std::visit(
            [](const auto& shape) -> std::optional<std::string> {
                if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, runtime::Csg>) return std::nullopt;
                else return runtime::objects::unsupported_variant(shape);
            },
            record.shape);
        if (lacking) {
            st.push(Value{Unevaluated{*lacking, in.position()}});
            return;
        }
        if (const auto* csg = std::get_if<runtime::Csg>(&record.shape)) {
            record.depth = 1;
            for (const auto& child : csg->children)
                record.depth = std::max(record.depth, child->depth + 1);
            if (record.depth > runtime::kMaxObjectDepth)
                Interpreter::fail(in.position(),
                                  "objects nested more than " +
                                      std::to_string(runtime::kMaxObjectDepth) +
                                      " deep (a union built up in a loop? a union of the "
                                      "objects side by side, or an array of them, does not nest)");
        }
        st.push(Value{runtime::ObjectPtr(std::make_shared<runtime::ObjectRecord>(std::move(record)))});
    }
};
template <> struct action<g::shape_block> : finish_object {};
template <> struct action<g::csg_block> : finish_object {};
template <> struct action<g::object_block> : finish_object {};

HEXANT_ACTION(csg_open) {
    HEXANT_APPLY {
        const std::string kind = st.pop_name();
        runtime::Csg csg;
        csg.kind = kind == "intersection" ? runtime::Csg::Kind::Intersection
                   : kind == "difference" ? runtime::Csg::Kind::Difference
                   : kind == "merge"      ? runtime::Csg::Kind::Merge
                                          : runtime::Csg::Kind::Union;
        runtime::ObjectRecord record;
        record.shape = std::move(csg);
        record.place = source_place(in);
        st.blocks.emplace_back(std::move(record));
    }
};
HEXANT_ACTION(csg_child) {
    HEXANT_APPLY {
        Value v = st.pop();
        auto& record = st.member_block(in.position());
        if (v.is<runtime::LightRecord>()) {
            record.lights.push_back(v.as<runtime::LightRecord>());
            return;
        }
        if (v.is<Unevaluated>())
            throw UnsupportedError(v.as<Unevaluated>().what + " is not supported by hexant");
        std::get<runtime::Csg>(record.shape).children.push_back(v.as<runtime::ObjectPtr>());
    }
};
HEXANT_ACTION(object_base) {
    HEXANT_APPLY {
        Value v = st.pop();
        if (v.is<runtime::ObjectPtr>()) {
            runtime::ObjectRecord copy = *v.as<runtime::ObjectPtr>();
            st.blocks.emplace_back(std::move(copy));
        } else if (v.is<runtime::LightRecord>()) {
            st.blocks.emplace_back(v.as<runtime::LightRecord>());
        } else if (v.is<Unevaluated>()) {
            const auto& u = v.as<Unevaluated>();
            throw UnsupportedError("this " + u.what + " (written at " + u.where.source + ":" +
                             std::to_string(u.where.line) + ":" + std::to_string(u.where.column) +
                             ") is not supported by hexant");
        } else {
            throw ValueError("object { } needs an object, not a " + type_name(v));
        }
    }
};

HEXANT_ACTION(charset_name) {
    HEXANT_APPLY {
        const std::string name = in.string();
        // POV-Ray 3.7 on Unix knows ascii and utf8 ("sys" has no conversion there).
        if (name != "ascii" && name != "utf8")
            throw ValueError("charset '" + name + "' is not supported (ascii or utf8, as POV-Ray 3.7 on Unix)");
        st.charset = name;
    }
};

// ------------------------------------------------------------ meshes

// The mesh being read: the object on top of the block stack.
inline runtime::objects::MeshData& mesh_data(Interpreter& st, const p::position& where) {
    auto& record = st.block<runtime::ObjectRecord>(where, "a mesh's part");
    auto* mesh = std::get_if<runtime::Mesh>(&record.shape);
    if (!mesh) throw ValueError("this belongs in a mesh or mesh2");
    return *mesh->data;
}
struct open_mesh {
    HEXANT_APPLY {
        runtime::ObjectRecord record;
        record.shape = runtime::Mesh{};
        record.place = source_place(in);
        st.blocks.emplace_back(std::move(record));
    }
};
template <> struct action<g::mesh_open> : open_mesh {};
template <> struct action<g::mesh2_open> : open_mesh {};
HEXANT_ACTION(mesh_triangle) {
    HEXANT_APPLY {
        Value v = st.pop();
        if (!v.is<runtime::ObjectPtr>()) throw ValueError("a mesh holds triangles and smooth_triangles only");
        add_mesh_triangle(mesh_data(st, in.position()), *v.as<runtime::ObjectPtr>());
    }
};
HEXANT_ACTION(mesh_inside_vector_value) {
    HEXANT_APPLY { set_inside_vector(mesh_data(st, in.position()), st.pop()); }
};
HEXANT_ACTION(mesh_hierarchy_value) {
    HEXANT_APPLY { (void)to_constant(st.pop(), "hierarchy"); (void)in; }
};
template <>
struct action<g::mesh2_section_name> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.push_name(word(in));
    }
};
HEXANT_ACTION(mesh2_value) {
    HEXANT_APPLY {
        (void)in;
        st.mesh2_values.push_back(mesh_value(st.pop(), "a mesh2 section"));
    }
};
HEXANT_ACTION(mesh2_values) {
    HEXANT_APPLY {
        (void)st.close_frame();  // each value was taken as it was read
        const std::string section = st.pop_name();
        std::vector<MeshValue> values = std::move(st.mesh2_values);
        st.mesh2_values.clear();
        read_mesh2_section(mesh_data(st, in.position()), section, values);
    }
};
HEXANT_ACTION(mesh2_texture_list) {
    HEXANT_APPLY { read_mesh2_textures(mesh_data(st, in.position()), st.close_frame()); }
};
// The hierarchy is built once all faces are read, before the modifiers'
// object is pushed as a value.
template <const char* Keyword>
struct close_mesh {
    HEXANT_APPLY {
        finish_mesh(mesh_data(st, in.position()), Keyword);
        finish_object::apply(in, st);
    }
};
inline constexpr char kMeshWord[] = "mesh";
inline constexpr char kMesh2Word[] = "mesh2";
template <> struct action<g::mesh_block> : close_mesh<kMeshWord> {};
template <> struct action<g::mesh2_block> : close_mesh<kMesh2Word> {};

// blob { }: its components are added as they are read
// (runtime/objects/blob/blob.hpp).
HEXANT_ACTION(blob_open) {
    HEXANT_APPLY {
        runtime::ObjectRecord record;
        record.shape = runtime::Blob{};
        record.place = source_place(in);
        st.blocks.emplace_back(std::move(record));
    }
};
template <>
struct action<g::blob_component_kind> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.push_name(word(in));
    }
};
HEXANT_ACTION(blob_component_modifier) {
    HEXANT_APPLY {
        (void)st;
        throw ValueError("hexant does not read a blob component's own '" + word(in) +
                         "' yet (POV-Ray does); give it to the whole blob");
    }
};
HEXANT_ACTION(blob_component) {
    HEXANT_APPLY {
        std::vector<Value> values = st.close_frame();
        const std::string kind = st.pop_name();
        auto& record = st.block<runtime::ObjectRecord>(in.position(), "a blob component");
        add_blob_component(record, kind, values, st, in.position());
    }
};
HEXANT_ACTION(blob_old_component) {
    HEXANT_APPLY {
        std::vector<Value> values = st.close_frame();
        auto& record = st.block<runtime::ObjectRecord>(in.position(), "a blob component");
        add_blob_component(record, "component", values, st, in.position());
    }
};
template <> struct action<g::blob_block> : finish_object {};

// The texture an object modifier changes, made if the object has none.
inline runtime::Texture& object_texture(Interpreter& st, const p::position& where) {
    auto& record = st.block<runtime::ObjectRecord>(where, "a texture");
    if (!record.texture) record.texture = runtime::Texture{};
    if (record.texture->is_patterned())
        throw ValueError("a pigment, normal or finish cannot be added to a patterned texture (texture_map), as in "
                         "POV-Ray");
    return *record.texture;
}

HEXANT_ACTION(object_texture) {
    HEXANT_APPLY {
        Value v = st.pop();
        auto& record = st.block<runtime::ObjectRecord>(in.position(), "a texture");
        auto texture = v.as<runtime::Texture>();
        // A texture on an object that has one is a layer on top, as in POV-Ray.
        record.texture = record.texture ? layered(std::move(texture), std::move(*record.texture)) : std::move(texture);
    }
};
HEXANT_ACTION(object_pigment) {
    HEXANT_APPLY { Value v = st.pop(); object_texture(st, in.position()).pigment = v.as<runtime::Pigment>(); }
};
HEXANT_ACTION(object_normal) {
    HEXANT_APPLY { Value v = st.pop(); object_texture(st, in.position()).normal = v.as<runtime::Normal>(); }
};
HEXANT_ACTION(object_finish) {
    HEXANT_APPLY { Value v = st.pop(); object_texture(st, in.position()).finish = v.as<runtime::Finish>(); }
};
HEXANT_ACTION(object_interior) {
    HEXANT_APPLY { Value v = st.pop(); st.block<runtime::ObjectRecord>(in.position(), "interior").interior = v.as<runtime::Interior>(); }
};
HEXANT_ACTION(object_material) {
    HEXANT_APPLY {
        MaterialBuilder m = std::get<MaterialBuilder>(st.blocks.back());
        st.blocks.pop_back();
        auto& record = st.block<runtime::ObjectRecord>(in.position(), "material");
        if (m.texture) record.texture = m.texture;
        if (m.interior) record.interior = m.interior;
    }
};
HEXANT_ACTION(object_flag) {
    HEXANT_APPLY {
        std::vector<Value> given = st.close_frame();
        const std::string name = st.pop_name();
        const bool on = given.empty() || runtime::pov_true(to_constant(given[0], name));
        if (!st.blocks.empty() && std::holds_alternative<runtime::LightRecord>(st.blocks.back()))
            throw ValueError("'" + name + "' does not belong in a light_source");
        auto& record = st.block<runtime::ObjectRecord>(in.position(), name.c_str());
        if (name == "no_shadow") record.no_shadow = on;
        else if (name == "hollow") record.hollow = on;
        else if (name == "inverse") record.inverse = on;
        // sturm, no_image, no_reflection, no_radiosity, double_illuminate: read, no effect.
    }
};
// A setting of the object's kind (runtime/objects/shape_kind.hpp).
HEXANT_ACTION(shape_setting) {
    HEXANT_APPLY {
        std::vector<Value> given = st.close_frame();
        const std::string name = st.pop_name();
        if (!st.blocks.empty() && std::holds_alternative<runtime::LightRecord>(st.blocks.back()))
            throw ValueError("'" + name + "' does not belong in a light_source");
        auto& record = st.block<runtime::ObjectRecord>(in.position(), name.c_str());
        set_shape_setting(record, name, given, st, in.position());
    }
};
// (The same, with vectors for values: uv_vectors.)
template <>
struct action<g::shape_vectors_setting> : action<g::shape_setting> {};
HEXANT_ACTION(object_ignored_block) {
    HEXANT_APPLY { st.warn(in.position(), word(in) + " { } is read and ignored"); }
};

// ------------------------------------------------------------ lights

HEXANT_ACTION(light_arguments) {
    HEXANT_APPLY {
        std::vector<Value> args = st.close_frame();
        // light_source { L modifiers }: a copy of the declared light, as
        // POV-Ray's Parse_Light_Source starts from a LIGHT_SOURCE_ID.
        if (args[0].is<runtime::LightRecord>()) {
            if (args.size() > 1) throw ValueError("a declared light_source takes modifiers after it, not a colour");
            st.blocks.emplace_back(args[0].as<runtime::LightRecord>());
            return;
        }
        runtime::LightRecord light;
        light.position = to_vector3(args[0], "the light's position");
        if (args.size() > 1) light.colour = to_colour(args[1], "the light's colour");
        else light.colour.c = {1.0, 1.0, 1.0, 0.0, 0.0};  // POV-Ray's default: white
        (void)in;
        st.blocks.emplace_back(std::move(light));
    }
};
HEXANT_ACTION(light_flag) {
    HEXANT_APPLY {
        const std::string w = word(in);
        auto& light = st.block<runtime::LightRecord>(in.position(), w.c_str());
        // (POV-Ray's Parse_Light_Source: the kind's keyword sets its
        // defaults, so radius, falloff and tightness come after it.)
        // shadowless is POV-Ray's fill light, a type of its own: it turns
        // a spotlight or cylinder back into a plain light, and either
        // keyword after it turns it into theirs, with shadows.
        if (w == "shadowless") {
            light.shadowless = true;
            light.kind = runtime::LightKind::Point;
        } else if (w == "spotlight") {
            light.shadowless = false;
            light.kind = runtime::LightKind::Spotlight;
            light.radius = 30.0;
            light.falloff = 45.0;
            light.tightness = 0.0;
        } else if (w == "cylinder") {
            light.shadowless = false;
            light.kind = runtime::LightKind::Cylinder;
            light.radius = 0.75;
            light.falloff = 1.0;
            light.tightness = 0.0;
            light.parallel = true;
        } else if (w == "parallel") light.parallel = true;
        else if (w == "jitter") light.jitter = true;
        else if (w == "circular") light.circular = true;
        else if (w == "orient") light.orient = true;
    }
};
HEXANT_ACTION(light_setting) {
    HEXANT_APPLY {
        Value v = st.pop();
        const std::string name = st.pop_name();
        auto& light = st.block<runtime::LightRecord>(in.position(), name.c_str());
        const bool shaped = light.kind != runtime::LightKind::Point;
        // (POV-Ray refuses these on a standard light, its Not_With.)
        if (((name == "radius" || name == "falloff" || name == "tightness") && !shaped) ||
            (name == "point_at" && !shaped && !light.parallel))
            throw ValueError("'" + name + "' needs a spotlight or cylinder light" +
                             (name == "point_at" ? " or a parallel one" : "") + " (say so before it)");
        if (name == "point_at") light.point_at = to_vector3(v, name);
        else if (name == "radius") light.radius = to_float(v, name);
        else if (name == "falloff") light.falloff = to_float(v, name);
        else if (name == "tightness") light.tightness = to_float(v, name);
        else if (name == "fade_distance") light.fade_distance = to_float(v, name);
        else if (name == "fade_power") light.fade_power = to_float(v, name);
        // adaptive: POV-Ray's shortcut to the area grid's average, which
        // hexant samples whole; media_interaction, media_attenuation: hexant
        // has no media. Read, no effect.
    }
};
HEXANT_ACTION(area_light) {
    HEXANT_APPLY {
        std::vector<Value> given = st.close_frame();
        auto& light = st.block<runtime::LightRecord>(in.position(), "area_light");
        runtime::AreaLight area;
        area.axis1 = to_vector3(given.at(0), "area_light's first axis");
        area.axis2 = to_vector3(given.at(1), "area_light's second axis");
        // (Lights along each axis: POV-Ray truncates to whole numbers and
        // refuses 0. hexant samples the grid, never stores it: 2^20 a side
        // is no limit a scene meets.)
        area.size1 = int(checked_integer(std::trunc(to_constant(given.at(2), "area_light's first size")),
                                         "area_light's first size", 1, 1 << 20));
        area.size2 = int(checked_integer(std::trunc(to_constant(given.at(3), "area_light's second size")),
                                         "area_light's second size", 1, 1 << 20));
        light.area = std::move(area);
    }
};
HEXANT_ACTION(light_projected_through) {
    HEXANT_APPLY { st.warn(in.position(), word(in) + " { } is read and ignored"); }
};
// POV-Ray's Parse_Light_Source: the object is moved to the light's centre,
// then its modifiers apply (a scale inside looks_like { } scales about the
// origin, after the move), then the light's own transforms
// (Interpreter::add_light).
HEXANT_ACTION(looks_like_base) {
    HEXANT_APPLY {
        action<g::object_base>::apply(in, st);
        if (st.blocks.size() < 2 || !std::holds_alternative<runtime::LightRecord>(st.blocks[st.blocks.size() - 2]) ||
            !std::holds_alternative<runtime::ObjectRecord>(st.blocks.back()))
            throw ValueError("looks_like { } needs an object");
        const auto& light = std::get<runtime::LightRecord>(st.blocks[st.blocks.size() - 2]);
        std::get<runtime::ObjectRecord>(st.blocks.back())
            .transform.append(runtime::TransformStep{runtime::TransformKind::Translate, light.position, {}, {}, false});
    }
};
HEXANT_ACTION(light_looks_like) {
    HEXANT_APPLY {
        // (The object's block, closed as object { } closes.)
        finish_object::apply(in, st);
        Value v = st.pop();
        if (!v.is<runtime::ObjectPtr>()) throw ValueError("looks_like { } needs an object, not a " + type_name(v));
        auto& light = st.block<runtime::LightRecord>(in.position(), "looks_like");
        if (light.looks_like) throw ValueError("only one looks_like is allowed per light_source (POV-Ray's rule)");
        light.looks_like = v.as<runtime::ObjectPtr>();
    }
};
template <> struct action<g::light_block> : finish_object {};

// ------------------------------------------------------------ camera and scene

HEXANT_ACTION(camera_open) {
    HEXANT_APPLY { (void)in; st.blocks.emplace_back(std::in_place_type<runtime::CameraRecord>); }
};
HEXANT_ACTION(camera_base) {
    HEXANT_APPLY {
        Value v = st.pop();
        if (!v.is<runtime::CameraRecord>()) throw ValueError("camera { } starts with a camera, not a " + type_name(v));
        st.block<runtime::CameraRecord>(in.position(), "a camera") = v.as<runtime::CameraRecord>();
    }
};
HEXANT_ACTION(camera_setting) {
    HEXANT_APPLY {
        Value v = st.pop();
        const std::string name = st.pop_name();
        auto& camera = st.block<runtime::CameraRecord>(in.position(), name.c_str());
        runtime::CameraItem item;
        using K = runtime::CameraItem::Kind;
        item.kind = name == "location" ? K::Location : name == "look_at" ? K::LookAt
                    : name == "direction" ? K::Direction : name == "right" ? K::Right
                    : name == "up" ? K::Up : K::Sky;
        item.vector = to_vector3(v, "the camera's " + name);
        camera.items.push_back(std::move(item));
    }
};
HEXANT_ACTION(camera_unsupported_type) {
    HEXANT_APPLY {
        (void)st;
        Interpreter::fail(in.position(), word(in) + " cameras are not supported by hexant (perspective, orthographic, "
                                                    "fisheye, panoramic and spherical are)");
    }
};
HEXANT_ACTION(camera_type) {
    HEXANT_APPLY {
        const std::string name = word(in);
        auto& camera = st.block<runtime::CameraRecord>(in.position(), name.c_str());
        // POV-Ray reads the type before any other item (the last of several
        // types in a row wins), and not at all after a camera identifier
        // (then only transforms may follow).
        const bool only_types = std::all_of(camera.items.begin(), camera.items.end(), [](const auto& item) {
            return item.kind == runtime::CameraItem::Kind::Type;
        });
        if (!only_types || !camera.pieces.empty() || camera.normal)
            throw ValueError("the camera's type (" + name + ") must come first in camera { }, before its other "
                             "items and not after a declared camera (as POV-Ray requires)");
        runtime::CameraItem item;
        item.kind = runtime::CameraItem::Kind::Type;
        using T = runtime::CameraType;
        item.type = name == "orthographic" ? T::Orthographic : name == "fisheye" ? T::Fisheye
                    : name == "panoramic" ? T::Panoramic : name == "spherical" ? T::Spherical : T::Perspective;
        camera.items.push_back(std::move(item));
    }
};
HEXANT_ACTION(camera_angle) {
    HEXANT_APPLY {
        std::vector<Value> given = st.close_frame();
        auto& camera = st.block<runtime::CameraRecord>(in.position(), "angle");
        using T = runtime::CameraType;
        T type = T::Perspective;
        for (const auto& item : camera.items)
            if (item.kind == runtime::CameraItem::Kind::Type) type = item.type;
        const char* name = type == T::Perspective ? "perspective" : type == T::Orthographic ? "orthographic"
                           : type == T::Fisheye ? "fisheye" : type == T::Panoramic ? "panoramic" : "spherical";
        // POV-Ray's Parse_Camera: an orthographic angle may be left out (0);
        // only a spherical camera takes a second (vertical) angle.
        if (given.empty() && type != T::Orthographic)
            throw ValueError(std::string("a ") + name + " camera's angle needs a value");
        if (given.size() > 1 && type != T::Spherical)
            throw ValueError(std::string("a ") + name + " camera's angle takes one value (two: a spherical camera's)");
        runtime::CameraItem item;
        item.kind = runtime::CameraItem::Kind::Angle;
        item.angle = given.empty() ? TimeFunction(0.0) : to_float(given[0], "the camera's angle");
        if (item.angle.is_constant()) {
            const double a = item.angle.constant();
            if (type == T::Perspective && (a <= 0.0 || a >= 180.0))
                throw ValueError("a perspective camera's angle must lie between 0 and 180 degrees");
            if (type == T::Orthographic && (a < 0.0 || a >= 180.0))
                throw ValueError("an orthographic camera's angle must lie in [0, 180) degrees");
            if (!(a >= 0.0)) throw ValueError(std::string("a ") + name + " camera's angle must not be negative");
        }
        camera.items.push_back(item);
        if (given.size() > 1) {
            runtime::CameraItem vertical;
            vertical.kind = runtime::CameraItem::Kind::VerticalAngle;
            vertical.angle = to_float(given[1], "the spherical camera's vertical angle");
            if (vertical.angle.is_constant() && !(vertical.angle.constant() >= 0.0))
                throw ValueError("a spherical camera's vertical angle must not be negative");
            camera.items.push_back(std::move(vertical));
        }
    }
};
HEXANT_ACTION(camera_blur_setting) {
    HEXANT_APPLY {
        std::vector<Value> given = st.close_frame();
        const std::string name = st.pop_name();
        auto& camera = st.block<runtime::CameraRecord>(in.position(), name.c_str());
        runtime::CameraItem item;
        using K = runtime::CameraItem::Kind;
        if (given.size() > 1 && name != "blur_samples")
            throw ValueError(name + " takes one value");
        if (name == "focal_point") {
            item.kind = K::FocalPoint;
            item.vector = to_vector3(given[0], "the camera's focal_point");
        } else {
            item.kind = name == "aperture" ? K::Aperture : K::BlurSamples;
            // (blur_samples MIN, MAX: POV-Ray's most is what counts here.)
            item.angle = to_float(given.back(), "the camera's " + name);
            if (name == "blur_samples") {
                // POV-Ray's rules: whole numbers (truncated) of 1 or more,
                // the least not above the most.
                double least = 1.0, most = 1.0;
                for (std::size_t k = 0; k < given.size(); ++k) {
                    const TimeFunction f = to_float(given[k], "the camera's blur_samples");
                    if (!f.is_constant()) continue;
                    const double v = std::trunc(f.constant());
                    if (!(v >= 1.0))
                        throw ValueError("blur_samples must be 1 or more (POV-Ray: illegal number of focal blur samples)");
                    (k + 1 == given.size() ? most : least) = v;
                }
                if (given.size() > 1 && least > most)
                    throw ValueError("blur_samples' least must not be above its most");
            }
        }
        camera.items.push_back(std::move(item));
    }
};
HEXANT_ACTION(camera_ignored_setting) {
    HEXANT_APPLY {
        st.warn(in.position(), word(in) + " is read and ignored (hexant samples by --spp or --target-error)");
    }
};
HEXANT_ACTION(camera_block) {
    HEXANT_APPLY {
        (void)in;
        Value v{std::get<runtime::CameraRecord>(st.blocks.back())};
        st.blocks.pop_back();
        st.push(std::move(v));
    }
};
HEXANT_ACTION(scene_camera) {
    HEXANT_APPLY {
        (void)in;
        ++st.camera_sets;  // (under a branch on clock: piecewise, split_time)
        st.scene.camera = st.pop().as<runtime::CameraRecord>();
        if (auto problem = runtime::bad_parameter(st.scene.camera, st.scene.animation))
            throw ValueError(*problem);
    }
};
HEXANT_ACTION(background_colour) {
    HEXANT_APPLY {
        (void)in;
        ++st.background_sets;
        st.scene.background = to_colour(st.pop(), "the background"); }
};
HEXANT_ACTION(sky_sphere_open) {
    HEXANT_APPLY { (void)in; st.blocks.emplace_back(std::in_place_type<runtime::SkySphere>); }
};
HEXANT_ACTION(sky_sphere_base) {
    HEXANT_APPLY {
        Value v = st.pop();
        if (!v.is<runtime::SkySphere>()) throw ValueError("sky_sphere { } starts with a sky_sphere, not a " + type_name(v));
        st.block<runtime::SkySphere>(in.position(), "a sky_sphere") = v.as<runtime::SkySphere>();
    }
};
HEXANT_ACTION(sky_sphere_pigment) {
    HEXANT_APPLY {
        Value v = st.pop();
        // (POV-Ray: "The 'uv_mapping' pattern cannot be used" without a surface.)
        if (v.as<runtime::Pigment>().uv_mapping != runtime::UvMapping::Off)
            throw ValueError("uv_mapping needs a surface's (u, v): not in a sky_sphere");
        st.block<runtime::SkySphere>(in.position(), "a pigment").pigments.push_back(v.as<runtime::Pigment>());
    }
};
HEXANT_ACTION(sky_sphere_emission) {
    HEXANT_APPLY {
        Value v = st.pop();
        st.block<runtime::SkySphere>(in.position(), "emission").emission = to_colour(v, "emission");
    }
};
HEXANT_ACTION(sky_sphere_block) {
    HEXANT_APPLY {
        auto& sky = st.block<runtime::SkySphere>(in.position(), "a sky_sphere");
        if (sky.pigments.empty()) throw ValueError("a sky_sphere needs a pigment (POV-Ray: empty sky_sphere statement)");
        Value v{std::move(sky)};
        st.blocks.pop_back();
        st.push(std::move(v));
    }
};
HEXANT_ACTION(scene_sky_sphere) {
    HEXANT_APPLY {
        st.require_whole_time(in.position(), "a sky_sphere");
        runtime::SkySphere sky = st.pop().as<runtime::SkySphere>();
        for (const auto& pigment : sky.pigments) check_pigment(pigment);
        st.scene.sky_sphere = std::move(sky);
    }
};

HEXANT_ACTION(fog_open) {
    HEXANT_APPLY {
        st.require_whole_time(in.position(), "a fog");
        st.blocks.emplace_back(std::in_place_type<runtime::Fog>);
    }
};
HEXANT_ACTION(fog_setting) {
    HEXANT_APPLY {
        Value v = st.pop();
        const std::string name = st.pop_name();
        auto& fog = st.block<runtime::Fog>(in.position(), name.c_str());
        const auto turbulence = [&]() -> runtime::pattern::Turbulence& {
            if (!fog.turbulence) fog.turbulence.emplace();
            return *fog.turbulence;
        };
        if (name == "distance") fog.distance = to_float(v, "distance");
        else if (name == "fog_type") {
            fog.type = static_cast<int>(checked_integer(to_constant(v, "fog_type"), "fog_type", 1, 2));
        }
        else if (name == "fog_alt") fog.alt = to_float(v, "fog_alt");
        else if (name == "fog_offset") fog.offset = to_float(v, "fog_offset");
        else if (name == "turb_depth") fog.turb_depth = to_float(v, "turb_depth");
        else if (name == "up") fog.up = to_vector3(v, "up");
        else if (name == "turbulence") turbulence().amount = to_vector3(v, "turbulence");
        else if (name == "octaves") turbulence().octaves = to_float(v, "octaves");
        else if (name == "omega") turbulence().omega = to_float(v, "omega");
        else turbulence().lambda = to_float(v, "lambda");
    }
};
HEXANT_ACTION(fog_colour) {
    HEXANT_APPLY {
        Value v = st.pop();
        auto& fog = st.block<runtime::Fog>(in.position(), "a fog's colour");
        // A bare number is the distance, as POV-Ray reads it (with its
        // warning to write `distance`).
        if (v.is<TimeFunction>()) {
            st.warn(in.position(), "a number in fog { } is its distance: write `distance` (as POV-Ray warns)");
            fog.distance = v.as<TimeFunction>();
        } else {
            fog.colour = to_colour(v, "a fog's colour");
        }
    }
};
HEXANT_ACTION(fog_block) {
    HEXANT_APPLY {
        (void)in;
        st.scene.fogs.push_back(std::move(std::get<runtime::Fog>(st.blocks.back())));
        st.blocks.pop_back();
    }
};

HEXANT_ACTION(global_motion_blur) {
    HEXANT_APPLY {
        st.require_whole_time(in.position(), "a global setting");
        std::vector<Value> items = st.close_frame();
        auto& g = st.scene.global;
        g.motion_blur_samples = static_cast<int>(
            checked_integer(to_constant(items.at(0), "motion_blur's samples"), "motion_blur's samples", 1, 1 << 20));
        g.motion_blur_time = to_constant(items.at(1), "motion_blur's time");
        if (!(*g.motion_blur_time >= 0.0) || !std::isfinite(*g.motion_blur_time))
            throw ValueError("motion_blur's time must be a finite number of clock units, at least 0");
    }
};

HEXANT_ACTION(global_setting) {
    HEXANT_APPLY {
        st.require_whole_time(in.position(), "a global setting");
        Value v = st.pop();
        const std::string name = st.pop_name();
        if (name == "assumed_gamma") st.scene.global.assumed_gamma = to_constant(v, name);
        else if (name == "noise_generator") {
            st.scene.global.noise_generator =
                static_cast<int>(checked_integer(to_constant(v, name), name, 1, 3));
            if (st.patterns_written > 0)
                st.warn(in.position(), "global noise_generator after patterns: hexant applies it to the patterns "
                                       "written after it (POV-Ray to all; put global_settings first)");
        }
        else if (name == "max_trace_level") {
            // As POV-Ray 3.7 (parser.cpp): at least 1, and above its limit
            // of 256 a warning and 256.
            long long level = checked_integer(to_constant(v, name), name, -kMaxExactInteger, kMaxExactInteger);
            if (level > 256) {
                st.warn(in.position(), "max_trace_level " + std::to_string(level) + " is above the limit: 256 used");
                level = 256;
            }
            st.scene.global.max_trace_level = static_cast<int>(std::max(1LL, level));
        }
        else st.scene.global.ambient_light = to_colour(v, name);
    }
};
HEXANT_ACTION(global_ignored_setting) {
    HEXANT_APPLY {
        st.close_frame();
        st.warn(in.position(), "global setting '" + st.pop_name() + "' is read and ignored");
    }
};
HEXANT_ACTION(unsupported_block) {
    HEXANT_APPLY { st.push(Value{Unevaluated{st.pop_name(), in.position()}}); }
};

// ------------------------------------------------------------ arrays and splines

HEXANT_ACTION(array_dimensions) {
    HEXANT_APPLY {
        (void)in;
        std::vector<Value> sizes = st.close_frame();
        auto array = std::make_shared<Array>();
        array->charge.attach(st.array_memory());
        std::size_t total = 1;
        for (auto& s : sizes) {
            // int dimensions; the memory limit below is the one that binds.
            const long long n = checked_integer(to_constant(s, "an array size"), "an array size", 1,
                                                kMaxArrayElements);
            array->dimensions.push_back(static_cast<int>(n));
            total *= static_cast<std::size_t>(n);
            if (total > static_cast<std::size_t>(kMaxArrayElements))
                throw ValueError("this array would hold more than 2^31 - 1 elements");
        }
        array->charge.add(total * kArraySlotBytes);
        array->elements.resize(total);
        st.push(Value{array});
    }
};
HEXANT_ACTION(array_initializer) {
    HEXANT_APPLY {
        (void)in;
        std::vector<Value> items = st.close_frame();
        auto list = std::make_shared<Array>();  // no dimensions: an initializer list
        list->charge.attach(st.array_memory());
        for (auto& item : items) {
            list->charge.add(kArraySlotBytes + element_bytes(item));
            list->elements.emplace_back(std::make_shared<Value>(std::move(item)));
        }
        st.push(Value{list});
    }
};
void fill_array(Array& array, const Array& list, std::size_t dimension, std::size_t& next);
HEXANT_ACTION(array_value) {
    HEXANT_APPLY {
        (void)in;
        Value top = st.pop();
        auto list = top.as<std::shared_ptr<Array>>();
        if (!list->dimensions.empty()) {  // no initializer
            st.push(std::move(top));
            return;
        }
        auto array = st.pop().as<std::shared_ptr<Array>>();
        std::size_t next = 0;
        fill_array(*array, *list, 0, next);
        st.push(Value{array});
    }
};
HEXANT_ACTION(spline_open) {
    HEXANT_APPLY { (void)in; st.blocks.emplace_back(std::in_place_type<SplineBuilder>); }
};
HEXANT_ACTION(spline_base) {
    HEXANT_APPLY {
        Value v = st.pop();
        if (!v.is<std::shared_ptr<const runtime::Spline>>())
            throw ValueError("spline { } starts with a spline, not a " + type_name(v));
        const auto& base = *v.as<std::shared_ptr<const runtime::Spline>>();
        auto& s = st.block<SplineBuilder>(in.position(), "a spline");
        s.kind = base.kind();
        s.keys = base.keys();
        s.dimensions = base.dimensions();
    }
};
HEXANT_ACTION(spline_kind) {
    HEXANT_APPLY {
        const std::string w = word(in);
        auto& s = st.block<SplineBuilder>(in.position(), w.c_str());
        using K = runtime::SplineKind;
        s.kind = w == "linear_spline" ? K::Linear : w == "quadratic_spline" ? K::Quadratic
                 : w == "cubic_spline" ? K::Cubic : K::Natural;
    }
};
HEXANT_ACTION(spline_key) {
    HEXANT_APPLY {
        Value v = st.pop();
        const double t = to_constant(st.pop(), "a spline key's time");
        auto& s = st.block<SplineBuilder>(in.position(), "a spline key");
        runtime::Spline::Key key{t, {0, 0, 0, 0, 0}};
        int dims = 1;
        if (v.is<TimeFunction>()) {
            key.value[0] = to_constant(v, "a spline key's value");
        } else {
            const Vector vec = to_vector(v, "a spline key's value");
            dims = vec.size;
            for (int i = 0; i < vec.size; ++i)
                key.value[i] = to_constant(Value{vec.c[i]}, "a spline key's value");
        }
        if (s.keys.empty()) s.dimensions = dims;
        else s.dimensions = std::max(s.dimensions, dims);
        s.keys.push_back(key);
    }
};
HEXANT_ACTION(spline_block) {
    HEXANT_APPLY {
        SplineBuilder b = std::get<SplineBuilder>(st.blocks.back());
        st.blocks.pop_back();
        if (b.keys.empty()) Interpreter::fail(in.position(), "a spline needs at least one key");
        st.push(Value{std::shared_ptr<const runtime::Spline>(
            std::make_shared<runtime::Spline>(b.kind, std::move(b.keys), b.dimensions))});
    }
};

HEXANT_ACTION(scene_object) {
    HEXANT_APPLY {
        Value v = st.pop();
        if (v.is<runtime::LightRecord>()) {
            if (auto problem = runtime::bad_parameter(v.as<runtime::LightRecord>(), st.scene.animation))
                throw ValueError(*problem);
            st.add_light(v.as<runtime::LightRecord>(), in.position());
        } else if (v.is<runtime::ObjectPtr>()) {
            st.add_object(v.as<runtime::ObjectPtr>(), in.position());
        } else if (v.is<Unevaluated>()) {
            throw ValueError(v.as<Unevaluated>().what + " is not supported by hexant");
        }
    }
};
HEXANT_ACTION(scene_unsupported) {
    HEXANT_APPLY {
        (void)in;
        throw ValueError(st.pop().as<Unevaluated>().what + " is not supported by hexant");
    }
};

#undef HEXANT_ACTION
#undef HEXANT_APPLY

}  // namespace hexant::language
