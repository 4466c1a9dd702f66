// Arrays and splines.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/scene.hpp"

namespace hexant::language {

// ------------------------------------------------------------ arrays and splines

template <>
struct action<g::array_dimensions> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        std::vector<Value> sizes = st.values.close_frame();
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
        st.values.push(Value{array});
    }
};
template <>
struct action<g::array_initializer> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        std::vector<Value> items = st.values.close_frame();
        auto list = std::make_shared<Array>();  // no dimensions: an initializer list
        list->charge.attach(st.array_memory());
        for (auto& item : items) {
            list->charge.add(kArraySlotBytes + element_bytes(item));
            list->elements.emplace_back(std::make_shared<Value>(std::move(item)));
        }
        st.values.push(Value{list});
    }
};
void fill_array(Array& array, const Array& list, std::size_t dimension, std::size_t& next);
template <>
struct action<g::array_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        Value top = st.values.pop();
        auto list = top.as<std::shared_ptr<Array>>();
        if (!list->dimensions.empty()) {  // no initializer
            st.values.push(std::move(top));
            return;
        }
        auto array = st.values.pop().as<std::shared_ptr<Array>>();
        std::size_t next = 0;
        fill_array(*array, *list, 0, next);
        st.values.push(Value{array});
    }
};
template <>
struct action<g::spline_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.blocks.open(std::in_place_type<SplineBuilder>);
    }
};
template <>
struct action<g::spline_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (!v.is<std::shared_ptr<const runtime::Spline>>())
            throw ValueError("spline { } starts with a spline, not a " + type_name(v));
        const auto& base = *v.as<std::shared_ptr<const runtime::Spline>>();
        auto& s = st.blocks.edit<SplineBuilder>(in.position(), "a spline");
        s.kind = base.kind();
        s.keys = base.keys();
        s.dimensions = base.dimensions();
    }
};
template <>
struct action<g::spline_kind> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const std::string w = word(in);
        auto& s = st.blocks.edit<SplineBuilder>(in.position(), w.c_str());
        using K = runtime::SplineKind;
        s.kind = w == "linear_spline"      ? K::Linear
                 : w == "quadratic_spline" ? K::Quadratic
                 : w == "cubic_spline"     ? K::Cubic
                                           : K::Natural;
    }
};
template <>
struct action<g::spline_key> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const double t = to_constant(st.values.pop(), "a spline key's time");
        auto& s = st.blocks.edit<SplineBuilder>(in.position(), "a spline key");
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
        if (s.keys.empty())
            s.dimensions = dims;
        else
            s.dimensions = std::max(s.dimensions, dims);
        s.keys.push_back(key);
    }
};
template <>
struct action<g::spline_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        SplineBuilder b = std::get<SplineBuilder>(st.blocks.top());
        st.blocks.close();
        if (b.keys.empty()) Interpreter::fail(in.position(), "a spline needs at least one key");
        st.values.push(Value{std::shared_ptr<const runtime::Spline>(
            std::make_shared<runtime::Spline>(b.kind, std::move(b.keys), b.dimensions))});
    }
};

// function { spline { } }: F(t) is the spline's vector at t (POV-Ray's
// spline function), a vector of the spline's dimensions (at least 2, as
// S(t) is).
template <>
struct action<g::function_spline> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const auto spline = st.values.pop().as<std::shared_ptr<const runtime::Spline>>();
        auto f = std::make_shared<runtime::UserFunction>();
        f->parameters = {"t"};
        const int size = std::max(spline->dimensions(), 2);
        for (int i = 0; i < size; ++i)
            f->components.push_back(
                TimeFunction::spline_component(spline, i, TimeFunction::argument(0)));
        st.values.push(Value{std::shared_ptr<const runtime::UserFunction>(std::move(f))});
    }
};

template <>
struct action<g::scene_object> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (v.is<runtime::LightRecord>()) {
            if (auto problem =
                    runtime::bad_parameter(v.as<runtime::LightRecord>(), st.scene.animation))
                throw ValueError(*problem);
            st.add_light(v.as<runtime::LightRecord>(), in.position());
        } else if (v.is<runtime::ObjectPtr>()) {
            st.add_object(v.as<runtime::ObjectPtr>(), in.position());
        } else if (v.is<Unevaluated>()) {
            throw ValueError(v.as<Unevaluated>().what + " is not supported by hexant");
        }
    }
};
template <>
struct action<g::scene_unsupported> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        throw ValueError(st.values.pop().as<Unevaluated>().what + " is not supported by hexant");
    }
};

}  // namespace hexant::language
