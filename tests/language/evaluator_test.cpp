// The interpreter as a whole: directives as they run, scoping, include
// search, the chain of places in errors, the records each scene item makes,
// and clock as a symbol.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "scene_text.hpp"

namespace fs = std::filesystem;
using hexant::language::ParseOptions;
using hexant::language::SceneError;
using hexant::runtime::SceneDescription;
using hexant::test::error_of;

namespace {

struct Run {
    SceneDescription scene;
    std::string debug;
};

Run run(const std::string& text, ParseOptions options = {}) {
    std::ostringstream messages;
    options.messages = &messages;
    Run r{hexant::language::parse_scene_text(text, "test.pov", options), {}};
    r.debug = messages.str();
    return r;
}

std::string debug(const std::string& text, ParseOptions options = {}) {
    return run(text, options).debug;
}

ParseOptions animation() {
    ParseOptions options;
    options.animation.final_frame = 10;
    return options;
}

template <typename Shape>
const Shape& shape(const SceneDescription& scene, std::size_t i) {
    REQUIRE(i < scene.objects.size());
    const Shape* s = std::get_if<Shape>(&scene.objects[i]->shape);
    REQUIRE(s != nullptr);
    return *s;
}

}  // namespace

TEST_CASE("directives run as the scene is read", "[evaluator]") {
    CHECK(debug("#declare I = 0; #while (I < 3) #debug str(I, 0, 0) #declare I = I + 1; #end") ==
          "012");
    CHECK(debug("#for (I, 5, 1, -2) #debug str(I, 0, 0) #end #debug str(I, 0, 0)") == "531-1");
    CHECK(debug("#for (I, 1, 0) #debug \"never\" #end #debug \"after\"") == "after");
    CHECK(debug("#if (0) #debug \"a\" #elseif (1) #debug \"b\" #else #debug \"c\" #end") == "b");
    CHECK(debug("#if (0) #if (1) #debug \"x\" #else #debug \"y\" #end #else #debug \"z\" #end") ==
          "z");
    CHECK(debug("#declare A = 1; #ifdef (A) #debug \"d\" #end #ifndef (B) #debug \"n\" #end") ==
          "dn");
    CHECK(
        debug("#declare A = 1; #undef A #ifdef (A) #debug \"still\" #else #debug \"gone\" #end") ==
        "gone");
    // #switch: the first matching clause runs to #break; without #break it falls through.
    const std::string s =
        "#switch (V) #case (1) #debug \"one\" #case (2) #debug \"two\" #break "
        "#range (3, 5) #debug \"few\" #break #else #debug \"many\" #end";
    CHECK(debug("#declare V = 1; " + s) == "onetwo");
    CHECK(debug("#declare V = 2; " + s) == "two");
    CHECK(debug("#declare V = 4; " + s) == "few");
    CHECK(debug("#declare V = 9; " + s) == "many");
}

// POV-Ray reads directives anywhere; among a shape's parameters a
// conditional directive whose branch starts with a value supplies
// parameters, while one whose branch starts with a modifier (or a macro
// call) is read among the modifiers as before.
TEST_CASE("conditional directives among a shape's parameters", "[evaluator]") {
    const auto r =
        run("#declare Flip = 1; #declare A = 0; #declare Corner = <0, 2, 0>;\n"
            "#macro Move() translate z #end\n"
            "smooth_triangle {\n"
            "  #if (Flip) <0,0,0>, -y, <1,0,0>, -y, <0,1,0>, -y\n"
            "  #else <0,0,0>, y, <1,0,0>, y, <0,1,0>, y #end\n"
            "}\n"
            "sphere { #ifndef (Undefined) Corner #end, #if (A) 3 #else 0.5 #end\n"
            "  #if (1) translate x #end #if (1) Move() #end }\n"
            "cylinder { 0, #if (A) x #else vrotate(y, 90 * z) #end, 1 }\n");
    REQUIRE(r.scene.objects.size() == 3);
    const auto& triangle = shape<hexant::runtime::SmoothTriangle>(r.scene, 0);
    CHECK(triangle.normals[0](0.0).y == -1.0);
    CHECK(triangle.points[2](0.0).y == 1.0);
    const auto& sphere = shape<hexant::runtime::Sphere>(r.scene, 1);
    CHECK(sphere.center(0.0).y == 2.0);
    CHECK(sphere.radius(0.0) == 0.5);
    const glm::dmat4 m = r.scene.objects[1]->transform.matrix_at(0.0);
    CHECK(m[3][0] == 1.0);  // translate x, then the macro's translate z
    CHECK(m[3][2] == 1.0);
    const auto& cylinder = shape<hexant::runtime::Cylinder>(r.scene, 2);
    CHECK(cylinder.cap(0.0).x == Approx(-1.0));
}

