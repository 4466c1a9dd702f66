// Branches whose condition depends on clock (language/time_branch.hpp): the
// interpreter reads each side on its own pieces of time. Objects made on a
// side live only then, switching between two neighbouring doubles where
// the condition's point value changes; variables set on the sides become
// piecewise in time; what cannot yet be piecewise is an error at its place.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/time/interval.hpp"
#include "scene_text.hpp"

using hexant::language::ParseOptions;
using hexant::runtime::SceneDescription;
using hexant::test::animation;
using hexant::test::error_of;

namespace rt = hexant::runtime;

namespace {

SceneDescription read(const std::string& text, ParseOptions options = animation()) {
    return hexant::language::parse_scene_text(text, "test.pov", options);
}

double before(double t) {
    return rt::interval_detail::next_down(t);
}

const rt::Sphere& sphere(const SceneDescription& scene, std::size_t i) {
    return std::get<rt::Sphere>(scene.objects.at(i)->shape);
}

}  // namespace

TEST_CASE("#if on clock: each side's objects live on its pieces, switching at the root",
          "[language][time]") {
    const auto scene = read(R"(
#if (clock * 10 > 3.1415)
  sphere { 0, 1 }
  #declare R = 0.3 + clock;
#else
  box { 0, 1 }
  #declare R = 0.2;
#end
sphere { y, R }
)");
    REQUIRE(scene.objects.size() == 3);
    REQUIRE(scene.time_splits.size() == 1);
    REQUIRE(scene.time_splits[0].instants.size() == 1);
    const double s = scene.time_splits[0].instants[0];
    CHECK(std::fabs(s - 0.31415) < 1e-15);
    // The switch sits between two neighbouring doubles.
    CHECK(s * 10 > 3.1415);
    CHECK_FALSE(before(s) * 10 > 3.1415);
    const rt::Lifetime& after = scene.objects[0]->lifetime;
    const rt::Lifetime& until = scene.objects[1]->lifetime;
    CHECK(after.contains(s));
    CHECK_FALSE(after.contains(before(s)));
    CHECK(until.contains(before(s)));
    CHECK_FALSE(until.contains(s));
    CHECK(until.contains(0.0));
    // (To the last instant a sample can have: the closing instant is not
    // in the animation, interpreter_state.hpp animation_time.)
    CHECK(after.contains(before(scene.animation.time_end())));
    CHECK_FALSE(after.contains(scene.animation.time_end()));
    // The object after the branch exists always, and its radius is each
    // side's own.
    CHECK(scene.objects[2]->lifetime.is_always());
    CHECK(sphere(scene, 2).radius(0.1) == 0.2);
    CHECK(sphere(scene, 2).radius(before(s)) == 0.2);
    CHECK(sphere(scene, 2).radius(0.5) == 0.3 + 0.5);
    CHECK(sphere(scene, 2).radius(s) == 0.3 + s);
}

TEST_CASE("#elseif chains split what the earlier conditions leave", "[language][time]") {
    const auto scene = read(R"(
#if (clock < 0.25)
  sphere { 0, 1 }
#elseif (clock < 0.5)
  sphere { 0, 2 }
#else
  sphere { 0, 3 }
#end
)");
    REQUIRE(scene.objects.size() == 3);
    for (const double t : {0.0, 0.1, before(0.25), 0.25, 0.3, before(0.5), 0.5, 0.9, 1.1}) {
        int alive = 0;
        for (const auto& object : scene.objects) alive += object->lifetime.contains(t);
        INFO("t = " << t);
        CHECK(alive == 1);  // exactly one at every instant
    }
    CHECK(scene.objects[0]->lifetime.contains(before(0.25)));
    CHECK(scene.objects[1]->lifetime.contains(0.25));
    CHECK(scene.objects[1]->lifetime.contains(before(0.5)));
    CHECK(scene.objects[2]->lifetime.contains(0.5));
}

