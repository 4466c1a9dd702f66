#include "runtime/objects/torus/torus_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/local_ray.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"
#include "runtime/time/interval.hpp"

namespace hexant::runtime::geometry {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

bool valid(const TorusGeometry& torus) {
    return torus.major >= 0.0 && torus.minor > 0.0 && std::isfinite(torus.major) &&
           std::isfinite(torus.minor);
}

// D and its derivative along the local ray, at points and over pieces.
class TorusAlongRay {
  public:
    TorusAlongRay(const TorusGeometry& torus, const LocalRay& ray)
        : major_(torus.major), minor_(torus.minor), o_(ray.origin), u_(ray.unit) {}

    // D at t, from the point's distance e = rho - major to the core circle
    // in the x-z direction. Far along a big torus rho and major agree in many
    // digits, and a thin tube's D lives in the digits they share: e is formed
    // as (x^2 + z^2 - major^2) / (rho + major), with the point's coordinates
    // and that sum of squares in double-double, so e (and D) is good to ulps
    // of itself rather than of major. This is what separates the two close
    // roots of a ray grazing the inner equator of a thin torus.
    struct Terms {
        double e;      // rho - major
        double y;      // the point's height
        double rho;    // its distance from the y axis
        double d_rho;  // d rho / dt (0 on the axis)
    };
    Terms terms(double t) const {
        const DoubleDouble x = two_product(t, u_.x) + DoubleDouble{o_.x, 0.0};
        const DoubleDouble y = two_product(t, u_.y) + DoubleDouble{o_.y, 0.0};
        const DoubleDouble z = two_product(t, u_.z) + DoubleDouble{o_.z, 0.0};
        const DoubleDouble rho_squared = x * x + z * z;
        const double rho = std::sqrt(std::max(rho_squared.value(), 0.0));
        const DoubleDouble excess = rho_squared + (-two_product(major_, major_));
        const double sum = rho + major_;
        const double e = sum > 0.0 ? excess.value() / sum : 0.0;
        const double d_rho = rho > 0.0 ? (x.value() * u_.x + z.value() * u_.z) / rho : 0.0;
        return {e, y.value(), rho, d_rho};
    }

    double value(double t) const {
        const Terms k = terms(t);
        return difference_of_squares(std::sqrt(k.e * k.e + k.y * k.y), minor_);
    }

    // dD/dt = 2 (e d_rho + y uy); on the axis (only a spindle's surface
    // reaches it) the kink's one-sided slope is irrelevant: d_rho = 0 there.
    double slope(double t) const {
        const Terms k = terms(t);
        return 2.0 * (k.e * k.d_rho + k.y * u_.y);
    }

    // An enclosure of D over [a, b]: the natural interval extension,
    // intersected with the mean value form D(m) + D'([a, b]) ([a, b] - m)
    // when rho stays positive (the latter shrinks quadratically with the
    // piece, which settles near-tangent pieces quickly).
    Interval enclosure(double a, double b, Interval& slope_out) const {
        const Interval t(a, b);
        const Interval x = Interval(o_.x) + t * Interval(u_.x);
        const Interval y = Interval(o_.y) + t * Interval(u_.y);
        const Interval z = Interval(o_.z) + t * Interval(u_.z);
        const Interval rho = sqrt(sqr(x) + sqr(z));
        const Interval natural = sqr(rho - Interval(major_)) + sqr(y) - sqr(Interval(minor_));
        if (!(rho.lo > 0.0)) {
            slope_out = Interval::entire();
            return natural;
        }
        slope_out = Interval(2.0) * ((Interval(1.0) - Interval(major_) / rho) *
                                         (x * Interval(u_.x) + z * Interval(u_.z)) +
                                     y * Interval(u_.y));
        const double m = Interval(a, b).mid();
        const Interval at_mid = point_enclosure(m);
        const Interval mean_value = at_mid + slope_out * (t - Interval(m));
        const Interval both = hexant::runtime::intersect(natural, mean_value);
        return both.is_empty() ? natural : both;
    }

  private:
    Interval point_enclosure(double t) const {
        const Interval x = Interval(o_.x) + Interval(t) * Interval(u_.x);
        const Interval y = Interval(o_.y) + Interval(t) * Interval(u_.y);
        const Interval z = Interval(o_.z) + Interval(t) * Interval(u_.z);
        const Interval rho = sqrt(sqr(x) + sqr(z));
        return sqr(rho - Interval(major_)) + sqr(y) - sqr(Interval(minor_));
    }

