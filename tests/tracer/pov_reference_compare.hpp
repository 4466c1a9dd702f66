// hexant against POV-Ray 3.7's recorded renders: reading them, rendering
// hexant's image of the same scene and comparing the two pixel by pixel
// (shared by the tests of tests/tracer/pov_reference/; its README says how
// the images are made).
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "image/image_format.hpp"

namespace hexant::test::pov_reference {

namespace fs = std::filesystem;
inline const fs::path kFolder = fs::path(HEXANT_SOURCE_DIR) / "tests/tracer/pov_reference";

struct Pixels {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
};

inline Pixels read_png(const fs::path& path) {
    const hexant::image::StoredImage in = hexant::image::read_stored_image(path);
    REQUIRE(in.channels == 3);
    Pixels p{in.width, in.height, std::vector<unsigned char>(in.values.size())};
    for (std::size_t i = 0; i < in.values.size(); ++i)
        p.rgb[i] = static_cast<unsigned char>(std::lround(in.values[i] * 255.0f));
    return p;
}

// Per pixel, the largest channel difference in 8-bit sRGB steps.
struct Agreement {
    int within = 0, total = 0, worst = 0;
    double mean = 0.0;
};

inline Agreement agree(const Pixels& ours, const Pixels& pov) {
    REQUIRE(ours.width == pov.width);
    REQUIRE(ours.height == pov.height);
    Agreement a;
    a.total = ours.width * ours.height;
    double sum = 0.0;
    for (int i = 0; i < a.total; ++i) {
        int d = 0;
        for (int c = 0; c < 3; ++c)
            d = std::max(d, std::abs(int(ours.rgb[i * 3 + c]) - int(pov.rgb[i * 3 + c])));
        a.worst = std::max(a.worst, d);
        sum += d;
        if (d <= 2)
            ++a.within;
        else if (std::getenv("HEXANT_POV_DIFF"))
            std::printf("%d %d: %d  ours %d %d %d pov %d %d %d\n", i % ours.width, i / ours.width,
                        d, ours.rgb[i * 3], ours.rgb[i * 3 + 1], ours.rgb[i * 3 + 2],
                        pov.rgb[i * 3], pov.rgb[i * 3 + 1], pov.rgb[i * 3 + 2]);
    }
    a.mean = sum / a.total;
    return a;
}

// Tolerance: 2 steps of 8-bit sRGB per channel (POV-Ray keeps colours in
// single precision and rounds its own way: one step either side of the
// rounding point) for at least 99.8% of the pixels; the other 0.2% (13
// pixels) may be pixel centres within rounding of an edge, where either
// colour is right. When this was written every pixel of the still was
// within 2 steps (mean 0.1); a systematic error (a half-pixel shift, a
// wrong gamma, a lighting term, the checker's edges, an object that should
// or should not be there) moves dozens to thousands.
// HEXANT_POV_DIFF=1 lists the pixels beyond the tolerance.
// At least `per_mille` of the pixels within 2 steps and a mean below
// `mean` (the still's tolerance by default; a looser one is argued where
// it is used).
inline void check_agreement(const Agreement& a, int per_mille = 998, double mean = 0.2) {
    INFO("within " << a.within << " of " << a.total << ", mean " << a.mean << ", worst "
                   << a.worst);
    CHECK(a.within >= a.total * per_mille / 1000);
    CHECK(a.mean < mean);
}

// What `command` (its stderr joined to stdout) printed, and whether it
// exited with 0.
struct Ran {
    bool ok = false;
    std::string said;
};
inline Ran run_command(const std::string& command) {
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    REQUIRE(pipe != nullptr);
    Ran r;
    char buffer[256];
    while (fgets(buffer, sizeof buffer, pipe)) r.said += buffer;
    r.ok = pclose(pipe) == 0;
    return r;
}

// The linear light of an 8-bit sRGB value.
inline double linear_light(unsigned char v) {
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// hexant's render with `flags`, written to a temporary PNG named `name`,
// frame number `frame` in its name (0: a still).
inline Pixels render(const fs::path& scene, const std::string& flags, const std::string& name,
                     int frame, const std::string& size = "-W 96 -H 72",
                     const std::string& sampling = "--spp 1 --no-jitter") {
    const fs::path pattern = fs::temp_directory_path() / (name + (frame ? "_####.png" : ".png"));
    char number[16];
    std::snprintf(number, sizeof number, "_%04d.png", frame);
    const fs::path out = frame ? fs::temp_directory_path() / (name + number) : pattern;
    fs::remove(out);
    const std::string command = std::string(HEXANT_BINARY) + " render " + scene.string() + " " +
                                size + " " + sampling + " --shutter 0 " + flags + " -o " +
                                pattern.string() + " > /dev/null";
    REQUIRE(std::system(command.c_str()) == 0);
    return read_png(out);
}

// A 64 by 48 still of `folder/name.pov` at each clock (plus `flags`) against
// POV-Ray's `folder/name_<clock>.png`, with the still's tolerance.
inline void check_stills(const std::string& folder, const std::string& name,
                         std::initializer_list<const char*> clocks, const std::string& flags = "") {
    for (const char* clock : clocks) {
        INFO(name << " at clock " << clock);
        check_agreement(agree(
            render(kFolder / folder / (name + ".pov"), "--clock " + std::string(clock) + flags,
                   "hexant_pov_" + name, 0, "-W 64 -H 48"),
            read_png(kFolder / folder / (name + "_" + clock + ".png"))));
    }
}

}  // namespace hexant::test::pov_reference
