// The shutter's shape (runtime/scene/shutter_curve.hpp) and the rolling shutter
// (runtime/scene/animation.hpp): a curve draws the samples' times with its
// density, a box changes nothing, and a rolling shutter slants a vertical
// bar that moves sideways by the angle its readout time gives.
#include <cmath>
#include <random>
#include <string>

#include <catch2/catch.hpp>

#include "app/command_line.hpp"
#include "language/interpreter.hpp"
#include "runtime/scene/shutter_curve.hpp"
#include "tracer/renderer.hpp"

// The scenes use POV-Ray 3.7's rules (without #version, POV-Ray reads a
// scene with its legacy gamma rule).
constexpr const char* kVersion37 = "#version 3.7;\n";

namespace rt = hexant::runtime;
namespace tr = hexant::tracer;

namespace {

// W(u), the curve's integral from 0, by the midpoint rule on a fine grid
// (independent of the closed form the warp inverts).
double integral(const rt::ShutterCurve& curve, double u) {
    const auto& k = curve.keys();
    const auto w = [&](double x) {
        for (std::size_t i = 1; i < k.size(); ++i)
            if (x <= k[i].u)
                return k[i - 1].weight +
                       (k[i].weight - k[i - 1].weight) * (x - k[i - 1].u) / (k[i].u - k[i - 1].u);
        return k.back().weight;
    };
    constexpr int kSteps = 200000;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) sum += w((i + 0.5) / kSteps * u);
    return sum * u / kSteps;
}

tr::Image render(const char* text, const rt::Animation& animation, int spp) {
    hexant::language::ParseOptions options;
    options.animation = animation;
    const auto scene = hexant::language::parse_scene_text(std::string(kVersion37) + text,
                                                          "shutter-test.pov", options);
    tr::RenderSettings settings;
    settings.samples_per_pixel = spp;
    tr::Renderer renderer(scene, settings);
    return renderer.render_frame(animation.initial_frame);
}

rt::Animation two_frames(int width, int height) {
    rt::Animation a;
    a.width = width;
    a.height = height;
    a.initial_frame = 1;
    a.final_frame = 2;
    a.initial_clock = 0.0;
    a.final_clock = 1.0;  // frame 1 opens at 0, clock_delta 1
    return a;
}

double brightness(const tr::Image& image, int x, int y) {
    const auto c = image.at(x, y);
    return (c[0] + c[1] + c[2]) / 3.0;
}

// Seen from <0, 0, -10> along +z with a direction of length 10, the plane
// z = 0 shows x and y from -0.5 to 0.5 across the image: pixel column
// (x + 0.5) W.
const char* kFlatView = R"(
camera { location <0, 0, -10> direction <0, 0, 10> right x up y }
light_source { <0, 0, -100>, rgb 1 }
background { rgb 0 }
)";

}  // namespace

TEST_CASE("a shutter curve's warp inverts its integral", "[tracer][shutter]") {
    for (const std::string text :
         {"triangle", "trapezoid", "0:0,1:1", "0:2,0.3:0,0.7:0,1:1", "0:0,0.1:1,0.9:1,1:0"}) {
        INFO(text);
        const rt::ShutterCurve curve = rt::ShutterCurve::parse(text);
        CHECK_FALSE(curve.is_box());
        const double total = integral(curve, 1.0);
        for (const double x : {0.0, 0.01, 0.125, 0.3, 0.5, 0.77, 0.999}) {
            const double u = curve.warp(x);
            CHECK(u >= 0.0);
            CHECK(u < 1.0);
            CHECK(integral(curve, u) == Approx(x * total).margin(1e-6));
        }
        // Monotone: stratification in the uniform coordinate carries over.
        double last = -1.0;
        for (int i = 0; i <= 1000; ++i) {
            const double u = curve.warp(i / 1000.0);
            CHECK(u >= last);
            last = u;
        }
    }
    // The triangle's first quarter holds an eighth of its area.
    CHECK(rt::ShutterCurve::parse("triangle").warp(0.125) == Approx(0.25).epsilon(1e-12));
}

