// hexant_embree_peer: a peer benchmark against Embree 3's multi-segment
// motion blur (issue 15).
//
// What it measures. For examples/atom.pov, examples/bounce.pov,
// examples/swarm.pov at N = 10^3, 10^4 and 10^5 spheres (--swarm-n; with
// their .ini files) and tests/bench/instance_union.pov (23,328 still
// triangles in a union under one moving transform, 160 by 120, 16 frames
// over clock 0 to 1), in one process and one run:
//   - hexant, spacetime mode and frames mode, rendered through hexant's own
//     library (tracer::Renderer, its own Owen-scrambled Sobol' samples), and
//     for the instance scene spacetime with the union split (--no-instances);
//   - Embree 3, one scene ("one motion BVH") per frame, every moving sphere
//     a RTC_GEOMETRY_TYPE_SPHERE_POINT with K+1 time steps (K = 2, 4, 8
//     linear motion segments over the frame's shutter), the static polygons,
//     boxes and prism as one triangle mesh of one time step, a union of
//     still triangles under a moving transform as an instance
//     (RTC_GEOMETRY_TYPE_INSTANCE of a scene built once, its transform at
//     the K+1 instants, which Embree blends entry by entry); build quality
//     RTC_BUILD_QUALITY_MEDIUM; single rays (rtcIntersect1, rtcOccluded1),
//     16x16 tiles in parallel with oneTBB as hexant's renderer does.
// For each: build time, render time, rays (primary + shadow) per second,
// and the RMSE (linear light, all three channels) of one frame (the middle
// one by default) against a hexant spacetime reference of that frame at
// --reference-spp (1024) with an independent scramble (sample_seed 1). For
// atom, also a time-to-error table of that frame: hexant spacetime and
// Embree K=4 at 1, 2, 4, ..., 64 spp.
//
// Run it (built only where libembree-dev is installed; `make bench` does
// all of it):
//   build/tests/bench/hexant_embree_peer [--scene atom|bounce|all] [--spp N] [--rounds 3]
//       [--frames A:B] [--size W] [--reference-spp N] [--error-frame K]
//       [--threads N] [--quick] [--write-images DIR]
//
// What compares and what does not:
//   - The work is the same: the same camera rays through the same pixels,
//     the same shading (POV-Ray's finish as tracer/shader.cpp: ambient,
//     diffuse with brilliance, phong, specular, hard shadows; shadowless
//     lights are fill lights), one shadow ray per sample and light.
//   - The samples differ. hexant uses its Owen-scrambled Sobol' points over
//     (pixel x, pixel y, time). Embree gets a plain, typical choice:
//     stratified jitter in the pixel (a sqrt(spp) x sqrt(spp) grid when spp
//     is a square, else N rooks) and an independent uniform time per sample
//     from PCG32 seeded by (frame, pixel); deterministic. So at equal spp the
//     errors differ by the sampling too, not only by the geometry.
//   - The motion differs. hexant intersects its exact motion at each ray's
//     time; Embree's spheres move along K linear segments per frame through
//     centres and radii that hexant evaluates exactly at the K+1 instants,
//     in single precision. Embree's images are therefore not hexant's: the
//     RMSE holds that bias besides the noise (it shrinks as K grows).
//   - Precision: Embree's rays and geometry are float. Its hit is moved onto
//     the surface in double (a triangle's plane as hexant places it, so that
//     checker squares whose edges lie in a wall fall as in hexant; a sphere
//     at the ray's time, interpolated as Embree interpolates), and the
//     shadow ray starts at the offset of Ray Tracing Gems ch. 6. hexant's
//     runtime/geometry/offset_ray.hpp is that offset for double (256 double
//     ulps); Embree rounds the start to float, which undoes it, so the same
//     method runs here at float precision with the paper's own constants.
//   - Build time: hexant's is its counters' (the sweeps and the lazy cells
//     as rays reach them, summed over threads, as `render --compare`
//     prints); Embree's is per frame: evaluating the sphere motion at K+1
//     instants, filling the buffers and rtcCommitScene. The wall column is
//     measured around everything each row does.
#include "tests/bench/embree_peer/frame.hpp"

