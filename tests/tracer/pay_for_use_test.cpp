// A scene pays only for what it uses, shown by the counters `--stats`
// prints (counts, never times): a static scene builds no time splits and the
// same hierarchy as in 3D; without deformations nothing is ever mapped
// through one; without reflection or refraction only shadow rays follow the
// primary ones; declarations a scene never uses are never built.
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "tracer/renderer.hpp"

namespace tr = hexant::tracer;

namespace {

hexant::runtime::SceneDescription parse(const std::string& text, int frames = 2) {
    hexant::language::ParseOptions options;
    options.animation.width = 32;
    options.animation.height = 24;
    options.animation.initial_frame = 1;
    options.animation.final_frame = frames;
    // (Each frame a whole clock step, the last not cut to Final_Clock: the
    // frames' shutters then tile the span the spacetime hierarchy covers,
    // so that its root is the frames' roots over the whole span.)
    options.animation.shutter_beyond_range = true;
    return hexant::language::parse_scene_text(text, "pay-for-use.pov", options);
}

// The counters of rendering every frame of the scene in one mode.
tr::Counters counters_of(const hexant::runtime::SceneDescription& scene, tr::Mode mode,
                         tr::BuildKind build = tr::BuildKind::Lazy,
                         tr::Criterion criterion = tr::Criterion::Cost) {
    tr::RenderSettings settings;
    settings.mode = mode;
    settings.build.build = build;
    settings.build.criterion = criterion;
    settings.samples_per_pixel = 2;
    tr::Renderer renderer(scene, settings);
    for (int k = scene.animation.initial_frame; k <= scene.animation.final_frame; ++k)
        renderer.render_frame(k);
    return renderer.counters();
}

const std::string kCamera =
    "camera { location <0, 2, -9> look_at <0, 0.5, 0> }\n"
    "light_source { <-4, 8, -6>, rgb 1 }\n";

// Enough objects that the hierarchy has several levels.
const std::string kStaticObjects = R"(
#declare I = 0;
#while (I < 12)
  sphere { <mod(I, 4) * 1.5 - 2.25, 0.5 + div(I, 4), mod(I, 3)>, 0.45 pigment { rgb 0.8 } }
  #declare I = I + 1;
#end
box { <-4, -0.2, -2>, <4, 0, 3> pigment { rgb 0.5 } }
)";

}  // namespace

TEST_CASE("a static scene builds no time splits and the same hierarchy as in 3D", "[tracer][pay]") {
    const auto scene = parse(kCamera + kStaticObjects, 2);
    // Built whole, so that the cells are counted alike, by the paper's rule,
    // which cuts thirteen objects into cells whatever the rays (the cost
    // criterion prices a hierarchy over two frames against twice a frame's
    // rays, and rightly builds it otherwise).
    const tr::Counters spacetime =
        counters_of(scene, tr::Mode::Spacetime, tr::BuildKind::Eager, tr::Criterion::Paper);
    // The same builder in 3D, once per frame.
    const tr::Counters frames =
        counters_of(scene, tr::Mode::Frames, tr::BuildKind::Eager, tr::Criterion::Paper);
    CHECK(spacetime.time_splits == 0);
    CHECK(frames.time_splits == 0);
    // The same hierarchy, built once instead of once per frame: nothing
    // moves, so no time is split, and every bound is the same box.
    CHECK(spacetime.cells > 1);
    CHECK(frames.cells == 2 * spacetime.cells);
    // So rays meet exactly the same bounds and objects.
    CHECK(spacetime.node_tests == frames.node_tests);
    CHECK(spacetime.bound_tests == frames.bound_tests);
    CHECK(spacetime.object_tests == frames.object_tests);
    // Something moving does split time.
    const auto moving =
        parse(kCamera + kStaticObjects + "sphere { <2 * clock, 2, -1>, 0.3 pigment { rgb 1 } }\n");
    CHECK(counters_of(moving, tr::Mode::Spacetime).time_splits > 0);
}

TEST_CASE("only a scene with deformations maps points through them", "[tracer][pay]") {
    const auto plain = parse(kCamera + kStaticObjects +
                             "box { <-0.5, 0, -0.5>, <0.5, 2, 0.5> rotate y * 90 * clock }\n");
    const tr::Counters c = counters_of(plain, tr::Mode::Spacetime);
    CHECK(c.deformation_maps == 0);
    CHECK(c.object_tests > 0);
    const auto twisted = parse(kCamera + kStaticObjects +
                               "box { <-0.5, 0, -0.5>, <0.5, 2, 0.5> twist y, 90 * clock }\n");
    CHECK(counters_of(twisted, tr::Mode::Spacetime).deformation_maps > 0);
}

TEST_CASE("without mirrors or glass only shadow rays follow the primary rays", "[tracer][pay]") {
    const tr::Counters c = counters_of(parse(kCamera + kStaticObjects, 1), tr::Mode::Spacetime);
    CHECK(c.primary_rays == 32u * 24u * 2u);
    CHECK(c.shadow_rays > 0);
    CHECK(c.reflected_rays == 0);
    CHECK(c.refracted_rays == 0);
    const tr::Counters mirror = counters_of(
        parse(
            kCamera + kStaticObjects +
                "sphere { <0, 1, -2>, 0.8 pigment { rgb 0.2 } finish { reflection 0.5 } }\n"
                "sphere { <2, 1, -2>, 0.6 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.5 } }\n",
            1),
        tr::Mode::Spacetime);
    CHECK(mirror.reflected_rays > 0);
    CHECK(mirror.refracted_rays > 0);
}

