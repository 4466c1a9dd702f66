// trace(), inside() and vturbulence() against the values POV-Ray 3.7
// printed for the same calls (#debug with vstr(3, V, ",", 0, 9), povray
// 3.7.0.10 on Debian), and array initializers and #declare values as
// POV-Ray reads them.
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "scene_text.hpp"

namespace {

std::string message(const std::string& text, hexant::language::ParseOptions options = {}) {
    return hexant::test::error_of("#version 3.7;\n" + text, options).what();
}

// Read as an animation, so that clock is not a constant.
hexant::language::ParseOptions animation() {
    hexant::language::ParseOptions options;
    options.animation.final_frame = 10;
    return options;
}

std::string debug(const std::string& text) {
    std::ostringstream messages;
    hexant::language::ParseOptions options;
    options.messages = &messages;
    (void)hexant::language::parse_scene_text("#version 3.7;\n" + text, "queries.pov", options);
    return messages.str();
}

// The three numbers of a "x,y,z" line.
std::vector<double> numbers(const std::string& s) {
    std::vector<double> out;
    std::stringstream in(s);
    std::string part;
    while (std::getline(in, part, ',')) out.push_back(std::stod(part));
    return out;
}

void check_vector(const std::string& got, std::vector<double> want, double margin) {
    INFO(got);
    const auto v = numbers(got);
    REQUIRE(v.size() == want.size());
    for (std::size_t i = 0; i < v.size(); ++i) CHECK(v[i] == Approx(want[i]).margin(margin));
}

const std::string kObjects =
    "#declare S = sphere { <1, 2, 3>, 2 scale <1, 0.5, 1> rotate 30 * z }\n"
    "#declare D = difference { box { -1, 1 } sphere { <0, 0, -1>, 0.8 } translate x }\n"
    "#declare N = <9, 9, 9>;\n";

}  // namespace

TEST_CASE("trace() finds the first hit and its outward normal, as POV-Ray's", "[language][trace]") {
    // A scaled and turned sphere from above; a box's cut by a sphere (the
    // normal of a difference's cut points out of the solid, into the hole);
    // a miss, which gives <0, 0, 0> for both. POV-Ray printed 9 decimals;
    // hexant's sphere and box are exact to ~1e-15, so 1e-8 is the print's
    // rounding.
    check_vector(debug(kObjects + "#declare P = trace(S, <1, 10, 3>, -y, N);\n"
                                  "#debug vstr(3, P, \",\", 0, 9)"),
                 {1.0, 2.657965716, 3.0}, 1e-8);
    check_vector(debug(kObjects + "#declare P = trace(S, <1, 10, 3>, -y, N);\n"
                                  "#debug vstr(3, N, \",\", 0, 9)"),
                 {-0.166184623, 0.986094656, 0.0}, 1e-8);
    check_vector(debug(kObjects + "#declare P = trace(D, <1.2, 0.1, -5>, z, N);\n"
                                  "#debug vstr(3, P, \",\", 0, 9)"),
                 {1.2, 0.1, -0.231885425}, 1e-8);
    check_vector(debug(kObjects + "#declare P = trace(D, <1.2, 0.1, -5>, z, N);\n"
                                  "#debug vstr(3, N, \",\", 0, 9)"),
                 {-0.25, -0.125, -0.960143218}, 1e-8);
    check_vector(debug(kObjects + "#declare P = trace(D, <1.2, 0.1, -5>, -z, N);\n"
                                  "#debug concat(vstr(3, P, \",\", 0, 9), \",\", "
                                  "vstr(3, N, \",\", 0, 9))"),
                 {0, 0, 0, 0, 0, 0}, 0.0);
    // Without the normal's name; a direction that is not unit.
    check_vector(debug(kObjects + "#declare P = trace(S, <1, 10, 3>, -7 * y);\n"
                                  "#debug vstr(3, P, \",\", 0, 9)"),
                 {1.0, 2.657965716, 3.0}, 1e-8);
    // The normal goes only into a declared name.
    CHECK(message(kObjects + "#declare P = trace(S, <1, 10, 3>, -y, Nope);").find("not declared") !=
          std::string::npos);
    CHECK(message("#declare P = trace(<1, 2, 3>, <1, 10, 3>, -y);").find("object") !=
          std::string::npos);
    // An object that moves with clock would give a point that moves: refused.
    CHECK(message("#declare M = sphere { 0, 1 translate clock * x }\n"
                  "#declare P = trace(M, <0, 5, 0>, -y);",
                  animation())
              .find("change with clock") != std::string::npos);
}

