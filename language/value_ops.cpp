#include "language/value_ops.hpp"

#include <algorithm>

namespace hexant::language {

using runtime::TimeOp;

std::string type_name(const Value& value) {
    struct Namer {
        std::string operator()(const TimeFunction&) const { return "float"; }
        std::string operator()(const Vector& v) const {
            return v.size == 5 ? "colour" : std::to_string(v.size) + "-component vector";
        }
        std::string operator()(const std::string&) const { return "string"; }
        std::string operator()(const TimedString&) const { return "string that depends on clock"; }
        std::string operator()(const runtime::ObjectPtr&) const { return "object"; }
        std::string operator()(const runtime::LightRecord&) const { return "light_source"; }
        std::string operator()(const runtime::CameraRecord&) const { return "camera"; }
        std::string operator()(const runtime::Texture&) const { return "texture"; }
        std::string operator()(const runtime::Pigment&) const { return "pigment"; }
        std::string operator()(const runtime::ColourMap&) const { return "color_map"; }
        std::string operator()(const runtime::Normal&) const { return "normal"; }
        std::string operator()(const runtime::SkySphere&) const { return "sky_sphere"; }
        std::string operator()(const runtime::Finish&) const { return "finish"; }
        std::string operator()(const runtime::Interior&) const { return "interior"; }
        std::string operator()(const runtime::Media&) const { return "media"; }
        std::string operator()(const Material&) const { return "material"; }
        std::string operator()(const runtime::Transform&) const { return "transform"; }
        std::string operator()(const std::shared_ptr<Array>&) const { return "array"; }
        std::string operator()(const std::shared_ptr<const runtime::Spline>&) const {
            return "spline";
        }
        std::string operator()(const std::shared_ptr<const Macro>&) const { return "macro"; }
        std::string operator()(const std::shared_ptr<const runtime::UserFunction>&) const {
            return "function";
        }
        std::string operator()(const Unevaluated& u) const { return u.what; }
    };
    return std::visit(Namer{}, value.v);
}

Value make_float(const TimeFunction& f) {
    return Value{f};
}

Value make_vector(std::initializer_list<TimeFunction> components) {
    Vector v;
    v.size = static_cast<int>(components.size());
    int i = 0;
    for (const auto& c : components) v.c[i++] = c;
    return Value{v};
}

namespace {

// A float promoted to a vector of `size` components.
Vector promote(const TimeFunction& f, int size) {
    Vector v;
    v.size = size;
    for (int i = 0; i < size; ++i) v.c[i] = f;
    return v;
}

std::string op_text(TimeOp op) {
    return std::string("'") + runtime::name(op) + "'";
}

}  // namespace

Value binary_op(TimeOp op, const Value& a, const Value& b) {
    if (a.is<TimeFunction>() && b.is<TimeFunction>())
        return Value{TimeFunction::apply(op, a.as<TimeFunction>(), b.as<TimeFunction>())};
    const bool a_numeric = a.is<TimeFunction>() || a.is<Vector>();
    const bool b_numeric = b.is<TimeFunction>() || b.is<Vector>();
    if (!a_numeric || !b_numeric)
        throw ValueError("cannot apply " + op_text(op) + " to " + type_name(a) + " and " +
                         type_name(b));
    const int size = std::max(a.is<Vector>() ? a.as<Vector>().size : 0,
                              b.is<Vector>() ? b.as<Vector>().size : 0);
    const Vector va = a.is<Vector>() ? a.as<Vector>() : promote(a.as<TimeFunction>(), size);
    const Vector vb = b.is<Vector>() ? b.as<Vector>() : promote(b.as<TimeFunction>(), size);
    Vector r;
    r.size = size;
    for (int i = 0; i < size; ++i) {
        const TimeFunction x = i < va.size ? va.c[i] : TimeFunction(0.0);
        const TimeFunction y = i < vb.size ? vb.c[i] : TimeFunction(0.0);
        switch (op) {
            case TimeOp::Add:
                r.c[i] = x + y;
                break;
            case TimeOp::Subtract:
                r.c[i] = x - y;
                break;
            case TimeOp::Multiply:
                r.c[i] = x * y;
                break;
            case TimeOp::Divide:
                r.c[i] = x / y;
                break;
            default:
                r.c[i] = TimeFunction::apply(op, x, y);
                break;
        }
    }
    return Value{r};
}

Value unary_op(TimeOp op, const Value& a) {
    if (a.is<TimeFunction>()) return Value{TimeFunction::apply(op, a.as<TimeFunction>())};
    if (a.is<Vector>()) {
        Vector r = a.as<Vector>();
        for (int i = 0; i < r.size; ++i) r.c[i] = TimeFunction::apply(op, r.c[i]);
        return Value{r};
    }
    throw ValueError("cannot apply " + op_text(op) + " to " + type_name(a));
}

Value conditional(const Value& a, const Value& b, const Value& c) {
    const TimeFunction cond = to_float(a, "the condition of '? :'");
    if (cond.is_constant()) return runtime::pov_true(cond.constant()) ? b : c;
    if (b.is<TimeFunction>() && c.is<TimeFunction>())
        return Value{TimeFunction::apply(TimeOp::Conditional, cond, b.as<TimeFunction>(),
                                         c.as<TimeFunction>())};
    if ((b.is<TimeFunction>() || b.is<Vector>()) && (c.is<TimeFunction>() || c.is<Vector>())) {
        // Component-wise on numbers, with the usual promotion and padding.
        const int size = std::max(b.is<Vector>() ? b.as<Vector>().size : 0,
                                  c.is<Vector>() ? c.as<Vector>().size : 0);
        auto widen = [size](const Value& v) {
            if (v.is<TimeFunction>()) return promote(v.as<TimeFunction>(), size);
            Vector r = v.as<Vector>();
            for (int i = r.size; i < size; ++i) r.c[i] = 0.0;
            r.size = size;
            return r;
        };
        const Vector vb = widen(b), vc = widen(c);
        Vector r;
        r.size = size;
        for (int i = 0; i < size; ++i)
            r.c[i] = TimeFunction::apply(TimeOp::Conditional, cond, vb.c[i], vc.c[i]);
        return Value{r};
    }
    throw ValueError("a condition that depends on clock cannot choose between a " + type_name(b) +
                     " and a " + type_name(c));
}

Value component(const Value& a, const std::string& name) {
    if (!a.is<Vector>())
        throw ValueError("'." + name + "' needs a vector or colour, not a " + type_name(a));
    const Vector& v = a.as<Vector>();
    if (name == "gray" || name == "grey") {
        if (v.size < 3) throw ValueError("'." + name + "' needs a colour");
        return Value{v.c[0] * 0.297 + v.c[1] * 0.589 + v.c[2] * 0.114};
    }
    int index = 0;
    if (name == "x" || name == "u" || name == "red")
        index = 0;
    else if (name == "y" || name == "v" || name == "green")
        index = 1;
    else if (name == "z" || name == "blue")
        index = 2;
    else if (name == "t" || name == "filter")
        index = 3;
    else if (name == "transmit")
        index = 4;
    if (index >= v.size)
        throw ValueError("'." + name + "' is not a component of a " + type_name(a));
    return Value{v.c[index]};
}

TimeFunction to_float(const Value& v, const std::string& what) {
    if (v.is<TimeFunction>()) return v.as<TimeFunction>();
    throw ValueError(what + " must be a float, not a " + type_name(v));
}

Vector to_vector(const Value& v, const std::string& what) {
    if (v.is<Vector>()) return v.as<Vector>();
    if (v.is<TimeFunction>()) return promote(v.as<TimeFunction>(), 3);
    throw ValueError(what + " must be a vector, not a " + type_name(v));
}

runtime::Vector3Function to_vector3(const Value& v, const std::string& what) {
    const Vector vec = to_vector(v, what);
    // A 2-component vector gets z = 0, as POV-Ray's Parse_Vector pads it
    // (fractalzoom.pov translates its pigment by <x, y>).
    if (vec.size == 2) return runtime::Vector3Function{{vec.c[0], vec.c[1], 0.0}};
    return runtime::Vector3Function{{vec.c[0], vec.c[1], vec.c[2]}};
}

runtime::Vector2Function to_vector2(const Value& v, const std::string& what) {
    const Vector vec = v.is<TimeFunction>() ? promote(v.as<TimeFunction>(), 2) : to_vector(v, what);
    return runtime::Vector2Function{{vec.c[0], vec.c[1]}};
}

runtime::ColourFunction to_colour(const Value& v, const std::string& what) {
    runtime::ColourFunction c;
    if (v.is<TimeFunction>()) {
        for (auto& f : c.c) f = v.as<TimeFunction>();
        return c;
    }
    if (!v.is<Vector>()) throw ValueError(what + " must be a colour, not a " + type_name(v));
    const Vector& vec = v.as<Vector>();
    if (vec.size < 3) throw ValueError(what + " must be a colour, not a " + type_name(v));
    for (int i = 0; i < vec.size; ++i) c.c[i] = vec.c[i];
    return c;
}

const std::string& to_string_value(const Value& v, const std::string& what) {
    if (v.is<std::string>()) return v.as<std::string>();
    if (v.is<TimedString>())
        throw PiecewiseError(what + " depends on clock (" + v.as<TimedString>().describe() +
                             "); hexant needs one string here");
    throw ValueError(what + " must be a string, not a " + type_name(v));
}

double to_constant(const Value& v, const std::string& what) {
    const TimeFunction f = to_float(v, what);
    if (!f.is_constant())
        throw PiecewiseError(what +
                             " depends on clock; it must be known while the scene is read "
                             "(hexant splits time on conditions, a #for's end and an index "
                             "read, not yet on this)");
    return f.constant();
}

Value colour_model(const std::string& model, const Value& v) {
    const bool srgb = model.rfind("srgb", 0) == 0;
    const std::string kind = srgb ? model.substr(1) : model;  // rgb, rgbf, rgbt, rgbft
    const bool f = kind == "rgbf" || kind == "rgbft";
    const bool t = kind == "rgbt" || kind == "rgbft";
    Vector r;
    r.size = 5;
    for (auto& c : r.c) c = 0.0;
    if (v.is<TimeFunction>()) {
        const TimeFunction x = v.as<TimeFunction>();
        r.c[0] = r.c[1] = r.c[2] = x;
        if (f) r.c[3] = x;
        if (t) r.c[4] = x;
    } else if (v.is<Vector>()) {
        const Vector& in = v.as<Vector>();
        // A 2-component vector's blue is 0, as POV-Ray pads a shorter
        // vector in a colour (rgb <1, 0.5> is rgb <1, 0.5, 0>).
        for (int i = 0; i < 3; ++i) r.c[i] = i < in.size ? in.c[i] : TimeFunction(0.0);
        int next = 3;
        if (f && next < in.size) r.c[3] = in.c[next++];
        if (t && next < in.size) r.c[4] = in.c[next++];
    } else {
        throw ValueError(model + " needs a float or a vector, not a " + type_name(v));
    }
    if (srgb)
        for (int i = 0; i < 3; ++i) r.c[i] = TimeFunction::apply(TimeOp::SrgbDecode, r.c[i]);
    return Value{r};
}

}  // namespace hexant::language