TEST_CASE("a macro that picks its formula by time returns a piecewise value", "[language][time]") {
    // real-animation case 01: a bounce whose height is one formula going up and
    // another coming down.
    const auto scene = read(R"(
#macro Height(T)
  #if (T < 0.5)
    #local H = 4 * T;
  #else
    #local H = 4 * (1 - T);
  #end
  H
#end
sphere { <0, Height(clock), 0>, 0.5 }
)");
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.objects[0]->lifetime.is_always());
    const auto& centre = sphere(scene, 0).center;
    CHECK(centre(0.25).y == 1.0);
    CHECK(centre(0.75).y == 1.0);
    CHECK(centre(0.5).y == 2.0);
    CHECK(centre(before(0.5)).y == 4 * before(0.5));
}

TEST_CASE("nested clock-dependent #if, and #if inside a loop", "[language][time]") {
    const auto scene = read(R"(
#for (I, 0, 3)
  #if (clock > I / 8)
    #if (clock < I / 8 + 0.5)
      sphere { <I, 0, 0>, 0.4 }
    #end
  #end
#end
)");
    // Sphere I lives on (I/8, I/8 + 0.5): they appear one by one.
    REQUIRE(scene.objects.size() == 4);
    for (int i = 0; i < 4; ++i) {
        const double from = i / 8.0;
        INFO("sphere " << i);
        CHECK_FALSE(scene.objects[i]->lifetime.contains(from));
        CHECK(scene.objects[i]->lifetime.contains(rt::interval_detail::next_up(from)));
        CHECK(scene.objects[i]->lifetime.contains(before(from + 0.5)));
        CHECK_FALSE(scene.objects[i]->lifetime.contains(from + 0.5));
    }
}

TEST_CASE("a switch on a vector's length: vlength(C) != 0", "[language][time]") {
    // real-animation case 04: a direction that vanishes once.
    const auto scene = read(R"(
#declare C = <clock - 0.5, 0, 0>;
#if (vlength(C) != 0)
  sphere { 0, 1 }
#end
)");
    REQUIRE(scene.objects.size() == 1);
    const rt::Lifetime& l = scene.objects[0]->lifetime;
    CHECK(l.contains(0.5 - 2e-10));
    CHECK_FALSE(l.contains(0.5));
    CHECK(l.contains(0.5 + 2e-10));
    REQUIRE(scene.time_splits.size() == 1);
    CHECK(scene.time_splits[0].instants.size() == 2);
}

TEST_CASE("a static scene and one without clock in its conditions split nothing",
          "[language][time]") {
    const auto scene = read(R"(
#declare A = clock;
#if (1 > 0) sphere { <A, 0, 0>, 1 } #end
#if (clock_delta > 0) box { 0, 1 } #end
)");
    CHECK(scene.time_splits.empty());
    for (const auto& object : scene.objects) CHECK(object->lifetime.is_always());
}

TEST_CASE("what cannot yet be piecewise in time is an error at the branch", "[language][time]") {
    // A spline set differently on the two sides.
    const auto e = error_of(R"(
#if (clock > 0.5)
  #declare S = spline { linear_spline 0, <0, 0, 0>, 1, <1, 1, 1> }
#else
  #declare S = spline { linear_spline 0, <0, 0, 0>, 1, <2, 1, 1> }
#end
)",
                            animation());
    CHECK(e.formatted().find("test.pov:2:5") != std::string::npos);
    CHECK(e.formatted().find("piecewise") != std::string::npos);
    // The object's own interior or transform under a branch inside its
    // block: refused at the branch (its texture is made piecewise, below).
    const auto own =
        error_of("sphere { 0, 1 pigment { rgb 1 } #if (clock > 0.5) interior { ior 1.5 } #end }\n",
                 animation());
    CHECK(own.formatted().find("test.pov:1:37") != std::string::npos);
    const auto moved = error_of(
        "sphere { 0, 1 #if (clock > 0.5) pigment { rgb 1 } translate x #end }\n", animation());
    CHECK(moved.formatted().find("test.pov:1:19") != std::string::npos);
    // Branches that close the block around them: on both sides or neither,
    // and nothing after the '}' in the branch.
    const auto one_side = error_of(
        "union { sphere { 0, 1 }\n#if (clock > 0.5) } #else sphere { x, 1 } #end }\n", animation());
    CHECK(one_side.formatted().find("test.pov:2:5") != std::string::npos);
    const auto goes_on = error_of(
        "union { sphere { 0, 1 }\n#if (clock > 0.5) } sphere { x, 1 } #else } #end\n", animation());
    CHECK(goes_on.formatted().find("goes on after it") != std::string::npos);
    // A texture set differently on the two sides.
    const auto texture = error_of(
        "#if (clock > 0.5) #declare T = pigment { rgb 1 }; #else #declare T = pigment { rgb 0 }; "
        "#end\n",
        animation());
    CHECK(texture.formatted().find("test.pov:1:5") != std::string::npos);
    // A condition that flickers without end stops at the limit, at its place.
    const auto flicker =
        error_of("#if (sin(1 / (clock - 0.5)) > 0) sphere { 0, 1 } #end\n", animation());
    CHECK(flicker.formatted().find("test.pov:1:5") != std::string::npos);
}

