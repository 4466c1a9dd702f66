// One frame read alone (ParseOptions::frame_alone), as a scene read frame by
// frame is (app/scene_reading.hpp): frame_number is a constant, the time read
// for is the frame's shutter (or its opening instant), and a whole reading
// that stops at what cannot be piecewise in time says so
// (SceneError::may_read_frame_by_frame), where an ordinary error does not.
#include <cmath>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "scene_text.hpp"

using hexant::language::ParseOptions;
using hexant::test::animation;
using hexant::test::read_error;
using hexant::test::scene_of;

namespace rt = hexant::runtime;

namespace {

// State carried from frame to frame as POV-Ray scenes carry it (the real
// animation ../shared/cases/2026-12-03/04): an array advanced once per
// frame, bouncing between limits, its direction flipped under #if.
const char* const kStepped = R"(
#declare A = array[2] { 0, 1 }
#declare I = 0;
#while (I < frame_number)
  #if (A[1] = 1)
    #declare A[0] = A[0] + 3;
    #if (A[0] >= 7) #declare A[1] = 0; #end
  #else
    #declare A[0] = A[0] - 3;
    #if (A[0] <= 0) #declare A[1] = 1; #end
  #end
  #declare I = I + 1;
#end
sphere { <A[0], 0, 0>, 1 }
)";

ParseOptions frame(int k, bool at_clock = false) {
    ParseOptions options = animation();
    options.frame_alone = ParseOptions::FrameAlone{k, at_clock};
    return options;
}

double centre_x(const rt::SceneDescription& scene) {
    const auto& sphere = std::get<rt::Sphere>(scene.objects.at(0)->shape);
    // (Any instant: the centre is a constant in every reading here.)
    return sphere.center(0.5).x;
}

}  // namespace

TEST_CASE("a scene stepped per frame stops the whole reading, marked for frame by frame",
          "[language][time]") {
    const auto e = read_error(kStepped, animation());
    REQUIRE(e);
    INFO(e->formatted());
    CHECK(e->may_read_frame_by_frame());
    // An error that no frame's reading passes is not marked.
    const auto plain = read_error("sphere { 0, Undeclared }", animation());
    REQUIRE(plain);
    CHECK_FALSE(plain->may_read_frame_by_frame());
}

TEST_CASE("each frame read alone steps the state as POV-Ray does at that frame",
          "[language][time]") {
    // Frame k runs the loop k times: 0 3 6 9 6 3 0 3 for frames 1 to 8
    // (the direction flips after 9 and after 0).
    const double expected[] = {3, 6, 9, 6, 3, 0, 3, 6};
    for (int k = 1; k <= 8; ++k) {
        INFO("frame " << k);
        CHECK(centre_x(scene_of(kStepped, frame(k))) == expected[k - 1]);
    }
}

TEST_CASE("frame_number read alone is a constant: an array's size, a string", "[language][time]") {
    std::ostringstream said;
    ParseOptions options = frame(5);
    options.messages = &said;
    (void)hexant::language::parse_scene_text(
        "#declare A = array[frame_number]\n#debug concat(\"n=\", str(dimension_size(A, 1), 0, "
        "0), \"\\n\")\nsphere { 0, 1 }",
        "test.pov", options);
    CHECK(said.str() == "n=5\n");
    // Read over the whole animation it is a function of time, refused as a size.
    CHECK(read_error("#declare A = array[frame_number]", animation()));
}

TEST_CASE("a frame's own shutter splits a branch inside it, its opening decides it alone",
          "[language][time]") {
    // Frames 1 to 8 over clock 0 to 1: frame 4's shutter is [3/7, 4/7),
    // which holds 0.5. An array element set on either side cannot be made
    // piecewise in time: frame 4 alone still stops (marked), and at its
    // opening instant it reads the side POV-Ray reads at clock 3/7.
    const char* text = R"(
#declare A = array[1]
#if (clock < 0.5) #declare A[0] = 1; #else #declare A[0] = 2; #end
sphere { <A[0], 0, 0>, 1 }
)";
    const auto e = read_error(text, frame(4));
    REQUIRE(e);
    CHECK(e->may_read_frame_by_frame());
    CHECK(centre_x(scene_of(text, frame(4, true))) == 1.0);
    CHECK(centre_x(scene_of(text, frame(3))) == 1.0);  // [2/7, 3/7): all before
    CHECK(centre_x(scene_of(text, frame(5))) == 2.0);  // [4/7, 5/7): all after
}

TEST_CASE("final_frame of a cyclic animation is one past its last, as POV-Ray declares it",
          "[language][time]") {
    std::ostringstream said;
    ParseOptions options = animation();
    options.messages = &said;
    (void)hexant::language::parse_scene_text("#debug str(final_frame, 0, 0)", "test.pov", options);
    options.animation.cyclic = true;
    (void)hexant::language::parse_scene_text("#debug str(final_frame, 0, 0)", "test.pov", options);
    CHECK(said.str() == "89");
}
