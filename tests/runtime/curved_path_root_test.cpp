// The curved-path root finder (runtime/geometry/curved_path_root.hpp) on paths made
// by hand: it finds a crossing of a continuous path, and a path that jumps
// (as a bend's inverse does across its branch cut) gives no hit from the
// chord between its two sides (issue 20: a height field and a
// superellipsoid under a bend were met off the ray's path).
#include "runtime/geometry/curved_path_root.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <catch2/catch.hpp>

namespace rt = hexant::runtime;
namespace geo = hexant::runtime::geometry;

namespace {

// The plane x = 5 as a surface: a box may meet it when it spans x = 5; a
// chord's hit is where it crosses x = 5 within [u0, u1].
bool plane_may_meet(const geo::Box3& box, const rt::Interval&) {
    return box.lo.x <= 5.0 && 5.0 <= box.hi.x;
}

std::optional<geo::SurfaceHit> plane_hit(const geo::Ray3& chord, double u0, double u1,
                                         const rt::Interval&) {
    if (chord.direction.x == 0.0) return std::nullopt;
    const double u = (5.0 - chord.origin.x) / chord.direction.x;
    if (!(u >= u0 && u <= u1)) return std::nullopt;
    geo::SurfaceHit hit{};
    hit.s = u;
    hit.normal = hit.shading_normal = {1, 0, 0};
    hit.point = chord.origin + u * chord.direction;
    return hit;
}

}  // namespace

TEST_CASE("curved path: a continuous path's crossing is found on its curve",
          "[object][intersect]") {
    // x = 10 s^2: crosses x = 5 at s = 1 / sqrt(2).
    const auto point_at = [](double s) { return glm::dvec3(10.0 * s * s, s, 0.0); };
    const auto box_over = [](const rt::Interval& s) {
        const double lo = std::max(s.lo, 0.0), hi = s.hi;
        return geo::Box3{{10.0 * lo * lo, s.lo, 0.0}, {10.0 * hi * hi, s.hi, 0.0}};
    };
    const auto found =
        rt::first_hit_on_curve(0.0, 1.0, 10.0, box_over, point_at, plane_may_meet, plane_hit);
    REQUIRE(found);
    CHECK(found->s == Approx(1.0 / std::sqrt(2.0)).epsilon(1e-6));
    CHECK(std::fabs(point_at(found->s).x - 5.0) <= 1e-4);
}

TEST_CASE("curved path: no hit from the chord across a jump of the path", "[object][intersect]") {
    // x = s below s = 0.5, x = s + 10 from there: the path never meets
    // x = 5, but it jumps over it; the box over a piece holding the jump
    // holds both sides, so the search halves down to the jump itself.
    const double jump = 0.5;
    const auto point_at = [&](double s) { return glm::dvec3(s < jump ? s : s + 10.0, 0.0, 0.0); };
    const auto box_over = [&](const rt::Interval& s) {
        const glm::dvec3 a = point_at(s.lo), b = point_at(s.hi);
        return geo::Box3{{std::min(a.x, b.x), 0.0, 0.0}, {std::max(a.x, b.x), 0.0, 0.0}};
    };
    const auto found =
        rt::first_hit_on_curve(0.0, 1.0, 10.0, box_over, point_at, plane_may_meet, plane_hit);
    CHECK(!found);
    // And a crossing after the jump is still found: x = 12 there, at s = 2.
    const auto after = rt::first_hit_on_curve(
        0.0, 3.0, 10.0,
        [&](const rt::Interval& s) {
            const glm::dvec3 a = point_at(s.lo), b = point_at(s.hi);
            return geo::Box3{{std::min(a.x, b.x) - 7.0, 0.0, 0.0},
                             {std::max(a.x, b.x) - 7.0, 0.0, 0.0}};
        },
        [&](double s) { return point_at(s) - glm::dvec3(7.0, 0.0, 0.0); }, plane_may_meet,
        plane_hit);
    REQUIRE(after);
    CHECK(after->s == Approx(2.0).epsilon(1e-9));
}