TEST_CASE("macros: values, objects, modifiers, locals and references", "[evaluator]") {
    CHECK(debug("#macro Sq(X) (X * X) #end #debug str(Sq(3) + 1, 0, 0)") == "10");
    CHECK(debug("#macro Pick(A, B) #if (A > B) A #else B #end #end #debug str(Pick(2, 7), 0, 0)") ==
          "7");
    CHECK(debug("#macro F() #local T = 4; T #end #declare T = 1; #debug str(F() + T, 0, 0)") ==
          "5");
    CHECK(debug("#macro Bump(V) #declare V = V + 1; #end #declare N = 1; Bump(N) #debug str(N, 0, "
                "0)") == "2");
    const auto r =
        run("#macro Move() translate <1, 2, 3> #end\n"
            "#macro Ball(R) sphere { 0, R Move() } #end\n"
            "Ball(2)\n#declare B = Ball(3);\nobject { B }\n");
    REQUIRE(r.scene.objects.size() == 2);
    CHECK(shape<hexant::runtime::Sphere>(r.scene, 0).radius.constant() == 2.0);
    const auto m = r.scene.objects[1]->transform.matrix_at(0.0);
    CHECK(m[3][0] == 1.0);
    CHECK(m[3][2] == 3.0);
}

TEST_CASE("runaway loops and recursion stop at the stated limits", "[evaluator]") {
    ParseOptions options;
    options.limits.loop_iterations = 1000;
    CHECK(std::string(error_of("#while (1) #end", options).message()).find("1000") !=
          std::string::npos);
    options.limits.macro_depth = 20;
    CHECK(std::string(error_of("#macro R() R() #end R()", options).message()).find("20 deep") !=
          std::string::npos);
}

TEST_CASE("#include searches the scene's folder, then each include path, then hexant's own",
          "[evaluator][include]") {
    const fs::path root = fs::temp_directory_path() / "hexant_include_test";
    fs::remove_all(root);
    fs::create_directories(root / "scene");
    fs::create_directories(root / "first");
    fs::create_directories(root / "second");
    std::ofstream(root / "scene" / "main.pov")
        << "#include \"a.inc\" #include \"b.inc\" #include \"colors.inc\"\n"
           "#debug concat(A, B) #debug str(Red.red, 0, 0)\n";
    std::ofstream(root / "scene" / "a.inc") << "#declare A = \"scene\";";
    std::ofstream(root / "first" / "a.inc") << "#declare A = \"first\";";
    std::ofstream(root / "first" / "b.inc") << "#declare B = \"first\";";
    std::ofstream(root / "second" / "b.inc") << "#declare B = \"second\";";
    ParseOptions options;
    options.include_paths = {root / "first", root / "second"};
    std::ostringstream messages;
    options.messages = &messages;
    hexant::language::parse_scene_file(root / "scene" / "main.pov", options);
    CHECK(messages.str() == "scenefirst1");

    std::ofstream(root / "scene" / "missing.pov") << "#include \"nowhere.inc\"\n";
    try {
        hexant::language::parse_scene_file(root / "scene" / "missing.pov", options);
        FAIL("expected an error");
    } catch (const SceneError& e) {
        CHECK(e.message().find("nowhere.inc") != std::string::npos);
        CHECK(e.message().find((root / "second").string()) != std::string::npos);
    }
}