TEST_CASE("trace() on an isosurface gives POV-Ray's normal, F's differences over accuracy",
          "[language][trace]") {
    // advanced/isocacti's first cactus: ridges that turn fast near the axis,
    // where the exact gradient and POV-Ray's forward differences over
    // `accuracy` (0.001) differ by up to 0.1 (its spines grow along these
    // normals). POV-Ray stops its root within accuracy and hexant refines
    // it to adjacent doubles: the points differ by up to 7e-4, and the
    // normals, differenced a few 1e-4 apart, by up to 4e-4; 1e-3 holds
    // both and is a tenth of the exact gradient's miss.
    const std::string body =
        "#declare Body = isosurface {\n"
        "  function { sqrt(x*x + pow(y - sqrt((x*x/4) + (z*z/4))*1.5, 2) + z*z) - 1 -\n"
        "             (sin(atan2(x, z)*40)*0.5*0.075) }\n"
        "  threshold 0 max_gradient 5 contained_by { sphere { 0, 3.1 } } }\n"
        "#declare N = y;\n";
    struct Case {
        double turn_x, turn_y;
        std::vector<double> point, normal;  // as POV-Ray 3.7 printed them
    };
    const Case cases[] = {
        {10,
         33,
         {-0.081026516, -0.843722502, -0.124769894},
         {-0.944321989, -0.169011705, 0.282295988}},
        {17,
         66,
         {-0.227617495, -0.814960298, -0.101341838},
         {-0.579833689, -0.275409793, 0.766773981}},
        {24,
         99,
         {-0.312556178, -0.710763346, 0.049504035},
         {-0.356900331, -0.192467176, -0.914099852}},
    };
    for (const auto& c : cases) {
        const std::string call = "#declare O = vrotate(vrotate(-y*50, x*" +
                                 std::to_string(c.turn_x) + "), y*" + std::to_string(c.turn_y) +
                                 ");\n#declare P = trace(Body, O, -O, N);\n";
        check_vector(debug(body + call + "#debug vstr(3, P, \",\", 0, 9)"), c.point, 1e-3);
        check_vector(debug(body + call + "#debug vstr(3, N, \",\", 0, 9)"), c.normal, 1e-3);
    }
}

TEST_CASE("inside() answers as POV-Ray's", "[language][trace]") {
    // POV-Ray printed "1 0 1".
    CHECK(debug(kObjects + "#debug concat(str(inside(D, <1.5, 0.9, 0>), 0, 0), str(inside(D, "
                           "<1, 0, -0.9>), 0, 0), str(inside(S, <0, 1, 1.5>), 0, 0))") == "101");
}

TEST_CASE("vturbulence() is POV-Ray's DTurbulence", "[language][noise]") {
    // POV-Ray printed these; the octaves 3.7 are truncated to 3.
    check_vector(debug("#debug vstr(3, vturbulence(2, 0.5, 6, <0.3, 1.7, -2.2>), \",\", 0, 9)"),
                 {0.089617971, 0.255222196, 0.123399333}, 2e-9);
    check_vector(
        debug("#debug vstr(3, vturbulence(2.5, 0.6, 3.7, <10.3, -1.7, 2.2>), \",\", 0, 9)"),
        {0.152257591, -0.392745276, -0.358269132}, 2e-9);
}

TEST_CASE("array elements need no commas, and a vector ends before the next '<'",
          "[language][array]") {
    // lemon.inc and tiling.pov of POV-Ray's distribution write them so.
    CHECK(debug("#declare A = array[4] { <1, 2>, <3, 4> <5, 6>\n <7, 8> }\n"
                "#debug vstr(2, A[2], \",\", 0, 0)") == "5,6");
    CHECK(debug("#declare R = 1; #declare G = 2;\n"
                "#declare A = array[3] { R, G\n R }\n#debug str(A[1] + A[2], 0, 0)") == "3");
    // A sum still joins its terms: POV-Ray reads `1 -2` as one element.
    CHECK(debug("#declare A = array[1] { 1 -2 }\n#debug str(A[0], 0, 0)") == "-1");
    CHECK(message("#declare A = array[2] { 1 2 3 }").find("array") != std::string::npos);
}

TEST_CASE("a #declare's value may be chosen by a directive", "[language][declare]") {
    // whiltile.pov: #declare Tile = #ifdef (DO_SIMPLE) box { } #else ... #end
    CHECK(debug("#declare X = #if (1) 4 #else 5 #end\n#debug str(X, 0, 0)") == "4");
    CHECK(debug("#declare X = #ifdef (Nothing) 4 #else 5 #end;\n#debug str(X, 0, 0)") == "5");
    CHECK(debug("#declare C = 2; #declare X = #switch (C) #case (1) 7 #break #case (2) 8 "
                "#break #end\n#debug str(X, 0, 0)") == "8");
    CHECK(debug("#declare O = #ifndef (Q) sphere { 0, 1 } #else box { 0, 1 } #end\n"
                "#debug str(max_extent(O).x, 0, 0)") == "1");
    CHECK(message("#declare X = #if (1) 4 5 #end").find("one") != std::string::npos);
    CHECK(message("#declare X = #if (0) 4 #end").find("one") != std::string::npos);
}

