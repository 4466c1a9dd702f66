// Where a frame's exposure sits against its clock (--shutter-position) and
// the cut of a non-cyclic animation's first and last exposures to
// [Initial_Clock, Final_Clock] (runtime/scene/animation.hpp): the windows'
// arithmetic, then rendered frames that would show a time outside the
// range, frame_number switching between centred exposures, and a moving
// bar's blur centred on the frame's clock.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "app/command_line.hpp"
#include "language/interpreter.hpp"
#include "tracer/renderer.hpp"

namespace rt = hexant::runtime;
namespace tr = hexant::tracer;

namespace {

rt::Animation make(int frames, double c0, double c1, bool cyclic, rt::ShutterPosition position) {
    rt::Animation a;
    a.width = 24;
    a.height = 8;
    a.initial_frame = 1;
    a.final_frame = frames;
    a.initial_clock = c0;
    a.final_clock = c1;
    a.cyclic = cyclic;
    a.shutter_position = position;
    return a;
}

tr::Image render(const std::string& text, const rt::Animation& animation, int frame, int spp) {
    hexant::language::ParseOptions options;
    options.animation = animation;
    const auto scene = hexant::language::parse_scene_text("#version 3.7;\n" + text,
                                                          "shutter-position-test.pov", options);
    tr::RenderSettings settings;
    settings.samples_per_pixel = spp;
    tr::Renderer renderer(scene, settings);
    return renderer.render_frame(frame);
}

double mean_brightness(const tr::Image& image) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const auto c = image.at(x, y);
            sum += (c[0] + c[1] + c[2]) / 3.0;
        }
    return sum / (double(image.width) * image.height);
}

// Seen from <0, 0, -10> along +z with a direction of length 10, the plane
// z = 0 shows x from -1.5 to 1.5 and y from -0.5 to 0.5 (24 x 8 pixels:
// right 3 x): pixel column (x / 3 + 0.5) W.
const std::string kFlatView = R"(
camera { location <0, 0, -10> direction <0, 0, 10> right 3*x up y }
background { rgb 0 }
)";

// A white card over the whole view, where `condition` (of clock or
// frame_number) holds.
std::string card_where(const std::string& condition) {
    return kFlatView + "#if (" + condition +
           ")\n box { <-2, -1, 0>, <2, 1, 1> pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n"
           "#end\n";
}

}  // namespace

TEST_CASE("a frame's exposure opens at, centres on or closes at its clock", "[tracer][shutter]") {
    using P = rt::ShutterPosition;
    // Cyclic, 4 frames over [0, 1]: clock_delta 1/4, never cut.
    for (const auto& [position, lead] :
         {std::pair{P::Start, 0.0}, std::pair{P::Centre, 0.5}, std::pair{P::End, 1.0}}) {
        rt::Animation a = make(4, 0.0, 1.0, true, position);
        a.shutter = 0.5;
        for (int k = 1; k <= 4; ++k) {
            const auto w = a.frame_window(k);
            CHECK(w.open == Approx(0.25 * (k - 1) - lead * 0.125).margin(1e-15));
            CHECK(w.length == Approx(0.125));
            // frame_number switches lead clock steps before the clock.
            CHECK(a.frame_start(k) == Approx(0.25 * (k - 1) - lead * 0.25).margin(1e-15));
            CHECK(a.frame_start(k) <= w.open);
            if (k > 1) CHECK(a.frame_window(k - 1).close() <= a.frame_start(k));
        }
        CHECK(a.time_begin() == Approx(-lead * 0.125).margin(1e-15));
    }
}

TEST_CASE("a non-cyclic animation's exposures are cut to its clock range unless asked",
          "[tracer][shutter]") {
    using P = rt::ShutterPosition;
    // 3 frames over [0, 1]: clocks 0, 0.5, 1, clock_delta 0.5.
    rt::Animation start = make(3, 0.0, 1.0, false, P::Start);
    CHECK(start.frame_window(1).open == 0.0);
    CHECK(start.frame_window(1).length == 0.5);
    // The last frame would run from 1 to 1.5: cut to the instant 1, where
    // POV-Ray renders it.
    CHECK(start.frame_window(3).open == 1.0);
    CHECK(start.frame_window(3).length == 0.0);
    CHECK(start.time_end() == 1.0);
    rt::Animation centre = make(3, 0.0, 1.0, false, P::Centre);
    CHECK(centre.frame_window(1).open == 0.0);
    CHECK(centre.frame_window(1).length == Approx(0.25));
    CHECK(centre.frame_window(2).open == Approx(0.25));
    CHECK(centre.frame_window(2).length == Approx(0.5));
    CHECK(centre.frame_window(3).open == Approx(0.75));
    CHECK(centre.frame_window(3).close() == Approx(1.0));
    rt::Animation end = make(3, 0.0, 1.0, false, P::End);
    CHECK(end.frame_window(1).length == 0.0);
    CHECK(end.frame_window(3).open == Approx(0.5));
    // Asked for: the exposures as placed.
    start.shutter_beyond_range = true;
    CHECK(start.frame_window(3).close() == Approx(1.5));
    CHECK(start.time_end() == Approx(1.5));
    // A clock running backwards is cut the same way: frames at 2, 0, -2.
    rt::Animation back = make(3, 2.0, -2.0, false, P::Centre);
    CHECK(back.frame_window(1).open == 2.0);
    CHECK(back.frame_window(1).length == Approx(-1.0));
    CHECK(back.frame_window(3).open == Approx(-1.0));
    CHECK(back.frame_window(3).close() == Approx(-2.0));
    // A cut window shortens the shutter and the rolling readout alike.
    rt::Animation rolling = make(3, 0.0, 1.0, false, P::Centre);
    rolling.shutter = 0.5;
    rolling.rolling_shutter = 0.5;  // exposure 1 step: frame 1 keeps half
    const auto clock = rolling.frame_clock(1);
    CHECK(clock.open == 0.0);
    CHECK(clock.shutter_length == Approx(0.125));
    CHECK(clock.rolling_length == Approx(0.125));
    CHECK(clock.at(1.0, 1.0) == Approx(rolling.frame_window(1).close()));
}