TEST_CASE("an error reports its place first, then the chain that led there",
          "[evaluator][include]") {
    const fs::path root = fs::temp_directory_path() / "hexant_chain_test";
    fs::create_directories(root);
    std::ofstream(root / "lib.inc") << "#macro Ball()\n  sphere { 0, Oops }\n#end\n";
    std::ofstream(root / "main.pov") << "#include \"lib.inc\"\n\nBall()\n";
    try {
        hexant::language::parse_scene_file(root / "main.pov", ParseOptions{});
        FAIL("expected an error");
    } catch (const SceneError& e) {
        REQUIRE(e.places().size() == 2);
        CHECK(e.places()[0].file == (root / "lib.inc").string());
        CHECK(e.places()[0].line == 2);
        CHECK(e.places()[0].column == 15);
        CHECK(e.places()[1].line == 3);
        CHECK(e.places()[1].note.find("macro 'Ball'") != std::string::npos);
        const std::string text = e.formatted();
        CHECK(text.find((root / "lib.inc").string() +
                        ":2:15: error: undeclared identifier 'Oops'") != std::string::npos);
        CHECK(text.find("  sphere { 0, Oops }\n") != std::string::npos);
        CHECK(text.find("              ^") != std::string::npos);
    }
}

TEST_CASE("each scene item makes its record", "[evaluator]") {
    const auto r =
        run("camera { location <0, 1, -5> look_at 0 }\n"
            "light_source { <1, 2, 3>, rgb <1, 0.5, 0> shadowless }\n"
            "background { rgb <0, 0, 0.5> }\n"
            "global_settings { assumed_gamma 2.2 max_trace_level 9 ambient_light rgb 0.5 radiosity "
            "{ } }\n"
            "sphere { <1, 2, 3>, 4 }\n"
            "box { <0, 0, 0>, 1 }\n"
            "cylinder { 0, y, 0.5 open }\n"
            "polygon { 3, <0, 0>, <1, 0>, <0, 1> }\n"
            "prism { 0, 2, 3, <0, 0>, <1, 0>, <0, 1> }\n"
            "union { sphere { 0, 1 } light_source { <0, 1, 0>, rgb 1 } translate x * 5 }\n"
            "difference { box { -1, 1 } sphere { 0, 1.2 } }\n"
            "sphere { 0, 1 texture { pigment { checker rgb 1, rgb 0 } finish { phong 0.5 "
            "reflection 0.25 } } "
            "interior { ior 1.5 } no_shadow }\n");
    const auto& s = r.scene;
    CHECK(s.lights.size() == 2);
    CHECK(s.lights[0].shadowless);
    CHECK(s.lights[0].colour.c[1].constant() == 0.5);
    // The light inside the union moves with it.
    CHECK(s.lights[1].transform.matrix_at(0)[3][0] == 5.0);
    CHECK(s.background.c[2].constant() == 0.5);
    CHECK(s.global.assumed_gamma == 2.2);
    CHECK(s.global.max_trace_level == 9);
    CHECK(s.global.radiosity.enabled);
    // The box's +x face in the plane of the difference's box's (their
    // corners, outside the subtracted sphere, overlap).
    REQUIRE(s.warnings.size() == 1);
    CHECK(s.warnings[0].find("coincident surfaces") != std::string::npos);
    REQUIRE(s.objects.size() == 8);
    CHECK(shape<hexant::runtime::Sphere>(s, 0).center.c[2].constant() == 3.0);
    CHECK(shape<hexant::runtime::Cylinder>(s, 2).open);
    CHECK(shape<hexant::runtime::Polygon>(s, 3).points.size() == 3);
    CHECK(shape<hexant::runtime::Prism>(s, 4).points.size() == 3);
    CHECK(shape<hexant::runtime::Csg>(s, 5).children.size() == 1);
    CHECK(shape<hexant::runtime::Csg>(s, 6).kind == hexant::runtime::Csg::Kind::Difference);
    const auto& last = *s.objects[7];
    REQUIRE(last.texture);
    CHECK(last.texture->pigment.pattern == hexant::runtime::Pigment::Pattern::Patterned);
    CHECK(last.texture->pigment.patterned->kind->name == "checker");
    CHECK(last.texture->finish->phong.constant() == 0.5);
    CHECK(last.texture->finish->reflection.c[0].constant() == 0.25);
    CHECK(last.interior->ior.constant() == 1.5);
    CHECK(last.no_shadow);
    const auto camera = s.camera.evaluate(0.0);
    CHECK(camera.location.y == 1.0);
}

