// Arithmetic and conversions on values with POV-Ray's rules: floats promote
// to vectors, vectors of different sizes pad with zeros, colours are five
// components. Type errors throw ValueError; the reader adds the place.
#pragma once

#include <stdexcept>
#include <string>

#include "language/value.hpp"
#include "runtime/time/time_ops.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::language {

struct ValueError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What hexant cannot yet make piecewise in time under a branch on clock (an
// array element set on one side, a texture the sides set differently):
// reading each frame alone may pass it (SceneError::may_read_frame_by_frame).
struct PiecewiseError : ValueError {
    using ValueError::ValueError;
};

// The use of something hexant lacks (a function, an isosurface ...): inside a
// #declare it makes the declaration unevaluated rather than an error.
struct UnsupportedError : ValueError {
    using ValueError::ValueError;
};

Value make_float(const TimeFunction& f);
Value make_vector(std::initializer_list<TimeFunction> components);

// Binary operators (+ - * / and comparisons, & |) component-wise.
Value binary_op(runtime::TimeOp op, const Value& a, const Value& b);
Value unary_op(runtime::TimeOp op, const Value& a);
// a ? b : c
Value conditional(const Value& a, const Value& b, const Value& c);
// .x .y .z .t .u .v .red .green .blue .filter .transmit .gray
Value component(const Value& a, const std::string& name);

// Conversions for parameters, naming `what` in the error.
TimeFunction to_float(const Value& v, const std::string& what);
runtime::Vector3Function to_vector3(const Value& v, const std::string& what);
runtime::Vector2Function to_vector2(const Value& v, const std::string& what);
runtime::ColourFunction to_colour(const Value& v, const std::string& what);
Vector to_vector(const Value& v, const std::string& what);  // any size, float promoted to 3
const std::string& to_string_value(const Value& v, const std::string& what);
// A number that must be known while parsing (a condition, an index).
double to_constant(const Value& v, const std::string& what);

// The conversion of rgb/rgbf/rgbt/rgbft/srgb* applied to a value.
Value colour_model(const std::string& model, const Value& v);

}  // namespace hexant::language
