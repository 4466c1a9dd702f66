#include "app/error_time_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <vector>

#include "app/log_log_plot.hpp"
#include "app/povray_render_options.hpp"
#include "app/render_command.hpp"
#include "app/scene_reading.hpp"
#include "language/interpreter.hpp"
#include "tracer/image_compare.hpp"
#include "tracer/image_output.hpp"
#include "tracer/renderer.hpp"
#include "tracer/whole_file.hpp"

namespace hexant::app {

namespace {

namespace fs = std::filesystem;

// The reference's samples are scrambled with their own seed, so that its
// noise is independent of every measured image's (which use seed 0).
constexpr std::uint32_t kReferenceSeed = 0x5eed;

// A comma list of `item`s (each parsed whole, or nothing when it is not
// one): --spp-list and --targets.
template <class T, class Parse>
std::vector<T> comma_list(const std::string& text, const char* flag, const char* expected,
                          Parse item) {
    std::vector<T> values;
    std::stringstream items(text +
                            ",");  // (every item ends with a comma: "1," has an empty last one)
    std::string one;
    while (std::getline(items, one, ',')) {
        std::optional<T> value;
        try {
            value = item(one);
        } catch (const std::exception&) {
        }
        if (!value)
            throw std::runtime_error(std::string(flag) + ": expected a comma list of " + expected +
                                     ", got '" + text + "'");
        values.push_back(*value);
    }
    return values;
}

std::vector<int> int_list(const std::string& text, const char* flag) {
    // (At most --spp's own limit, 2^20: the reference takes four times the largest.)
    return comma_list<int>(text, flag, "whole numbers from 1 to 1048576",
                           [](const std::string& item) {
                               std::size_t used = 0;
                               const int value = std::stoi(item, &used);
                               return used == item.size() && value >= 1 && value <= (1 << 20)
                                          ? std::optional<int>(value)
                                          : std::nullopt;
                           });
}

std::vector<tracer::Mode> mode_list(const std::string& text) {
    std::vector<tracer::Mode> modes;
    std::stringstream items(text);
    std::string item;
    while (std::getline(items, item, ',')) {
        const tracer::Mode mode = tracer::parse_mode(item);
        if (std::find(modes.begin(), modes.end(), mode) != modes.end())
            throw std::runtime_error("--modes " + text + ": " + item + " is named twice");
        modes.push_back(mode);
    }
    if (modes.empty()) throw std::runtime_error("--modes: no mode named");
    return modes;
}

std::string file_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// What the reference depends on: the scene and .ini texts, the settings that
// change the image, and the reference's sample count.
std::string reference_key(const ErrorTimeArguments& args, const runtime::SceneDescription& scene,
                          int frame, int reference_spp) {
    std::ostringstream key;
    key.precision(17);  // (two shutters that print alike at 6 digits differ)
    for (const auto& file : args.scene.files) {
        const fs::path path = file.substr(0, file.find('['));
        key << file << '\n' << file_text(path) << '\n';
    }
    key << scene.animation.width << 'x' << scene.animation.height << " frame " << frame << " spp "
        << reference_spp << " shutter " << scene.animation.shutter << " clock "
        << scene.animation.initial_clock << ':' << scene.animation.final_clock << " frames "
        << scene.animation.initial_frame << ':' << scene.animation.final_frame << " cyclic "
        << scene.animation.cyclic << " rolling " << scene.animation.rolling_shutter << " lead "
        << scene.animation.shutter_lead() << " beyond " << scene.animation.shutter_beyond_range
        << " curve";
    // (Every key of the shutter's curve, to the last bit; a box is keyless.)
    if (!scene.animation.shutter_curve.is_box())
        for (const auto& k : scene.animation.shutter_curve.keys())
            key << ' ' << std::hexfloat << k.u << ':' << k.weight;
    key << std::defaultfloat;  // (precision 17 still)
    for (const auto& d : args.scene.declares) key << " declare " << d;
    for (const auto& path : args.scene.include_paths) key << " include " << path;
    std::ostringstream hex;
    hex << std::hex << std::setw(16) << std::setfill('0') << std::hash<std::string>{}(key.str());
    return hex.str();
}

struct Point {
    tracer::Mode mode;
    int spp;
    double seconds, build_seconds, render_seconds;
    std::uint64_t rays;
    tracer::ImageError error;
    // The frame's own estimate of its RMSE (tracer/frame_estimate.hpp): at
    // every count of 2 or more.
    std::optional<double> estimate;
    double mean_spp = 0.0;         // samples per pixel taken (adaptive: the mean)
    std::optional<double> target;  // adaptive sampling's target
};

// Renders `frame` once and writes it; the build time is charged as the
// frame's share: spacetime builds one hierarchy for all the animation's
// frames, frames mode builds one per frame.
Point measure_once(const runtime::SceneDescription& scene, tracer::Mode mode, int spp, int frame,
                   const ErrorTimeArguments& args, const fs::path& image, std::uint32_t sample_seed,
                   std::optional<double> target) {
    tracer::RenderSettings settings;
    settings.mode = mode;
    settings.samples_per_pixel = spp;
    settings.sample_seed = sample_seed;
    if (target) settings.target_error = *target;
    settings.threads = args.threads;
    settings.build = args.hierarchy.options();
    settings.first_frame = settings.last_frame = frame;
    tracer::Renderer renderer(scene, settings);
    const tracer::Image rendered = renderer.render_frame(frame);
    tracer::write_image(rendered, image);
    const tracer::Counters& c = renderer.counters();
    // The renderer builds for this frame's time only (RenderSettings'
    // first and last frame), in either mode: its build is the frame's own,
    // charged whole.
    const double build_share = c.build_seconds;
    std::optional<double> estimate;
    if (renderer.last_estimate()) estimate = renderer.last_estimate()->rmse;
    const double mean_spp =
        double(renderer.last_sample_count()) / (double(rendered.width) * rendered.height);
    return {mode,
            spp,
            build_share + c.render_seconds,
            build_share,
            c.render_seconds,
            c.rays(),
            {},
            estimate,
            mean_spp,
            target};
}

// measure_once `repeat` times: the times are the median run's (every run
// makes the same image).
Point measure(const runtime::SceneDescription& scene, tracer::Mode mode, int spp, int frame,
              const ErrorTimeArguments& args, const fs::path& image, std::uint32_t sample_seed = 0,
              std::optional<double> target = std::nullopt, int repeat = 1) {
    std::vector<Point> runs;
    for (int r = 0; r < repeat; ++r)
        runs.push_back(measure_once(scene, mode, spp, frame, args, image, sample_seed, target));
    std::sort(runs.begin(), runs.end(),
              [](const Point& a, const Point& b) { return a.seconds < b.seconds; });
    return runs[runs.size() / 2];
}

const char* colour_of(tracer::Mode mode) {
    switch (mode) {
        case tracer::Mode::Spacetime:
            return "#d62728";
        case tracer::Mode::Frames:
            return "#1f77b4";
        default:
            return "#2ca02c";
    }
}

// Time (or with `samples`, samples per pixel) a mode needs to reach
// `error`: log-log interpolation between its points; nothing when the error
// lies outside them.
std::optional<double> time_for(const std::vector<Point>& points, tracer::Mode mode, double error,
                               bool samples = false) {
    std::vector<std::pair<double, double>> curve;  // (error, time)
    for (const Point& p : points)
        if (p.mode == mode) curve.emplace_back(p.error.rmse, samples ? p.mean_spp : p.seconds);
    for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
        const auto [e0, t0] = curve[i];
        const auto [e1, t1] = curve[i + 1];
        if ((e0 >= error && error >= e1) || (e1 >= error && error >= e0)) {
            if (e0 == e1) return t0;
            const double f = std::log(error / e0) / std::log(e1 / e0);
            return std::exp(std::log(t0) + f * std::log(t1 / t0));
        }
    }
    return std::nullopt;
}

// The least-squares slope of log y against log x over the points with
// both positive; nothing under two such points.
std::optional<double> log_log_slope(const std::vector<std::pair<double, double>>& xy) {
    double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (const auto& [x, y] : xy) {
        if (!(x > 0.0) || !(y > 0.0)) continue;
        const double u = std::log(x), v = std::log(y);
        n += 1.0;
        sx += u;
        sy += v;
        sxx += u * u;
        sxy += u * v;
    }
    const double d = n * sxx - sx * sx;
    if (n < 2.0 || !(d > 0.0)) return std::nullopt;
    return (n * sxy - sx * sy) / d;
}

}  // namespace

