// The object kinds registered in runtime/objects/kinds.hpp, as the language
// sees them: every kind's keyword, option words and settings come from the
// registration alone.
#include <string>
#include <string_view>

#include <catch2/catch.hpp>

#include "language/grammar.hpp"
#include "language/interpreter.hpp"
#include "runtime/objects/kinds.hpp"
#include "runtime/objects/shapes.hpp"
#include "tests/language/scene_text.hpp"

namespace rt = hexant::runtime;
using hexant::test::error_of;

namespace {

using Words = rt::objects::KindWords<rt::ShapeKinds>;

template <class... Kinds>
void each_kind(rt::objects::KindList<Kinds...>, auto&& check) {
    (check(static_cast<Kinds*>(nullptr)), ...);
}

const rt::Shape& only_shape(const rt::SceneDescription& scene) {
    REQUIRE(scene.objects.size() == 1);
    return scene.objects[0]->shape;
}

}  // namespace

TEST_CASE("every registered kind is read by its keyword, names itself and is reserved",
          "[language][object-kinds]") {
    int kinds = 0;
    each_kind(rt::ShapeKinds{}, [&]<class Kind>(Kind*) {
        // Its index in the list (how a shape block carries its kind) and back.
        const std::size_t index = rt::objects::kind_index(rt::ShapeKinds{}, Kind::keyword);
        CHECK(index == static_cast<std::size_t>(kinds));
        CHECK(rt::objects::kind_keyword(rt::ShapeKinds{}, index) == Kind::keyword);
        ++kinds;
        const std::string keyword(Kind::keyword);
        INFO(keyword);
        CHECK(std::binary_search(Words::keywords.begin(), Words::keywords.end(), Kind::keyword));
        CHECK(hexant::language::grammar::is_reserved_word(keyword));
        CHECK(rt::shape_name(rt::Shape{Kind{}}) == keyword);
        // An empty block is the grammar's error; a string where the kind
        // wants numbers is the kind's own reading's, which names the kind.
        // (Kinds with a rule of their own, mesh, say so in their own tests.)
        if constexpr (rt::objects::kind_detail::own_syntax<Kind>()) return;
        const auto e = error_of(keyword + " { }");
        CHECK(std::string(e.what()).find("expected the object's parameters") != std::string::npos);
        const auto wrong = error_of(keyword + " { \"a string\" }");
        CHECK(std::string(wrong.what()).find(keyword) != std::string::npos);
    });
    CHECK(kinds == static_cast<int>(Words::keywords.size()));
    CHECK(rt::objects::kind_index(rt::ShapeKinds{}, "no_such_kind") ==
          rt::objects::kind_count(rt::ShapeKinds{}));
    CHECK(std::is_sorted(Words::options.begin(), Words::options.end()));
    CHECK(std::is_sorted(Words::settings.begin(), Words::settings.end()));
}

TEST_CASE("a kind's option words and settings reach that kind only", "[language][object-kinds]") {
    using hexant::language::parse_scene_text;
    const auto prism = parse_scene_text(
        "prism { linear_sweep linear_spline 0, 1, 3, <0,0>, <1,0>, <0,1> open }", "t.pov", {});
    const auto& p = std::get<rt::Prism>(only_shape(prism));
    CHECK(p.open);
    CHECK(p.points.size() == 3);

    const auto cylinder = parse_scene_text("cylinder { 0, y, 1 open off }", "t.pov", {});
    CHECK_FALSE(std::get<rt::Cylinder>(only_shape(cylinder)).open);
    const auto cone = parse_scene_text("cone { 0, 1, y, 0.5 open }", "t.pov", {});
    CHECK(std::get<rt::Cone>(only_shape(cone)).open);

    // A setting of other kinds: the message names them.
    const auto e = error_of("sphere { 0, 1 open }");
    CHECK(std::string(e.what()).find(
              "'open' belongs to a cylinder, cone, prism, sor or isosurface, not a sphere") !=
          std::string::npos);
    // smooth is height_field's; double_illuminate (POV-Ray's word) any object's.
    const auto smooth = error_of("sphere { 0, 1 smooth }");
    CHECK(std::string(smooth.what()).find("'smooth' belongs to a height_field, not a sphere") !=
          std::string::npos);
    hexant::test::reads("sphere { 0, 1 double_illuminate }");
    hexant::test::reads("sphere { 0, 1 sturm double_illuminate off }");
    // An option word of another kind.
    const auto o = error_of("sphere { linear_spline 0, 1 }");
    CHECK(std::string(o.what()).find("sphere takes no 'linear_spline'") != std::string::npos);
    // Every spline and sweep reads; a prism POV-Ray refuses (this cubic
    // closes on its last point, leaving no point to steer the closing
    // segment: Compute_Prism's "Too few points") is refused at its place.
    const auto conic = parse_scene_text(
        "prism { conic_sweep bezier_spline 0.5, 1, 8, <0,0>, <1,0>, <1,1>, <0,0>, <0,0>, <0,1>, "
        "<-1,1>, <0,0> }",
        "t.pov", {});
    const auto& c = std::get<rt::Prism>(only_shape(conic));
    CHECK(c.spline == rt::geometry::PrismSpline::bezier);
    CHECK(c.sweep == rt::geometry::PrismSweep::conic);
    const auto refused = error_of(
        "#declare P = prism { cubic_spline 0, 1, 6, <0,0>, <1,0>, <1,1>, <0,1>, <0,0>, <1,0> }");
    CHECK(std::string(refused.what()).find("Too few points in prism.") != std::string::npos);
}
