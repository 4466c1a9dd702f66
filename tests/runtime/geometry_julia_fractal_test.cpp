// Static ray/julia_fractal geometry: the complex functions against
// std::complex; the quaternion z^2 + 0 and z^3 + 0, whose Julia sets are
// the unit ball, against the analytic sphere (hits, normals, inside);
// POV-Ray's radii (Compute_BBox) and slice checks; surface_may_meet
// never "no" beside a hit; and no NaN or Inf out for extreme rays.
#include <complex>
#include <limits>

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include "runtime/objects/julia_fractal/julia_fractal_geometry.hpp"

namespace geo = hexant::runtime::geometry;
using geo::JuliaAlgebra;
using geo::JuliaFunction;

namespace {

geo::JuliaFractalGeometry ball(JuliaFunction f, int iterations = 8) {
    return geo::make_julia_fractal({0.0, 0.0, 0.0, 0.0}, JuliaAlgebra::quaternion, f, {},
                                   iterations, 400.0, {0.0, 0.0, 0.0, 1.0}, 0.0);
}

}  // namespace

TEST_CASE("julia_fractal: the complex functions are the principal ones",
          "[geometry][julia_fractal]") {
    using C = std::complex<double>;
    const C z(0.3, -0.7);
    const auto at = [&](JuliaFunction f) {
        const geo::Complex r = geo::complex_function(f, {z.real(), z.imag()}, {2.0, 0.5});
        return C(r.x, r.y);
    };
    const auto near = [](C a, C b) { return std::abs(a - b) < 1e-12; };
    CHECK(near(at(JuliaFunction::exp), std::exp(z)));
    CHECK(near(at(JuliaFunction::ln), std::log(z)));
    CHECK(near(at(JuliaFunction::sin), std::sin(z)));
    CHECK(near(at(JuliaFunction::cos), std::cos(z)));
    CHECK(near(at(JuliaFunction::tan), std::tan(z)));
    CHECK(near(at(JuliaFunction::sinh), std::sinh(z)));
    CHECK(near(at(JuliaFunction::cosh), std::cosh(z)));
    CHECK(near(at(JuliaFunction::tanh), std::tanh(z)));
    CHECK(near(at(JuliaFunction::asin), std::asin(z)));
    CHECK(near(at(JuliaFunction::asinh), std::asinh(z)));
    CHECK(near(at(JuliaFunction::atan), std::atan(z)));
    CHECK(near(at(JuliaFunction::atanh), std::atanh(z)));
    CHECK(near(at(JuliaFunction::pwr), std::pow(z, C(2.0, 0.5))));
    // acos and acosh: POV-Ray's formulas are other branches of the same
    // functions (cos and cosh of the result give z back).
    CHECK(near(std::cos(at(JuliaFunction::acos)), z));
    CHECK(near(std::cosh(at(JuliaFunction::acosh)), z));
}

