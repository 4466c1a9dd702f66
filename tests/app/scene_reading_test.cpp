// A scene read for rendering (app/scene_reading.hpp): whole where it can be,
// frame by frame where the whole reading stops under a branch on clock, each
// frame at its shutter or, where that splits what cannot be split, at its
// opening; warnings said once over all the frames.
#include "app/scene_reading.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/scene_error.hpp"

namespace fs = std::filesystem;
using hexant::app::ResolvedScene;
using hexant::app::SceneReading;

namespace {

// `text` written as a scene file, read over frames 1 to 4 (clock 0 to 1)
// with its #debug output to `said`.
ResolvedScene scene_file(const std::string& name, const std::string& text, std::ostream& said) {
    const fs::path path = fs::temp_directory_path() / ("hexant_scene_reading_" + name + ".pov");
    std::ofstream(path) << text;
    ResolvedScene resolved;
    resolved.scene = path;
    resolved.options.animation.initial_frame = 1;
    resolved.options.animation.final_frame = 4;
    resolved.options.messages = &said;
    return resolved;
}

// Frame k of 4 over clock 0 to 1 opens at (k - 1) / 3: frame 2's shutter,
// [1/3, 2/3), holds 0.5.
const char* const kStepped = R"(
#declare A = array[1] { 0 }
#declare I = 0;
#while (I < frame_number)
  #declare A[0] = A[0] + 1;
  #declare I = I + 1;
#end
#if (clock < 0.5) #declare A[0] = A[0] + 10; #end
#debug concat("x=", str(A[0], 0, 0), "\n")
global_settings { adc_bailout 0.01 }
sphere { <A[0], 0, 0>, 1 }
)";

}  // namespace

TEST_CASE("a scene that reads whole is read once", "[app][time]") {
    std::ostringstream said, err;
    SceneReading reading(scene_file("whole", "sphere { <clock, 0, 0>, 1 }\n", said), err);
    CHECK_FALSE(reading.frame_by_frame());
    CHECK(reading.scene().objects.size() == 1);
    CHECK(err.str().empty());
}

TEST_CASE("a scene stepped per frame is read frame by frame, as POV-Ray reads it", "[app][time]") {
    std::ostringstream said, err;
    SceneReading reading(scene_file("stepped", kStepped, said), err);
    REQUIRE(reading.frame_by_frame());
    CHECK(err.str().find("is read frame by frame") != std::string::npos);
    CHECK(err.str().find(".pov:5: ") != std::string::npos);  // where the whole reading stopped
    CHECK(said.str().empty());                               // (said when a frame is read)
    err.str("");
    for (int k = 1; k <= 4; ++k) (void)reading.read_frame(k);
    // Frame 1 opens at 0 (+10), frame 2's shutter splits the array and is
    // decided at its opening, 1/3 (+10), frames 3 and 4 are past 0.5.
    CHECK(said.str().find("x=11\n") != std::string::npos);
    CHECK(said.str().find("x=12\n") != std::string::npos);
    CHECK(said.str().find("x=3\n") != std::string::npos);
    CHECK(said.str().find("x=4\n") != std::string::npos);
    CHECK(err.str().find("warning: frame 2: its shutter holds what hexant cannot make") !=
          std::string::npos);
    CHECK(err.str().find("frame 1:") == std::string::npos);
    CHECK(err.str().find("frame 3:") == std::string::npos);
    // adc_bailout's warning (a scene warning, not the note) once over the
    // four frames.
    const std::string all = said.str();
    const auto first = all.find("warning:");
    REQUIRE(first != std::string::npos);
    CHECK(all.find("warning:", first + 1) == std::string::npos);
}

TEST_CASE("what needs a constant of clock reads frame by frame, at the frames' openings",
          "[app][time]") {
    // An array sized by clock and a string of clock that changes at every
    // instant: over the whole animation, and over a frame's shutter, they
    // cannot be read; at each frame's opening clock they can, as in POV-Ray.
    std::ostringstream said, err;
    SceneReading reading(
        scene_file("constant",
                   "#declare A = array[int(clock * 3) + 1]\n"
                   "#debug concat(\"n=\", str(dimension_size(A, 1), 0, 0), \" c=\", "
                   "str(clock, 0, 6), \"\\n\")\nsphere { 0, 1 }\n",
                   said),
        err);
    REQUIRE(reading.frame_by_frame());
    for (int k = 1; k <= 4; ++k) (void)reading.read_frame(k);
    CHECK(said.str() == "n=1 c=0.000000\nn=2 c=0.333333\nn=3 c=0.666667\nn=4 c=1.000000\n");
}

TEST_CASE("an error no frame's reading passes names its place and the frame", "[app][time]") {
    std::ostringstream said, err;
    const std::string text =
        std::string(kStepped) + "#if (frame_number = 3) #error \"three\" #end\n";
    SceneReading reading(scene_file("error", text, said), err);
    REQUIRE(reading.frame_by_frame());
    (void)reading.read_frame(2);
    try {
        (void)reading.read_frame(3);
        FAIL("frame 3 read");
    } catch (const hexant::language::SceneError& e) {
        CHECK(e.formatted().find("three") != std::string::npos);
        CHECK(e.formatted().find("reading frame 3 alone") != std::string::npos);
    }
}