namespace hexant_embree_peer {

// ---------------------------------------------------------------------------
// Measuring

double rmse(const tracer::Image& image, const tracer::Image& reference) {
    if (image.width != reference.width || image.height != reference.height)
        throw std::logic_error("rmse: images differ in size");
    double sum = 0.0;
    for (std::size_t i = 0; i < image.rgb.size(); ++i) {
        const double e = double(image.rgb[i]) - double(reference.rgb[i]);
        sum += e * e;
    }
    return std::sqrt(sum / double(std::max<std::size_t>(1, image.rgb.size())));
}

struct Row {
    std::string method;
    double build = 0.0, render = 0.0, wall = 0.0;
    std::uint64_t rays = 0;
    // hexant's node and object tests (0 for Embree, which does not count).
    std::uint64_t node_tests = 0, object_tests = 0;
    double total = 0.0;  // build + render (of one run; a median of them in a table)
    double rmse = 0.0;
    tracer::Image error_image;
};

// The row of `rounds` runs of one method: the median of each time (and of
// the totals, taken per run), the counts and the image of the first run
// (both tracers are deterministic: every run draws the same samples).
Row median_row(std::vector<Row> runs) {
    const auto median = [&](auto field) {
        std::vector<double> v;
        for (const Row& r : runs) v.push_back(field(r));
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    };
    Row out = std::move(runs.front());
    out.build = median([](const Row& r) { return r.build; });
    out.render = median([](const Row& r) { return r.render; });
    out.total = median([](const Row& r) { return r.total; });
    out.wall = median([](const Row& r) { return r.wall; });
    return out;
}

Row run_hexant(const Job& job, tracer::Mode mode, int spp, int first, int last, int threads,
               bool instances = true) {
    Row row;
    row.method = std::string("hexant ") + tracer::mode_name(mode) + (instances ? "" : " split");
    const auto start = Clock::now();
    tracer::RenderSettings settings;
    settings.mode = mode;
    settings.build.instances = instances;
    settings.samples_per_pixel = spp;
    settings.threads = threads;
    settings.first_frame = first;  // the hierarchy spans these frames' time
    settings.last_frame = last;
    tracer::Renderer renderer(job.scene, settings);
    for (int f = first; f <= last; ++f) {
        tracer::Image image = renderer.render_frame(f);
        if (f == job.error_frame) row.error_image = std::move(image);
    }
    row.wall = seconds_since(start);
    const tracer::Counters& c = renderer.counters();
    row.build = c.build_seconds;
    row.render = c.render_seconds;
    row.rays = c.rays();
    row.node_tests = c.node_tests;
    row.object_tests = c.object_tests;
    row.total = row.build + row.render;
    return row;
}

Row run_embree(const Job& job, const PeerScene& peer, RTCDevice device, int segments, int spp,
               int first, int last) {
    Row row;
    row.method = "embree K=" + std::to_string(segments);
    const auto start = Clock::now();
    const EmbreeInstances instances(device, peer);  // once: only their transforms move
    row.build += seconds_since(start);
    for (int f = first; f <= last; ++f) {
        const auto build_start = Clock::now();
        const EmbreeFrame frame(device, peer, instances, f, segments);
        row.build += seconds_since(build_start);
        const auto render_start = Clock::now();
        tracer::Image image = render_embree_frame(peer, frame, f, spp, row.rays);
        row.render += seconds_since(render_start);
        if (f == job.error_frame) row.error_image = std::move(image);
    }
    row.wall = seconds_since(start);
    row.total = row.build + row.render;
    return row;
}

std::string thousands(std::uint64_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

void print_table(const Job& job, const std::vector<Row>& rows, int rounds) {
    if (rounds > 1)
        std::printf("  (times: the median of %d runs, the methods taking turns in each round)\n",
                    rounds);
    std::printf("  %-22s %9s %9s %9s %9s %14s %8s %8s %8s %14s\n", "method", "build s", "render s",
                "total s", "wall s", "rays", "Mrays/s", "nodes/r", "objs/r",
                ("RMSE(frame " + std::to_string(job.error_frame) + ")").c_str());
    for (const Row& r : rows) {
        const double per = r.rays > 0 ? 1.0 / double(r.rays) : 0.0;
        const auto count = [&](std::uint64_t n) {
            char text[32];
            if (n == 0)
                std::snprintf(text, sizeof text, "-");
            else
                std::snprintf(text, sizeof text, "%.2f", double(n) * per);
            return std::string(text);
        };
        std::printf("  %-22s %9.3f %9.3f %9.3f %9.3f %14s %8.2f %8s %8s %14.4e\n", r.method.c_str(),
                    r.build, r.render, r.total, r.wall, thousands(r.rays).c_str(),
                    r.render > 0.0 ? double(r.rays) / r.render * 1e-6 : 0.0,
                    count(r.node_tests).c_str(), count(r.object_tests).c_str(), r.rmse);
    }
    // Each scene's ratios, as the issue asks them (total time, hexant over
    // Embree K=4, and spacetime over frames).
    const auto find = [&](const std::string& method) -> const Row* {
        for (const Row& r : rows)
            if (r.method == method) return &r;
        return nullptr;
    };
    const Row* spacetime = find("hexant spacetime");
    const Row* frames = find("hexant frames");
    const Row* embree = find("embree K=4");
    if (spacetime && embree && embree->total > 0.0)
        std::printf("  hexant spacetime / embree K=4, total: %.2f\n",
                    spacetime->total / embree->total);
    if (spacetime && frames && frames->total > 0.0)
        std::printf("  hexant spacetime / frames, total: %.2f\n", spacetime->total / frames->total);
}

// Time to reach `error` along a curve of (time, error) points, by log-log
// interpolation between neighbours (as `hexant bench error-time`).
std::optional<double> time_to_reach(const std::vector<std::pair<double, double>>& curve,
                                    double error) {
    for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
        const auto [t0, e0] = curve[i];
        const auto [t1, e1] = curve[i + 1];
        if ((e0 >= error && error >= e1) || (e1 >= error && error >= e0)) {
            if (e0 == e1) return t0;
            const double f = std::log(error / e0) / std::log(e1 / e0);
            return std::exp(std::log(t0) + f * std::log(t1 / t0));
        }
    }
    if (!curve.empty() && curve.front().second <= error) return curve.front().first;
    return std::nullopt;
}

void time_to_error(const Job& job, const PeerScene& peer, RTCDevice device,
                   const tracer::Image& reference, int threads) {
    constexpr int kSegments = 4;
    std::printf("\n%s, frame %d: time to error, one frame (%dx%d), against the %d-spp reference\n",
                job.name.c_str(), job.error_frame, job.scene.animation.width,
                job.scene.animation.height, job.reference_spp);
    std::printf(
        "  hexant spacetime: a new Renderer per count, over that frame's time: build + render;\n"
        "  embree K=%d: that frame's scene build + render.\n",
        kSegments);
    std::printf("  %5s %18s %12s %16s %12s\n", "spp", "hexant spacetime s", "RMSE",
                ("embree K=" + std::to_string(kSegments) + " s").c_str(), "RMSE");
    std::vector<std::pair<double, double>> hexant_curve, embree_curve;
    for (const int spp : job.ladder) {
        const Row h = run_hexant(job, tracer::Mode::Spacetime, spp, job.error_frame,
                                 job.error_frame, threads);
        const Row e =
            run_embree(job, peer, device, kSegments, spp, job.error_frame, job.error_frame);
        const double he = rmse(h.error_image, reference), ee = rmse(e.error_image, reference);
        hexant_curve.emplace_back(h.build + h.render, he);
        embree_curve.emplace_back(e.build + e.render, ee);
        std::printf("  %5d %18.4f %12.4e %16.4f %12.4e\n", spp, h.build + h.render, he,
                    e.build + e.render, ee);
    }
    const auto at = std::find(job.ladder.begin(), job.ladder.end(), 32);
    const std::size_t i =
        at != job.ladder.end() ? std::size_t(at - job.ladder.begin()) : job.ladder.size() - 1;
    const auto [embree_time, embree_error] = embree_curve[i];
    std::printf("  embree K=%d at %d spp: RMSE %.4e in %.4f s; ", kSegments, job.ladder[i],
                embree_error, embree_time);
    if (const auto t = time_to_reach(hexant_curve, embree_error))
        std::printf("hexant spacetime reaches it in %.4f s (%.2f times embree's time)\n", *t,
                    *t / embree_time);
    else
        std::printf("hexant spacetime does not reach it within %d spp\n", job.ladder.back());
    const auto [hexant_time, hexant_error] = hexant_curve[i];
    std::printf("  hexant spacetime at %d spp: RMSE %.4e in %.4f s; ", job.ladder[i], hexant_error,
                hexant_time);
    if (const auto t = time_to_reach(embree_curve, hexant_error))
        std::printf("embree K=%d reaches it in %.4f s (%.2f times hexant's time)\n", kSegments, *t,
                    *t / hexant_time);
    else
        std::printf("embree K=%d does not reach it within %d spp\n", kSegments, job.ladder.back());
}

// The first three fields of /proc/loadavg: on a shared machine the times
// mean little without them.
std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    if (!(in >> one >> five >> fifteen)) return "unknown";
    return one + " " + five + " " + fifteen;
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("model name", 0) != 0) continue;
        const auto colon = line.find(':');
        if (colon != std::string::npos)
            return line.substr(line.find_first_not_of(" \t", colon + 1));
    }
    return "unknown";
}