TEST_CASE("a box shutter curve and no rolling give the sample times they always gave",
          "[tracer][shutter]") {
    // Today's formula, bit for bit: open + when * (shutter * clock_delta).
    rt::Animation a = two_frames(8, 8);
    a.initial_clock = 0.3;
    a.final_clock = 1.7;
    a.final_frame = 7;
    a.shutter = 0.37;
    // (The last frame's exposure as placed, not cut to Final_Clock.)
    a.shutter_beyond_range = true;
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (const std::string curve : {"box", "0:3,0.5:3,1:3"}) {
        a.shutter_curve = rt::ShutterCurve::parse(curve);
        REQUIRE(a.shutter_curve.is_box());
        for (int i = 0; i < 1000; ++i) {
            const int frame = 1 + i % 7;
            const double when = uniform(random), row = uniform(random);
            const double today = a.clock_of_frame(frame) + when * (a.shutter * a.clock_delta());
            CHECK(a.sample_time(frame, row, when) == today);
        }
    }
    // And the images: a box written as keys renders the default's pixels.
    const std::string scene = std::string(kFlatView) +
                              "sphere { <-0.3 + 0.6 * clock, 0, 0>, 0.1 pigment { rgb 1 } finish { "
                              "ambient 1 diffuse 0 } }";
    rt::Animation keyed = two_frames(24, 24);
    keyed.shutter_curve = rt::ShutterCurve::parse("0:1,1:1");
    const tr::Image plain = render(scene.c_str(), two_frames(24, 24), 8);
    const tr::Image boxed = render(scene.c_str(), keyed, 8);
    CHECK(plain.rgb == boxed.rgb);
}

TEST_CASE("a shutter curve weights the samples' times: a ramp blurs toward the late end",
          "[tracer][shutter]") {
    // A small glowing sphere sweeps x from -0.3 to 0.3 over the shutter.
    // Its smear's brightness-weighted centre lies where the sphere is at
    // the mean time of the curve's density: 1/2 for the box, 2/3 for the
    // ramp 0:0,1:1 (w(u) = u, mean of u^2 / (1/2) = 2/3).
    const std::string scene = std::string(kFlatView) +
                              "sphere { <-0.3 + 0.6 * clock, 0, 0>, 0.05 pigment { rgb 1 } finish "
                              "{ ambient 1 diffuse 0 } }";
    constexpr int kSize = 64;
    const auto centre = [&](const rt::Animation& a) {
        const tr::Image image = render(scene.c_str(), a, 64);
        double sum = 0.0, weighted = 0.0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                sum += brightness(image, x, y);
                weighted += brightness(image, x, y) * (x + 0.5);
            }
        return weighted / sum / kSize - 0.5;  // in scene units on z = 0
    };
    rt::Animation box = two_frames(kSize, kSize);
    rt::Animation ramp = box;
    ramp.shutter_curve = rt::ShutterCurve::parse("0:0,1:1");
    // (Tolerance: a tenth of a pixel; the smear's sampling noise at 64
    // samples is far below that over its ~1,000 lit pixels.)
    CHECK(centre(box) == Approx(0.0).margin(0.1 / kSize));
    CHECK(centre(ramp) == Approx(-0.3 + 0.6 * 2.0 / 3.0).margin(0.1 / kSize));
}