    double major_, minor_;
    glm::dvec3 o_, u_;
};

// Safeguarded Newton on a piece [a, b] where D is monotone and changes sign
// (da = D(a)): Newton steps that stay inside the shrinking bracket, bisection
// otherwise; stops when a step is below rounding of the local scale or the
// bracket is down to adjacent doubles.
double polish(const TorusAlongRay& d, double a, double b, double da, double scale) {
    double x = 0.5 * a + 0.5 * b;
    for (int i = 0; i < 200; ++i) {
        const double dx = d.value(x);
        if (dx == 0.0) return x;
        if ((dx < 0.0) == (da < 0.0)) {
            a = x;
            da = dx;
        } else {
            b = x;
        }
        const double mid = 0.5 * a + 0.5 * b;
        if (!(a < mid && mid < b)) return x;
        const double slope = d.slope(x);
        const double step = slope != 0.0 ? dx / slope : kInf;
        const double newton = x - step;
        if (newton > a && newton < b) {
            if (std::fabs(step) <= 2.0 * kEpsilon * (std::fabs(x) + scale)) return newton;
            x = newton;
        } else {
            x = mid;
        }
    }
    return x;
}

// The roots of D along [lo, hi] in increasing order, one per next() call.
// The pieces are always halves of the same fixed range, and which pieces are
// examined does not change the others, so a root comes out as exactly the
// same double whatever part of the range a caller asks about: a caller
// walking the hits with s_min = the previous hit never sees one root twice.
// floor: pieces wholly below it are not examined (they cannot hold roots
// the caller wants); scale: the torus's size, below whose rounding (a few
// ulps) a piece is not split further.
class RootWalk {
  public:
    // The range is given as up to two pieces in increasing order.
    RootWalk(const TorusAlongRay& d, const double (*pieces)[2], int count, double floor,
             double scale)
        : d_(d), floor_(floor), scale_(scale) {
        for (int i = count - 1; i >= 0; --i) stack_[top_++] = {pieces[i][0], pieces[i][1]};
    }

    std::optional<double> next() {
        while (top_ > 0 && examined_ < 100000) {
            const Piece piece = stack_[--top_];
            ++examined_;
            if (piece.b < floor_) continue;
            Interval slope;
            const Interval e = d_.enclosure(piece.a, piece.b, slope);
            if (e.lo > 0.0 || e.hi < 0.0) continue;  // provably no root here
            if (slope.lo > 0.0 || slope.hi < 0.0) {
                // Monotone: one root exactly when the ends' signs differ. A
                // root at the piece's far end belongs to the next piece.
                const double da = d_.value(piece.a), db = d_.value(piece.b);
                if (da == 0.0) return piece.a;
                if (db != 0.0 && (da < 0.0) != (db < 0.0)) {
                    return polish(d_, piece.a, piece.b, da, scale_);
                }
                continue;
            }
            const double m = 0.5 * piece.a + 0.5 * piece.b;
            const double tiny = 4.0 * kEpsilon * (std::fabs(piece.a) + std::fabs(piece.b) + scale_);
            if (piece.b - piece.a <= tiny || !(piece.a < m && m < piece.b) || top_ >= 254) {
                // Undecided at the level of rounding: a tangency, which
                // counts as a hit where D is not positive.
                if (d_.value(m) <= 0.0) return m;
                continue;
            }
            stack_[top_++] = {m, piece.b};  // the far half is examined last
            stack_[top_++] = {piece.a, m};
        }
        return std::nullopt;
    }

  private:
    struct Piece {
        double a, b;
    };
    const TorusAlongRay& d_;
    double floor_, scale_;
    Piece stack_[256];
    int top_ = 0;
    int examined_ = 0;
};

glm::dvec2 torus_uv(const TorusGeometry& torus, const glm::dvec3& p) {
    const double u = 1.0 - (std::atan2(p.z, p.x) + kPi) / (2.0 * kPi);
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    const double v = (std::atan2(p.y, rho - torus.major) + kPi) / (2.0 * kPi);
    return {u, v};
}

}  // namespace