TEST_CASE("frame_number switches exactly at each frame's clock", "[language][time]") {
    // real-animation case 06: a countdown whose tens digit goes once the count
    // is below 10 (a sphere stands in for the text).
    for (const int frames : {8, 10, 30}) {
        ParseOptions options = animation();
        options.animation.final_frame = frames;
        const auto scene = read(R"(
#declare Count = 12 - frame_number;
union {
  #if (Count > 9) sphere { 0, 1 } #end
  box { 0, 1 }
}
)",
                                options);
        INFO(frames << " frames");
        REQUIRE(scene.time_splits.size() == 1);
        REQUIRE(scene.time_splits[0].instants.size() == 1);
        // Frames 1 and 2 have Count > 9: the tens go at frame 3's clock.
        CHECK(scene.time_splits[0].instants[0] == scene.animation.clock_of_frame(3));
        const auto& members = std::get<rt::Csg>(scene.objects.at(0)->shape).children;
        REQUIRE(members.size() == 2);
        CHECK(members[0]->lifetime.contains(before(scene.animation.clock_of_frame(3))));
        CHECK_FALSE(members[0]->lifetime.contains(scene.animation.clock_of_frame(3)));
        CHECK(members[1]->lifetime.is_always());
        // And frame_number is each frame's own at its clock and just before
        // the next one.
        const auto frame = read("#declare F = frame_number; sphere { 0, F }", options);
        for (int k = 1; k <= frames; ++k) {
            const double t = frame.animation.clock_of_frame(k);
            CHECK(sphere(frame, 0).radius(t) == k);
            if (k < frames)
                CHECK(sphere(frame, 0).radius(before(frame.animation.clock_of_frame(k + 1))) == k);
        }
    }
}

TEST_CASE("an #if in a macro that gives a value gives a piecewise value", "[language][time]") {
    // real-animation case 01: the macro's body is the #if; each side leaves
    // one value.
    const auto scene = read(R"(
#macro Hop(T)
  #if (T < 0.5)
    (cos(pi*T))
  #else
    (-cos(pi*T))
  #end
#end
sphere { <0, Hop(clock), 0>, 0.2 }
)");
    const auto& centre = sphere(scene, 0).center;
    CHECK(centre(0.0).y == 1.0);
    CHECK(centre(0.25).y == std::cos(M_PI * 0.25));
    CHECK(centre(0.75).y == -std::cos(M_PI * 0.75));
    CHECK(centre(1.0).y == -std::cos(M_PI));
}

TEST_CASE("#while on clock: objects that appear one by one", "[language][time]") {
    const auto scene = read(R"(
#declare I = 0;
#while (I < clock * 8)
  sphere { <I, 0, 0>, 0.4 }
  #declare I = I + 1;
#end
sphere { <0, 5, 0>, I }
)");
    // Sphere I exists once 8 clock > I: after I / 8 (to 8/7, the end of
    // the last frame's shutter: I up to 9).
    REQUIRE(scene.objects.size() == 11);
    for (int i = 0; i < 10; ++i) {
        INFO("sphere " << i);
        const double from = i / 8.0;
        CHECK_FALSE(scene.objects[i]->lifetime.contains(from));
        CHECK(scene.objects[i]->lifetime.contains(rt::interval_detail::next_up(from)));
        CHECK(scene.objects[i]->lifetime.contains(before(scene.animation.time_end())));
    }
    // The count after the loop is piecewise too: ceil(8 clock).
    for (const double t : {0.0, 0.1, 0.3, 0.5, 0.99})
        CHECK(sphere(scene, 10).radius(t) == std::ceil(8 * t));
}