TEST_CASE("a rolling shutter slants a vertical bar moving sideways by its readout time",
          "[tracer][shutter]") {
    // The bar moves at v = 0.5 scene units per clock unit; the shutter is
    // an instant, the rows open over 0.5 of the clock step (1): the bottom
    // row sees the bar 0.25 further right than the top row. On z = 0 a
    // scene unit is the image's width, so the bar's column shifts by
    // 0.25 W over H rows: a slope of 0.25 W / H columns per row, the bar
    // leaning by atan(0.25) from the vertical.
    const std::string scene =
        std::string(kFlatView) +
        "box { <-0.03, -1, -0.01>, <0.03, 1, 0.01> translate x * (-0.125 + 0.5 * clock) "
        "pigment { rgb 1 } finish { ambient 1 diffuse 0 } }";
    constexpr int kWidth = 96, kHeight = 64;
    rt::Animation a = two_frames(kWidth, kHeight);
    a.shutter = 0.0;
    a.rolling_shutter = 0.5;
    const tr::Image image = render(scene.c_str(), a, 16);
    // Each row's bar centre (brightness-weighted column), then the least
    // squares slope of centre against row.
    double sy = 0, sx = 0, syy = 0, sxy = 0;
    for (int y = 0; y < kHeight; ++y) {
        double sum = 0.0, weighted = 0.0;
        for (int x = 0; x < kWidth; ++x) {
            sum += brightness(image, x, y);
            weighted += brightness(image, x, y) * (x + 0.5);
        }
        REQUIRE(sum > 0.0);
        const double centre = weighted / sum, row = y + 0.5;
        sy += row;
        sx += centre;
        syy += row * row;
        sxy += row * centre;
    }
    const double slope = (kHeight * sxy - sy * sx) / (kHeight * syy - sy * sy);
    const double expected = 0.25 * kWidth / kHeight;
    // (1%: each row's centre is exact to a small fraction of a pixel at 16
    // samples; over 64 rows the fitted slope's error is far below that.)
    CHECK(slope == Approx(expected).epsilon(0.01));
    CHECK(std::atan(slope * kHeight / kWidth) * 180.0 / M_PI ==
          Approx(std::atan(0.25) * 180.0 / M_PI).epsilon(0.01));
    // A global shutter: upright.
    a.rolling_shutter = 0.0;
    const tr::Image upright = render(scene.c_str(), a, 16);
    double top = 0, bottom = 0, top_sum = 0, bottom_sum = 0;
    for (int x = 0; x < kWidth; ++x) {
        top += brightness(upright, x, 0) * x;
        top_sum += brightness(upright, x, 0);
        bottom += brightness(upright, x, kHeight - 1) * x;
        bottom_sum += brightness(upright, x, kHeight - 1);
    }
    CHECK(top / top_sum == Approx(bottom / bottom_sum).margin(0.05));
}

TEST_CASE(
    "the shutter curve and rolling shutter flags refuse what they cannot use, naming the fault",
    "[tracer][shutter][app]") {
    const auto resolve = [](const std::string& curve, double rolling) {
        hexant::app::SceneArguments arguments;
        arguments.files = {"a.pov"};
        if (!curve.empty()) arguments.shutter_curve = curve;
        arguments.rolling_shutter = rolling;
        return hexant::app::resolve(arguments);
    };
    CHECK(resolve("trapezoid", 0.25).options.animation.rolling_shutter == 0.25);
    CHECK_FALSE(resolve("trapezoid", 0.0).options.animation.shutter_curve.is_box());
    CHECK_THROWS_WITH(resolve("round", 0.0),
                      Catch::Contains("--shutter-curve") && Catch::Contains("'round'"));
    CHECK_THROWS_WITH(resolve("0:1,0.5:-1,1:1", 0.0),
                      Catch::Contains("key 2") && Catch::Contains("at least 0"));
    CHECK_THROWS_WITH(resolve("0:1,0.7:1,0.5:1,1:1", 0.0),
                      Catch::Contains("key 3") && Catch::Contains("increase"));
    CHECK_THROWS_WITH(resolve("0.1:1,1:1", 0.0), Catch::Contains("begin at time 0"));
    CHECK_THROWS_WITH(resolve("0:0,1:0", 0.0), Catch::Contains("open somewhere"));
    CHECK_THROWS_WITH(resolve("0:nan,1:1", 0.0), Catch::Contains("finite"));
    CHECK_THROWS_WITH(resolve("", 1.5), Catch::Contains("--rolling-shutter"));
    CHECK_THROWS_WITH(resolve("", std::nan("")), Catch::Contains("--rolling-shutter"));
}