void run_job(const Job& job, const Options& options, RTCDevice device, int threads) {
    const runtime::Animation& a = job.scene.animation;
    const auto convert_start = Clock::now();
    const PeerScene peer = Converter(job.scene).convert();
    const double convert_seconds = seconds_since(convert_start);

    std::printf(
        "\n== %s: %dx%d, frames %d..%d of %d..%d, %d spp, shutter %g of the clock step "
        "%g, error frame %d ==\n",
        job.name.c_str(), a.width, a.height, job.first, job.last, a.initial_frame, a.final_frame,
        job.spp, a.shutter, a.clock_delta(), job.error_frame);
    std::size_t instanced = 0;
    for (const PeerInstance& instance : peer.instances)
        instanced += instance.local.triangles.size();
    std::printf(
        "  Embree scene per frame: %zu sphere points (one geometry, K+1 time steps), "
        "%zu static triangles, %zu instances of %zu triangles in all (their scenes built once, "
        "their transforms at K+1 time steps), %zu light sources; records converted in %.1f ms "
        "(once)\n",
        peer.spheres.size(), peer.statics.triangles.size(), peer.instances.size(), instanced,
        peer.lights.size(), convert_seconds * 1e3);

    const auto reference_start = Clock::now();
    tracer::Image reference;
    {
        tracer::RenderSettings settings;
        settings.mode = tracer::Mode::Spacetime;
        settings.samples_per_pixel = job.reference_spp;
        settings.sample_seed = 1;  // independent of the measured renders' samples
        settings.threads = threads;
        settings.first_frame = settings.last_frame = job.error_frame;
        tracer::Renderer renderer(job.scene, settings);
        reference = renderer.render_frame(job.error_frame);
    }
    std::printf("  reference: hexant spacetime, frame %d, %d spp, sample_seed 1: %.1f s\n\n",
                job.error_frame, job.reference_spp, seconds_since(reference_start));
    std::fflush(stdout);

    std::vector<std::function<Row()>> methods;
    methods.push_back([&] {
        return run_hexant(job, tracer::Mode::Spacetime, job.spp, job.first, job.last, threads);
    });
    // The paper's baseline boxes each sphere over a whole frame's orbit: at
    // 10^4 swarm spheres it takes 20 times spacetime's time, at 10^5 it
    // would take a quarter of an hour; above --frames-max it is left out.
    // The instance against its members split into objects of their own.
    if (!peer.instances.empty())
        methods.push_back([&] {
            return run_hexant(job, tracer::Mode::Spacetime, job.spp, job.first, job.last, threads,
                              false);
        });
    if (job.objects <= options.frames_max)
        methods.push_back([&] {
            return run_hexant(job, tracer::Mode::Frames, job.spp, job.first, job.last, threads);
        });
    else
        std::printf("  (hexant frames left out: %zu objects, over --frames-max %zu)\n", job.objects,
                    options.frames_max);
    for (const int k : {2, 4, 8})
        methods.push_back(
            [&, k] { return run_embree(job, peer, device, k, job.spp, job.first, job.last); });
    // Rounds of every method in turn: a slow spell of a shared machine
    // falls on all of them alike.
    std::vector<std::vector<Row>> runs(methods.size());
    for (int round = 0; round < options.rounds; ++round)
        for (std::size_t m = 0; m < methods.size(); ++m) {
            runs[m].push_back(methods[m]());
            if (round > 0) runs[m].back().error_image = {};  // (the first run's is kept)
        }
    std::vector<Row> rows;
    for (auto& r : runs) rows.push_back(median_row(std::move(r)));
    for (Row& r : rows) r.rmse = rmse(r.error_image, reference);
    print_table(job, rows, options.rounds);
    std::fflush(stdout);

    if (options.write_images) {
        const fs::path dir(*options.write_images);
        fs::create_directories(dir);
        const std::string frame = "frame" + std::to_string(job.error_frame);
        const auto file_name = [](std::string text) {
            for (char& c : text)
                if (c == ' ' || c == '=') c = '_';
            return text;
        };
        const std::string scene = file_name(job.name);
        tracer::write_image(reference, dir / (scene + "_" + frame + "_reference.png"));
        for (const Row& r : rows)
            tracer::write_image(r.error_image,
                                dir / (scene + "_" + frame + "_" + file_name(r.method) + ".png"));
        std::printf("  images of frame %d written to %s\n", job.error_frame, dir.c_str());
    }

    if (job.name == "atom") time_to_error(job, peer, device, reference, threads);
    std::fflush(stdout);
}