void add_error_time_arguments(CLI::App& command, ErrorTimeArguments& a) {
    add_scene_arguments(command, a.scene);
    command.add_option("--frame", a.frame, "The frame to measure (default: the middle one)");
    command.add_option("--spp-list", a.spp_list,
                       "Sample counts to measure (default 1,2,4,...,256)");
    command.add_option("--modes", a.modes, "Modes to measure (default spacetime,frames)");
    command
        .add_option("--reference-spp", a.reference_spp,
                    "Samples of the reference (default 4 times the largest measured)")
        ->check(CLI::Range(1, 1 << 20));
    command.add_option("-o,--output", a.output_dir,
                       "Folder for the CSV, the plot, the images and the cached reference "
                       "(default out/SCENE/error-time)");
    command.add_option("--threads", a.threads, "Worker threads (default: all cores)");
    command
        .add_option("--repeat", a.repeat,
                    "Render each point this many times and take the median time (default 1)")
        ->check(CLI::Range(1, 99));
    command.add_option(
        "--targets", a.targets,
        "Also render with adaptive sampling at these RMSE targets (a comma list, e.g. "
        "0.01,0.004; the largest of --spp-list is the ceiling) and print the samples and time "
        "uniform sampling needs for the same true error");
    add_hierarchy_arguments(command, a.hierarchy);
}