TEST_CASE("clock is a symbol in an animation and a number in a still", "[evaluator][time]") {
    const auto r =
        run("sphere { vrotate(3 * x, 360 * clock * z), 1 + clock }\n"
            "box { 0, 1 twist y, 90 * clock }\n",
            animation());
    const auto& sphere = shape<hexant::runtime::Sphere>(r.scene, 0);
    CHECK(sphere.center.depends_on_time());
    CHECK(sphere.center(0.25).x == Approx(0.0).margin(1e-12));
    CHECK(sphere.center(0.25).y == Approx(3.0));
    CHECK(sphere.radius(0.5) == 1.5);
    const auto& steps = r.scene.objects[1]->transform.steps();
    REQUIRE(steps.size() == 1);
    CHECK(steps[0].kind == hexant::runtime::TransformKind::Twist);
    CHECK(steps[0].amount.depends_on_time());
    CHECK(steps[0].amount(0.5) == 45.0);

    ParseOptions still;
    still.animation.initial_clock = 0.25;
    const auto s = run("sphere { x * clock, 1 }", still);
    CHECK(shape<hexant::runtime::Sphere>(s.scene, 0).center.c[0].constant() == 0.25);

    // One cyclic frame over clock 0..1 (--frame-count 1 --cyclic --clock
    // 0:1): its shutter spans the cycle, so clock moves there too.
    ParseOptions cycle;
    cycle.animation.initial_clock = 0.0;
    cycle.animation.final_clock = 1.0;
    cycle.animation.cyclic = true;
    const auto c = run("sphere { x * clock, 1 }", cycle);
    CHECK(shape<hexant::runtime::Sphere>(c.scene, 0).center.depends_on_time());
    CHECK(c.scene.animation.time_end() == Approx(c.scene.animation.shutter));

    // (#if, #elseif, #while, #switch, a #for's end and an index read on clock
    // split time: tests/language/time_branch_test.cpp; str() and the string
    // functions: timed_string_test.cpp.)
    for (const char* needs_a_number : {"#declare A = array[2] {1, 2}; #declare A[clock] = 3;",
                                       "#declare S = seed(clock);", "#for (I, clock, 1) #end"}) {
        INFO(needs_a_number);
        CHECK(
            std::string(error_of(needs_a_number, animation()).message()).find("depends on clock") !=
            std::string::npos);
    }
}

