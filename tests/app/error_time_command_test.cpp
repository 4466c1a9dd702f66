// `hexant bench error-time`: a CSV and a plot with one curve per mode, the
// error falling as samples grow, the reference cached, bad lists refused.
#include "app/error_time_command.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "app/log_log_plot.hpp"
#include "tracer/renderer.hpp"

namespace fs = std::filesystem;
using hexant::app::ErrorTimeArguments;
using hexant::app::run_error_time;

namespace {

std::string read_text(const fs::path& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("error-time measures each mode at each sample count against a cached reference",
          "[app][bench]") {
    const fs::path folder = fs::temp_directory_path() / "hexant_error_time_test";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const fs::path scene = folder / "moving.pov";
    std::ofstream(scene) << "camera { location <0, 0, -5> look_at 0 }\n"
                            "light_source { <0, 5, -5>, rgb 1 }\n"
                            "sphere { <2 * clock - 1, 0, 0>, 0.8 pigment { rgb <1, 0.5, 0.2> } }\n"
                            "plane { z, 1 pigment { checker rgb 1, rgb 0.2 scale 0.5 } }\n";
    ErrorTimeArguments a;
    a.scene.files = {scene.string()};
    a.scene.width = 24;
    a.scene.height = 16;
    a.scene.frame_count = 3;
    a.spp_list = "4,1";
    a.reference_spp = 64;
    a.output_dir = (folder / "out").string();
    std::ostringstream out, err;
    REQUIRE(run_error_time(a, out, err) == 0);
    INFO(out.str() << err.str());

    // One row per mode and sample count.
    const std::string csv = read_text(folder / "out/error_time.csv");
    REQUIRE(
        csv.rfind(
            "mode,spp,seconds,build_seconds,render_seconds,rays,rmse,relative_mse,estimated_rmse,"
            "target,mean_spp\n",
            0) == 0);
    std::map<std::string, double> rmse;           // "mode spp" -> rmse
    std::map<std::string, std::string> estimate;  // "mode spp" -> the estimate's field
    std::istringstream rows(csv);
    std::string row;
    std::getline(rows, row);
    while (std::getline(rows, row)) {
        std::istringstream fields(row);
        std::string mode, spp, skip, value;
        std::getline(fields, mode, ',');
        std::getline(fields, spp, ',');
        for (int i = 0; i < 4; ++i) std::getline(fields, skip, ',');
        std::getline(fields, value, ',');
        rmse[mode + " " + spp] = std::stod(value);
        std::getline(fields, skip, ',');  // relative MSE
        std::getline(fields, estimate[mode + " " + spp], ',');
    }
    REQUIRE(rmse.size() == 4);
    // More samples, less error; the modes trace the same samples, so their
    // errors agree (up to ties between equal distances).
    CHECK(rmse["spacetime 4"] < rmse["spacetime 1"]);
    CHECK(rmse["frames 4"] < rmse["frames 1"]);
    CHECK(rmse["spacetime 1"] == Approx(rmse["frames 1"]).epsilon(1e-6));
    CHECK(rmse["spacetime 4"] > 0.0);
    // A count of 2 or more estimates its own error (its blocks), one
    // sample not; the modes trace the same samples, so their estimates are
    // equal.
    CHECK(estimate["spacetime 1"].empty());
    REQUIRE(!estimate["spacetime 4"].empty());
    CHECK(std::stod(estimate["spacetime 4"]) > 0.0);
    CHECK(estimate["spacetime 4"] == estimate["frames 4"]);
    CHECK(out.str().find("estimated") != std::string::npos);

    const std::string svg = read_text(folder / "out/error_time.svg");
    // Each mode's measured curve, and its estimate dashed beside it.
    CHECK(count_of(svg, "<polyline") == 4);
    CHECK(count_of(svg, "stroke-dasharray") == 4);  // two curves, two legend lines
    CHECK(svg.find("spacetime") != std::string::npos);

    // The reference is rendered once.
    out.str("");
    REQUIRE(run_error_time(a, out, err) == 0);
    CHECK(out.str().find("(cached)") != std::string::npos);
    // ... and again for another shutter: its curve or a rolling shutter
    // change the image (a fresh user found the cached one reused).
    for (const auto& [curve, rolling] :
         {std::pair<std::string, double>{"triangle", 0.0}, {"box", 0.5}}) {
        ErrorTimeArguments other = a;
        other.scene.shutter_curve = curve;
        other.scene.rolling_shutter = rolling;
        out.str("");
        REQUIRE(run_error_time(other, out, err) == 0);
        CHECK(out.str().find("(cached)") == std::string::npos);
    }

    // Adaptive sampling at a target: a row of its own, its true error and
    // what uniform sampling needs for it.
    a.spp_list = "2,8,32";
    a.reference_spp = 256;
    a.modes = "spacetime";
    a.targets = "0.02";
    out.str("");
    REQUIRE(run_error_time(a, out, err) == 0);
    CHECK(out.str().find("target 2.000e-02: ") != std::string::npos);
    CHECK(out.str().find("uniform needs") != std::string::npos);
    CHECK(out.str().find("slope: rmse ~ spp^-") != std::string::npos);
    const std::string with_target = read_text(folder / "out/error_time.csv");
    const auto at = with_target.find(",0.02,");
    REQUIRE(at != std::string::npos);
    // (Its mean samples per pixel: at least the first round's, at most
    // the ceiling, the largest of --spp-list.)
    const double mean = std::stod(with_target.substr(at + 6));
    CHECK(mean >= hexant::tracer::RenderSettings::kFirstRoundSamples);
    CHECK(mean <= 32.0);
    CHECK(count_of(read_text(folder / "out/error_time.svg"), "stroke-dasharray=\"2,3\"") == 2);
    // (A fraction as --target-error takes it.)
    a.targets = "1/50";
    out.str("");
    REQUIRE(run_error_time(a, out, err) == 0);
    CHECK(out.str().find("target 2.000e-02: ") != std::string::npos);
    for (const char* bad : {"0", "x", "0.1,", "-1", "0x10", "1/0"}) {
        a.targets = bad;
        err.str("");
        CHECK(run_error_time(a, out, err) != 0);
        CHECK(err.str().find("--targets") != std::string::npos);
    }
    a.targets = "0.02";
    a.spp_list = "1";
    err.str("");
    CHECK(run_error_time(a, out, err) != 0);
    CHECK(err.str().find("must be 2 or more") != std::string::npos);
    a.targets.clear();
    a.modes = "spacetime,frames";

    // Bad requests name the flag.
    for (const char* bad : {"1,,2", "0", "x", "2000000"}) {
        a.spp_list = bad;
        err.str("");
        CHECK(run_error_time(a, out, err) != 0);
        CHECK(err.str().find("--spp-list") != std::string::npos);
    }
    a.spp_list = "1";
    a.modes = "frames,frames";
    err.str("");
    CHECK(run_error_time(a, out, err) != 0);
    CHECK(err.str().find("frames is named twice") != std::string::npos);
    a.modes = "spacetime,fast";
    err.str("");
    CHECK(run_error_time(a, out, err) != 0);
    CHECK(err.str().find("fast") != std::string::npos);
    a.modes = "spacetime";
    a.frame = 7;
    err.str("");
    CHECK(run_error_time(a, out, err) != 0);
    CHECK(err.str().find("--frame 7") != std::string::npos);
    // --repeat renders each point again for the median time: still one
    // row a point, the same error (every run makes the same image).
    a.frame.reset();
    a.spp_list = "4";
    a.repeat = 3;
    out.str("");
    REQUIRE(run_error_time(a, out, err) == 0);
    const std::string repeated = read_text(folder / "out/error_time.csv");
    CHECK(count_of(repeated, "\nspacetime,4,") == 1);
    CHECK(count_of(out.str(), "spp     4 ") == 1);
    fs::remove_all(folder);
}

TEST_CASE("a log-log plot leaves out points it cannot place", "[app][bench]") {
    hexant::app::LogLogPlot plot;
    plot.title = "a < b";
    plot.curves.push_back({"one", "red", {{1.0, 0.1}, {10.0, 0.01}, {0.0, 1.0}, {5.0, -1.0}}});
    const std::string svg = hexant::app::to_svg(plot);
    CHECK(count_of(svg, "<circle") == 2);
    CHECK(svg.find("a &lt; b") != std::string::npos);
    CHECK(svg.find("nan") == std::string::npos);
    CHECK(svg.find("inf") == std::string::npos);
}

TEST_CASE("error-time on a frame without error prints no NaN", "[app][bench]") {
    // Only a background: every image equals the reference; an estimate
    // against a true error of 0 has no ratio, and no time to reach 0.
    const fs::path folder = fs::temp_directory_path() / "hexant_error_time_flat_test";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const fs::path scene = folder / "flat.pov";
    std::ofstream(scene) << "camera { location <0, 0, -5> look_at 0 }\nbackground { rgb 0.5 }\n";
    ErrorTimeArguments a;
    a.scene.files = {scene.string()};
    a.scene.width = 16;
    a.scene.height = 16;
    a.scene.frame_count = 2;
    a.spp_list = "2,8";
    a.reference_spp = 32;
    a.targets = "0.01";
    a.output_dir = (folder / "out").string();
    std::ostringstream out, err;
    REQUIRE(run_error_time(a, out, err) == 0);
    INFO(out.str());
    CHECK(out.str().find("nan") == std::string::npos);
    CHECK(out.str().find("rmse 0.000e+00") != std::string::npos);
    fs::remove_all(folder);
}