TEST_CASE("#switch on clock: #range, #case and #else each on their pieces", "[language][time]") {
    const auto scene = read(R"(
#switch (clock)
  #range (0, 0.25) sphere { 0, 1 } #break
  #case (0.5) box { 0, 1 } #break
  #else cylinder { 0, y, 1 }
#end
)");
    REQUIRE(scene.objects.size() == 3);
    const auto alive = [&](double t) {
        std::string which;
        for (const auto& object : scene.objects)
            if (object->lifetime.contains(t)) which += rt::shape_name(object->shape);
        return which;
    };
    CHECK(alive(0.0) == "sphere");
    CHECK(alive(0.25) == "sphere");
    CHECK(alive(rt::interval_detail::next_up(0.25)) == "cylinder");
    CHECK(alive(0.5) == "box");
    CHECK(alive(0.5 + 2e-10) == "cylinder");
    CHECK(alive(1.0) == "cylinder");
}

TEST_CASE("vnormalize of a zero vector gives <0, 0, 0> with a warning, known or on clock",
          "[language][time]") {
    // real-animation case 03: POV-Ray warns and gives <0, 0, 0>; hexant stopped
    // on a known zero and made a silent NaN of one on clock. (#version 3.7:
    // without it the legacy gamma rule's warning comes too.)
    const auto still = read("#version 3.7;\nsphere { vnormalize(<0, 0, 0>), 1 }\n");
    CHECK(sphere(still, 0).center(0.0) == glm::dvec3(0.0));
    REQUIRE(still.warnings.size() == 1);
    CHECK(still.warnings[0].find("zero-length") != std::string::npos);

    const auto moving = read("#version 3.7;\nsphere { vnormalize(<clock - 0.5, 0, 0>), 1 }\n");
    const auto& centre = sphere(moving, 0).center;
    CHECK(centre(0.25) == glm::dvec3(-1.0, 0.0, 0.0));
    CHECK(centre(0.75) == glm::dvec3(1.0, 0.0, 0.0));
    CHECK(centre(0.5) == glm::dvec3(0.0));  // not NaN
    REQUIRE(moving.warnings.size() == 1);
    CHECK(moving.warnings[0].find("at clock 0.5") != std::string::npos);
    // Never zero: no warning.
    CHECK(read("#version 3.7;\nsphere { vnormalize(<clock + 1, 0, 0>), 1 }\n").warnings.empty());
}

TEST_CASE("a camera and a background chosen by branches on clock", "[language][time]") {
    const auto scene = read(R"(
camera { location <0, 0, -9> look_at 0 }
#if (clock < 0.5)
  camera { location <0, 0, -5> look_at 0 }
#elseif (clock < 0.75)
  camera { location <0, 0, 5> look_at 0 }
#end
#if (clock > 0.5) background { rgb 1 } #end
)");
    CHECK(scene.camera.depends_on_time());
    CHECK(scene.camera.evaluate(0.25).location == glm::dvec3(0, 0, -5));
    CHECK(scene.camera.evaluate(before(0.5)).location == glm::dvec3(0, 0, -5));
    CHECK(scene.camera.evaluate(0.5).location == glm::dvec3(0, 0, 5));
    CHECK(scene.camera.evaluate(0.75).location == glm::dvec3(0, 0, -9));  // the first camera again
    CHECK(scene.background(0.25)[0] == 0.0);
    CHECK(scene.background(0.5)[0] == 0.0);
    CHECK(scene.background(0.75)[0] == 1.0);
}

TEST_CASE("#for to a clock-dependent end, in a macro, with an #if on clock inside",
          "[language][time]") {
    const auto scene = read(R"(
#macro Row(N)
  #for (I, 1, N)
    #if (clock < 0.75)
      sphere { <I, 0, 0>, 0.3 }
    #end
  #end
#end
Row(clock * 4)
)");
    // Sphere I lives while I <= 4 clock (within POV-Ray's epsilon, 1e-10)
    // and clock < 0.75: from I/4 to 0.75; spheres 1 and 2, and 3 for the
    // 2.5e-11 before 0.75 where 3 <= 4 clock + 1e-10.
    REQUIRE(scene.objects.size() == 3);
    const rt::Lifetime& third = scene.objects[2]->lifetime;
    CHECK(third.contains(before(0.75)));
    CHECK(third.contains(0.75 - 2e-11));
    CHECK_FALSE(third.contains(0.75 - 3e-11));
    for (int i = 1; i <= 2; ++i) {
        INFO("sphere " << i);
        const rt::Lifetime& l = scene.objects[i - 1]->lifetime;
        CHECK(l.contains(i / 4.0));
        CHECK_FALSE(l.contains(i / 4.0 - 1e-9));
        CHECK(l.contains(before(0.75)));
        CHECK_FALSE(l.contains(0.75));
    }
}

