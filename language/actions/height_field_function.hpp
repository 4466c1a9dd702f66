// height_field { function W, H { F } }: the grid sampled from F when its
// body closes, into the height field on top of the block stack
// (runtime/objects/height_field/height_field_function.hpp).
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/polys.hpp"
#include "runtime/objects/height_field/height_field_function.hpp"

namespace hexant::language {

// ------------------------------------------------------------ height_field function

template <>
struct action<g::height_field_function_open> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        runtime::ObjectRecord record;
        record.shape = runtime::HeightField{};
        record.place = source_place(in);
        st.blocks.open(std::move(record));
    }
};

template <>
struct action<g::height_field_function_body> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        const Value body = st.values.pop();
        // (POV-Ray: int(W + 0.5).)
        const auto size = [&](const char* what) {
            const double v = to_constant(st.values.pop(), what);
            if (!(v >= 2.0 && v <= runtime::objects::kMaxFunctionGridSide))
                throw ValueError(std::string(what) + " is 2 to " +
                                 std::to_string(runtime::objects::kMaxFunctionGridSide) + ", not " +
                                 std::to_string(v));
            return static_cast<int>(v + 0.5);
        };
        const int height = size("the height_field function's height");
        const int width = size("the height_field function's width");
        auto& record = st.blocks.edit<runtime::ObjectRecord>(in.position(), "a height_field");
        auto& field = std::get<runtime::HeightField>(record.shape);
        field.file = "function";
        try {
            if (body.is<runtime::Pigment>()) {
                const runtime::PigmentFunction pigment(body.as<runtime::Pigment>());
                if (pigment.depends_on_time())
                    throw UnsupportedError(
                        "a height_field of a pigment that moves with clock: hexant samples the "
                        "grid once for the whole animation");
                field.data =
                    runtime::objects::heights_of_pigment(width, height, [&](double x, double y) {
                        return std::array<double, 3>{pigment.at(0, {x, y, 0.0}, 0.0),
                                                     pigment.at(1, {x, y, 0.0}, 0.0),
                                                     pigment.at(2, {x, y, 0.0}, 0.0)};
                    });
                return;
            }
            const auto& f = *body.as<std::shared_ptr<const runtime::UserFunction>>();
            if (!f.unimplemented.empty())
                throw UnsupportedError("the internal function " + f.unimplemented +
                                       " is not implemented by hexant");
            const runtime::SpaceFunction function(f.body);
            if (function.depends_on_time())
                throw UnsupportedError(
                    "a height_field of a function that moves with clock: hexant samples the "
                    "grid once for the whole animation");
            field.data =
                runtime::objects::heights_of_function(width, height, [&](double x, double y) {
                    return function.at({x, y, 0.0}, 0.0);
                });
        } catch (const runtime::ObjectError& e) {
            throw UnsupportedError(std::string("the height_field function's pigment: ") + e.what());
        } catch (const runtime::objects::HeightFieldError& e) {
            throw ValueError(e.what());
        }
    }
};

template <>
struct action<g::height_field_function_block> : finish_object {};

}  // namespace hexant::language
