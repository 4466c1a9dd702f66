// clipped_by { } and bounded_by { } as the language reads them
// (runtime/objects/object.hpp's ObjectLimits): the objects kept in the
// host's space, POV-Ray's linking of the two lists and its refusals. How
// they render is checked against POV-Ray's own render
// (tests/tracer/pov_reference/shapes/clipped_by.pov).
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/objects/object_factory.hpp"
#include "tests/language/scene_text.hpp"

namespace rt = hexant::runtime;
using hexant::test::error_of;

namespace {

rt::ObjectPtr object_of(const std::string& text) {
    const auto scene = hexant::language::parse_scene_text(text, "t.pov", {});
    REQUIRE(scene.objects.size() == 1);
    return scene.objects[0];
}

bool says(const std::string& scene, const std::string& part) {
    const std::string message = error_of(scene).what();
    INFO(message);
    return message.find(part) != std::string::npos;
}

// Is the world point inside the object as the tracer builds it?
bool inside(const rt::ObjectPtr& object, glm::dvec3 p) {
    const auto built = rt::make_intelligent_object(*object);
    return built->inside(rt::Event(p.x, p.y, p.z, 0.0));
}

}  // namespace

TEST_CASE("clipped_by and bounded_by keep their objects", "[language][clipped_by]") {
    const auto o = object_of(
        "sphere { 0, 1 clipped_by { plane { y, 0 } box { -1, 1 } } bounded_by { sphere { 0, 2 } "
        "} }");
    REQUIRE(o->limits);
    CHECK(o->limits->clipped_by.size() == 2);
    CHECK(o->limits->bounded_by.size() == 1);
    // bounded_by { clipped_by } takes the clips as they are then.
    const auto linked =
        object_of("sphere { 0, 1 clipped_by { plane { y, 0 } } bounded_by { clipped_by } }");
    CHECK(linked->limits->bounded_by == linked->limits->clipped_by);
    CHECK(object_of("sphere { 0, 1 }")->limits == nullptr);
}

TEST_CASE("a clip written before a transform moves with the object's later ones",
          "[language][clipped_by]") {
    // The clip keeps y <= 0 where it is written; the object's turn after it
    // turns the clip too (POV-Ray's Transform_Object), the translate before
    // it does not move the clip.
    const auto o =
        object_of("sphere { 0, 1 translate y * 0.5 clipped_by { plane { y, 0 } } rotate z * 180 }");
    // Before the turn: the sphere at y = 0.5 cut at y = 0 keeps -0.5..0;
    // turned about z, that is y = 0..0.5.
    CHECK(inside(o, {0.0, 0.25, 0.0}));
    CHECK_FALSE(inside(o, {0.0, -0.25, 0.0}));
    CHECK_FALSE(inside(o, {0.0, 0.75, 0.0}));
}

TEST_CASE("clipped_by and bounded_by refuse what POV-Ray refuses", "[language][clipped_by]") {
    CHECK(
        says("sphere { 0, 1 clipped_by { plane { y, 0 } } bounded_by { clipped_by } "
             "clipped_by { box { -1, 1 } } }",
             "after linking clipped_by and bounded_by"));
    CHECK(says("sphere { 0, 1 clipped_by { plane { y, 0 } } clipped_by { bounded_by } }",
               "cannot link bounded_by"));
    CHECK(says("sphere { 0, 1 clipped_by { clipped_by } }", "names itself"));
    CHECK(says("sphere { 0, 1 clipped_by { 3 } }", "expected '}' or an object"));
    CHECK(says("sphere { 0, 1 clipped_by { plane { y, 0 } }", "expected"));
}

TEST_CASE("a clip inside its own declaration nests no deeper than objects may",
          "[language][clipped_by]") {
    // Each turn clips the last object by a copy of itself: one level a turn.
    const std::string loop =
        "#declare O = sphere { 0, 1 }\n"
        "#for (i, 1, 20000) #declare O = sphere { 0, 1 clipped_by { object { O } } } #end\n"
        "object { O }\n";
    CHECK(says(loop, "nested more than"));
}
