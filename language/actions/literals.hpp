// Literals: numbers, strings, vectors, colours, names and calls.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/action.hpp"
#include "language/array_index.hpp"
#include "language/function_internals.hpp"

namespace hexant::language {

// ------------------------------------------------------------ literals

template <>
struct action<g::number_text> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.values.push(Value{TimeFunction(std::strtod(in.string().c_str(), nullptr))});
    }
};

template <>
struct action<g::string_content> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const std::string raw = in.string();
        std::string out;
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (raw[i] != '\\' || i + 1 == raw.size()) {
                out += raw[i];
                continue;
            }
            const char c = raw[++i];
            switch (c) {
                case 'n':
                    out += '\n';
                    break;
                case 't':
                    out += '\t';
                    break;
                case 'r':
                    out += '\r';
                    break;
                case 'a':
                    out += '\a';
                    break;
                case 'b':
                    out += '\b';
                    break;
                case 'f':
                    out += '\f';
                    break;
                case 'v':
                    out += '\v';
                    break;
                case '0':
                    out += '\0';
                    break;
                default:
                    out += c;
                    break;
            }
        }
        st.values.push(Value{out});
    }
};

template <>
struct action<g::frame_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.values.open_frame();
    }
};

template <>
struct action<g::vector_literal> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> items = st.values.close_frame();
        if (items.size() < 2 || items.size() > 5)
            throw ValueError("a vector has 2 to 5 components, not " + std::to_string(items.size()));
        Vector v;
        v.size = static_cast<int>(items.size());
        for (std::size_t i = 0; i < items.size(); ++i)
            v.c[i] = to_float(items[i], "a vector component");
        st.values.push(Value{v});
    }
};