TEST_CASE(
    "only transparent objects filter shadow rays, and only finite light runs rays through time",
    "[tracer][pay]") {
    // A scene of opaque objects under instant light: its shadow rays ask
    // only whether something blocks them, and every ray is at one instant.
    const tr::Counters c = counters_of(parse(kCamera + kStaticObjects, 1), tr::Mode::Spacetime);
    CHECK(c.shadow_rays > 0);
    CHECK(c.filtered_surfaces == 0);
    CHECK(c.travelling_rays == 0);
    const auto glass = parse(kCamera + kStaticObjects +
                                 "sphere { <2, 1, -2>, 0.6 pigment { rgbf <1, 0.5, 0.5, 0.9> } }\n",
                             1);
    CHECK(counters_of(glass, tr::Mode::Spacetime).filtered_surfaces > 0);
    CHECK(counters_of(glass, tr::Mode::Spacetime).travelling_rays == 0);
}

TEST_CASE("declarations a scene never uses are never built", "[tracer][pay]") {
    const std::string declarations = R"(
#declare Unused_Sphere = sphere { 0, 1 }
#declare Unused_Union = union { #declare J = 0; #while (J < 50) sphere { <J, 0, 0>, 0.5 } #declare J = J + 1; #end }
#declare Unused_Function = function(x) { x * x }
#macro Unused_Macro(N) #declare K = 0; #while (K < N) box { 0, 1 } #declare K = K + 1; #end #end
#declare Used = sphere { <0, 1, 0>, 0.5 pigment { rgb 1 } }
)";
    const auto scene = parse(kCamera + declarations + "object { Used }\nplane { y, 0 }\n", 1);
    const tr::Counters c = counters_of(scene, tr::Mode::Spacetime);
    CHECK(c.objects == 2);
}

TEST_CASE("branches that do not split time cost nothing", "[tracer][pay]") {
    // A branch on a constant, and one on clock that holds all the time: the
    // same objects, none with a lifetime, so the same hierarchy and tests
    // as the scene written without them (a split's pieces cost only where
    // an object lives part of the time: tests/tracer/lifetime_render_test).
    const tr::Counters plain = counters_of(parse(kCamera + kStaticObjects), tr::Mode::Spacetime);
    const tr::Counters constant = counters_of(
        parse(kCamera + "#if (1 > 0)\n" + kStaticObjects + "#end\n"), tr::Mode::Spacetime);
    const tr::Counters always = counters_of(
        parse(kCamera + "#if (clock > -1)\n" + kStaticObjects + "#end\n"), tr::Mode::Spacetime);
    for (const tr::Counters* c : {&constant, &always}) {
        CHECK(c->time_splits == plain.time_splits);
        CHECK(c->cells == plain.cells);
        CHECK(c->node_tests == plain.node_tests);
        CHECK(c->bound_tests == plain.bound_tests);
        CHECK(c->object_tests == plain.object_tests);
    }
    // A branch that does split: its objects live part of the time.
    const auto split = parse(kCamera + "#if (clock > 0.5)\n" + kStaticObjects + "#end\n");
    for (const auto& object : split.objects) CHECK_FALSE(object->lifetime.is_always());
}

// A shadow ray leaving a flat surface toward a light on its own side, or a
// convex solid toward a light outside it, cannot meet that surface again:
// it is not tested (runtime::IntelligentObject::flat, convex). With the
// ground the only object and every camera ray on it, each camera ray makes
// the one test of the ground and its shadow ray none: a plane (kept
// outside the hierarchy), a polygon, a triangle, a disc, a turning plane,
// a sphere and a box (inside it), in every mode. Before, each shadow ray
// tested the ground again: twice the tests. A torus is neither, so its
// shadow rays still test it.
TEST_CASE("a shadow ray does not test the flat or convex surface it leaves", "[tracer][pay]") {
    const std::string camera =
        "camera { location <0, 6, -0.5> look_at 0 angle 30 }\n"
        "light_source { <-3, 9, -2>, rgb 1 }\n";
    for (const char* ground :
         {"plane { y, 0 pigment { rgb 1 } }",
          "polygon { 5, <-20, 0, -20>, <20, 0, -20>, <20, 0, 20>, <-20, 0, 20>, <-20, 0, -20> "
          "pigment { rgb 1 } }",
          "triangle { <-40, 0, -40>, <40, 0, -40>, <0, 0, 60> pigment { rgb 1 } }",
          "disc { 0, y, 40 pigment { rgb 1 } }",
          "plane { y, 0 pigment { rgb 1 } rotate <0, 0, 10 * clock> }",
          "sphere { <0, -100, 0>, 100 pigment { rgb 1 } }",
          "box { <-20, -5, -20>, <20, 0, 20> pigment { rgb 1 } rotate <0, 30 * clock, 0> }"}) {
        const auto scene = parse(camera + ground + "\n");
        for (const tr::Mode mode : {tr::Mode::Spacetime, tr::Mode::Frames, tr::Mode::Brute}) {
            INFO(ground << ", mode " << int(mode));
            const tr::Counters c = counters_of(scene, mode);
            REQUIRE(c.shadow_rays == c.primary_rays);
            CHECK(c.object_tests == c.primary_rays);
        }
    }
    // A torus as the ground (the top of its tube under the camera): its
    // shadow rays test it.
    const auto round =
        parse(camera + "torus { 100, 50 translate <100, -50, 0> pigment { rgb 1 } }\n");
    const tr::Counters c = counters_of(round, tr::Mode::Spacetime);
    REQUIRE(c.shadow_rays == c.primary_rays);
    CHECK(c.object_tests == c.primary_rays + c.shadow_rays);
}
