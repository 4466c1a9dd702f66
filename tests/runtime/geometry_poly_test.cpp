// Ray/polynomial-surface geometry (runtime/objects/poly/): POV-Ray's term
// order, hits on surfaces whose roots are known in closed form (a sphere
// as a quadric, a torus as a quartic, from near and from 1e6 away), normals
// against the exact ones, inside(), and surface_may_meet around the
// surface.
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "runtime/objects/poly/poly.hpp"
#include "runtime/objects/poly/poly_geometry.hpp"

namespace rt = hexant::runtime;
using rt::geometry::PolyGeometry;

namespace {

// p = sum of c * x^i y^j z^k over the given terms, as a geometry.
PolyGeometry poly(int order, const std::vector<std::pair<std::array<int, 3>, double>>& terms) {
    PolyGeometry g;
    g.order = order;
    g.coefficients.assign(static_cast<std::size_t>(rt::poly_term_count(order)), 0.0);
    for (const auto& [e, c] : terms)
        g.coefficients[static_cast<std::size_t>(rt::poly_term_index(order, e[0], e[1], e[2]))] += c;
    return g;
}

// The torus of radii R, r about the y axis: (x^2 + y^2 + z^2 + R^2 - r^2)^2
// - 4 R^2 (x^2 + z^2).
PolyGeometry torus(double R, double r) {
    const double a = R * R - r * r;
    return poly(4, {{{4, 0, 0}, 1},
                    {{0, 4, 0}, 1},
                    {{0, 0, 4}, 1},
                    {{2, 2, 0}, 2},
                    {{2, 0, 2}, 2},
                    {{0, 2, 2}, 2},
                    {{2, 0, 0}, 2 * a - 4 * R * R},
                    {{0, 2, 0}, 2 * a},
                    {{0, 0, 2}, 2 * a - 4 * R * R},
                    {{0, 0, 0}, a * a}});
}

}  // namespace

TEST_CASE("poly terms come in POV-Ray's order", "[geometry][poly]") {
    // The geometry's table and the language's index agree term by term.
    for (int order = 2; order <= 15; ++order) {
        const auto& terms = rt::geometry::poly_terms(order);
        REQUIRE(static_cast<int>(terms.size()) == rt::poly_term_count(order));
        for (std::size_t n = 0; n < terms.size(); ++n)
            CHECK(rt::poly_term_index(order, terms[n][0], terms[n][1], terms[n][2]) ==
                  static_cast<int>(n));
    }
    // The cubic's twenty terms as POV-Ray's documentation lists them.
    const std::vector<std::array<int, 3>> cubic = {
        {3, 0, 0}, {2, 1, 0}, {2, 0, 1}, {2, 0, 0}, {1, 2, 0}, {1, 1, 1}, {1, 1, 0},
        {1, 0, 2}, {1, 0, 1}, {1, 0, 0}, {0, 3, 0}, {0, 2, 1}, {0, 2, 0}, {0, 1, 2},
        {0, 1, 1}, {0, 1, 0}, {0, 0, 3}, {0, 0, 2}, {0, 0, 1}, {0, 0, 0}};
    REQUIRE(rt::poly_term_count(3) == 20);
    for (int n = 0; n < 20; ++n) {
        const auto& e = cubic[static_cast<std::size_t>(n)];
        CHECK(rt::poly_term_index(3, e[0], e[1], e[2]) == n);
    }
    // The quartic's 35; y^2 is its 26th (index 25) and z^2 its 33rd, as in
    // POV-Ray's piriform sample.
    CHECK(rt::poly_term_count(4) == 35);
    CHECK(rt::poly_term_index(4, 0, 2, 0) == 25);
    CHECK(rt::poly_term_index(4, 0, 0, 2) == 32);
    CHECK(rt::poly_term_index(15, 0, 0, 0) == rt::poly_term_count(15) - 1);
}

TEST_CASE("a sphere and a torus as polys are hit where they are", "[geometry][poly]") {
    const PolyGeometry sphere =
        poly(2, {{{2, 0, 0}, 1}, {{0, 2, 0}, 1}, {{0, 0, 2}, 1}, {{0, 0, 0}, -4}});
    for (const double far : {5.0, 1e3, 1e6}) {
        INFO(far);
        const auto hit = intersect(sphere, {{0.3, 0.4, -far}, {0, 0, 1}}, 0.0, INFINITY);
        REQUIRE(hit);
        const double z = -std::sqrt(4.0 - 0.25);
        CHECK(hit->point.z == Approx(z).epsilon(1e-12));
        CHECK(hit->s == Approx(far + z).epsilon(1e-15));
        CHECK(glm::length(hit->normal - glm::dvec3(0.3, 0.4, z) / 2.0) < 1e-12);
    }
    // From inside: the far side; a miss; a range that ends before the hit.
    CHECK(intersect(sphere, {{0, 0, 0}, {1, 0, 0}}, 0.0, INFINITY)->point.x == Approx(2.0));
    CHECK_FALSE(intersect(sphere, {{0, 3, -5}, {0, 0, 1}}, 0.0, INFINITY));
    CHECK_FALSE(intersect(sphere, {{0, 0, -5}, {0, 0, 1}}, 0.0, 2.9));
    CHECK(inside(sphere, {0, 1.9, 0}));
    CHECK_FALSE(inside(sphere, {0, 2.1, 0}));

    // A thin torus along the x axis: the tube at x = 1 +- 0.1.
    const PolyGeometry ring = torus(1.0, 0.1);
    const auto hit = intersect(ring, {{-3, 0, 0}, {1, 0, 0}}, 0.0, INFINITY);
    REQUIRE(hit);
    CHECK(hit->point.x == Approx(-1.1).epsilon(1e-13));
    const auto through = intersect(ring, {{0, 0, 0}, {1, 0, 0}}, 0.0, INFINITY);
    REQUIRE(through);
    CHECK(through->point.x == Approx(0.9).epsilon(1e-13));
    CHECK(glm::length(through->normal - glm::dvec3(-1, 0, 0)) < 1e-9);
    CHECK(inside(ring, {1.0, 0.05, 0.0}));
    CHECK_FALSE(inside(ring, {0.0, 0.0, 0.0}));
}

TEST_CASE("poly's surface_may_meet holds the surface", "[geometry][poly]") {
    const PolyGeometry ring = torus(1.0, 0.3);
    // Boxes about surface points meet it; boxes well away do not.
    for (double a = 0.0; a < 6.28; a += 0.4) {
        const glm::dvec3 p((1.0 + 0.3 * std::cos(a)), 0.3 * std::sin(a), 0.0);
        CHECK(surface_may_meet(ring, {p - 0.01, p + 0.01}));
    }
    CHECK_FALSE(surface_may_meet(ring, {glm::dvec3(-0.2), glm::dvec3(0.2)}));
    CHECK_FALSE(surface_may_meet(ring, {glm::dvec3(3.0), glm::dvec3(4.0)}));
}
