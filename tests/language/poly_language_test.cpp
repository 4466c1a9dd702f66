// quadric, cubic, quartic, poly and polynomial as the language reads them
// (runtime/objects/poly/poly.hpp): coefficients in POV-Ray's order, the
// polynomial { } terms, clock in coefficients, and the refusals.
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/objects/shapes.hpp"
#include "tests/language/scene_text.hpp"

namespace rt = hexant::runtime;
using hexant::test::error_of;

namespace {

const rt::PolySurface& poly_of(const std::string& text, rt::SceneDescription& keep) {
    keep = hexant::language::parse_scene_text("#version 3.7;\n" + text, "t.pov", {});
    REQUIRE(keep.objects.size() == 1);
    return std::visit(
        [](const auto& shape) -> const rt::PolySurface& {
            if constexpr (std::is_base_of_v<rt::PolySurface, std::decay_t<decltype(shape)>>)
                return shape;
            else
                throw std::logic_error("not a poly");
        },
        keep.objects[0]->shape);
}

bool says(const std::string& scene, const std::string& part) {
    const std::string message = error_of(scene).what();
    INFO(message);
    return message.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("polys read their coefficients in POV-Ray's order", "[language][poly]") {
    rt::SceneDescription s;
    // quadric: A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J.
    const auto& q = poly_of("quadric { <1, 2, 3>, <4, 5, 6>, <7, 8, 9>, 10 }", s);
    REQUIRE(q.order == 2);
    const double expected[10] = {1, 4, 5, 7, 2, 6, 8, 3, 9, 10};
    for (int n = 0; n < 10; ++n) CHECK(q.coefficients[n].constant() == expected[n]);
    const auto& c = poly_of(
        "cubic { <1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, "
        "18, 19, 20> }",
        s);
    CHECK(c.order == 3);
    CHECK(c.coefficients[19].constant() == 20);
    // polynomial's terms land where poly's would, the others are 0.
    const auto& p = poly_of(
        "polynomial { 4, xyz(0, 2, 0): 1, xyz(0, 0, 2): 1 xyz(4, 0, 0): 4 "
        "xyz(3, 0, 0): -4 }",
        s);
    const auto& same = p.coefficients;
    rt::SceneDescription s2;
    const auto& quartic = poly_of(
        "quartic { <4, 0, 0, -4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, "
        "1, 0, 0, 0, 0, 0, 0, 1, 0, 0> }",
        s2);
    REQUIRE(same.size() == 35);
    for (int n = 0; n < 35; ++n) CHECK(same[n].constant() == quartic.coefficients[n].constant());
}

TEST_CASE("a poly's coefficients may move with clock", "[language][poly]") {
    hexant::language::ParseOptions options;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 2;
    const auto scene = hexant::language::parse_scene_text(
        "#version 3.7;\npoly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -clock> }", "t.pov", options);
    const auto& p = std::get<rt::Poly>(scene.objects[0]->shape);
    CHECK(p.coefficients[9].depends_on_time());
    CHECK(p.coefficients[9](0.5) == -0.5);
}

TEST_CASE("polys refuse what they cannot be", "[language][poly]") {
    CHECK(says("cubic { <1, 2, 3> }", "has 20 coefficients, not 3"));
    CHECK(says("poly { 1, <1, 2, 3, 4> }", "order is a whole number from 2 to 15"));
    CHECK(says("poly { 20, <1> }", "POV-Ray reads up to 35"));
    CHECK(says("polynomial { 3, xyz(2, 2, 0): 1 }", "add up to more than the order"));
    CHECK(says("polynomial { 3, xyz(1.5, 0, 0): 1 }", "whole numbers"));
    CHECK(says("quartic { 4, <1> }", "has its order"));
    CHECK(says("poly { <1, 2> }", "needs its order"));
    CHECK(says("quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0> }", "needs"));
}