int run(const Options& options) {
    std::vector<std::string> names;
    if (options.scene == "all")
        names = {"atom", "bounce", "swarm", "instance"};
    else if (options.scene == "atom" || options.scene == "bounce" || options.scene == "swarm" ||
             options.scene == "instance")
        names = {options.scene};
    else
        throw std::runtime_error("--scene must be atom, bounce, swarm, instance or all, not '" +
                                 options.scene + "'");
    for (const int n : options.swarm_counts)
        if (n < 1) throw std::runtime_error("--swarm-n takes counts of at least 1");
    if (options.threads < 0) throw std::runtime_error("--threads must be 0 (all) or more");
    if (options.rounds < 1) throw std::runtime_error("--rounds must be at least 1");

    // Both tracers run under the same limit.
    std::unique_ptr<tbb::global_control> limit;
    if (options.threads > 0)
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      options.threads);
    const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
    const std::string config =
        options.threads > 0 ? "threads=" + std::to_string(options.threads) : "";
    RTCDevice device = rtcNewDevice(config.empty() ? nullptr : config.c_str());
    if (!device) throw std::runtime_error("rtcNewDevice failed");
    rtcSetDeviceErrorFunction(device, embree_error, nullptr);
    warm_up(device);
    const long tasking = rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_TASKING_SYSTEM);

    char date[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M:%S %Z", std::localtime(&now));
    std::printf(
        "hexant_embree_peer: hexant against Embree 3 multi-segment motion blur (issue 15)\n");
    std::printf("date      %s\n", date);
    std::printf("cpu       %s (%u hardware threads)\n", cpu_model().c_str(),
                std::thread::hardware_concurrency());
    std::printf("load      %s (1, 5, 15 minutes, at start)\n", load_average().c_str());
    std::printf("threads   %d (both tracers; 16x16 tiles, tbb::parallel_for)\n", threads);
    std::printf(
        "embree    %s (RTC_VERSION_STRING), tasking: %s, build quality "
        "RTC_BUILD_QUALITY_MEDIUM, single rays (rtcIntersect1, rtcOccluded1)\n",
        RTC_VERSION_STRING,
        tasking == 1   ? "TBB"
        : tasking == 0 ? "internal"
                       : "other");
    std::printf(
        "%s", options.quick ? "mode      --quick (a smoke test: the figures mean nothing)\n" : "");
    std::printf(
        "legend    hexant spacetime/frames: hexant's Renderer (Owen-scrambled Sobol' samples over\n"
        "          pixel and shutter); build s = its build before the frames (sweeps, the root;\n"
        "          a lazy build's cells are built inside the render), render s = its frames'.\n"
        "          embree K=n: one Embree scene per frame, spheres on n linear motion segments\n"
        "          through hexant's exact motion at n+1 instants; stratified jitter (sqrt(spp)^2\n"
        "          grid, else N rooks) with an independent uniform time per sample (PCG32 by "
        "frame\n"
        "          and pixel); build s = per frame: motion evaluation, buffers, rtcCommitScene.\n"
        "          total s = build + render; wall s = measured around the whole row; rays =\n"
        "          primary + shadow; Mrays/s = rays / render s; RMSE in linear light over RGB\n"
        "          against a hexant spacetime reference of that frame with sample_seed 1.\n");
    std::fflush(stdout);

    for (const auto& name : names) {
        if (name != "swarm") {
            run_job(load_job(name, options), options, device, options.threads);
            continue;
        }
        for (const int n : options.quick ? std::vector<int>{100} : options.swarm_counts)
            run_job(load_job(name, options, n), options, device, options.threads);
    }
    rtcReleaseDevice(device);
    return 0;
}

}  // namespace hexant_embree_peer