TEST_CASE("an array read at an index on clock gives each piece's element", "[language][time]") {
    const auto scene = read(R"(
#declare Sizes = array[4] { 0.1, 0.2, 0.3, 0.4 }
sphere { 0, Sizes[min(clock * 4, 3)] }
#declare Shapes = array[2] { sphere { 0, 1 }, box { 0, 1 } }
object { Shapes[min(clock * 2, 1)] }
)");
    REQUIRE(scene.objects.size() == 2);
    CHECK(sphere(scene, 0).radius(0.1) == 0.1);
    CHECK(sphere(scene, 0).radius(before(0.25)) == 0.1);
    CHECK(sphere(scene, 0).radius(0.25) == 0.2);
    CHECK(sphere(scene, 0).radius(0.6) == 0.3);
    CHECK(sphere(scene, 0).radius(1.1) == 0.4);
    // The objects: each living on its pieces.
    const auto& both = std::get<rt::Csg>(scene.objects[1]->shape).children;
    REQUIRE(both.size() == 2);
    const auto alive = [&](double t) {
        std::string which;
        for (const auto& o : both)
            if (o->lifetime.contains(t)) which += rt::shape_name(o->shape);
        return which;
    };
    CHECK(alive(0.2) == "sphere");
    CHECK(alive(before(0.5)) == "sphere");
    CHECK(alive(0.5) == "box");
    // Out of range at some clock: an error at its place.
    const auto e =
        error_of("#declare A = array[2] { 1, 2 }\nsphere { 0, A[clock * 4] }\n", animation());
    CHECK(e.formatted().find("test.pov:2:") != std::string::npos);
}

TEST_CASE("a name declared on one side only is declared only on its pieces", "[language][time]") {
    // Used where it is not declared: the error POV-Ray gives at that clock,
    // naming it.
    const auto e =
        error_of("#if (clock > 0.5) #declare V = <1, 2, 3>; #end\nsphere { V, 1 }\n", animation());
    CHECK(e.formatted().find("test.pov:2:10") != std::string::npos);
    CHECK(e.formatted().find("not declared at clock 0") != std::string::npos);
    // Used only where it is: fine.
    hexant::test::reads(
        "#if (clock > 0.5) #declare V = 2; #end\n#if (clock > 0.6) sphere { 0, V } #end\n",
        animation());
    // #ifdef, #ifndef and defined() split on where it is declared; #undef on
    // one side undeclares it there only.
    const auto scene = read(R"(
#declare V = 1;
#if (clock > 0.5) #undef V #end
#ifdef (V) sphere { 0, V } #end
#ifndef (V) box { -1, 1 } #end
#if (defined(V)) cylinder { 0, y, 1 } #end
#ifndef (V) #declare V = 7; #end
sphere { 0, V }
)");
    REQUIRE(scene.objects.size() == 4);
    CHECK(scene.objects[0]->lifetime.contains(0.5));
    CHECK_FALSE(scene.objects[0]->lifetime.contains(0.6));
    CHECK_FALSE(scene.objects[1]->lifetime.contains(0.5));
    CHECK(scene.objects[1]->lifetime.contains(0.6));
    CHECK(scene.objects[2]->lifetime == scene.objects[0]->lifetime);
    // Declared again where it was not: 1 before, 7 after.
    CHECK(scene.objects[3]->lifetime.is_always());
    CHECK(sphere(scene, 3).radius(0.5) == 1.0);
    CHECK(sphere(scene, 3).radius(0.6) == 7.0);
}