TEST_CASE("a text of blanks has POV-Ray's box", "[language][text]") {
    // shapes.inc's Circle_Text measures each character with max_extent,
    // spaces too: POV-Ray printed 1,2,3 and 1,2,4 for this (the thickness
    // along z, placed), and +-1e10 for an empty string.
    CHECK(debug("#declare T = text { ttf \"timrom.ttf\" \" \" 0.5, 0 scale 2 translate <1,2,3> }\n"
                "#debug concat(vstr(3, min_extent(T), \",\", 0, 4), \" \", "
                "vstr(3, max_extent(T), \",\", 0, 4))") ==
          "1.0000,2.0000,3.0000 1.0000,2.0000,4.0000");
    CHECK(debug("#declare T = text { ttf \"timrom.ttf\" \"\" 0.5, 0 }\n"
                "#debug str(max_extent(T).x, 0, 0)") == "10000000000");
}

TEST_CASE("a macro's value may end with a semicolon", "[language][declare]") {
    // tracevines.pov's FindTmp ends `#if (Safety) Q; #else <0,0,0>; #end`.
    CHECK(debug("#macro F(S) #local Q = 3; #if (S) Q; #else 4; #end #end\n"
                "#declare X = F(1); #declare Y = F(0);\n#debug str(10 * X + Y, 0, 0)") == "34");
}

TEST_CASE("a branch may open a block that the text after #end closes", "[language][declare]") {
    // shapes.inc's Circle_Text: #if (UseMerge) merge { #else union { #end
    // ... }; a real animation's `#declare A = #if (..) object { #else union {
    // object { .. } #end object { .. } };`. POV-Ray's directives act on its
    // tokens, so either branch opens the object the rest fills.
    const std::string macro =
        "#macro Pair(UseMerge)\n"
        "  #if (UseMerge)\n    merge {\n  #else\n    union {\n  #end\n"
        "      sphere { 0, 1 } sphere { x, 1 }\n    }\n#end\n";
    CHECK(debug(macro + "#declare A = Pair(1);\n#declare B = Pair(0);\n"
                        "#debug str(max_extent(A).x + max_extent(B).x, 0, 0)") == "4");
    CHECK(debug("#declare C = 1;\n"
                "#declare O = #if (C = 0) object { #else union { object { sphere { 0, 1 } "
                "translate y } #end object { sphere { 0, 1 } } };\n"
                "#debug str(max_extent(O).y, 0, 0)") == "2");
    CHECK(debug("#declare C = 0;\n"
                "#declare O = #if (C = 0) object { #else union { object { sphere { 0, 1 } "
                "translate y } #end sphere { 0, 1 } };\n"
                "#debug str(max_extent(O).y, 0, 0)") == "1");
    // The lines after it keep their numbers: an error there names its place.
    const std::string bad = message(macro + "#declare A = Pair(1);\n#declare Z = nope;\n");
    CHECK(bad.find("nope") != std::string::npos);
    CHECK(hexant::test::error_of("#version 3.7;\n" + macro +
                                 "#declare A = Pair(1);\n#declare Z = nope;\n")
              .places()
              .front()
              .line == 12);
}

TEST_CASE("a branch may close the block its directive is in", "[language][declare]") {
    // A real animation's pawn: `#if (clock >= 0.05) cone { } texture { } }
    // #else cone { } texture { } } #end`, each branch ending the union
    // around it. POV-Ray reads the tokens of the branch taken; so does
    // hexant, and steps over the rest of the directive after the block.
    const auto pair = [](const std::string& condition) {
        return "#declare P = union {\n  sphere { 0, 1 }\n  #if (" + condition +
               ")\n    sphere { 2 * x, 1 } }\n  #else\n    sphere { y, 1 } }\n  #end\n"
               "#debug str(max_extent(P).x + 10 * max_extent(P).y, 0, 0)";
    };
    CHECK(debug(pair("1")) == "13");  // x: 3, y: 1
    CHECK(debug(pair("0")) == "21");  // x: 1, y: 2
    // #ifdef and #ifndef too, and items after the block in the branch.
    CHECK(debug("#declare P = union { sphere { 0, 1 }\n#ifndef (Nothing) } #declare Q = 5;\n"
                "#else } #declare Q = 6;\n#end\n#debug str(Q, 0, 0)") == "5");
    // A branch whose items stop before its '}' names the directive.
    CHECK(hexant::test::error_of(
              "#version 3.7;\nunion { sphere { 0, 1 }\n#if (1) sphere { 0, 1 } nope }\n#end")
              .places()
              .front()
              .line == 3);
    // (Under a branch on clock: time_branch_test.cpp.)
}