int run_error_time(const ErrorTimeArguments& args, std::ostream& out, std::ostream& err) {
    return run_reporting_errors(err, [&] {
        const ResolvedScene resolved = resolve(args.scene);
        for (const auto& warning : resolved.warnings) err << warning << "\n";
        note_render_only(resolved, "bench error-time", err);
        SceneReading reading(resolved, err);
        const runtime::Animation a = reading.scene().animation;
        const int frame = args.frame.value_or((a.initial_frame + a.final_frame) / 2);
        if (frame < a.initial_frame || frame > a.final_frame)
            throw std::runtime_error(
                "--frame " + std::to_string(frame) + ": the animation has frames " +
                std::to_string(a.initial_frame) + " to " + std::to_string(a.final_frame));
        // (A scene read frame by frame: that frame's reading.)
        const runtime::SceneDescription scene =
            reading.frame_by_frame() ? reading.read_frame(frame) : std::move(reading.scene());
        std::vector<int> spps = int_list(args.spp_list, "--spp-list");
        std::sort(spps.begin(), spps.end());
        spps.erase(std::unique(spps.begin(), spps.end()), spps.end());
        const std::vector<tracer::Mode> modes = mode_list(args.modes);
        std::vector<double> targets;
        if (!args.targets.empty()) {
            // (Each as --target-error reads it: a number or a fraction.)
            targets = comma_list<double>(args.targets, "--targets",
                                         "positive numbers or fractions such as 1/128",
                                         [](const std::string& item) {
                                             return std::optional<double>(parse_target_error(item));
                                         });
            if (spps.back() < 2)
                throw std::runtime_error(
                    "--targets: the largest of --spp-list is the ceiling and must be 2 or more "
                    "(the estimate compares blocks of a pixel's samples); it is " +
                    std::to_string(spps.back()));
        }
        const int reference_spp =
            args.reference_spp > 0 ? args.reference_spp : std::min(4 * spps.back(), 1 << 20);
        const fs::path dir = args.output_dir
                                 ? fs::path(*args.output_dir)
                                 : fs::path("out") / resolved.scene.stem() / "error-time";
        fs::create_directories(dir);

        // The reference, cached by what it depends on.
        const fs::path reference =
            dir / ("reference_" + reference_key(args, scene, frame, reference_spp) + ".exr");
        if (fs::exists(reference)) {
            out << "reference: " << reference.string() << " (cached)\n";
        } else {
            out << "reference: rendering frame " << frame << " at " << reference_spp
                << " samples per pixel ..." << std::flush;
            // (Its own seed: the reference is independent of every measured
            // image.)
            measure(scene, tracer::Mode::Spacetime, reference_spp, frame, args, reference,
                    kReferenceSeed);
            out << " " << reference.string() << "\n";
        }

        // Sample counts in the outer loop, modes inside: a slow spell of a
        // shared machine then falls on both modes alike.
        std::vector<Point> points;
        for (const int spp : spps) {
            for (const tracer::Mode mode : modes) {
                const fs::path image = dir / (std::string(tracer::mode_name(mode)) + "_spp" +
                                              std::to_string(spp) + ".exr");
                Point p =
                    measure(scene, mode, spp, frame, args, image, 0, std::nullopt, args.repeat);
                p.error = tracer::image_error(image, reference);
                points.push_back(p);
                out << std::left << std::setw(10) << tracer::mode_name(mode) << std::right
                    << " spp " << std::setw(5) << spp << "  " << std::fixed << std::setprecision(3)
                    << std::setw(8) << p.seconds << " s  rmse " << std::scientific
                    << std::setprecision(3) << p.error.rmse << "  estimated ";
                if (p.estimate) {
                    out << *p.estimate;
                    // (Against a true error of 0, a flat frame, no ratio.)
                    if (p.error.rmse > 0.0)
                        out << " (" << std::fixed << std::setprecision(2)
                            << *p.estimate / p.error.rmse << "x)";
                } else {
                    out << "-";
                }
                out << std::scientific << std::setprecision(3) << "  relMSE "
                    << p.error.relative_mse << std::defaultfloat << "\n";
            }
        }
        std::stable_sort(points.begin(), points.end(),
                         [](const Point& x, const Point& y) { return x.mode < y.mode; });
        // How fast the error falls, against samples and against time, and
        // how near the frame's own estimate keeps to the truth.
        for (const tracer::Mode mode : modes) {
            std::vector<std::pair<double, double>> by_spp, by_time;
            std::vector<double> ratios;
            for (const Point& p : points) {
                if (p.mode != mode) continue;
                by_spp.emplace_back(p.spp, p.error.rmse);
                by_time.emplace_back(p.seconds, p.error.rmse);
                if (p.estimate && p.error.rmse > 0.0) ratios.push_back(*p.estimate / p.error.rmse);
            }
            out << std::left << std::setw(10) << tracer::mode_name(mode) << std::right
                << " slope: rmse ~ spp^";
            const auto per_spp = log_log_slope(by_spp), per_second = log_log_slope(by_time);
            out << std::fixed << std::setprecision(2);
            const auto print = [&](const std::optional<double>& v) {
                if (v)
                    out << *v;
                else
                    out << "?";
            };
            print(per_spp);
            out << ", rmse ~ seconds^";
            print(per_second);
            if (!ratios.empty()) {
                std::sort(ratios.begin(), ratios.end());
                out << "; estimate / true " << ratios.front() << " to " << ratios.back()
                    << " (median " << ratios[ratios.size() / 2] << ")";
            }
            out << std::defaultfloat << "\n";
        }

        // Adaptive sampling at each target: its true error, and what
        // uniform sampling (the points above) needs for that error.
        std::vector<Point> adaptive;
        for (const double target : targets) {
            for (const tracer::Mode mode : modes) {
                std::ostringstream name;
                name << tracer::mode_name(mode) << "_target" << target << ".exr";
                const fs::path image = dir / name.str();
                Point p =
                    measure(scene, mode, spps.back(), frame, args, image, 0, target, args.repeat);
                p.error = tracer::image_error(image, reference);
                adaptive.push_back(p);
                out << std::left << std::setw(10) << tracer::mode_name(mode) << std::right
                    << " target " << std::scientific << std::setprecision(3) << target << ": "
                    << std::fixed << std::setprecision(3) << p.seconds << " s, "
                    << std::setprecision(1) << p.mean_spp << " spp, rmse " << std::scientific
                    << std::setprecision(3) << p.error.rmse << " (" << std::fixed
                    << std::setprecision(2) << p.error.rmse / target << "x the target";
                if (p.estimate && p.error.rmse > 0.0)
                    out << ", estimated " << *p.estimate / p.error.rmse << "x the truth";
                out << "); ";
                // (Uniform sampling's own time to the target, then to the
                // error adaptive sampling reached.)
                if (const auto own = time_for(points, mode, target))
                    out << "uniform reaches the target in " << std::setprecision(3) << *own
                        << " s (" << std::setprecision(2) << *own / p.seconds << "x); ";
                out << "uniform needs ";
                const auto spp = time_for(points, mode, p.error.rmse, true);
                const auto seconds = time_for(points, mode, p.error.rmse);
                if (spp && seconds)
                    out << std::setprecision(1) << *spp << " spp (" << std::setprecision(2)
                        << *spp / p.mean_spp << "x the samples), " << std::setprecision(3)
                        << *seconds << " s (" << std::setprecision(2) << *seconds / p.seconds
                        << "x the time)\n";
                else {
                    // Which side of the measured curve: fewer samples than
                    // its first point (a larger error), or more than its last.
                    double largest = 0.0;
                    for (const Point& q : points)
                        if (q.mode == mode) largest = std::max(largest, q.error.rmse);
                    out << (p.error.rmse > largest ? "fewer samples than the smallest of --spp-list"
                                                   : "more samples than the largest of --spp-list")
                        << " (outside the measured range)\n";
                }
            }
        }
        std::stable_sort(adaptive.begin(), adaptive.end(),
                         [](const Point& x, const Point& y) { return x.mode < y.mode; });

        const fs::path csv = dir / "error_time.csv";
        {
            std::ostringstream table;
            table << "mode,spp,seconds,build_seconds,render_seconds,rays,rmse,relative_mse,"
                     "estimated_rmse,"
                     "target,mean_spp\n"
                  << std::setprecision(9);
            std::vector<Point> rows = points;
            rows.insert(rows.end(), adaptive.begin(), adaptive.end());
            for (const Point& p : rows) {
                table << tracer::mode_name(p.mode) << ',' << p.spp << ',' << p.seconds << ','
                      << p.build_seconds << ',' << p.render_seconds << ',' << p.rays << ','
                      << p.error.rmse << ',' << p.error.relative_mse << ',';
                if (p.estimate) table << *p.estimate;  // (empty: 1 sample, no estimate)
                table << ',';
                if (p.target) table << *p.target;  // (empty: uniform sampling)
                table << ',' << p.mean_spp << '\n';
            }
            tracer::write_text_file(csv, table.str());
        }
        LogLogPlot plot;
        plot.title = resolved.scene.stem().string() + ", frame " + std::to_string(frame) +
                     ": error against time";
        plot.x_label = "seconds for the frame (render + its share of the build)";
        plot.y_label = "RMSE against " + std::to_string(reference_spp) + " spp (linear)";
        for (const tracer::Mode mode : modes) {
            PlotCurve curve{tracer::mode_name(mode), colour_of(mode), {}};
            PlotCurve estimated{
                std::string(tracer::mode_name(mode)) + ", estimated", colour_of(mode), {}, true};
            for (const Point& p : points)
                if (p.mode == mode) {
                    curve.points.emplace_back(p.seconds, p.error.rmse);
                    if (p.estimate) estimated.points.emplace_back(p.seconds, *p.estimate);
                }
            plot.curves.push_back(std::move(curve));
            if (!estimated.points.empty()) plot.curves.push_back(std::move(estimated));
            PlotCurve targeted{std::string(tracer::mode_name(mode)) + ", adaptive",
                               colour_of(mode),
                               {},
                               false,
                               true};
            for (const Point& p : adaptive)
                if (p.mode == mode) targeted.points.emplace_back(p.seconds, p.error.rmse);
            if (!targeted.points.empty()) plot.curves.push_back(std::move(targeted));
        }
        const fs::path svg = dir / "error_time.svg";
        tracer::write_text_file(svg, to_svg(plot));

        // Time to reach the same error: at each error the first mode
        // reached, how long each other mode needs (interpolated).
        if (modes.size() > 1) {
            out << "time to reach the same RMSE (" << tracer::mode_name(modes[1]) << " / "
                << tracer::mode_name(modes[0]) << "):\n";
            for (const Point& p : points) {
                if (p.mode != modes[0] || !(p.error.rmse > 0.0))
                    continue;  // (a flat frame: no error to reach)
                const auto other = time_for(points, modes[1], p.error.rmse);
                out << "  rmse " << std::scientific << std::setprecision(3) << p.error.rmse
                    << std::fixed << std::setprecision(3) << ": " << p.seconds << " s against ";
                if (other)
                    out << *other << " s, ratio " << std::setprecision(2) << *other / p.seconds
                        << "\n";
                else
                    out << "(outside the measured range)\n";
            }
            out << std::defaultfloat;
        }
        out << "csv: " << csv.string() << "\nplot: " << svg.string() << "\n";
        return 0;
    });
}

}  // namespace hexant::app