TEST_CASE("the last frame of a non-cyclic animation never shows a time past Final_Clock",
          "[tracer][shutter]") {
    // A card that exists only after the animation's end: frame 3's
    // exposure, opening at clock 1, would show it for all of its samples.
    const std::string scene = card_where("clock > 1");
    rt::Animation a = make(3, 0.0, 1.0, false, rt::ShutterPosition::Start);
    CHECK(mean_brightness(render(scene, a, 3, 4)) == 0.0);
    // Its instant, Final_Clock itself, is in the animation and is what the
    // last frame shows (POV-Ray's last frame).
    CHECK(mean_brightness(render(card_where("clock >= 1"), a, 3, 4)) > 0.99);
    a.shutter_beyond_range = true;
    CHECK(mean_brightness(render(scene, a, 3, 4)) > 0.99);
    // And the first frame never a time before Initial_Clock (end position).
    rt::Animation e = make(3, 0.0, 1.0, false, rt::ShutterPosition::End);
    CHECK(mean_brightness(render(card_where("clock < 0"), e, 1, 4)) == 0.0);
}

TEST_CASE("frame_number holds over a frame's whole centred exposure", "[tracer][shutter]") {
    // Cyclic, 4 frames: frame 2's exposure is centred on clock 0.25, from
    // 0.125 to 0.375; frame_number is 2 throughout it, so the card fills
    // frame 2 and is absent from frames 1 and 3 (were frame_number to
    // switch at the clocks, half of each would show it).
    const std::string scene = card_where("frame_number = 2");
    const rt::Animation a = make(4, 0.0, 1.0, true, rt::ShutterPosition::Centre);
    CHECK(mean_brightness(render(scene, a, 2, 4)) > 0.99);
    CHECK(mean_brightness(render(scene, a, 1, 4)) == 0.0);
    CHECK(mean_brightness(render(scene, a, 3, 4)) == 0.0);
}

TEST_CASE("a centred exposure blurs a moving bar evenly about its place at the frame's clock",
          "[tracer][shutter]") {
    // A thin bar moving along x at 1 unit per clock unit, at x = 0 at
    // clock 0.25 (frame 2's clock); cyclic, 4 frames, full shutter: frame
    // 2's exposure spans a quarter of the clock. The brightness-weighted
    // mean column is where the bar is at the middle of the exposure.
    const std::string scene =
        kFlatView +
        "box { <-0.02, -1, 0>, <0.02, 1, 1> pigment { rgb 1 } finish { ambient 1 diffuse 0 }\n"
        "      translate x * (clock - 0.25) }\n";
    const auto mean_x = [&](rt::ShutterPosition position) {
        rt::Animation a = make(4, 0.0, 1.0, true, position);
        a.width = 96;
        const tr::Image image = render(scene, a, 2, 16);
        double sum = 0.0, weight = 0.0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const auto c = image.at(x, y);
                const double b = (c[0] + c[1] + c[2]) / 3.0;
                sum += b * (x + 0.5);
                weight += b;
            }
        // Column back to x: (column / W - 0.5) 3.
        return (sum / weight / image.width - 0.5) * 3.0;
    };
    // Start: the bar from 0 to 0.25 (middle 0.125); centre: -0.125 to
    // 0.125 (middle 0, the bar's place at clock 0.25); end: -0.25 to 0.
    // (16 samples a pixel over a quarter-unit sweep: the mean lands within
    // a few hundredths of the middle.)
    CHECK(mean_x(rt::ShutterPosition::Start) == Approx(0.125).margin(0.02));
    CHECK(mean_x(rt::ShutterPosition::Centre) == Approx(0.0).margin(0.02));
    CHECK(mean_x(rt::ShutterPosition::End) == Approx(-0.125).margin(0.02));
}

TEST_CASE("the shutter position flag takes start, centre or center and end, and names a bad one",
          "[tracer][shutter][app]") {
    const auto resolve = [](const std::string& position, bool beyond) {
        hexant::app::SceneArguments arguments;
        arguments.files = {"a.pov"};
        arguments.shutter_position = position;
        arguments.shutter_beyond_range = beyond;
        return hexant::app::resolve(arguments).options.animation;
    };
    CHECK(resolve("start", false).shutter_position == rt::ShutterPosition::Start);
    CHECK(resolve("centre", false).shutter_position == rt::ShutterPosition::Centre);
    CHECK(resolve("center", false).shutter_position == rt::ShutterPosition::Centre);
    CHECK(resolve("end", true).shutter_position == rt::ShutterPosition::End);
    CHECK(resolve("end", true).shutter_beyond_range);
    CHECK_FALSE(resolve("end", false).shutter_beyond_range);
    CHECK_THROWS_WITH(resolve("middle", false),
                      Catch::Contains("--shutter-position") && Catch::Contains("'middle'"));
}