TEST_CASE("a macro in object { } may give the object and then its modifiers",
          "[language][declare]") {
    // object_pattern.pov: `object { Obj2(0, false) translate ... }` whose
    // body is `Obj rotate Angle*y #if (Flip) ... #end`: POV-Ray reads the
    // body's tokens in place, so the object is the body's first value and
    // what follows modifies it, then the modifiers after the call.
    CHECK(
        debug("#declare Obj = sphere { 0, 1 }\n"
              "#macro Turned(Flip) Obj translate x #if (Flip) scale 2 #end #end\n"
              "#declare O = object { Turned(true) translate y };\n"
              "#declare P = object { Turned(false) };\n"
              "#debug str(max_extent(O).x + 10 * max_extent(O).y + 100 * max_extent(P).x, 0, 0)") ==
        "234");
    // A macro that gives a whole object, or calls one that does, as before.
    CHECK(debug("#macro Ball(R) sphere { 0, R } #end\n#macro Outer() Ball(3) #end\n"
                "#declare O = object { Outer() scale 2 };\n"
                "#debug str(max_extent(O).x, 0, 0)") == "6");
    // One that gives no object is an error at the call.
    const auto none =
        hexant::test::error_of("#version 3.7;\n#macro Nothing() #end\nobject { Nothing() }\n");
    INFO(none.formatted());
    CHECK(none.formatted().find(":3:") != std::string::npos);
}

TEST_CASE("a '#' that starts no directive is ignored with a warning", "[language][declare]") {
    // image_size.pov: `look_at <0,2,0>#` at a line's end. POV-Ray's
    // Parse_Directive ungets what follows a '#' that names no directive.
    hexant::language::ParseOptions options;
    std::ostringstream messages;
    options.messages = &messages;
    const auto scene = hexant::language::parse_scene_text(
        "#version 3.7;\ncamera { location <0, 2, -10> look_at <0, 2, 0>#\n }\n"
        "sphere { 0, 1 # }\n",
        "hash.pov", options);
    CHECK(scene.objects.size() == 1);
    REQUIRE(scene.warnings.size() == 2);
    INFO(scene.warnings[0]);
    CHECK(scene.warnings[0].find("hash.pov:2:49") != std::string::npos);
    CHECK(scene.warnings[0].find("ignored") != std::string::npos);
    // A word after it is still an unknown directive.
    CHECK(message("#delcare X = 1;").find("unknown directive '#delcare'") != std::string::npos);
}

TEST_CASE("a rainbow is read and prepared as POV-Ray's Parse_Rainbow", "[language]") {
    hexant::language::ParseOptions options;
    const auto scene = hexant::language::parse_scene_text(
        "#version 3.7;\nrainbow { angle 40 width 4 direction <0, 0, 2> arc_angle 120\n"
        "color_map { [0 rgb 1] [1 rgbf <1, 0, 0, 0.5>] } }\n",
        "rainbow.pov", options);
    REQUIRE(scene.rainbows.size() == 1);
    const auto& r = scene.rainbows[0];
    CHECK(r.direction.z == Approx(1.0));
    CHECK(r.angle == Approx(38.0 * 3.141592653589793 / 180.0));  // its inner edge
    CHECK(r.width == Approx(4.0 * 3.141592653589793 / 180.0));
    CHECK(r.arc_angle == Approx(60.0 * 3.141592653589793 / 180.0));  // halved
    CHECK(r.falloff_angle == r.arc_angle);                           // an arc alone: no falloff
    CHECK(r.colour_at(0.5)[3] == Approx(0.25));
    // POV-Ray's errors, each at the rainbow.
    for (const char* bad : {"rainbow { direction 0 }", "rainbow { direction z up z }",
                            "rainbow { direction z arc_angle 90 falloff_angle 120 }",
                            "rainbow { direction z arc_angle 400 }"}) {
        INFO(bad);
        CHECK(hexant::test::error_of(std::string("#version 3.7;\n") + bad).places().front().line ==
              2);
    }
    CHECK(hexant::test::error_of("#version 3.7;\nrainbow { direction z angle clock }",
                                 hexant::test::animation())
              .places()
              .front()
              .line == 2);
}

TEST_CASE("an object macro's body may branch before it gives its object", "[language][declare]") {
    // shapes.inc's Circle_Text and Round_Box: #if/#else around #local lines
    // before the object; the branch's #end is not the object.
    CHECK(debug("#macro M(A) #if (A > 1) #local R = 2; #else #if (A > 0) #local R = 1; #end #end\n"
                "sphere { 0, R } #end\n"
                "#declare O = object { M(1) };\n#debug str(max_extent(O).x, 0, 0)") == "1");
}
