// Object records: the shape's name, and what about an object depends on time.
#include "runtime/objects/object.hpp"

#include <memory>

#include <catch2/catch.hpp>

namespace rt = hexant::runtime;

namespace {

rt::TimeFunction symbolic_clock() {
    return rt::TimeFunction::clock();
}

rt::Vector3Function vec(rt::TimeFunction x, rt::TimeFunction y, rt::TimeFunction z) {
    return rt::Vector3Function{{x, y, z}};
}

std::shared_ptr<rt::ObjectRecord> object(rt::Shape shape) {
    auto o = std::make_shared<rt::ObjectRecord>();
    o->shape = std::move(shape);
    return o;
}

}  // namespace

TEST_CASE("shape names are POV-Ray's keywords, a CSG is named by its kind", "[runtime][object]") {
    CHECK(std::string(rt::shape_name(rt::Sphere{})) == "sphere");
    CHECK(std::string(rt::shape_name(rt::SmoothTriangle{})) == "smooth_triangle");
    CHECK(std::string(rt::shape_name(rt::Prism{})) == "prism");
    CHECK(std::string(rt::shape_name(rt::Csg{rt::Csg::Kind::Union, {}})) == "union");
    CHECK(std::string(rt::shape_name(rt::Csg{rt::Csg::Kind::Merge, {}})) == "merge");
    CHECK(std::string(rt::shape_name(rt::Csg{rt::Csg::Kind::Intersection, {}})) == "intersection");
    CHECK(std::string(rt::shape_name(rt::Csg{rt::Csg::Kind::Difference, {}})) == "difference");
}

TEST_CASE("a static object depends on nothing", "[runtime][object]") {
    auto sphere = object(rt::Sphere{vec(1.0, 2.0, 3.0), 1.0});
    sphere->texture = rt::Texture{};
    sphere->interior = rt::Interior{};
    CHECK_FALSE(sphere->depends_on_time());
    CHECK(sphere->timed_parameters().empty());
    CHECK_FALSE(sphere->texture_depends_on_time());
}

TEST_CASE("each part of an object that may depend on time", "[runtime][object]") {
    SECTION("shape parameters, by name") {
        auto cone = object(rt::Cone{vec(0.0, symbolic_clock(), 0.0), 1.0, vec(0.0, 1.0, 0.0),
                                    symbolic_clock() * 2.0, false});
        CHECK(cone->depends_on_time());
        CHECK(cone->shape_depends_on_time());
        CHECK(cone->timed_parameters() == std::vector<std::string>{"base", "cap_radius"});
    }
    SECTION("the transform") {
        auto box = object(rt::Box{vec(0.0, 0.0, 0.0), vec(1.0, 1.0, 1.0)});
        rt::TransformStep rotate{};
        rotate.kind = rt::TransformKind::Rotate;
        rotate.vector = vec(0.0, symbolic_clock() * 360.0, 0.0);
        box->transform.append(rotate);
        CHECK(box->depends_on_time());
        CHECK_FALSE(box->shape_depends_on_time());
    }
    SECTION("a pigment colour, a finish, a pattern's transform") {
        auto plane = object(rt::Plane{vec(0.0, 1.0, 0.0), 0.0});
        rt::Texture texture;
        texture.pigment.colours[0].c[3] = symbolic_clock();
        plane->texture = texture;
        CHECK(plane->texture_depends_on_time());
        CHECK(plane->depends_on_time());
        texture = rt::Texture{};
        texture.finish.edit().reflection.c[1] = symbolic_clock();
        plane->texture = texture;
        CHECK(plane->depends_on_time());
        // (A pattern's transform: a plain colour does not read its own.)
        texture = rt::Texture{};
        texture.pigment.pattern = rt::Pigment::Pattern::Patterned;
        texture.pigment.patterned = rt::pattern::Pattern::of(*rt::pattern::find_kind("checker"));
        plane->texture = texture;
        CHECK_FALSE(plane->depends_on_time());
        rt::TransformStep scale{};
        scale.kind = rt::TransformKind::Scale;
        scale.vector = vec(symbolic_clock() + 1.0, 1.0, 1.0);
        texture.pigment.transform.append(scale);
        plane->texture = texture;
        CHECK(plane->depends_on_time());
    }
    SECTION("the index of refraction") {
        auto torus = object(rt::Torus{2.0, 0.5});
        rt::Interior interior;
        interior.ior = symbolic_clock() + 1.0;
        torus->interior = interior;
        CHECK(torus->depends_on_time());
        CHECK(torus->timed_parameters().empty());
    }
    SECTION("a CSG's children") {
        auto moving = object(rt::Sphere{vec(0.0, 0.0, 0.0), symbolic_clock() + 1.0});
        auto still = object(rt::Sphere{vec(0.0, 0.0, 0.0), 1.0});
        auto inner = object(rt::Csg{rt::Csg::Kind::Merge, {still, moving}});
        auto outer = object(rt::Csg{rt::Csg::Kind::Union, {still, inner}});
        CHECK(outer->depends_on_time());
        CHECK(outer->timed_parameters() == std::vector<std::string>{"children"});
        auto quiet = object(rt::Csg{rt::Csg::Kind::Union, {still, still}});
        CHECK_FALSE(quiet->depends_on_time());
    }
}
