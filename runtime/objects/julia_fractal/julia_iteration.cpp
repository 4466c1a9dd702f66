#include "runtime/objects/julia_fractal/julia_iteration.hpp"

#include <cmath>
#include <type_traits>

#include "runtime/time/interval.hpp"

namespace hexant::runtime::geometry {

namespace {

// hcmplx.cpp's Fractal_Tolerance (fractal.cpp has its own, 1e-7).
constexpr double kHypercomplexTolerance = 1e-8;

template <class T>
T square(const T& a) {
    if constexpr (std::is_same_v<T, double>)
        return a * a;
    else
        return sqr(a);
}

template <class T>
struct Q {
    T x, y, z, w;
};

// q0 of p: w from the slice (the Iteration methods' first lines).
template <class T>
Q<T> start(const JuliaFractalGeometry& g, const T& x, const T& y, const T& z) {
    const T w = (T(g.slice_distance) - T(g.slice[0]) * x - T(g.slice[1]) * y - T(g.slice[2]) * z) /
                T(g.slice[3]);
    return {x, y, z, w};
}

// The value each Iteration method compares with Exit_Value before a step.
template <class T>
T norm_of(const JuliaFractalGeometry& g, const Q<T>& q) {
    if (g.algebra == JuliaAlgebra::quaternion) {
        const T d = square(q.y) + square(q.z) + square(q.w);
        return d + square(q.x);  // Iteration_Julia, Iteration_z3
    }
    if (g.function == JuliaFunction::sqr) {
        const T yz = square(q.y) + square(q.z);
        const T xw = square(q.x) + square(q.w);
        return xw + yz;  // Iteration_HCompl
    }
    return square(q.x) + square(q.y) + square(q.z) + square(q.w);
}

// POV-Ray's HSqr.
template <class T>
Q<T> hsqr(const Q<T>& a) {
    return {square(a.x) - square(a.y) - square(a.z) + square(a.w), 2.0 * (a.x * a.y - a.z * a.w),
            2.0 * (a.z * a.x - a.w * a.y), 2.0 * (a.w * a.x + a.z * a.y)};
}

// POV-Ray's HMult(r, a, b).
Q<double> hmult(const Q<double>& a, const Q<double>& b) {
    return {a.x * b.x - a.y * b.y - a.z * b.z + a.w * b.w,
            a.y * b.x + a.x * b.y - a.w * b.z - a.z * b.w,
            a.z * b.x - a.w * b.y + a.x * b.z - a.y * b.w,
            a.w * b.x + a.z * b.y + a.y * b.z + a.x * b.w};
}

// POV-Ray's HReciprocal; false where it divides by zero (POV-Ray then
// leaves its result unset: 0 here).
template <class T>
bool hreciprocal(const Q<T>& a, Q<T>& r) {
    const T det = (square(a.x - a.w) + square(a.y + a.z)) * (square(a.x + a.w) + square(a.y - a.z));
    if constexpr (std::is_same_v<T, double>) {
        if (det == 0.0) {
            r = {0.0, 0.0, 0.0, 0.0};
            return false;
        }
    } else {
        if (det.contains_zero() || !(det.lo == det.lo)) return false;
    }
    const T mod = square(a.x) + square(a.y) + square(a.z) + square(a.w);
    const T xt_minus_yz = a.x * a.w - a.y * a.z;
    r = {(a.x * mod - 2.0 * a.w * xt_minus_yz) / det, (-a.y * mod - 2.0 * a.z * xt_minus_yz) / det,
         (-a.z * mod - 2.0 * a.y * xt_minus_yz) / det, (a.w * mod - 2.0 * a.x * xt_minus_yz) / det};
    return true;
}

// One step q -> f(q) + c of the algebraic maps, in POV-Ray's operations.
// False where the interval version cannot follow (a reciprocal near 0).
template <class T>
bool advance(const JuliaFractalGeometry& g, Q<T>& q) {
    const auto& c = g.c;
    if (g.algebra == JuliaAlgebra::quaternion) {
        const T d = square(q.y) + square(q.z) + square(q.w);
        const T x2 = square(q.x);
        if (g.function == JuliaFunction::cube) {  // Iteration_z3
            const T tmp = 3.0 * x2 - d;
            q = {q.x * (x2 - 3.0 * d) + c[0], q.y * tmp + c[1], q.z * tmp + c[2], q.w * tmp + c[3]};
        } else {  // Iteration_Julia
            const T x = 2.0 * q.x;
            q = {x2 - d + c[0], x * q.y + c[1], x * q.z + c[2], x * q.w + c[3]};
        }
        return true;
    }
    Q<T> r;
    switch (g.function) {
        case JuliaFunction::sqr: {  // Iteration_HCompl
            const T yz = square(q.y) + square(q.z);
            const T xw = square(q.x) + square(q.w);
            q = {xw - yz + c[0], 2.0 * (q.x * q.y - q.z * q.w) + c[1],
                 2.0 * (q.x * q.z - q.w * q.y) + c[2], 2.0 * (q.x * q.w + q.y * q.z) + c[3]};
            return true;
        }
        case JuliaFunction::cube:  // Iteration_HCompl_z3: the square again
            r = hsqr(q);
            break;
        case JuliaFunction::reciprocal:
            if (!hreciprocal(q, r) && !std::is_same_v<T, double>) return false;
            break;
        default:
            if constexpr (std::is_same_v<T, double>)
                hypercomplex_function(g.function, g.exponent, q.x, q.y, q.z, q.w, r.x, r.y, r.z,
                                      r.w);
            else
                return false;
    }
    q = {r.x + c[0], r.y + c[1], r.z + c[2], r.w + c[3]};
    return true;
}

void store(JuliaStack& s, int i, const Q<double>& q) {
    s.q[0][i] = q.x;
    s.q[1][i] = q.y;
    s.q[2][i] = q.z;
    s.q[3][i] = q.w;
}
Q<double> load(const JuliaStack& s, int i) {
    return {s.q[0][i], s.q[1][i], s.q[2][i], s.q[3][i]};
}

// q0 of p, stored: Iteration_HCompl_Func alone reads z from p's y.
Q<double> first(const JuliaFractalGeometry& g, const glm::dvec3& p, bool iteration, JuliaStack& s) {
    const bool quirk =
        iteration && g.algebra == JuliaAlgebra::hypercomplex && g.function < JuliaFunction::sqr;
    const Q<double> q = start<double>(g, p.x, p.y, quirk ? p.y : p.z);
    store(s, 0, q);
    return q;
}

// The quaternion distance estimate at an escape at step i
// (D_Iteration_Julia, D_Iteration_z3).
double quaternion_distance(const JuliaFractalGeometry& g, int i, double norm, const JuliaStack& s) {
    const bool cube = g.function == JuliaFunction::cube;
    Q<double> q = load(s, 0);
    double pow = cube ? 1.0 / 3.0 : 1.0 / 2.0;
    for (int j = 1; j < i; ++j) {
        const Q<double> k = load(s, j);
        double yy, zz, w;
        const double xx = q.x * k.x - q.y * k.y - q.z * k.z - q.w * k.w;
        if (cube) {
            yy = q.x * k.y + q.y * k.x - q.z * k.w + q.w * k.z;
            zz = q.x * k.z + q.y * k.w + q.z * k.x - q.w * k.y;
            w = q.x * k.w - q.y * k.z + q.z * k.y + q.w * k.x;
            pow /= 3.0;
        } else {
            yy = q.x * k.y + q.y * k.x + q.w * k.z - q.z * k.w;
            zz = q.x * k.z + q.z * k.x + q.y * k.w - q.w * k.y;
            w = q.x * k.w + q.w * k.x + q.z * k.y - q.y * k.z;
            pow /= 2.0;
        }
        q = {xx, yy, zz, w};
    }
    return pow * std::sqrt(norm / (q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w)) * std::log(norm);
}

// Normal_Calc_Julia and Normal_Calc_z3: the Jacobian's rows times q_N.
glm::dvec3 quaternion_normal(const JuliaFractalGeometry& g, int n_max, const JuliaStack& s) {
    double n[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    Q<double> q = load(s, 0);
    for (int i = 1; i <= n_max; ++i) {
        if (g.function == JuliaFunction::cube) {
            const double tmp = q.y * q.y + q.z * q.z + q.w * q.w;
            const double x2 = q.x * q.x;
            const double x3 = x2 - tmp, x4 = 3.0 * x2 - tmp;
            for (auto& r : n) {  // Deriv_z3
                const double dtmp = 2.0 * (r[1] * q.y + r[2] * q.z + r[3] * q.w);
                const double dtmp2 = 6.0 * q.x * r[0] - dtmp;
                r[0] = (r[0] * x3 - q.x * dtmp) * 3.0;
                r[1] = r[1] * x4 + q.y * dtmp2;
                r[2] = r[2] * x4 + q.z * dtmp2;
                r[3] = r[3] * x4 + q.w * dtmp2;
            }
        } else {
            for (auto& r : n) {  // Deriv_z2
                const double tmp = r[0] * q.x - r[1] * q.y - r[2] * q.z - r[3] * q.w;
                r[1] = r[0] * q.y + q.x * r[1];
                r[2] = r[0] * q.z + q.x * r[2];
                r[3] = r[0] * q.w + q.x * r[3];
                r[0] = tmp;
            }
        }
        q = load(s, i);
    }
    glm::dvec3 out;
    for (int k = 0; k < 3; ++k)
        out[k] = n[k][0] * q.x + n[k][1] * q.y + n[k][2] * q.z + n[k][3] * q.w;
    return out;
}

// Normal_Calc_HCompl, _z3, _Reciprocal and _Func.
glm::dvec3 hypercomplex_normal(const JuliaFractalGeometry& g, int n_max, const JuliaStack& s) {
    Q<double> q = load(s, 0);
    double pow = 2.0;
    for (int i = 1; i < n_max; ++i) {
        const Q<double> k = load(s, i);
        switch (g.function) {
            case JuliaFunction::sqr:
                q = hmult(k, q);
                pow *= 2.0;
                break;
            case JuliaFunction::cube:
                q = hmult(k, q);
                break;
            case JuliaFunction::reciprocal: {
                Q<double> r;
                hreciprocal(k, r);
                const Q<double> r2 = hsqr(r);
                q = hmult(q, {-r2.x, -r2.y, -r2.z, -r2.w});
                break;
            }
            default: {
                Q<double> r;
                hypercomplex_function(g.function, g.exponent, k.x, k.y, k.z, k.w, r.x, r.y, r.z,
                                      r.w);
                q = hmult(r, q);
            }
        }
    }
    Q<double> n = load(s, n_max);
    if (g.function == JuliaFunction::sqr) n = {n.x * pow, n.y * pow, n.z * pow, n.w * pow};
    return {q.x * n.x + q.y * n.y + q.z * n.z + q.w * n.w,
            -q.y * n.x + q.x * n.y - q.w * n.z + q.z * n.w,
            -q.z * n.x - q.w * n.y + q.x * n.z + q.y * n.w};
}

}  // namespace

void JuliaStack::ensure(int iterations) {
    const std::size_t n = static_cast<std::size_t>(iterations) + 1;
    for (auto& row : q)
        if (row.size() < n) row.resize(n, 0.0);
}

JuliaStack& thread_julia_stack() {
    thread_local JuliaStack stack;
    return stack;
}

bool julia_iterate(const JuliaFractalGeometry& g, const glm::dvec3& p, JuliaStack& s) {
    Q<double> q = first(g, p, true, s);
    for (int i = 1; i <= g.iterations; ++i) {
        if (norm_of(g, q) > g.exit_value) return false;
        advance(g, q);
        store(s, i, q);
    }
    return true;
}

bool julia_distance_iterate(const JuliaFractalGeometry& g, const glm::dvec3& p,
                            const glm::dvec3& direction, double& dist, JuliaStack& s) {
    Q<double> q = first(g, p, false, s);
    for (int i = 1; i <= g.iterations; ++i) {
        const double norm = norm_of(g, q);
        if (norm > g.exit_value) {
            if (g.algebra == JuliaAlgebra::quaternion) {
                dist = quaternion_distance(g, i, norm, s);
                return false;
            }
            // The step from the normal's slope (D_Iteration_HCompl and kin).
            const glm::dvec3 normal = hypercomplex_normal(g, i - 1, s);
            double step = normal.x * direction.x + normal.y * direction.y + normal.z * direction.z;
            if (step < -kHypercomplexTolerance) {
                step = -2.0 * step;
                if (norm > g.precision * step && norm < 30 * g.precision * step) {
                    dist = norm / step;
                    return false;
                }
            }
            dist = g.precision;
            return false;
        }
        advance(g, q);
        store(s, i, q);
    }
    dist = g.precision;
    return true;
}

glm::dvec3 julia_normal(const JuliaFractalGeometry& g, int n_max, const JuliaStack& s) {
    return g.algebra == JuliaAlgebra::quaternion ? quaternion_normal(g, n_max, s)
                                                 : hypercomplex_normal(g, n_max, s);
}

bool julia_uniform_over(const JuliaFractalGeometry& g, const glm::dvec3& lo, const glm::dvec3& hi) {
    if (g.algebra == JuliaAlgebra::hypercomplex && g.function < JuliaFunction::sqr) return false;
    Q<Interval> q =
        start<Interval>(g, Interval(lo.x, hi.x), Interval(lo.y, hi.y), Interval(lo.z, hi.z));
    for (int i = 1; i <= g.iterations; ++i) {
        const Interval norm = norm_of(g, q);
        if (norm.lo > g.exit_value) return true;       // all escape here (or before)
        if (!(norm.hi <= g.exit_value)) return false;  // some may escape, some not
        if (!advance(g, q)) return false;
    }
    return true;  // none escapes
}

}  // namespace hexant::runtime::geometry