template <>
struct action<g::trace_normal_name> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        // (Kept with the arguments, as the name of the vector to set.)
        st.values.push(Value{word(in)});
    }
};
// trace(OBJECT, A, B [, N]) (language/scene_queries.hpp): the hit point, or
// <0, 0, 0> on a miss; N, a declared vector, gets the normal (or <0, 0, 0>).
template <>
struct action<g::trace_call> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        std::vector<Value> args = st.values.close_frame();
        if (!args[0].is<runtime::ObjectPtr>())
            throw ValueError("trace() needs an object first, as in POV-Ray");
        const auto origin = to_vector3(args[1], "trace()'s start point");
        const auto direction = to_vector3(args[2], "trace()'s direction");
        if (origin.depends_on_time() || direction.depends_on_time())
            throw ValueError(
                "trace() of a ray that moves with clock is not supported by "
                "hexant yet");
        const auto& object = st.queried_objects.placed(args[0].as<runtime::ObjectPtr>(),
                                                       st.animation_time(), "trace()");
        const double t = st.animation_time().lo;
        const std::optional<TraceHit> hit = trace_object(object, origin(t), direction(t), t);
        const glm::dvec3 point = hit ? hit->point : glm::dvec3(0.0);
        const glm::dvec3 normal = hit ? hit->normal : glm::dvec3(0.0);
        if (args.size() == 4) {
            const std::string& target = args[3].as<std::string>();
            const Value* held = st.symbols.lookup(target);
            if (!held)
                throw ValueError("trace()'s normal goes into '" + target +
                                 "', which is not declared (POV-Ray needs a declared vector)");
            st.symbols.assign(target, make_vector({normal.x, normal.y, normal.z}));
        }
        st.values.push(make_vector({point.x, point.y, point.z}));
    }
};
template <>
struct action<g::function_call> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        std::vector<Value> args = st.values.close_frame();
        const std::string name = st.values.pop_name();
        // POV-Ray's function bodies know its float functions only
        // (parser/fnsyntax.cpp): a string or vector one is an error there.
        static constexpr std::array<std::string_view, 29> kInBodies = {
            "abs",  "acos", "acosh", "asin",    "asinh", "atan", "atan2",   "atanh",
            "ceil", "cos",  "cosh",  "degrees", "div",   "exp",  "floor",   "int",
            "ln",   "log",  "max",   "min",     "mod",   "pow",  "radians", "select",
            "sin",  "sinh", "sqrt",  "tan",     "tanh"};
        if (!st.functions_open.empty() &&
            std::find(kInBodies.begin(), kInBodies.end(), name) == kInBodies.end())
            throw ValueError("'" + name +
                             "' cannot be used in a function's body (POV-Ray's "
                             "functions take float functions only)");
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
        // file_exists(NAME): 1 only for a file the scene may read, found as
        // #include finds it (POV-Ray's Locate_File searches the library
        // paths too). Never a probe past the confinement: it answered for
        // /etc/shadow, and the answer could steer the image (issue 45).
        if (name == "file_exists") {
            if (args.size() != 1) throw ValueError("file_exists() takes one string");
            const auto exists = [&](const std::string& file) {
                return st.find_readable(file, "file").error.empty() ? 1.0 : 0.0;
            };
            if (args[0].is<std::string>()) {
                st.values.push(Value{TimeFunction(exists(args[0].as<std::string>()))});
                return;
            }
            if (!args[0].is<TimedString>())
                throw ValueError("file_exists() takes a string, not a " + type_name(args[0]));
            std::vector<runtime::Interval> times;
            std::vector<double> values;
            for (const auto& piece : args[0].as<TimedString>().pieces) {
                times.push_back(piece.time);
                values.push_back(exists(piece.text));
            }
            st.values.push(Value{piecewise_constant(times, values)});
            return;
        }
        // The box of an object (language/object_extent.hpp).
        if (name == "min_extent" || name == "max_extent") {
            if (args.size() != 1 || !args[0].is<runtime::ObjectPtr>())
                throw ValueError(name + "() takes one object, as in POV-Ray");
            st.values.push(object_extent(*args[0].as<runtime::ObjectPtr>(), name == "max_extent",
                                         st.animation_time(), st.options.limits.time_pieces));
            return;
        }
        // inside(OBJECT, P) (language/scene_queries.hpp).
        if (name == "inside") {
            if (args.size() != 2 || !args[0].is<runtime::ObjectPtr>())
                throw ValueError("inside() takes an object and a point, as in POV-Ray");
            const auto point = to_vector3(args[1], "the point of inside()");
            if (point.depends_on_time())
                throw ValueError(
                    "inside() of a point that moves with clock is not supported "
                    "by hexant yet");
            const auto& object = st.queried_objects.placed(args[0].as<runtime::ObjectPtr>(),
                                                           st.animation_time(), "inside()");
            const double t = st.animation_time().lo;
            st.values.push(Value{inside_object(object, point(t), t) ? 1.0 : 0.0});
            return;
        }
        // (A string function of arguments that depend on clock: once a
        // piece of time, language/timed_call.hpp.)
        std::optional<Value> timed =
            call_over_time(name, args, st.domain.within(st.animation_time()),
                           st.options.limits.time_pieces, st.random);
        Value result = timed ? std::move(*timed) : call_builtin(name, args, st.random);
        if (name == "vnormalize")
            if (const auto zero = vnormalize_zero_at(args, st.animation_time())) {
                std::ostringstream note;
                note << "vnormalize() of a zero-length vector gives <0, 0, 0>, as in POV-Ray";
                bool moves = false;
                const Vector v = to_vector(args.at(0), "the argument of vnormalize()");
                for (int i = 0; i < v.size; ++i) moves = moves || v.c[i].depends_on_time();
                if (moves)
                    note << " (at clock " << std::setprecision(17) << *zero
                         << " and wherever else it is zero)";
                st.warn(in.position(), note.str());
            }
        if (result.is<std::string>())
            st.check_string_length(result.as<std::string>().size(), name + "()'s result");
        if (result.is<TimedString>())
            st.check_string_length(result.as<TimedString>().longest(), name + "()'s result");
        st.values.push(std::move(result));
    }
};

template <>
struct action<g::defined_call> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        // (Declared part of the time: 1 on those pieces, language/time_branch.hpp.)
        const runtime::Lifetime* when = st.symbols.declared_when(st.values.pop_name());
        st.values.push(Value{when ? indicator(*when) : TimeFunction(0.0)});
    }
};

