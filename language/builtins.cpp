#include "language/builtins.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>

#include "language/checked_integer.hpp"
#include "language/value_ops.hpp"
#include "runtime/texture/pattern/noise.hpp"
#include "runtime/time/switching_instants.hpp"

namespace hexant::language {

using runtime::TimeOp;

std::string format_number(double value, int length, int precision) {
    // POV-Ray 3.7's Parse_Str: "%f" with the width (zero-padded when
    // negative) and, when not negative, the precision ("%f" alone prints 6
    // places); "%g" instead when "%f" would not fit its 255 characters
    // (1e300 to 2 places).
    const bool zero_pad = length < 0;
    const int width = std::min(std::abs(length), 200);
    const auto print = [&](char conversion) {
        char format[16];
        std::snprintf(format, sizeof format, "%%%s*%s%c", zero_pad ? "0" : "",
                      precision >= 0 ? ".*" : "", conversion);
        char buffer[1024];
        const int n = precision >= 0 ? std::snprintf(buffer, sizeof buffer, format, width,
                                                     std::min(precision, 100), value)
                                     : std::snprintf(buffer, sizeof buffer, format, width, value);
        return std::pair<std::string, int>(buffer, n);
    };
    auto [text, n] = print('f');
    if (n < 0 || n >= 255) text = print('g').first;
    return text;
}

namespace {

using Args = std::vector<Value>;

void expect_count(const std::string& name, const Args& args, std::size_t lo, std::size_t hi) {
    if (args.size() < lo || args.size() > hi) {
        std::string want = lo == hi   ? std::to_string(lo)
                           : hi > 100 ? "at least " + std::to_string(lo)
                                      : std::to_string(lo) + " to " + std::to_string(hi);
        throw ValueError(name + "() takes " + want + " argument" + (hi == 1 ? "" : "s") + ", not " +
                         std::to_string(args.size()));
    }
}

TimeFunction arg_float(const std::string& name, const Args& args, std::size_t i) {
    return to_float(args[i], "argument " + std::to_string(i + 1) + " of " + name + "()");
}
double arg_constant(const std::string& name, const Args& args, std::size_t i) {
    return to_constant(args[i], "argument " + std::to_string(i + 1) + " of " + name + "()");
}
// The widths and precisions str() and vstr() accept: far beyond any use
// (POV-Ray formats into a fixed buffer), small enough that a typo such as
// 1e300 is an error rather than a string of that length.
constexpr long long kMaxWidth = 10'000;
constexpr long long kMaxPrecision = 100;
// An operand of bitwise_and/or/xor: an integer a double holds exactly.
long long bitwise_operand(const std::string& name, const Args& args, std::size_t i) {
    return checked_integer(arg_constant(name, args, i),
                           "argument " + std::to_string(i + 1) + " of " + name + "()",
                           -kMaxExactInteger, kMaxExactInteger);
}
runtime::Vector3Function arg_vector(const std::string& name, const Args& args, std::size_t i) {
    return to_vector3(args[i], "argument " + std::to_string(i + 1) + " of " + name + "()");
}
const std::string& arg_string(const std::string& name, const Args& args, std::size_t i) {
    return to_string_value(args[i], "argument " + std::to_string(i + 1) + " of " + name + "()");
}

Value vec3(const TimeFunction& a, const TimeFunction& b, const TimeFunction& c) {
    return make_vector({a, b, c});
}

constexpr double kPi = 3.14159265358979323846;

// v rotated by r degrees about x, then y, then z (POV-Ray's vrotate).
Value rotate_vector(runtime::Vector3Function v, const runtime::Vector3Function& r) {
    for (int axis = 0; axis < 3; ++axis) {
        const TimeFunction angle = r.c[axis] * (kPi / 180.0);
        if (angle.is_constant() && angle.constant() == 0.0) continue;
        const TimeFunction s = TimeFunction::apply(TimeOp::Sin, angle);
        const TimeFunction c = TimeFunction::apply(TimeOp::Cos, angle);
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        const TimeFunction va = v.c[a], vb = v.c[b];
        v.c[a] = va * c - vb * s;
        v.c[b] = va * s + vb * c;
    }
    return vec3(v.c[0], v.c[1], v.c[2]);
}

TimeFunction dot(const runtime::Vector3Function& a, const runtime::Vector3Function& b) {
    return a.c[0] * b.c[0] + a.c[1] * b.c[1] + a.c[2] * b.c[2];
}

runtime::Vector3Function cross(const runtime::Vector3Function& a,
                               const runtime::Vector3Function& b) {
    return {{a.c[1] * b.c[2] - a.c[2] * b.c[1], a.c[2] * b.c[0] - a.c[0] * b.c[2],
             a.c[0] * b.c[1] - a.c[1] * b.c[0]}};
}

TimeFunction length(const runtime::Vector3Function& a) {
    return TimeFunction::apply(TimeOp::Sqrt, dot(a, a));
}

using Builtin = std::function<Value(const std::string&, const Args&, RandomStreams&)>;

Builtin unary(TimeOp op) {
    return [op](const std::string& name, const Args& args, RandomStreams&) {
        expect_count(name, args, 1, 1);
        return Value{TimeFunction::apply(op, arg_float(name, args, 0))};
    };
}

Builtin binary(TimeOp op) {
    return [op](const std::string& name, const Args& args, RandomStreams&) {
        expect_count(name, args, 2, 2);
        return Value{TimeFunction::apply(op, arg_float(name, args, 0), arg_float(name, args, 1))};
    };
}

Builtin fold(TimeOp op) {
    return [op](const std::string& name, const Args& args, RandomStreams&) {
        expect_count(name, args, 2, 1000);
        TimeFunction r = arg_float(name, args, 0);
        for (std::size_t i = 1; i < args.size(); ++i)
            r = TimeFunction::apply(op, r, arg_float(name, args, i));
        return Value{r};
    };
}

Builtin hyperbolic(double sign, bool tangent) {
    return [sign, tangent](const std::string& name, const Args& args, RandomStreams&) {
        expect_count(name, args, 1, 1);
        const TimeFunction x = arg_float(name, args, 0);
        const TimeFunction ep = TimeFunction::apply(TimeOp::Exp, x);
        const TimeFunction em = TimeFunction::apply(TimeOp::Exp, -x);
        if (tangent) return Value{(ep - em) / (ep + em)};
        return Value{(ep + em * sign) * 0.5};
    };
}

const std::map<std::string, Builtin>& table() {
    static const std::map<std::string, Builtin> functions = {
        {"abs", unary(TimeOp::Abs)},
        {"sin", unary(TimeOp::Sin)},
        {"cos", unary(TimeOp::Cos)},
        {"tan", unary(TimeOp::Tan)},
        {"asin", unary(TimeOp::Asin)},
        {"acos", unary(TimeOp::Acos)},
        {"atan", unary(TimeOp::Atan)},
        {"sqrt", unary(TimeOp::Sqrt)},
        {"exp", unary(TimeOp::Exp)},
        {"log", unary(TimeOp::Log10)},
        {"ln", unary(TimeOp::Ln)},
        {"int", unary(TimeOp::Int)},
        {"floor", unary(TimeOp::Floor)},
        {"ceil", unary(TimeOp::Ceil)},
        {"sinh", hyperbolic(-1.0, false)},
        {"cosh", hyperbolic(1.0, false)},
        {"tanh", hyperbolic(1.0, true)},
        // The inverses by their logarithms (POV-Ray calls the C library's).
        {"asinh",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             const TimeFunction x = arg_float(n, a, 0);
             return Value{TimeFunction::apply(TimeOp::Ln,
                                              x + TimeFunction::apply(TimeOp::Sqrt, x * x + 1.0))};
         }},
        {"acosh",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             const TimeFunction x = arg_float(n, a, 0);
             return Value{TimeFunction::apply(TimeOp::Ln,
                                              x + TimeFunction::apply(TimeOp::Sqrt, x * x - 1.0))};
         }},
        {"atanh",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             const TimeFunction x = arg_float(n, a, 0);
             return Value{TimeFunction::apply(TimeOp::Ln, (1.0 + x) / (1.0 - x)) * 0.5};
         }},
        {"atan2", binary(TimeOp::Atan2)},
        {"pow", binary(TimeOp::Pow)},
        {"mod", binary(TimeOp::Mod)},
        {"div", binary(TimeOp::IntDiv)},
        {"min", fold(TimeOp::Min)},
        {"max", fold(TimeOp::Max)},
        {"radians",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             return Value{arg_float(n, a, 0) * (kPi / 180.0)};
         }},
        {"degrees",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             return Value{arg_float(n, a, 0) * (180.0 / kPi)};
         }},
        {"select",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 3, 4);
             const TimeFunction s = arg_float(n, a, 0);
             if (a.size() == 3) {
                 if (s.is_constant()) return s.constant() < 0.0 ? a[1] : a[2];
                 return Value{TimeFunction::apply(TimeOp::Select, s, arg_float(n, a, 1),
                                                  arg_float(n, a, 2))};
             }
             if (s.is_constant())
                 return s.constant() < 0.0 ? a[1] : (s.constant() == 0.0 ? a[2] : a[3]);
             const TimeFunction is_zero = TimeFunction::apply(TimeOp::Equal, s, 0.0);
             return Value{
                 TimeFunction::apply(TimeOp::Select, s, arg_float(n, a, 1),
                                     TimeFunction::apply(TimeOp::Conditional, is_zero,
                                                         arg_float(n, a, 2), arg_float(n, a, 3)))};
         }},
        {"vlength",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             return Value{length(arg_vector(n, a, 0))};
         }},
        {"vnormalize",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             const auto v = arg_vector(n, a, 0);
             const TimeFunction l = length(v);
             // POV-Ray's rule: a zero-length vector gives <0, 0, 0> (with
             // a warning, vnormalize_zero_at), at every instant it is zero.
             if (l.is_constant() && l.constant() == 0.0) return vec3(0.0, 0.0, 0.0);
             if (l.is_constant()) return vec3(v.c[0] / l, v.c[1] / l, v.c[2] / l);
             const TimeFunction nonzero = TimeFunction::apply(TimeOp::Greater, l, 0.0);
             const auto part = [&](const TimeFunction& c) {
                 return TimeFunction::apply(TimeOp::Conditional, nonzero, c / l, 0.0);
             };
             return vec3(part(v.c[0]), part(v.c[1]), part(v.c[2]));
         }},
        {"vdot",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 2, 2);
             return Value{dot(arg_vector(n, a, 0), arg_vector(n, a, 1))};
         }},
        {"vcross",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 2, 2);
             const auto c = cross(arg_vector(n, a, 0), arg_vector(n, a, 1));
             return vec3(c.c[0], c.c[1], c.c[2]);
         }},
        {"vturbulence",
         [](const std::string& n, const Args& a, RandomStreams&) {
             // vturbulence(Lambda, Omega, Octaves, V): POV-Ray's DTurbulence
             // at V, the octaves truncated and clamped to 1..10
             // (parser_expressions.cpp).
             expect_count(n, a, 4, 4);
             const auto v = arg_vector(n, a, 3);
             if (v.depends_on_time())
                 throw ValueError(
                     "vturbulence() at a point that moves with clock is not "
                     "supported by hexant");
             const runtime::pattern::Octaves o = runtime::pattern::octaves_of(
                 arg_constant(n, a, 2), arg_constant(n, a, 1), arg_constant(n, a, 0));
             const glm::dvec3 d = runtime::pattern::dturbulence(v(0.0), o);
             return vec3(d.x, d.y, d.z);
         }},
        {"vrotate",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 2, 2);
             return rotate_vector(arg_vector(n, a, 0), arg_vector(n, a, 1));
         }},
        {"vaxis_rotate",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 3, 3);
             const auto v = arg_vector(n, a, 0);
             auto k = arg_vector(n, a, 1);
             const TimeFunction l = length(k);
             if (l.is_constant() && l.constant() == 0.0)
                 throw ValueError("vaxis_rotate() about a zero-length axis");
             for (auto& c : k.c) c = c / l;
             const TimeFunction angle = arg_float(n, a, 2) * (kPi / 180.0);
             const TimeFunction s = TimeFunction::apply(TimeOp::Sin, angle);
             const TimeFunction c = TimeFunction::apply(TimeOp::Cos, angle);
             const auto kv = cross(k, v);
             const TimeFunction kd = dot(k, v) * (TimeFunction(1.0) - c);
             return vec3(v.c[0] * c + kv.c[0] * s + k.c[0] * kd,
                         v.c[1] * c + kv.c[1] * s + k.c[1] * kd,
                         v.c[2] * c + kv.c[2] * s + k.c[2] * kd);
         }},
        {"str",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 3, 3);
             return Value{format_number(
                 arg_constant(n, a, 0),
                 static_cast<int>(checked_integer(arg_constant(n, a, 1), "str()'s length",
                                                  -kMaxWidth, kMaxWidth)),
                 static_cast<int>(checked_integer(arg_constant(n, a, 2), "str()'s precision",
                                                  -kMaxWidth, kMaxPrecision)))};
         }},
        {"vstr",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 5, 5);
             // POV-Ray's order: vstr(components, vector, separator, length, precision)
             const int dims =
                 static_cast<int>(checked_integer(arg_constant(n, a, 0), "vstr()'s component count",
                                                  -kMaxExactInteger, kMaxExactInteger));
             const Vector v = to_vector(a[1], "argument 2 of vstr()");
             const std::string& sep = arg_string(n, a, 2);
             const int len = static_cast<int>(
                 checked_integer(arg_constant(n, a, 3), "vstr()'s length", -kMaxWidth, kMaxWidth));
             const int prec = static_cast<int>(checked_integer(
                 arg_constant(n, a, 4), "vstr()'s precision", -kMaxWidth, kMaxPrecision));
             std::string out;
             for (int i = 0; i < std::clamp(dims, 1, 5); ++i) {
                 if (i) out += sep;
                 const TimeFunction c = i < v.size ? v.c[i] : TimeFunction(0.0);
                 out +=
                     format_number(to_constant(Value{c}, "a component given to vstr()"), len, prec);
             }
             return Value{out};
         }},
        {"concat",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 100000);
             std::string out;
             for (std::size_t i = 0; i < a.size(); ++i) out += arg_string(n, a, i);
             return Value{out};
         }},
        {"chr",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             const long long c =
                 checked_integer(arg_constant(n, a, 0), "chr()'s character code", 1, 127);
             return Value{std::string(1, static_cast<char>(c))};
         }},
        {"asc",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             const std::string& s = arg_string(n, a, 0);
             return Value{TimeFunction(s.empty() ? 0.0 : static_cast<unsigned char>(s[0]))};
         }},
        {"strlen",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             return Value{TimeFunction(static_cast<double>(arg_string(n, a, 0).size()))};
         }},
        {"substr",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 3, 3);
             const std::string& s = arg_string(n, a, 0);
             const long long size = static_cast<long long>(s.size());
             const long long p =
                 checked_integer(arg_constant(n, a, 1), "substr()'s start", 1, size + 1);
             const long long l =
                 checked_integer(arg_constant(n, a, 2), "substr()'s length", 0, size + 1 - p);
             return Value{s.substr(static_cast<std::size_t>(p - 1), static_cast<std::size_t>(l))};
         }},
        {"strupr",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             std::string s = arg_string(n, a, 0);
             for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
             return Value{s};
         }},
        {"strlwr",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             std::string s = arg_string(n, a, 0);
             for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
             return Value{s};
         }},
        {"strcmp",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 2, 2);
             // POV-Ray's UCS2_strcmp: the difference of the first characters
             // that differ (the end of a string counting as 0).
             const std::string &x = arg_string(n, a, 0), &y = arg_string(n, a, 1);
             for (std::size_t i = 0;; ++i) {
                 const int cx = i < x.size() ? static_cast<unsigned char>(x[i]) : 0;
                 const int cy = i < y.size() ? static_cast<unsigned char>(y[i]) : 0;
                 if (cx != cy || cx == 0) return Value{TimeFunction(static_cast<double>(cx - cy))};
             }
         }},
        {"val",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             return Value{TimeFunction(std::strtod(arg_string(n, a, 0).c_str(), nullptr))};
         }},
        {"file_exists",
         [](const std::string&, const Args&, RandomStreams&) -> Value {
             // (Confined to the folders a scene may read: answered by the
             // interpreter, language/actions/literals.hpp.)
             throw std::logic_error("file_exists() is answered by the Interpreter");
         }},
        {"dimensions",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 1, 1);
             if (!a[0].is<std::shared_ptr<Array>>())
                 throw ValueError("dimensions() needs an array, not a " + type_name(a[0]));
             return Value{TimeFunction(
                 static_cast<double>(a[0].as<std::shared_ptr<Array>>()->dimensions.size()))};
         }},
        {"dimension_size",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 2, 2);
             if (!a[0].is<std::shared_ptr<Array>>())
                 throw ValueError("dimension_size() needs an array, not a " + type_name(a[0]));
             const auto& dims = a[0].as<std::shared_ptr<Array>>()->dimensions;
             // POV-Ray gives 0 for a dimension the array does not have.
             const long long d =
                 checked_integer(arg_constant(n, a, 1), "dimension_size()'s dimension",
                                 -kMaxExactInteger, kMaxExactInteger);
             if (d < 1 || d > static_cast<long long>(dims.size())) return Value{TimeFunction(0.0)};
             return Value{TimeFunction(static_cast<double>(dims[static_cast<std::size_t>(d) - 1]))};
         }},
        {"seed",
         [](const std::string& n, const Args& a, RandomStreams& r) {
             expect_count(n, a, 1, 1);
             r.streams.emplace_back(arg_constant(n, a, 0));
             return Value{TimeFunction(static_cast<double>(r.streams.size() - 1))};
         }},
        {"rand",
         [](const std::string& n, const Args& a, RandomStreams& r) {
             expect_count(n, a, 1, 1);
             if (r.streams.empty())
                 throw ValueError("rand() needs a stream made by seed(), and none was made");
             const long long s =
                 checked_integer(arg_constant(n, a, 0), "rand()'s stream (made by seed())", 0,
                                 static_cast<long long>(r.streams.size()) - 1);
             return Value{TimeFunction(r.streams[static_cast<std::size_t>(s)].next())};
         }},
        {"bitwise_and",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 2, 1000);
             long long r = bitwise_operand(n, a, 0);
             for (std::size_t i = 1; i < a.size(); ++i) r &= bitwise_operand(n, a, i);
             return Value{TimeFunction(static_cast<double>(r))};
         }},
        {"bitwise_or",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 2, 1000);
             long long r = bitwise_operand(n, a, 0);
             for (std::size_t i = 1; i < a.size(); ++i) r |= bitwise_operand(n, a, i);
             return Value{TimeFunction(static_cast<double>(r))};
         }},
        {"bitwise_xor",
         [](const std::string& n, const Args& a, RandomStreams&) {
             expect_count(n, a, 2, 1000);
             long long r = bitwise_operand(n, a, 0);
             for (std::size_t i = 1; i < a.size(); ++i) r ^= bitwise_operand(n, a, i);
             return Value{TimeFunction(static_cast<double>(r))};
         }},
    };
    return functions;
}

}  // namespace

Value call_builtin(const std::string& name, const std::vector<Value>& args, RandomStreams& random) {
    const auto& functions = table();
    auto it = functions.find(name);
    if (it == functions.end()) throw ValueError("unknown function " + name + "()");
    return it->second(name, args, random);
}

std::optional<double> vnormalize_zero_at(const std::vector<Value>& args,
                                         const runtime::Interval& time) {
    if (args.size() != 1) return std::nullopt;
    const TimeFunction l = length(arg_vector("vnormalize", args, 0));
    if (l.is_constant()) return l.constant() == 0.0 ? std::optional<double>(time.lo) : std::nullopt;
    // Its zeros, exactly (runtime/time/switching_instants.hpp); a length that
    // comes and goes too often is reported at the start.
    try {
        const auto pieces =
            runtime::split_by_truth(TimeFunction::apply(TimeOp::Greater, l, 0.0), {time}, 10'000);
        if (pieces.when_false.is_never()) return std::nullopt;
        return pieces.when_false.pieces().front().lo;
    } catch (const runtime::LimitError&) {
        return time.lo;
    }
}

}  // namespace hexant::language