TEST_CASE("what a scene declares but never uses cannot fail", "[evaluator]") {
    const auto r =
        run("#declare F = function { pigment { rgb 1 } }\n#declare G = F(2, 0, 0);\n"
            "#declare P = pigment { tiling 5 }\n#declare I = parametric { function { u } "
            "function { v } function { 0 } <0, 0>, <1, 1> }\n"
            "#declare T = texture { pigment { rgb 1 } } texture { pigment { rgbt 1 } }\n"
            "sphere { 0, 1 }\n");
    CHECK(r.scene.objects.size() == 1);
    const auto used =
        error_of("#declare P = pigment { tiling 5 }\nsphere { 0, 1 pigment { P } }\n");
    CHECK(used.places()[0].line == 2);
    CHECK(used.message().find("test.pov:1:") != std::string::npos);  // where it was written
    CHECK(error_of("#declare I = parametric { function { u } function { v } function { 0 } <0, "
                   "0>, <1, 1> }\nobject { I }\n")
              .places()[0]
              .line == 2);
    CHECK(error_of("#declare F = function { pigment { rgb 1 } }\n#declare G = F(1, 0, 0);\n"
                   "sphere { 0, G }\n")
              .places()[0]
              .line == 3);
}

TEST_CASE("no input makes the reader crash: it either reads or says where it fails",
          "[evaluator][robust]") {
    const std::string valid =
        "#declare R = 1.5;\n#macro M(A) sphere { A, R pigment { rgb <1, 0, 0> } } #end\n"
        "camera { location <0, 1, -5> look_at 0 }\n#for (I, 0, 3) M(<I, 0, 0>) #end\n"
        "union { box { -1, 1 } cylinder { 0, y, 0.5 } rotate 45 * y }\n"
        "#if (R > 1) plane { y, 0 } #else #error \"no\" #end\n/* done */ // end\n";
    std::mt19937 random(1234);
    const std::string alphabet = "{}()<>[],;#\"/*+-.0123456789 abcxyz\n";
    for (int trial = 0; trial < 400; ++trial) {
        std::string text = valid;
        const int kind = trial % 3;
        const std::size_t at = random() % text.size();
        if (kind == 0)
            text.resize(at);  // truncated
        else if (kind == 1)
            text[at] = alphabet[random() % alphabet.size()];  // one character changed
        else
            text.erase(at, 1 + random() % 5);  // a few characters gone
        INFO(text);
        try {
            hexant::language::ParseOptions options;
            std::ostringstream sink;
            options.messages = &sink;
            hexant::language::parse_scene_text(text, "fuzz.pov", options);
        } catch (const SceneError& e) {
            CHECK(e.places().front().line >= 1);
        }
    }
}

TEST_CASE(
    "a declared light is copied with its modifiers, and looks_like places its object at the light",
    "[evaluator]") {
    const auto r =
        run("#declare L = light_source { <0, 5, -3>, rgb <1, 0.5, 0.25> spotlight point_at 0 }\n"
            "light_source { L translate x * 2 }\n"
            "light_source { <1, 2, 3>, rgb 1 looks_like { sphere { 0, 0.5 } } translate y }\n"
            "union { sphere { 0, 1 } light_source { 0, rgb 1 looks_like { box { -1, 1 } } } "
            "translate z * 4 }\n");
    const auto& s = r.scene;
    REQUIRE(s.lights.size() == 3);
    // The copy keeps the declared light's kind and colour; its translate
    // comes after.
    CHECK(s.lights[0].kind == hexant::runtime::LightKind::Spotlight);
    CHECK(s.lights[0].colour.c[1].constant() == 0.5);
    CHECK(s.lights[0].transform.matrix_at(0)[3][0] == 2.0);
    // Each looks_like object: at the light's position, then through its
    // transforms (a union's included), casting no shadow.
    REQUIRE(s.objects.size() == 3);  // the sphere, the union, the box
    const auto& sphere = *s.objects[0];
    CHECK(sphere.no_shadow);
    const glm::dmat4 m = sphere.transform.matrix_at(0.0);
    CHECK(m[3][0] == 1.0);
    CHECK(m[3][1] == 3.0);
    CHECK(m[3][2] == 3.0);
    CHECK(s.objects[2]->no_shadow);
    CHECK(s.objects[2]->transform.matrix_at(0.0)[3][2] == 4.0);
    CHECK_FALSE(s.lights[1].looks_like);
}