TEST_CASE("julia_fractal: z^2 and z^3 of c = 0 are the unit ball", "[geometry][julia_fractal]") {
    for (const JuliaFunction f : {JuliaFunction::sqr, JuliaFunction::cube}) {
        const auto g = ball(f);
        REQUIRE(g.valid);
        // Compute_BBox: R = 1 + |c| + 1e-7, Exit_Value = R^2 + 1e-7.
        CHECK(g.radius == Approx(1.0 + 1e-7).epsilon(1e-15));
        CHECK(geo::inside(g, {0.0, 0.5, 0.5}));
        CHECK_FALSE(geo::inside(g, {0.0, 0.8, 0.8}));
        for (int i = 0; i < 200; ++i) {
            const double a = 0.031 * i, b = 0.017 * i;
            const glm::dvec3 d(std::cos(a) * std::cos(b), std::sin(b), std::sin(a) * std::cos(b));
            const geo::Ray3 ray{-5.0 * d + glm::dvec3(0.0, 0.3, -0.2) * (i % 3 == 0 ? 1.0 : 0.0),
                                2.0 * d};
            const auto hit = geo::intersect(g, ray, 0.0, std::numeric_limits<double>::infinity());
            REQUIRE(hit);
            // On the sphere to the march's 1e-7 and the set's own width.
            CHECK(glm::length(hit->point) == Approx(1.0).margin(1e-5));
            CHECK(glm::length(ray.origin + hit->s * ray.direction - hit->point) < 1e-9);
            CHECK(glm::dot(hit->normal, glm::normalize(hit->point)) > 0.999);
            CHECK(geo::surface_may_meet(g, {hit->point - 1e-3, hit->point + 1e-3}));
        }
        // Wholly inside or wholly outside: no surface there.
        CHECK_FALSE(geo::surface_may_meet(g, {glm::dvec3(-0.1), glm::dvec3(0.1)}));
        CHECK_FALSE(geo::surface_may_meet(g, {glm::dvec3(0.9), glm::dvec3(1.0)}));
        CHECK(geo::surface_may_meet(g, {glm::dvec3(0.5), glm::dvec3(0.7)}));
    }
}

TEST_CASE("julia_fractal: POV-Ray's radii and slice checks", "[geometry][julia_fractal]") {
    const auto q = geo::make_julia_fractal({3.0, 0.0, 0.0, 0.0}, JuliaAlgebra::quaternion,
                                           JuliaFunction::sqr, {}, 5, 20.0, {0, 0, 0, 1}, 0.0);
    CHECK(q.radius == 2.0);
    CHECK(q.exit_value == 4.0 + 1e-7);
    const auto h = geo::make_julia_fractal({0.1, 0.0, 0.0, 0.0}, JuliaAlgebra::hypercomplex,
                                           JuliaFunction::sin, {}, 0, 0.5, {0, 0, 0, 1}, 0.0);
    CHECK(h.radius == 4.0);
    CHECK(h.exit_value == 16.0);
    CHECK(h.iterations == 1);
    CHECK(h.precision == 1.0);  // precision below 1 is 1
    CHECK_FALSE(geo::make_julia_fractal({0, 0, 0, 0}, JuliaAlgebra::quaternion, JuliaFunction::sqr,
                                        {}, 5, 20.0, {1, 0, 0, 0}, 0.0)
                    .valid);
    CHECK_FALSE(geo::make_julia_fractal({0, 0, 0, 0}, JuliaAlgebra::quaternion, JuliaFunction::sqr,
                                        {}, 5, 20.0, {0, 0, 0, 0}, 0.0)
                    .valid);
}

TEST_CASE("julia_fractal: no NaN or Inf for extreme rays and every function",
          "[geometry][julia_fractal]") {
    for (int f = 0; f <= static_cast<int>(JuliaFunction::reciprocal); ++f) {
        const auto g = geo::make_julia_fractal(
            {-0.54, 0.57, 0.0, -0.37}, JuliaAlgebra::hypercomplex, static_cast<JuliaFunction>(f),
            {1.5, -0.5}, 6, 20.0, {0.2, 0.1, 0.3, 1.0}, 0.1);
        REQUIRE(g.valid);
        for (int i = 0; i < 300; ++i) {
            const double a = 0.7 * i, b = 0.3 * i;
            const glm::dvec3 d(std::cos(a) * std::cos(b), std::sin(b), std::sin(a) * std::cos(b));
            const double far = std::pow(10.0, (i % 40) - 5.0);
            const geo::Ray3 ray{-far * d, std::pow(10.0, (i % 13) - 6.0) * d};
            const auto hit = geo::intersect(g, ray, 0.0, std::numeric_limits<double>::infinity());
            if (!hit) continue;
            CHECK(geo::is_finite(*hit));
            CHECK(glm::length(hit->normal) == Approx(1.0));
            CHECK(glm::length(hit->point) <= 4.0 + 1e-9);
        }
    }
}