TEST_CASE("an #if on clock inside a #while on clock inside a macro", "[language][time]") {
    // Posts that rise one by one (the #while on clock), each lit red once
    // it is past its own instant (the #if on clock), made by a macro.
    const auto scene = read(R"(
#macro Posts(Rate)
  #local I = 0;
  #while (I < clock * Rate)
    #if (sin(2 * pi * clock) > 0.5)
      sphere { <I, 1, 0>, 0.2 }
    #else
      box { <I, 0, 0>, <I + 0.5, 0.5, 0.5> }
    #end
    #local I = I + 1;
  #end
#end
Posts(4)
)");
    // Post I appears once 4 clock > I; each is a sphere while sin(2 pi clock)
    // > 0.5 (1/12 to 5/12) and a box otherwise.
    const double a = 1.0 / 12.0, b = 5.0 / 12.0;
    for (const auto& object : scene.objects) {
        const std::string kind = rt::shape_name(object->shape);
        const auto& pieces = object->lifetime.pieces();
        REQUIRE_FALSE(pieces.empty());
        for (const auto& piece : pieces) {
            const double mid = piece.mid();
            INFO(kind << " on [" << piece.lo << ", " << piece.hi << "]");
            CHECK((std::sin(2 * M_PI * mid) > 0.5) == (kind == "sphere"));
        }
    }
    // The sphere of post 0 starts exactly where sin(2 pi clock) > 0.5 does.
    bool found = false;
    for (const auto& object : scene.objects)
        if (std::string(rt::shape_name(object->shape)) == "sphere" &&
            object->lifetime.contains(0.2)) {
            const double start = object->lifetime.pieces().front().lo;
            CHECK(std::fabs(start - a) < 1e-15);
            CHECK(std::sin(2 * M_PI * start) > 0.5);
            CHECK_FALSE(std::sin(2 * M_PI * before(start)) > 0.5);
            CHECK(std::fabs(object->lifetime.pieces().front().hi - b) < 1e-15);
            found = true;
            break;
        }
    CHECK(found);
}

TEST_CASE("an object's texture under a branch on clock switches with it", "[language][time]") {
    // A real animation's pawn (../shared/cases/2026-12-03/07): pigment and
    // finish chosen by `#if (clock >= 0.05)` inside the sphere's block, and
    // a branch on each side of which a texture is given to the union and
    // the union closed. The texture becomes a texture_map over a pattern of
    // time alone, exactly 0 or 1, so that its entries never blend.
    const auto scene = read(R"(
sphere { 0, 1 pigment { rgb 1 }
  #if (clock > 0.5) pigment { rgb <1, 0, 0> } finish { phong 1 } #end }
union { sphere { 0, 1 } sphere { x, 1 }
#if (clock > 0.25)
  cone { 0, 1, y, 0 } texture { pigment { rgb 0.5 } } }
#else
  cone { 0, 1, 2 * y, 0 } texture { pigment { rgb 0.2 } } }
#end
)");
    REQUIRE(scene.objects.size() == 2);
    const auto check_switch = [](const rt::Texture& t, double at) {
        REQUIRE(t.is_patterned());
        REQUIRE(t.texture_map.size() == 2);
        REQUIRE(t.patterned->function);
        const rt::SpaceFunction& f = *t.patterned->function;
        CHECK(f.at({0.3, -2.0, 5.0}, at) == 1.0);
        CHECK(f.at({0.0, 0.0, 0.0}, before(at)) == 0.0);
        CHECK(f.at({0.0, 0.0, 0.0}, 0.0) == 0.0);
        CHECK(f.at({0.0, 0.0, 0.0}, 1.0) == 1.0);
    };
    // (The first switch is after 0.5: clock > 0.5 holds from next_up(0.5).)
    check_switch(*scene.objects[0]->texture, std::nextafter(0.5, 1.0));
    const auto& when_true = *scene.objects[0]->texture->texture_map[1].texture;
    CHECK(when_true.finish->phong.constant() == 1.0);
    CHECK(scene.objects[0]->texture->texture_map[0].texture->finish->phong.constant() == 0.0);
    // The union: both cones (each living on its side) and the switching texture.
    const auto& csg = std::get<rt::Csg>(scene.objects[1]->shape);
    CHECK(csg.children.size() == 4);
    check_switch(*scene.objects[1]->texture, std::nextafter(0.25, 1.0));
}