std::optional<SurfaceHit> intersect(const TorusGeometry& torus, const Ray3& ray, double s_min,
                                    double s_max) {
    if (!valid(torus)) return std::nullopt;
    const double R = torus.major, r = torus.minor;
    const double outer = R + r;
    const auto local = local_ray(ray, glm::dvec3(0.0), outer);
    if (!local) return std::nullopt;
    const glm::dvec3& o = local->origin;
    const glm::dvec3& u = local->unit;

    // The search range: where the ray runs within the sphere of radius
    // R + 2r, the slab |y| <= 2r and the shell between the cylinders about y
    // of radii R - 2r and R + 2r. These hold the torus with a margin of r, so
    // D is clearly positive (at least 3 r^2, far above its rounding) at every
    // end of the range: a root never sits at an end, where rounding could
    // hide its sign change (a ray grazing the outer equator grazes the outer
    // sphere and cylinder). The shell leaves up to two pieces, and keeps the
    // interval search away from the axis, where it is loosest.
    const double reach = R + 2.0 * r;
    const QuadraticRoots ball =
        solve_quadratic(1.0, glm::dot(o, u), difference_of_squares(safe_length(o), reach),
                        difference_of_squares(reach, safe_length(glm::cross(o, u))));
    if (ball.count == 0) return std::nullopt;
    double lo = ball.t[0], hi = ball.t[ball.count - 1];
    if (u.y != 0.0) {
        double ya = (-2.0 * r - o.y) / u.y, yb = (2.0 * r - o.y) / u.y;
        if (ya > yb) std::swap(ya, yb);
        lo = std::max(lo, ya);
        hi = std::min(hi, yb);
    } else if (std::fabs(o.y) > 2.0 * r) {
        return std::nullopt;
    }
    // In the x-z plane: rho(t)^2 = a t^2 + 2 b t + c, solved as for the sphere.
    const double a = u.x * u.x + u.z * u.z;
    const double b = o.x * u.x + o.z * u.z;
    const double rho0 = std::hypot(o.x, o.z);
    const double across = std::fabs(difference_of_products(o.x, u.z, o.z, u.x));  // |o x u| in 2D
    const double inner = R - 2.0 * r;
    double hole[2] = {0.0, 0.0};  // where rho < inner: no roots
    bool has_hole = false;
    if (a > 0.0) {
        const double root_a = std::sqrt(a);
        const QuadraticRoots shell = solve_quadratic(a, b, difference_of_squares(rho0, reach),
                                                     difference_of_squares(reach * root_a, across));
        if (shell.count == 0) return std::nullopt;
        lo = std::max(lo, shell.t[0]);
        hi = std::min(hi, shell.t[shell.count - 1]);
        if (inner > 0.0) {
            const QuadraticRoots core =
                solve_quadratic(a, b, difference_of_squares(rho0, inner),
                                difference_of_squares(inner * root_a, across));
            if (core.count == 2) {
                hole[0] = core.t[0];
                hole[1] = core.t[1];
                has_hole = true;
            }
        }
    } else if (rho0 > reach || rho0 < inner) {
        return std::nullopt;  // parallel to the axis, outside the shell
    }
    if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) return std::nullopt;
    double pieces[2][2];
    int count = 0;
    if (has_hole && hole[0] < hole[1]) {
        if (lo < std::min(hi, hole[0]))
            pieces[count][0] = lo, pieces[count++][1] = std::min(hi, hole[0]);
        if (std::max(lo, hole[1]) < hi)
            pieces[count][0] = std::max(lo, hole[1]), pieces[count++][1] = hi;
    } else {
        pieces[count][0] = lo;
        pieces[count++][1] = hi;
    }
    // Roots below s_min are skipped, not searched past from a new start:
    // see RootWalk for why the range must not depend on s_min.
    const double t_floor = local->to_t(s_min);
    const double floor = t_floor - 16.0 * kEpsilon * (outer + std::fabs(t_floor));

    const TorusAlongRay d(torus, *local);
    RootWalk walk(d, pieces, count, floor, outer);
    while (auto t = walk.next()) {
        const double s = local->to_s(*t);
        if (!(s > s_min)) continue;
        if (!(s < s_max)) return std::nullopt;
        SurfaceHit hit;
        hit.s = s;
        hit.point = local->at(*t);
        // The root is found to about 16 ulps of outer + |t| (the search's
        // own floor above) and the point formed from an origin within a few
        // outer radii: gamma(32) of the point's and the torus's magnitude
        // bounds its distance from the surface.
        hit.error = rounding_gamma(32) * (glm::abs(hit.point) + outer);
        const glm::dvec3& p = hit.point;
        // From the nearest point of the core circle to the hit point: e (the
        // accurate rho - R) along the radial direction, and the height.
        const auto k = d.terms(*t);
        const glm::dvec3 from_core =
            k.rho > 0.0 ? glm::dvec3(k.e * p.x / k.rho, k.y, k.e * p.z / k.rho) : p;
        const double len = safe_length(from_core);
        hit.normal = len > 0.0 ? from_core / len : glm::dvec3(0.0, 1.0, 0.0);
        hit.shading_normal = hit.normal;
        hit.uv = torus_uv(torus, p);
        hit.part = 0;
        if (is_finite(hit)) return hit;
        return std::nullopt;
    }
    return std::nullopt;
}

bool inside(const TorusGeometry& torus, glm::dvec3 p) {
    if (!valid(torus)) return false;
    const double e = std::sqrt(p.x * p.x + p.z * p.z) - torus.major;
    return std::sqrt(e * e + p.y * p.y) <= torus.minor;
}

Box3 object_bounds(const TorusGeometry& torus) {
    const double outer = std::fabs(torus.major) + std::fabs(torus.minor);
    const double r = std::fabs(torus.minor);
    return {{-outer, -r, -outer}, {outer, r, outer}};
}

bool surface_may_meet(const TorusGeometry& torus, const Box3& box) {
    if (!valid(torus)) return false;
    const Box3 b = widened(box, meet_slack(box, torus.major + torus.minor));
    // x, y and z each appear once in D = (sqrt(x^2 + z^2) - R)^2 + y^2 - r^2,
    // so its interval extension over the box is the exact range (up to the
    // outward rounding), and the surface D = 0 meets the (connected) box
    // exactly when that range holds 0.
    const Interval x(b.lo.x, b.hi.x), y(b.lo.y, b.hi.y), z(b.lo.z, b.hi.z);
    const Interval rho = sqrt(sqr(x) + sqr(z));
    const Interval range = sqr(rho - Interval(torus.major)) + sqr(y) - sqr(Interval(torus.minor));
    return !(range.lo > 0.0) && !(range.hi < 0.0);
}

}  // namespace hexant::runtime::geometry