using namespace hexant_embree_peer;

int main(int argc, char** argv) {
    CLI::App app{
        "hexant against Embree 3's multi-segment motion blur on atom, bounce, swarm and instance"};
    Options options;
    app.add_option("--scene", options.scene, "atom, bounce, swarm, instance or all (default)");
    app.add_option("--swarm-n", options.swarm_counts,
                   "The swarm's sphere counts (default 1000 10000 100000)")
        ->delimiter(',');
    app.add_option("--spp", options.spp, "Samples per pixel (default: atom 32, bounce 4)");
    app.add_option("--frames", options.frames, "Frames A:B (default: the .ini's)");
    app.add_option("--size", options.size, "Image width; the height keeps the .ini's aspect");
    app.add_option("--reference-spp", options.reference_spp, "The reference's spp (default 1024)");
    app.add_option("--error-frame", options.error_frame,
                   "The frame whose RMSE is measured (default: the middle one)");
    app.add_option("--threads", options.threads, "Worker threads (default: all)");
    app.add_option("--frames-max", options.frames_max,
                   "Render hexant's frames mode only for scenes of at most this many objects "
                   "(default 20000)");
    app.add_option("--rounds", options.rounds,
                   "Runs of each method, taking turns; times are their medians (default 3)");
    app.add_flag("--quick", options.quick,
                 "A tiny run for a smoke test: 32 wide, 2 frames, 2 spp, reference 16 spp");
    app.add_option("--write-images", options.write_images,
                   "Write the error frame of every row and the reference as PNG files here");
    CLI11_PARSE(app, argc, argv);
    if (options.quick && app.count("--rounds") == 0) options.rounds = 1;
    try {
        return run(options);
    } catch (const language::SceneError& e) {
        std::cerr << e.formatted();
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "hexant_embree_peer: error: " << e.what() << "\n";
        return 1;
    }
}
