// Static ray/prism geometry of the curved path (prism_curve.hpp): POV-Ray's
// outline rules (segment counts of its distribution's prism1.pov lists,
// its refusals), hits on straight-sided Bezier outlines against analytic
// values for both sweeps (a conic sweep through its apex too), inside, and
// a ray along an outline's lowest joint that must not see a cap.
// Tolerance: 1e-12 on s and normals (the analytic hits are exact up to a
// few roundings of numbers of size 5).
#include <vector>

#include "geometry_test_support.hpp"
#include "runtime/objects/prism/prism_geometry.hpp"
#include "runtime/objects/prism/prism_outline.hpp"

using namespace geometry_test;
namespace geo = hexant::runtime::geometry;

namespace {

// prism1.pov's quadratic list (12 points); its cubic list adds a first point.
const std::vector<glm::dvec2> kQuadratic = {{0.2, -1},   {0.2, 0.2}, {1, -0.2}, {1, 0.2},
                                            {0.2, 1},    {-0.2, 1},  {-1, 0.2}, {-1, -0.2},
                                            {-0.2, 0.2}, {-0.2, -1}, {0.2, -1}, {0.2, 0.2}};

std::vector<glm::dvec2> cubic_list() {
    std::vector<glm::dvec2> p = {{-0.2, -1}};
    p.insert(p.end(), kQuadratic.begin(), kQuadratic.end());
    return p;
}

// The square [-1, 1]^2 as four straight Bezier segments.
std::vector<glm::dvec2> bezier_square() {
    const glm::dvec2 c[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    std::vector<glm::dvec2> p;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p.push_back(c[i] + (c[(i + 1) % 4] - c[i]) * (j / 3.0));
    return p;
}

void check_hit(const geo::PrismGeometry& g, glm::dvec3 o, glm::dvec3 d, double s, glm::dvec3 n) {
    const auto hit = geo::intersect(g, Ray3{o, d}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(well_formed(*hit));
    CHECK(std::fabs(hit->s - s) < 1e-12);
    CHECK(glm::length(hit->normal - glm::normalize(n)) < 1e-12);
}

}  // namespace

TEST_CASE("prism outlines follow POV-Ray's rules", "[geometry][prism]") {
    using geo::PrismSpline;
    CHECK(geo::prism_outline(PrismSpline::quadratic, kQuadratic).segments.size() == 10);
    CHECK(geo::prism_outline(PrismSpline::cubic, cubic_list()).segments.size() == 10);
    // A linear outline left open is closed back to its first point.
    const std::vector<glm::dvec2> open(kQuadratic.begin(), kQuadratic.begin() + 10);
    const auto linear = geo::prism_outline(PrismSpline::linear, open);
    REQUIRE(linear.segments.size() == 10);
    CHECK(linear.segments.back()[0] == 9);
    CHECK(linear.segments.back()[1] == 0);
    // Refused as POV-Ray refuses: a quadratic outline that does not close, a
    // cubic one closing on its last point (no point steers it), counts.
    const std::vector<glm::dvec2> unclosed(kQuadratic.begin(), kQuadratic.begin() + 11);
    CHECK(geo::prism_outline(PrismSpline::quadratic, unclosed).error == "Too few points in prism.");
    const std::vector<glm::dvec2> cubic6 = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}};
    CHECK(geo::prism_outline(PrismSpline::cubic, cubic6).error == "Too few points in prism.");
    CHECK(geo::prism_count_error(PrismSpline::bezier, 6) ==
          "Prism with Bezier splines must have four points per segment.");
    // A Bezier outline that does not end on its start is ignored (drawn as nothing).
    std::vector<glm::dvec2> bent = bezier_square();
    bent.back() = {-1, -0.5};
    const auto ignored = geo::prism_outline(PrismSpline::bezier, bent);
    CHECK(ignored.ignored);
    CHECK(ignored.segments.empty());
}

TEST_CASE("prism sides, caps, normals and inside for curved outlines", "[geometry][prism]") {
    using geo::PrismSpline;
    using geo::PrismSweep;
    const auto straight =
        geo::make_prism(PrismSpline::bezier, PrismSweep::linear, 0, 1, bezier_square(), false);
    REQUIRE(straight.segments.size() == 4);
    check_hit(straight, {-5, 0.5, 0.3}, {1, 0, 0}, 4.0, {-1, 0, 0});
    check_hit(straight, {0.2, 5, 0.3}, {0, -1, 0}, 4.0, {0, 1, 0});
    // Conic: the face x = y (|z| <= y) between heights 0.5 and 2.
    const auto cone =
        geo::make_prism(PrismSpline::bezier, PrismSweep::conic, 0.5, 2, bezier_square(), false);
    check_hit(cone, {5, 1, 0}, {-1, 0, 0}, 4.0, {1, -1, 0});
    check_hit(cone, {0, -5, 0}, {0, 1, 0}, 5.5, {0, -1, 0});
    // Through the apex (heights given high first, as POV-Ray swaps them):
    // below it the outline turns by 180 degrees, the face x = -y.
    const auto both =
        geo::make_prism(PrismSpline::bezier, PrismSweep::conic, 1, -1, bezier_square(), false);
    check_hit(both, {5, -0.5, 0}, {-1, 0, 0}, 4.5, {1, 1, 0});
    CHECK(geo::inside(both, {0, 0.5, 0}));
    CHECK(geo::inside(both, {0.4, -0.5, 0}));
    CHECK_FALSE(geo::inside(both, {0.6, -0.5, 0}));
    CHECK_FALSE(geo::inside(both, {0, 0, 0}));  // POV-Ray: nothing at the apex
    // Open: no caps.
    const auto open =
        geo::make_prism(PrismSpline::bezier, PrismSweep::linear, 0, 1, bezier_square(), true);
    CHECK_FALSE(geo::intersect(open, Ray3{{0.2, 5, 0.3}, {0, -1, 0}}, 0.0, kInf));
    check_hit(open, {-5, 0.5, 0.3}, {1, 0, 0}, 4.0, {-1, 0, 0});
}

TEST_CASE("a ray along an outline's lowest joint sees no cap", "[geometry][prism]") {
    // prism1.pov's cubic outline swept conically: its lowest points lie at
    // z = -1 at height 1, so a ray in the cap's plane line z = -1 (x < -1)
    // only touches the outline's lowest joints' line.
    const auto g = geo::make_prism(geo::PrismSpline::cubic, geo::PrismSweep::conic, 0.25, 1,
                                   cubic_list(), false);
    REQUIRE(g.segments.size() == 10);
    for (const double x : {-1.7, -1.5, -1.2}) CHECK_FALSE(geo::inside(g, {x, 1.0, -1.0}));
    CHECK(geo::inside(g, {0.0, 1.0, 0.0}));
}