template <>
struct action<g::builtin_constant_name> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const std::string w = in.string();
        // A user function's parameter (x, y, z by default) in its body.
        if (const auto k = st.function_parameter(w)) {
            st.values.push(Value{TimeFunction::argument(*k)});
            return;
        }
        const auto& a = st.options.animation;
        auto f = [&](double v) { st.values.push(Value{TimeFunction(v)}); };
        if (w == "pi")
            f(3.14159265358979323846);
        else if (w == "tau")
            f(2 * 3.14159265358979323846);
        else if (w == "true" || w == "yes" || w == "on")
            f(1.0);
        else if (w == "false" || w == "no" || w == "off")
            f(0.0);
        else if (w == "x")
            st.values.push(make_vector({1.0, 0.0, 0.0}));
        else if (w == "y")
            st.values.push(make_vector({0.0, 1.0, 0.0}));
        else if (w == "z")
            st.values.push(make_vector({0.0, 0.0, 1.0}));
        else if (w == "t")
            st.values.push(make_vector({0.0, 0.0, 0.0, 1.0}));
        else if (w == "u")
            st.values.push(make_vector({1.0, 0.0}));
        else if (w == "v")
            st.values.push(make_vector({0.0, 1.0}));
        else if (w == "image_width")
            f(a.width);
        else if (w == "image_height")
            f(a.height);
        else if (w == "clock") {
            // (A frame read at its clock alone: that clock, a constant.)
            const auto& alone = st.options.frame_alone;
            st.values.push(Value{alone && alone->at_clock
                                     ? TimeFunction(a.clock_of_frame(alone->frame))
                                 : a.clock_runs() ? TimeFunction::clock()
                                                  : TimeFunction(a.initial_clock)});
        } else if (w == "clock_delta")
            f(a.clock_delta());
        else if (w == "clock_on")
            f(a.clock_runs() || a.clock_given ? 1.0 : 0.0);
        // In a still, POV-Ray reads these four (and frame_number) as 0.
        else if (w == "initial_clock")
            f(a.clock_runs() ? a.initial_clock : 0.0);
        else if (w == "final_clock")
            f(a.clock_runs() ? a.final_clock : 0.0);
        else if (w == "initial_frame")
            f(a.is_animation() ? a.initial_frame : 0.0);
        else if (w == "final_frame")
            // A cyclic animation's is one past its last frame, as POV-Ray
            // declares it (AnimationProcessing: finalFrame++ when cyclic,
            // the frame whose clock is Final_Clock).
            f(a.is_animation() ? a.final_frame + (a.cyclic ? 1 : 0) : 0.0);
        else if (w == "version")
            f(st.version);
        else if (w == "frame_number") {
            // The frame whose shutter holds the time: constant within a
            // frame, and switching exactly at each frame's first instant as
            // the renderer computes it (Animation::frame_start: c0 + n *
            // delta - lead, the same operations here), so that a branch on it
            // splits time at the frames' first instants. The quotient may
            // be a frame off next to a boundary; the comparisons with the
            // frame's own clock and the next one's correct it.
            if (st.options.frame_alone) {
                f(st.options.frame_alone->frame);  // (a frame read alone)
            } else if (!a.is_animation() || a.clock_delta() == 0.0) {
                f(a.is_animation() ? a.initial_frame : 0.0);
            } else {
                const TimeFunction t = TimeFunction::clock();
                const double delta = a.clock_delta();
                // (Frames switch at their first instants,
                // Animation::frame_start: a frame's clock less its lead,
                // the clock itself when the shutter opens at it.)
                const double lead = a.shutter_lead() * delta;
                const TimeFunction n = TimeFunction::apply(
                    TimeOp::Floor, (t - a.frame_start(a.initial_frame)) / delta);
                const TimeFunction start = a.initial_clock + n * delta - lead;
                const TimeFunction next = a.initial_clock + (n + 1.0) * delta - lead;
                // (A clock running backwards, delta < 0: a frame holds the
                // times from its clock down to the next one's.)
                const bool forward = delta > 0.0;
                const TimeFunction past_next = TimeFunction::apply(
                    forward ? TimeOp::GreaterEqual : TimeOp::LessEqual, t, next);
                const TimeFunction before_start =
                    TimeFunction::apply(forward ? TimeOp::Less : TimeOp::Greater, t, start);
                const TimeFunction exact = n + past_next - before_start;
                st.values.push(Value{TimeFunction::apply(
                    TimeOp::Min, exact + double(a.initial_frame), double(a.final_frame))});
            }
        }
    }
};

