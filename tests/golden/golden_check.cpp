// hexant_golden: renders some frames of an example at a small size and
// compares each with its stored golden image; with --update, stores them as
// the new golden images instead (`make golden`, never automatic).
//
// On a failure it leaves the new frame and a difference image (|new - golden|
// times 4) in --out-dir, and prints both paths for a person to look at.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/render_command.hpp"
#include "tracer/image_compare.hpp"
#include "tracer/image_output.hpp"

namespace fs = std::filesystem;
namespace tr = hexant::tracer;

namespace {

struct Tolerance {
    double fail = 0.0;           // in linear light: no pixel may differ more
    double warn = 2.0 / 255.0;   // in 8-bit sRGB: a pixel beyond this "warns"
    double max_warning = 0.005;  // fraction of the pixels that may warn
};

std::vector<int> frame_list(const std::string& text) {
    std::vector<int> frames;
    std::stringstream items(text);
    std::string item;
    while (std::getline(items, item, ',')) frames.push_back(std::stoi(item));
    return frames;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App cli{"Render frames of an example and compare them with its golden images"};
    std::string scene, ini, frames, golden_dir, out_dir;
    int size = 96, spp = 8;
    bool update = false;
    cli.add_option("--scene", scene, "The example's .pov file")->required();
    cli.add_option("--ini", ini, "Its .ini file")->required();
    cli.add_option("--frames", frames, "Comma list of frames")->required();
    cli.add_option("--size", size, "Width and height in pixels");
    cli.add_option("--spp", spp, "Samples per pixel")->check(CLI::Range(1, 4096));
    cli.add_option("--golden-dir", golden_dir, "Where the golden images are stored")->required();
    cli.add_option("--out-dir", out_dir, "Where the new frames (and differences) go")->required();
    cli.add_flag("--update", update, "Store the new frames as the golden images");
    CLI11_PARSE(cli, argc, argv);

    // The tolerance. The frames are deterministic (each sample is seeded by
    // frame, pixel and index), so the machine that made the golden images
    // renders them again bit for bit, and any difference there is a change.
    // Another compiler, libm or CPU may round differently: a shade then moves
    // by at most one 8-bit step, and a sample may cross an edge or a shadow's
    // border, which changes its pixel by at most that sample's share of the
    // light, 1/spp of the largest contrast (1.0, in linear light). So:
    // - in linear light, no pixel may differ by more than 1/spp plus two
    //   8-bit steps (0.02 at the bright end): one sample cannot explain it;
    // - in 8-bit sRGB, at most 0.5% of the pixels (46 of 96 x 96) may differ
    //   by more than 2 steps: edges where single samples flipped.
    // For scale, the noise of these images at 8 spp (their difference from
    // 256-spp renders of the same frames, measured when they were made)
    // moves 5% (dino) to 56% (glider) of the pixels by more than 2 steps, so
    // a change in lighting, camera, motion or sampling fails by far.
    Tolerance tolerance;
    tolerance.fail = 1.0 / spp + 0.02;

    hexant::app::RenderArguments render;
    render.scene.files = {scene, ini};
    render.scene.width = size;
    render.scene.height = size;
    render.frames = frames;
    render.samples_per_pixel = spp;
    render.output = (fs::path(out_dir) / "frame_####.png").string();
    std::ostringstream render_out;
    if (const int status = hexant::app::run_render(render, render_out, std::cerr); status != 0)
        return status;

    int failures = 0;
    for (const int frame : frame_list(frames)) {
        const fs::path fresh = tr::frame_path(*render.output, frame);
        const fs::path golden =
            tr::frame_path((fs::path(golden_dir) / "frame_####.png").string(), frame);
        if (update) {
            fs::create_directories(golden.parent_path());
            fs::copy_file(fresh, golden, fs::copy_options::overwrite_existing);
            std::cout << "stored " << golden.string() << "\n";
            continue;
        }
        if (!fs::exists(golden)) {
            std::cout << "frame " << frame << ": no golden image " << golden.string()
                      << " (make golden stores one)\n";
            ++failures;
            continue;
        }
        const tr::ImageDifference linear = tr::compare_images(
            fresh, golden, tolerance.fail, tolerance.fail, tr::ImageSpace::Linear);
        const tr::ImageDifference stored =
            tr::compare_images(fresh, golden, tolerance.warn, tolerance.warn);
        const double warning_fraction = double(stored.warning) / double(stored.pixels);
        const bool ok = linear.failing == 0 && warning_fraction <= tolerance.max_warning;
        std::printf(
            "frame %d: %s  rms %.5f, max %.4f at (%d, %d) in 8-bit sRGB; "
            "%zu pixels beyond %.3f in linear light (none allowed), "
            "%zu beyond 2 steps (%.2f%%, up to %.2f%% allowed)\n",
            frame, ok ? "ok" : "DIFFERENT", stored.rms, stored.max, stored.max_x, stored.max_y,
            linear.failing, tolerance.fail, stored.warning, 100.0 * warning_fraction,
            100.0 * tolerance.max_warning);
        if (!ok) {
            const fs::path difference =
                fs::path(out_dir) / ("difference_" + fresh.filename().string());
            tr::write_difference_image(fresh, golden, difference, 4.0);
            std::cout << "  new image:  " << fresh.string() << "\n  golden:     " << golden.string()
                      << "\n  difference: " << difference.string() << " (x4)\n";
            ++failures;
        }
    }
    return failures == 0 ? 0 : 1;
}
