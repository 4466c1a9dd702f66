#include "runtime/objects/sphere_sweep/sphere_sweep_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/polynomial_roots.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"

namespace hexant::runtime::geometry {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Slack of the pruning boxes in the scaled frame (the sweep's size is ~1):
// pruning only, never a hit's position.
constexpr double kBoxSlack = 1e-9;
// Pieces surface_may_meet may visit before it answers "may".
constexpr int kPieceBudget = 1 << 14;
constexpr int kMaxDepth = 32;

double eval3(const double p[4], double u) {
    return ((p[3] * u + p[2]) * u + p[1]) * u + p[0];
}

// The range of a cubic over [0, 1]: its ends and critical points, widened by
// the rounding of evaluating it.
void cubic_range(const double p[4], double& lo, double& hi) {
    lo = std::min(eval3(p, 0.0), eval3(p, 1.0));
    hi = std::max(eval3(p, 0.0), eval3(p, 1.0));
    const std::array<double, 3> slope{p[1], 2.0 * p[2], 3.0 * p[3]};
    for (const double u : polynomial_roots(slope, 0.0, 1.0)) {
        lo = std::min(lo, eval3(p, u));
        hi = std::max(hi, eval3(p, u));
    }
    const double margin =
        16.0 * kEpsilon * (std::fabs(p[0]) + std::fabs(p[1]) + std::fabs(p[2]) + std::fabs(p[3]));
    lo -= margin;
    hi += margin;
}

// The box of a segment's balls from its coefficients.
Box3 segment_box(const glm::dvec4 coef[4]) {
    Box3 box;
    for (int k = 0; k < 3; ++k) {
        const double p[4] = {coef[0][k], coef[1][k], coef[2][k], coef[3][k]};
        cubic_range(p, box.lo[k], box.hi[k]);
    }
    const double r[4] = {coef[0].w, coef[1].w, coef[2].w, coef[3].w};
    double r_lo, r_hi;
    cubic_range(r, r_lo, r_hi);
    const double reach = std::max(std::fabs(r_lo), std::fabs(r_hi));
    box.lo -= reach;
    box.hi += reach;
    return box;
}

bool valid(const SphereSweepGeometry& g) {
    return !g.segments.empty() && g.size > 0.0 && std::isfinite(g.size);
}

// Product of two polynomials (ascending coefficients).
template <std::size_t A, std::size_t B>
std::array<double, A + B - 1> times(const std::array<double, A>& a,
                                    const std::array<double, B>& b) {
    std::array<double, A + B - 1> out{};
    for (std::size_t i = 0; i < A; ++i)
        for (std::size_t j = 0; j < B; ++j) out[i + j] = std::fma(a[i], b[j], out[i + j]);
    return out;
}

template <std::size_t N>
std::array<double, N - 1> derivative(const std::array<double, N>& p) {
    std::array<double, N - 1> out{};
    for (std::size_t i = 1; i < N; ++i) out[i - 1] = static_cast<double>(i) * p[i];
    return out;
}

// The sphere at u seen from the ray: m = d.(c - o), D = r^2 - |perp|^2 (the
// squared half chord), both from the sphere's own centre and radius.
struct Chord {
    double m, D;
};

Chord chord(const SweepSegment& s, const glm::dvec3& o, const glm::dvec3& d, double u) {
    const glm::dvec4 sphere = s.at(u);
    const glm::dvec3 w = glm::dvec3(sphere) - o;
    const double m = glm::dot(d, w);
    const glm::dvec3 across = w - m * d;
    const double q = safe_length(across), r = std::fabs(sphere.w);
    return {m, (r - q) * (r + q)};
}

// One connected stretch of the ray within a segment's balls, and the
// spheres (u) that give its two ends.
struct Stretch {
    double lo, hi;
    int segment_lo, segment_hi;
    double u_lo, u_hi;
};

void segment_stretches(const SweepSegment& s, int index, const glm::dvec3& o, const glm::dvec3& d,
                       std::vector<Stretch>& out) {
    // w(u) = c(u) - o, m(u) = d.w(u), perp(u) = w(u) - m(u) d, all cubics.
    std::array<double, 4> m{}, rho{};
    std::array<std::array<double, 4>, 3> perp{};
    for (int j = 0; j < 4; ++j) {
        glm::dvec3 w(s.coef[j]);
        if (j == 0) w -= o;
        m[j] = glm::dot(d, w);
        const glm::dvec3 across = w - m[j] * d;
        for (int k = 0; k < 3; ++k) perp[k][j] = across[k];
        rho[j] = s.coef[j].w;
    }
    std::array<double, 7> D = times(rho, rho);
    for (int k = 0; k < 3; ++k) {
        const auto sq = times(perp[k], perp[k]);
        for (std::size_t i = 0; i < D.size(); ++i) D[i] -= sq[i];
    }
    // Critical points of m -+ sqrt(D): 2 m' sqrt(D) = +-D', squared.
    const auto m1 = derivative(m);
    const auto D1 = derivative(D);
    const auto lead = times(times(m1, m1), D);
    const auto tail = times(D1, D1);
    std::array<double, 11> P{};
    for (std::size_t i = 0; i < P.size(); ++i)
        P[i] = 4.0 * lead[i] - (i < tail.size() ? tail[i] : 0.0);

    const PolynomialRoots d_roots = polynomial_roots(D, 0.0, 1.0);
    const PolynomialRoots critical = polynomial_roots(P, 0.0, 1.0);

    std::array<double, kMaxPolynomialDegree + 2> breaks{};
    int count = 0;
    breaks[count++] = 0.0;
    for (const double u : d_roots)
        if (u > 0.0 && u < 1.0) breaks[count++] = u;
    breaks[count++] = 1.0;

    for (int b = 0; b + 1 < count; ++b) {
        const double a = breaks[b], z = breaks[b + 1];
        if (!(z > a)) continue;
        const double mid = 0.5 * (a + z);
        const Chord at_mid = chord(s, o, d, mid);
        if (!(at_mid.D >= 0.0)) continue;
        Stretch st{kInf, -kInf, index, index, mid, mid};
        auto consider = [&](double u, bool end) {
            Chord c = chord(s, o, d, u);
            if (!(c.D >= 0.0)) {
                if (!end) return;
                c.D = 0.0;  // a root of D: the ray touches this sphere
            }
            const double half = std::sqrt(c.D);
            const double lo = c.m - half, hi = c.m + half;
            if (lo < st.lo) {
                st.lo = lo;
                st.u_lo = u;
            }
            if (hi > st.hi) {
                st.hi = hi;
                st.u_hi = u;
            }
        };
        consider(a, true);
        consider(z, true);
        consider(mid, false);
        for (const double u : critical)
            if (u >= a && u <= z) consider(u, false);
        if (std::isfinite(st.lo) && std::isfinite(st.hi) && st.lo <= st.hi) out.push_back(st);
    }
}

// Where the ray (o + k d) lies within a box widened by slack: [ka, kb], or
// false when it misses.
bool slab(const Box3& box, const glm::dvec3& o, const glm::dvec3& d, double slack, double& ka,
          double& kb) {
    ka = -kInf;
    kb = kInf;
    for (int i = 0; i < 3; ++i) {
        const double lo = box.lo[i] - slack, hi = box.hi[i] + slack;
        if (d[i] == 0.0) {
            if (o[i] < lo || o[i] > hi) return false;
            continue;
        }
        double t1 = (lo - o[i]) / d[i], t2 = (hi - o[i]) / d[i];
        if (t1 > t2) std::swap(t1, t2);
        ka = std::max(ka, t1);
        kb = std::min(kb, t2);
    }
    return ka <= kb;
}

glm::dvec3 to_frame(const SphereSweepGeometry& g, const glm::dvec3& p) {
    return (p - g.origin) * g.inverse_scale;
}

}  // namespace

int sphere_sweep_segment_count(SweepSpline spline, std::size_t spheres) {
    const long long n = static_cast<long long>(spheres);
    const long long segments = spline == SweepSpline::linear ? n - 1 : n - 3;
    return static_cast<int>(std::max(segments, 0LL));
}

SphereSweepGeometry make_sphere_sweep(SweepSpline spline, const std::vector<glm::dvec3>& centres,
                                      const std::vector<double>& radii) {
    SphereSweepGeometry g;
    g.spline = spline;
    const std::size_t n = std::min(centres.size(), radii.size());
    for (std::size_t i = 0; i < n; ++i)
        if (!is_finite(centres[i]) || !std::isfinite(radii[i])) return g;
    const int count = sphere_sweep_segment_count(spline, n);
    if (count <= 0) return g;

    // The segments in object space, and their boxes.
    std::vector<SweepSegment> raw(static_cast<std::size_t>(count));
    Box3 bounds = Box3::nowhere();
    for (int i = 0; i < count; ++i) {
        double c[4][4];
        sphere_sweep_polynomial<double>(
            spline, i,
            [&](int j, int k) {
                const std::size_t at = static_cast<std::size_t>(j);
                return k < 3 ? centres[at][k] : radii[at];
            },
            c);
        SweepSegment& s = raw[static_cast<std::size_t>(i)];
        for (int p = 0; p < 4; ++p) s.coef[p] = glm::dvec4(c[p][0], c[p][1], c[p][2], c[p][3]);
        s.box = segment_box(s.coef);
        bounds = hull(bounds, s.box);
    }
    if (!is_finite(bounds.lo) || !is_finite(bounds.hi)) return g;
    const double size = half_diagonal(bounds);
    if (!(size > 0.0) || !std::isfinite(size)) return g;
    int exponent = 0;
    (void)std::frexp(size, &exponent);  // size < 2^exponent
    if (exponent > 1000 || exponent < -1000) return g;
    g.scale = std::ldexp(1.0, exponent);
    g.inverse_scale = std::ldexp(1.0, -exponent);
    g.origin = centre(bounds);
    g.bounds = bounds;
    g.size = size;

    // The same segments in the scaled frame.
    g.segments.reserve(raw.size());
    for (const SweepSegment& s : raw) {
        SweepSegment t;
        for (int p = 0; p < 4; ++p) {
            glm::dvec4 v = s.coef[p];
            if (p == 0) v -= glm::dvec4(g.origin, 0.0);
            t.coef[p] = v * g.inverse_scale;
        }
        const Box3 own = segment_box(t.coef);
        const Box3 mapped{to_frame(g, s.box.lo), to_frame(g, s.box.hi)};
        t.box = widened(hull(own, mapped), 1e-12);
        g.segments.push_back(t);
    }
    return g;
}

std::optional<SurfaceHit> intersect(const SphereSweepGeometry& g, const Ray3& ray, double s_min,
                                    double s_max) {
    if (!valid(g)) return std::nullopt;
    const auto local = local_ray(ray, centre(g.bounds), g.size);
    if (!local) return std::nullopt;
    if (!(s_min < s_max)) return std::nullopt;
    const glm::dvec3 o = to_frame(g, local->origin);
    const glm::dvec3& d = local->unit;
    if (!is_finite(o)) return std::nullopt;
    // The asked range in the frame, a little wider (the final test is exact).
    const double k_lo = local->to_t(s_min) * g.inverse_scale - kBoxSlack;
    const double k_hi = local->to_t(s_max) * g.inverse_scale + kBoxSlack;
    if (std::isnan(k_lo) || std::isnan(k_hi)) return std::nullopt;

    std::vector<Stretch> stretches;
    for (std::size_t j = 0; j < g.segments.size(); ++j) {
        const SweepSegment& s = g.segments[j];
        double ka, kb;
        if (!slab(s.box, o, d, kBoxSlack, ka, kb)) continue;
        if (kb < k_lo || ka > k_hi) continue;
        segment_stretches(s, static_cast<int>(j), o, d, stretches);
    }
    if (stretches.empty()) return std::nullopt;
    std::sort(stretches.begin(), stretches.end(),
              [](const Stretch& a, const Stretch& b) { return a.lo < b.lo; });

    // The union of the stretches, and its ends in order along the ray.
    struct End {
        double k;
        int segment;
        double u;
        bool entry;
    };
    std::vector<End> ends;
    Stretch cur = stretches.front();
    auto flush = [&](const Stretch& st) {
        ends.push_back({st.lo, st.segment_lo, st.u_lo, true});
        ends.push_back({st.hi, st.segment_hi, st.u_hi, false});
    };
    for (std::size_t i = 1; i < stretches.size(); ++i) {
        const Stretch& st = stretches[i];
        if (st.lo <= cur.hi) {
            if (st.hi > cur.hi) {
                cur.hi = st.hi;
                cur.segment_hi = st.segment_hi;
                cur.u_hi = st.u_hi;
            }
            continue;
        }
        flush(cur);
        cur = st;
    }
    flush(cur);

    for (const End& e : ends) {
        const double k = e.k * g.scale;
        const double s_hit = local->to_s(k);
        if (!(s_hit > s_min)) continue;
        if (!(s_hit < s_max)) return std::nullopt;
        const SweepSegment& seg = g.segments[static_cast<std::size_t>(e.segment)];
        SurfaceHit hit;
        hit.s = s_hit;
        hit.part = e.segment;
        hit.point = local->at(k);
        hit.error = rounding_gamma(64) * (glm::abs(hit.point) + g.size);
        const glm::dvec4 sphere = seg.at(e.u);
        const glm::dvec3 p = o + e.k * d;
        glm::dvec3 n = p - glm::dvec3(sphere);
        const double length = safe_length(n);
        if (length > 0.0 && std::isfinite(length)) {
            n /= length;
        } else {
            n = e.entry ? -d : d;
        }
        const double check = safe_length(n);
        if (!(check > 0.0)) n = e.entry ? -d : d;
        hit.normal = n / safe_length(n);
        hit.shading_normal = hit.normal;
        hit.uv = {std::min((e.u + e.segment) / static_cast<double>(g.segments.size()), 1.0), 0.0};
        if (!is_finite(hit)) return std::nullopt;
        return hit;
    }
    return std::nullopt;
}

bool inside(const SphereSweepGeometry& g, glm::dvec3 point) {
    if (!valid(g)) return false;
    if (!is_finite(point)) return false;
    const glm::dvec3 p = to_frame(g, point);
    for (const SweepSegment& s : g.segments) {
        if (!contains(s.box, p)) continue;
        // h(u) = |c(u) - p|^2 - r(u)^2; its least value over [0, 1].
        std::array<double, 4> rho{};
        std::array<std::array<double, 4>, 3> w{};
        for (int j = 0; j < 4; ++j) {
            glm::dvec3 v(s.coef[j]);
            if (j == 0) v -= p;
            for (int k = 0; k < 3; ++k) w[k][j] = v[k];
            rho[j] = s.coef[j].w;
        }
        std::array<double, 7> h{};
        for (int k = 0; k < 3; ++k) {
            const auto sq = times(w[k], w[k]);
            for (std::size_t i = 0; i < h.size(); ++i) h[i] += sq[i];
        }
        const auto rr = times(rho, rho);
        for (std::size_t i = 0; i < h.size(); ++i) h[i] -= rr[i];
        auto within = [&](double u) {
            const glm::dvec4 sphere = s.at(u);
            return safe_length(p - glm::dvec3(sphere)) <= std::fabs(sphere.w);
        };
        if (within(0.0) || within(1.0)) return true;
        for (const double u : polynomial_roots(derivative(h), 0.0, 1.0))
            if (within(u)) return true;
    }
    return false;
}

Box3 object_bounds(const SphereSweepGeometry& g) {
    if (g.segments.empty()) return {glm::dvec3(0.0), glm::dvec3(0.0)};
    return g.bounds;
}

bool surface_may_meet(const SphereSweepGeometry& g, const Box3& box) {
    if (!valid(g)) return false;
    const Box3 wide_object = widened(box, meet_slack(box, g.size) + 1e-12 * g.size);
    if (!overlaps(wide_object, g.bounds)) return false;
    Box3 wide{to_frame(g, wide_object.lo), to_frame(g, wide_object.hi)};
    if (!is_finite(wide.lo) || !is_finite(wide.hi)) return true;
    // Rounding of the frame change: ulps of the coordinates.
    wide = widened(wide, 8.0 * kEpsilon * (max_abs(wide.lo) + max_abs(wide.hi) + 1.0));

    // The farthest and nearest distances between two boxes.
    auto nearest = [](const Box3& a, const Box3& b) {
        glm::dvec3 gap;
        for (int k = 0; k < 3; ++k) gap[k] = std::max({0.0, a.lo[k] - b.hi[k], b.lo[k] - a.hi[k]});
        return safe_length(gap);
    };
    auto farthest = [](const Box3& a, const Box3& b) {
        glm::dvec3 span;
        for (int k = 0; k < 3; ++k)
            span[k] = std::max(std::fabs(a.hi[k] - b.lo[k]), std::fabs(b.hi[k] - a.lo[k]));
        return safe_length(span);
    };

    struct Piece {
        double u0, u1;
        int depth;
    };
    // A box within one ball lies inside, off the surface: a few balls first.
    for (const SweepSegment& s : g.segments) {
        if (!overlaps(s.box, wide)) continue;
        for (const double u : {0.0, 0.5, 1.0}) {
            const glm::dvec4 at = s.at(u);
            const Box3 point{glm::dvec3(at), glm::dvec3(at)};
            const double slack =
                16.0 * kEpsilon * (max_abs(glm::dvec3(at)) + std::fabs(at.w) + 1.0);
            if (farthest(point, wide) + slack < std::fabs(at.w)) return false;
        }
    }
    int budget = kPieceBudget;
    bool undecided = false;
    for (const SweepSegment& s : g.segments) {
        if (!overlaps(s.box, wide)) continue;
        const glm::dvec4 size =
            glm::abs(s.coef[0]) + glm::abs(s.coef[1]) + glm::abs(s.coef[2]) + glm::abs(s.coef[3]);
        Piece stack[kMaxDepth + 2];
        int top = 0;
        stack[top++] = {0.0, 1.0, 0};
        while (top > 0) {
            const Piece piece = stack[--top];
            if (--budget < 0) return true;
            // Enclosures over [u0, u1] by the mean value form around the middle.
            const double mid = 0.5 * (piece.u0 + piece.u1), half = 0.5 * (piece.u1 - piece.u0);
            const glm::dvec4 at = s.at(mid);
            const double umax = piece.u1;
            const glm::dvec4 slope_bound = 3.0 * glm::abs(s.coef[3]) * umax * umax +
                                           2.0 * glm::abs(s.coef[2]) * umax + glm::abs(s.coef[1]);
            const glm::dvec4 margin = slope_bound * half + 16.0 * kEpsilon * size;
            const Box3 centres{glm::dvec3(at) - glm::dvec3(margin),
                               glm::dvec3(at) + glm::dvec3(margin)};
            const double r_hi = std::fabs(at.w) + margin.w;
            const double r_lo = std::fabs(at.w) - margin.w;
            if (nearest(centres, wide) > r_hi * (1.0 + 4.0 * kEpsilon)) continue;  // out of reach
            if (r_lo > 0.0 && farthest(centres, wide) < r_lo * (1.0 - 4.0 * kEpsilon))
                return false;  // the box lies within one ball: inside, off the surface
            // Undecidable: the sphere of every ball of this piece passes
            // through the box. No smaller piece, whose centres lie within
            // these (the diagonal below) and whose radii within [r_lo, r_hi],
            // can put the box out of reach or within one ball, so the search
            // goes on to the other pieces, one of whose balls may hold the
            // whole box. (Answering "may" here, at depth 32, sent a deformed
            // sweep's curved paths inside the solid down to a chord every
            // 1e-6 of its size: 10^5 pieces and 22 s for one ray.)
            const double diagonal = 2.0 * std::sqrt(3.0) * std::max({margin.x, margin.y, margin.z});
            const bool crosses = nearest(centres, wide) + diagonal < r_lo &&
                                 farthest(centres, wide) - diagonal > r_hi;
            if (crosses || piece.depth >= kMaxDepth || !(half > 0.0)) {
                undecided = true;
                continue;
            }
            stack[top++] = {mid, piece.u1, piece.depth + 1};
            stack[top++] = {piece.u0, mid, piece.depth + 1};
        }
    }
    return undecided;
}

}  // namespace hexant::runtime::geometry