template <>
struct action<g::colour_model_literal> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Value v = st.values.pop();
        st.values.push(colour_model(st.values.pop_name(), v));
    }
};

template <>
struct action<g::colour_keyword> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Vector black;
        black.size = 5;
        st.values.push(Value{black});
    }
};

// Components alone, as in a colour_map entry: they change black.
template <>
struct action<g::bare_colour_start> : action<g::colour_keyword> {};

template <>
struct action<g::colour_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Value v = st.values.pop();
        const runtime::ColourFunction c = to_colour(v, "the colour after 'color'");
        Vector r;
        r.size = 5;
        for (int i = 0; i < 5; ++i) r.c[i] = c.c[i];
        st.values.top() = Value{r};
    }
};

// red, green, blue, filter, transmit: the component's index in a colour.
inline int colour_component_index(const std::string& name) {
    return name == "red" ? 0 : name == "green" ? 1 : name == "blue" ? 2 : name == "filter" ? 3 : 4;
}

template <>
struct action<g::colour_component_setting> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        const TimeFunction v = to_float(st.values.pop(), "a colour component");
        const std::string name = st.values.pop_name();
        // (A float or vector before it becomes a colour, as POV-Ray's
        // Parse_Colour promotes it.)
        if (!st.values.top().is<Vector>() || st.values.top().as<Vector>().size != 5) {
            const runtime::ColourFunction colour =
                to_colour(st.values.top(), "the colour '" + name + "' changes");
            Vector promoted;
            promoted.size = 5;
            for (int i = 0; i < 5; ++i) promoted.c[i] = colour.c[i];
            st.values.top() = Value{promoted};
        }
        Vector& c = st.values.top().as<Vector>();
        c.c[colour_component_index(name)] = v;
    }
};

template <>
struct action<g::reference> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const std::string name = word(in);
        if (const auto k = st.function_parameter(name)) {
            st.values.push(Value{TimeFunction::argument(*k)});
            return;
        }
        const Value* v = st.symbols.lookup(name);
        if (v == nullptr) throw ValueError("undeclared identifier '" + name + "'");
        st.check_declared(name);
        if (v->is<Unevaluated>()) {
            const auto& u = v->as<Unevaluated>();
            throw UnsupportedError("'" + name + "' is a " + u.what + " (declared at " +
                                   u.where.source + ":" + std::to_string(u.where.line) + ":" +
                                   std::to_string(u.where.column) +
                                   "), which hexant does not support");
        }
        if (v->is<std::shared_ptr<Array>>()) {
            // Arrays are values: a copy, so that changing it leaves the original alone.
            st.values.push(Value{std::make_shared<Array>(*v->as<std::shared_ptr<Array>>())});
            return;
        }
        st.values.push(*v);
    }
};

template <>
struct action<g::component_access> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Value v = st.values.pop();
        st.values.push(component(v, st.values.pop_name()));
    }
};

// A[index] where the index depends on clock: the element of each piece of
// time where floor(index) is one number (runtime::split_by_value), made
// piecewise as a branch's sides are (time_branch.hpp: floats and vectors
// as `floor(index) = k ? A[k] : ...`, objects each living on its pieces).
inline Value element_by_clock(const Array& array, const TimeFunction& index, Interpreter& st) {
    if (array.dimensions.size() != 1)
        throw ValueError(
            "an index that depends on clock into an array of " +
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
            throw ValueError("array element " + std::to_string(i) +
                             " is used (by clock) before it is set");
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

template <>
struct action<g::index_suffix> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        const TimeFunction index_f = to_float(st.values.pop(), "an array index");
        Value a = st.values.pop();
        if (!a.is<std::shared_ptr<Array>>())
            throw ValueError("'[ ]' needs an array, not a " + type_name(a));
        auto array = a.as<std::shared_ptr<Array>>();
        if (index_f.depends_on_time()) {
            st.values.push(element_by_clock(*array, index_f, st));
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
            sub->elements.assign(
                array->elements.begin() + static_cast<std::ptrdiff_t>(start),
                array->elements.begin() + static_cast<std::ptrdiff_t>(start + stride));
            st.values.push(Value{sub});
            return;
        }
        const std::size_t i = element_index(*array, {index});
        if (!array->elements[i])
            throw ValueError("array element " + std::to_string(i) + " is used before it is set");
        st.values.push(**array->elements[i]);
    }
};

