// hexant against POV-Ray 3.7 on a static scene: with one sample at each
// pixel's centre at the frame's clock (--spp 1 --no-jitter --shutter 0),
// hexant's image must match the one POV-Ray made of the same scene (stored
// here; the command that made it is in pov_reference/README.md).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tracer/image_format.hpp"

namespace {

namespace fs = std::filesystem;
const fs::path kFolder = fs::path(HEXANT_SOURCE_DIR) / "tests/tracer/pov_reference";

struct Pixels {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
};

Pixels read_png(const fs::path& path) {
    const hexant::tracer::StoredImage in = hexant::tracer::read_stored_image(path);
    REQUIRE(in.channels == 3);
    Pixels p{in.width, in.height, std::vector<unsigned char>(in.values.size())};
    for (std::size_t i = 0; i < in.values.size(); ++i)
        p.rgb[i] = static_cast<unsigned char>(std::lround(in.values[i] * 255.0f));
    return p;
}

}  // namespace

TEST_CASE("a still agrees with POV-Ray 3.7's render of it pixel by pixel", "[tracer][pov]") {
    const fs::path out = fs::temp_directory_path() / "hexant_pov_still.png";
    fs::remove(out);
    const std::string command = std::string(HEXANT_BINARY) + " render " +
                                (kFolder / "still.pov").string() +
                                " -W 96 -H 72 --spp 1 --no-jitter --shutter 0 -o " + out.string() +
                                " > /dev/null";
    REQUIRE(std::system(command.c_str()) == 0);
    const Pixels ours = read_png(out);
    const Pixels pov = read_png(kFolder / "still.pov.png");
    REQUIRE(ours.width == pov.width);
    REQUIRE(ours.height == pov.height);
    // Per pixel, the largest channel difference in 8-bit sRGB steps.
    int within = 0, total = ours.width * ours.height, worst = 0;
    double sum = 0.0;
    for (int i = 0; i < total; ++i) {
        int d = 0;
        for (int c = 0; c < 3; ++c)
            d = std::max(d, std::abs(int(ours.rgb[i * 3 + c]) - int(pov.rgb[i * 3 + c])));
        worst = std::max(worst, d);
        sum += d;
        if (d <= 2) ++within; else if (std::getenv("HEXANT_POV_DIFF")) std::printf("%d %d: %d  ours %d %d %d pov %d %d %d\n", i % ours.width, i / ours.width, d, ours.rgb[i*3], ours.rgb[i*3+1], ours.rgb[i*3+2], pov.rgb[i*3], pov.rgb[i*3+1], pov.rgb[i*3+2]);
    }
    INFO("within " << within << " of " << total << ", mean " << sum / total << ", worst " << worst);
    // Tolerance: 2 steps of 8-bit sRGB per channel (POV-Ray keeps colours in
    // single precision and rounds its own way: one step either side of the
    // rounding point) for at least 99.8% of the pixels; the other 0.2% (13
    // pixels) may be pixel centres within rounding of an edge, where either
    // colour is right. When this was written every pixel was within 2 steps
    // (mean 0.1); a systematic error (a half-pixel shift, a wrong gamma, a
    // lighting term, the checker's edges) moves dozens to thousands.
    // HEXANT_POV_DIFF=1 lists the pixels beyond the tolerance.
    CHECK(within >= total * 998 / 1000);
    CHECK(sum / total < 0.2);
}
