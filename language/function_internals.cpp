#include "language/function_internals.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "language/value_ops.hpp"
#include "runtime/texture/pattern/noise_function.hpp"

namespace hexant::language {

namespace {

using runtime::TimeFunction;
using runtime::TimeOp;
using F = TimeFunction;
using Params = std::vector<TimeFunction>;  // x, y, z, then the function's own

F sqrt_(const F& a) {
    return F::apply(TimeOp::Sqrt, a);
}
F abs_(const F& a) {
    return F::apply(TimeOp::Abs, a);
}
F pow_(const F& a, const F& b) {
    return F::apply(TimeOp::Pow, a, b);
}
F min_(const F& a, const F& b) {
    return F::apply(TimeOp::Min, a, b);
}
F max_(const F& a, const F& b) {
    return F::apply(TimeOp::Max, a, b);
}
F atan2_(const F& a, const F& b) {
    return F::apply(TimeOp::Atan2, a, b);
}
F less_(const F& a, const F& b) {
    return F::apply(TimeOp::Less, a, b);
}
F greater_(const F& a, const F& b) {
    return F::apply(TimeOp::Greater, a, b);
}
F choose(const F& condition, const F& yes, const F& no) {
    return F::apply(TimeOp::Conditional, condition, yes, no);
}
// POV-Ray's min(10., max(P0 * r, -10.)) of the algebraic surfaces.
F clamp_field(const F& strength, const F& r) {
    return min_(10.0, max_(strength * r, -10.0));
}

// Each as in fnintern.cpp, operation for operation.
// POV-Ray's `if` on a parameter: decided here when the parameter is a
// constant (both sides are not evaluated, so the other may be undefined
// there: 2 / 0), else each time.
F branch(const F& condition, const F& yes, const F& no) {
    if (condition.is_constant()) return condition.constant() != 0.0 ? yes : no;
    return choose(condition, yes, no);
}
// The helices' cross section of (x, z): 1 a circle, 0 a square, else the
// superellipse of exponent 2 / p5.
F helix_section(const F& x, const F& z, const F& p5) {
    const F two = 2.0;
    const F rounded = pow_(pow_(abs_(x), two / p5) + pow_(abs_(z), two / p5), p5 * 0.5);
    const F square = max_(abs_(x), abs_(z));
    return branch(F::apply(TimeOp::NotEqual, p5, 0.0), rounded, square);
}

F f_ellipsoid(const Params& p) {  // 17
    return sqrt_(p[0] * p[0] * p[3] * p[3] + p[1] * p[1] * p[4] * p[4] + p[2] * p[2] * p[5] * p[5]);
}
F f_heart(const Params& p) {  // 23
    const F x2 = p[0] * p[0], y2 = p[1] * p[1], z2 = p[2] * p[2];
    const F a = 2.0 * x2 + y2 + z2 - 1.0;
    const F r = -(a * a * a - 0.1 * x2 * z2 * p[2] - y2 * z2 * p[2]);
    return clamp_field(p[3], r);
}
F f_helix1(const Params& p) {  // 25
    constexpr double kTwoPi = 6.283185307179586476925286766559;
    constexpr double kPi = 3.1415926535897932384626;
    const F r = sqrt_(p[0] * p[0] + p[2] * p[2]);
    // (POV-Ray moves x off 0 where x and z are both 0; atan2 is 0 there
    // either way.)
    F th = F::apply(TimeOp::Mod, atan2_(p[2], p[0]) * p[3] + p[1] * p[4] * p[3], kTwoPi);
    th = th + choose(less_(th, 0.0), kTwoPi, 0.0);
    const F z = (th - kPi) / p[7] / (p[4] * p[3]);
    const F x = r - p[6];
    const F circle = sqrt_(x * x + z * z);
    // (A turn of the section by p6 degrees; 0 turns nothing.)
    const F c = F::apply(TimeOp::Cos, p[9] * (kPi / 180.0));
    const F s = F::apply(TimeOp::Sin, p[9] * (kPi / 180.0));
    const F other = helix_section(x * c - z * s, x * s + z * c, p[8]);
    const F r2 = branch(F::apply(TimeOp::Equal, p[8], 1.0), circle, other);
    return -p[5] + min_(p[6] + r, r2);
}
F f_helix2(const Params& p) {  // 26
    const F th = p[1] * p[4];
    const F c = F::apply(TimeOp::Cos, th), s = F::apply(TimeOp::Sin, th);
    const F x2 = p[0] - p[6] * c, z2 = p[2] - p[6] * s;
    const F x = x2 * c + z2 * s, z = -x2 * s + z2 * c;
    const F circle = sqrt_(x * x + z * z);
    return branch(F::apply(TimeOp::Equal, p[8], 1.0), circle, helix_section(x, z, p[8])) - p[5];
}
F f_paraboloid(const Params& p) {  // 45
    return clamp_field(p[3], -(p[0] * p[0] - p[1] + p[2] * p[2]));
}
F f_ph(const Params& p) {  // 47
    return atan2_(sqrt_(p[0] * p[0] + p[2] * p[2]), p[1]);
}
F f_pillow(const Params& p) {  // 48
    const F x2 = p[0] * p[0], y2 = p[1] * p[1], z2 = p[2] * p[2];
    return clamp_field(p[3], x2 * x2 + y2 * y2 + z2 * z2 - (x2 + y2 + z2));
}
F f_r(const Params& p) {  // 57
    return sqrt_(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
}
F f_rounded_box(const Params& p) {  // 60
    const F& r = p[3];
    F d[3];
    for (int i = 0; i < 3; ++i) {
        const F far_side = p[4 + i] - r;
        const F beyond = choose(less_(p[i], far_side), 0.0, p[i] - far_side);
        const F near_side = r - p[4 + i];
        const F before = choose(greater_(p[i], near_side), 0.0, near_side - p[i]);
        d[i] = max_(before, beyond);
    }
    return -r + sqrt_(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - 1e-6;
}
F f_sphere(const Params& p) {  // 61
    return -p[3] + sqrt_(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
}
F f_superellipsoid(const Params& p) {  // 68
    const F e = 2.0 / p[3], n = 1.0 / p[4];
    return 1.0 - pow_(pow_(pow_(abs_(p[0]), e) + pow_(abs_(p[1]), e), p[3] * n) +
                          pow_(abs_(p[2]), 2.0 * n),
                      p[4] * 0.5);
}
F f_th(const Params& p) {  // 69
    return atan2_(p[0], p[2]);
}
F f_torus(const Params& p) {  // 70
    const F ring = sqrt_(p[0] * p[0] + p[2] * p[2]) - p[3];
    return -p[4] + sqrt_(ring * ring + p[1] * p[1]);
}
F f_torus2(const Params& p) {  // 71
    const F x2 = p[0] * p[0], y2 = p[1] * p[1], z2 = p[2] * p[2];
    const F ph = p[4] * p[4], th = p[5] * p[5];
    const F r = -(x2 * x2 + y2 * y2 + z2 * z2 + 2.0 * x2 * y2 + 2.0 * x2 * z2 + 2.0 * y2 * z2 -
                  2.0 * (ph + th) * x2 + 2.0 * (ph - th) * y2 - 2.0 * (ph + th) * z2 +
                  (ph - th) * (ph - th));
    return clamp_field(p[3], r);
}

// ---- POV-Ray's fractal noises, made per call: their octaves count a loop.

// A parameter the body's shape depends on: a number, not moving with clock.
double fixed(const F& value, const char* function, const char* what) {
    if (!value.is_constant())
        throw UnsupportedError(std::string(function) + "'s " + what +
                               " moves with clock; hexant needs it fixed");
    return value.constant();
}
// The octaves a loop runs: at most 64 (beyond, each octave's noise is
// below a double's resolution of the first for any H > 0).
double octaves_of(const F& value, const char* function) {
    const double n = fixed(value, function, "octaves");
    if (!(n >= 0.0 && n <= 64.0))
        throw ValueError(std::string(function) + "'s octaves must be 0 to 64, not " +
                         std::to_string(n));
    return n;
}
// Noise(V, ngen) of fnintern.cpp, generator G & 3.
F noise_at(const F& x, const F& y, const F& z, int generator) {
    return F::point_call(noise_function(generator & 3), 0, x, y, z);
}
int generator_of(const F& value, const char* function) {
    const double g = fixed(value, function, "noise generator");
    if (!(std::fabs(g) < 1e9))
        throw ValueError(std::string(function) + "'s noise generator is 1, 2 or 3");
    return static_cast<int>(g);
}

// f_ridged_mf(x, y, z, H, Lacunarity, Octaves, Offset, Gain, Generator):
// Musgrave's ridged multifractal as fnintern.cpp computes it. (POV-Ray
// keeps the octaves' weights, freq^-H, of the function's first evaluation
// for all its later calls, whatever their H and lacunarity: benchmark.pov
// calls it with two. Each call here has its own.)
F f_ridged_mf(const Params& p) {
    const char* name = "f_ridged_mf";
    const double octaves = octaves_of(p[5], name);
    const int generator = generator_of(p[8], name);
    const F& lacunarity = p[4];
    F x = p[0], y = p[1], z = p[2];
    const auto ridge = [&] {
        const F a = abs_(noise_at(x, y, z, generator) * 2.0 - 1.0);
        const F signal = p[6] - a;
        return signal * signal;
    };
    F signal = ridge();
    F result = signal;
    F frequency = lacunarity;  // (POV-Ray's exponent array: freq^-H)
    for (int i = 1; i < octaves; ++i) {
        x = x * lacunarity;
        y = y * lacunarity;
        z = z * lacunarity;
        const F weight = min_(max_(signal * p[7], 0.0), 1.0);
        signal = ridge() * weight;
        result = result + signal * pow_(frequency, -p[3]);
        frequency = frequency * lacunarity;
    }
    return result;
}

// f_hetero_mf(x, y, z, H, Lacunarity, Octaves, Offset, T, Generator).
F f_hetero_mf(const Params& p) {
    const char* name = "f_hetero_mf";
    const double octaves = octaves_of(p[5], name);
    const double t = fixed(p[7], name, "T");
    if (!(std::fabs(t) < 64.0)) throw ValueError("f_hetero_mf's T must be below 64");
    const int generator = generator_of(p[8], name);
    const F& lacunarity = p[4];
    F x = p[0], y = p[1], z = p[2];
    const auto step = [&] { return noise_at(x, y, z, generator) * 2.0 - 1.0 + p[6]; };
    F signal = step();
    const auto next = [&] {
        x = x * lacunarity;
        y = y * lacunarity;
        z = z * lacunarity;
    };
    next();
    const F scale = pow_(lacunarity, -p[3]);
    F ea = scale;
    for (int i = 1; i < octaves; ++i) {
        F increment = step() * ea;
        for (int k = static_cast<int>(t); k > 0; --k) increment = increment * signal;
        signal = signal + increment;
        next();
        ea = ea * scale;
    }
    const double rem = octaves - static_cast<int>(octaves);
    if (rem != 0.0) signal = signal + rem * (step() * ea) * signal;
    return signal;
}

// f_ridge(x, y, z, Lambda, Octaves, Omega, Offset, Ridge, Generator).
F f_ridge(const Params& p) {
    const char* name = "f_ridge";
    const double octaves_value = octaves_of(p[4], name);
    const int octaves = static_cast<int>(octaves_value);
    const double resid = octaves_value - octaves;
    const int generator = generator_of(p[8], name);
    const F rscale = 1.0 / max_(p[7], 1.0 - p[7]);
    const F scale = 1.0 / max_(p[6], 1.0 - p[6]);
    const auto ridged = [&](const F& by) {
        return abs_(noise_at(p[0] * by, p[1] * by, p[2] * by, generator) - p[7]) * rscale;
    };
    F value = abs_(noise_at(p[0], p[1], p[2], generator) - p[7]) * rscale - p[6];
    F total = 1.0, l = p[3], o = p[5];
    for (int i = 2; i <= octaves; ++i) {
        value = value + o * (ridged(l) - p[6]);
        total = total + o;
        l = l * p[3];
        o = o * p[5];
    }
    if (resid != 0.0) {
        value = value + o * (ridged(l) - p[6]) * resid;
        total = total + o * resid;
    }
    return value * scale / total;
}

struct Internal {
    std::string_view name;
    int extra;                              // parameters after x, y, z
    std::function<F(const Params&)> build;  // empty where hexant lacks it
    // Built for each call's arguments (UserFunction::at_call) rather than
    // once over arguments: its octaves count a loop.
    bool per_call = false;
};

// POVFPU_TrapTable, in its order: N is the index.
const std::array<Internal, 79>& internals() {
    static const std::array<Internal, 79> table = {{
        {"f_algbr_cyl1", 5, {}},
        {"f_algbr_cyl2", 5, {}},
        {"f_algbr_cyl3", 5, {}},
        {"f_algbr_cyl4", 5, {}},
        {"f_bicorn", 2, {}},
        {"f_bifolia", 2, {}},
        {"f_blob", 5, {}},
        {"f_blob2", 4, {}},
        {"f_boy_surface", 2, {}},
        {"f_comma", 1, {}},
        {"f_cross_ellipsoids", 4, {}},
        {"f_crossed_trough", 1, {}},
        {"f_cubic_saddle", 1, {}},
        {"f_cushion", 1, {}},
        {"f_devils_curve", 1, {}},
        {"f_devils_curve_2d", 6, {}},
        {"f_dupin_cyclid", 6, {}},
        {"f_ellipsoid", 3, f_ellipsoid},
        {"f_enneper", 1, {}},
        {"f_flange_cover", 4, {}},
        {"f_folium_surface", 3, {}},
        {"f_folium_surface_2d", 6, {}},
        {"f_glob", 1, {}},
        {"f_heart", 1, f_heart},
        {"f_helical_torus", 10, {}},
        {"f_helix1", 7, f_helix1},
        {"f_helix2", 7, f_helix2},
        {"f_hex_x", 1, {}},
        {"f_hex_y", 1, {}},
        {"f_hetero_mf", 6, f_hetero_mf, true},
        {"f_hunt_surface", 1, {}},
        {"f_hyperbolic_torus", 3, {}},
        {"f_isect_ellipsoids", 4, {}},
        {"f_kampyle_of_eudoxus", 3, {}},
        {"f_kampyle_of_eudoxus_2d", 6, {}},
        {"f_klein_bottle", 1, {}},
        {"f_kummer_surface_v1", 1, {}},
        {"f_kummer_surface_v2", 4, {}},
        {"f_lemniscate_of_gerono", 1, {}},
        {"f_lemniscate_of_gerono_2d", 6, {}},
        {"f_mesh1", 5, {}},
        {"f_mitre", 1, {}},
        {"f_nodal_cubic", 1, {}},
        {"f_odd", 1, {}},
        {"f_ovals_of_cassini", 4, {}},
        {"f_paraboloid", 1, f_paraboloid},
        {"f_parabolic_torus", 3, {}},
        {"f_ph", 0, f_ph},
        {"f_pillow", 1, f_pillow},
        {"f_piriform", 1, {}},
        {"f_piriform_2d", 7, {}},
        {"f_poly4", 5, {}},
        {"f_polytubes", 6, {}},
        {"f_quantum", 1, {}},
        {"f_quartic_paraboloid", 1, {}},
        {"f_quartic_saddle", 1, {}},
        {"f_quartic_cylinder", 3, {}},
        {"f_r", 0, f_r},
        {"f_ridge", 6, f_ridge, true},
        {"f_ridged_mf", 6, f_ridged_mf, true},
        {"f_rounded_box", 4, f_rounded_box},
        {"f_sphere", 1, f_sphere},
        {"f_spikes", 5, {}},
        {"f_spikes_2d", 4, {}},
        {"f_spiral", 6, {}},
        {"f_steiners_roman", 1, {}},
        {"f_strophoid", 4, {}},
        {"f_strophoid_2d", 7, {}},
        {"f_superellipsoid", 2, f_superellipsoid},
        {"f_th", 0, f_th},
        {"f_torus", 2, f_torus},
        {"f_torus2", 3, f_torus2},
        {"f_torus_gumdrop", 1, {}},
        {"f_umbrella", 1, {}},
        {"f_witch_of_agnesi", 2, {}},
        {"f_witch_of_agnesi_2d", 6, {}},
        {"f_noise3d", 0, {}},
        {"f_pattern", 0, {}},
        {"f_noise_generator", 1, {}},
    }};
    return table;
}

}  // namespace

std::shared_ptr<const runtime::PointFunction> noise_function(int generator) {
    // (One per generator, so that tapes calling it share it.)
    static const std::array<std::shared_ptr<const runtime::PointFunction>, 4> all = {
        std::make_shared<const runtime::pattern::NoiseFunction>(0),
        std::make_shared<const runtime::pattern::NoiseFunction>(1),
        std::make_shared<const runtime::pattern::NoiseFunction>(2),
        std::make_shared<const runtime::pattern::NoiseFunction>(3)};
    return all[static_cast<std::size_t>(generator & 3)];
}

std::shared_ptr<const runtime::UserFunction> internal_function(int n) {
    const auto& table = internals();
    if (n < 0 || n >= static_cast<int>(table.size()))
        throw ValueError("internal(" + std::to_string(n) +
                         ") is no internal function of POV-Ray 3.7 (0 to " +
                         std::to_string(table.size() - 1) + ")");
    const Internal& entry = table[static_cast<std::size_t>(n)];
    auto f = std::make_shared<runtime::UserFunction>();
    f->parameters = {"x", "y", "z"};
    for (int i = 0; i < entry.extra; ++i) f->parameters.push_back("P" + std::to_string(i));
    if (entry.name == std::string_view("f_noise3d") ||
        entry.name == std::string_view("f_noise_generator")) {
        f->noise = entry.extra == 0 ? runtime::UserFunction::Noise::SceneGenerator
                                    : runtime::UserFunction::Noise::ArgumentGenerator;
        f->body = TimeFunction::point_call(noise_function(runtime::pattern::kDefaultNoiseGenerator),
                                           0, TimeFunction::argument(0), TimeFunction::argument(1),
                                           TimeFunction::argument(2));
        return f;
    }
    if (entry.per_call) {
        f->at_call = entry.build;
        f->unimplemented = std::string(entry.name) + " (internal(" + std::to_string(n) +
                           ")) without its arguments (hexant makes it where it is called)";
        return f;
    }
    if (!entry.build) {
        f->unimplemented = std::string(entry.name) + " (internal(" + std::to_string(n) + "))";
        return f;
    }
    Params p;
    for (std::size_t i = 0; i < f->parameters.size(); ++i)
        p.push_back(TimeFunction::argument(static_cast<int>(i)));
    f->body = entry.build(p);
    return f;
}

}  // namespace hexant::language