// F(a, b, ...): the body with the arguments in place (folded to a number
// when they are numbers). POV-Ray wants one argument per parameter. A call
// made before with the same arguments (the same nodes) gives the same
// node (Interpreter::function_calls), so a function that calls another
// twice, G = F(x, y, z) + F(x, y, z), shares F's body instead of copying
// it: a chain of such functions stays linear in size, not exponential.
inline Value call_user_function(Interpreter& st,
                                const std::shared_ptr<const runtime::UserFunction>& f,
                                const std::vector<Value>& args) {
    if (!f->unimplemented.empty() && !f->at_call)
        throw UnsupportedError("the internal function " + f->unimplemented +
                               " is not implemented by hexant");
    if (args.size() != f->parameters.size())
        throw ValueError("this function takes " + std::to_string(f->parameters.size()) +
                         " arguments, not " + std::to_string(args.size()));
    std::vector<TimeFunction> values;
    for (const Value& a : args) values.push_back(to_float(a, "a function's argument"));
    if (f->at_call) return Value{f->at_call(values)};
    if (f->noise != runtime::UserFunction::Noise::None) {
        int generator = st.scene.global.noise_generator;
        if (f->noise == runtime::UserFunction::Noise::ArgumentGenerator) {
            const TimeFunction& g = values[3];
            if (!g.is_constant())
                throw UnsupportedError(
                    "f_noise_generator's generator moves with clock; hexant needs it fixed");
            if (!(std::fabs(g.constant()) < 1e9))
                throw ValueError("f_noise_generator's generator is 1, 2 or 3");
            generator = static_cast<int>(g.constant());
        }
        return Value{TimeFunction::point_call(noise_function(generator), 0, values[0], values[1],
                                              values[2])};
    }
    if (!f->components.empty()) {
        // (A pigment function's colour: its components, read by .red, .x, ...)
        Vector v;
        v.size = static_cast<int>(f->components.size());
        for (int i = 0; i < v.size; ++i)
            v.c[static_cast<std::size_t>(i)] =
                runtime::substitute_arguments(f->components[static_cast<std::size_t>(i)], values);
        return Value{v};
    }
    Interpreter::FunctionCall key;
    key.push_back(reinterpret_cast<std::uintptr_t>(f.get()));
    for (const TimeFunction& v : values)
        key.push_back(v.is_constant() ? std::bit_cast<std::uint64_t>(v.constant()) ^ 1u
                                      : reinterpret_cast<std::uintptr_t>(v.node()));
    if (const auto it = st.function_calls.find(key); it != st.function_calls.end())
        return Value{it->second.result};
    TimeFunction result = runtime::substitute_arguments(f->body, values);
    // The entry keeps the function and the arguments alive, so that no
    // other takes their addresses while it stands.
    st.function_calls.emplace(std::move(key), Interpreter::CalledFunction{f, values, result});
    return Value{result};
}

template <>
struct action<g::spline_call> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        std::vector<Value> args = st.values.close_frame();
        Value s = st.values.pop();
        if (s.is<std::shared_ptr<const runtime::UserFunction>>()) {
            st.values.push(
                call_user_function(st, s.as<std::shared_ptr<const runtime::UserFunction>>(), args));
            return;
        }
        if (!s.is<std::shared_ptr<const runtime::Spline>>())
            throw ValueError("only a spline can be called like this, not a " + type_name(s));
        if (args.empty() || args.size() > 2)
            throw ValueError("a spline takes one argument, the time");
        const auto spline = s.as<std::shared_ptr<const runtime::Spline>>();
        const TimeFunction t = to_float(args[0], "the spline's argument");
        // POV-Ray's S(t) is a vector even for a spline of floats (the value in .x).
        Vector v;
        v.size = std::max(spline->dimensions(), 2);
        for (int i = 0; i < v.size; ++i) v.c[i] = TimeFunction::spline_component(spline, i, t);
        st.values.push(Value{v});
    }
};

}  // namespace hexant::language
