// However the hierarchy is built, the image is the same: lazy or eager,
// the cost criterion or the paper's, any style of bound, with the same
// samples every ray finds the same first hit, so every pixel is equal, on
// each example. And a lazy hierarchy built by many threads at once, from
// cold, gives the image one thread gives, every time.
//
// Under ThreadSanitizer (README.md, "Tests"): cmake -S . -B build-tsan
// -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHEXANT_SANITIZE=thread, build
// hexant_tests there, then build-tsan/tests/hexant_tests "[tsan]": plain
// threads race through one cold lazy hierarchy (oneTBB, not built with
// ThreadSanitizer here, hides its own synchronisation from it, so the
// renderer's TBB threads give false reports; the builds before the race
// run on one thread).
#include <atomic>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>
#include <tbb/global_control.h>

#include "../runtime/object_test_support.hpp"
#include "app/command_line.hpp"
#include "language/interpreter.hpp"
#include "tracer/ray_query.hpp"
#include "tracer/renderer.hpp"

namespace tr = hexant::tracer;

namespace {

hexant::runtime::SceneDescription example(const std::string& name, int size,
                                          const std::vector<std::string>& declares = {}) {
    hexant::app::SceneArguments arguments;
    arguments.files = {std::string(HEXANT_SOURCE_DIR) + "/examples/" + name + ".pov",
                       std::string(HEXANT_SOURCE_DIR) + "/examples/" + name + ".ini"};
    arguments.width = size;
    arguments.height = size;
    arguments.declares = declares;
    const hexant::app::ResolvedScene resolved = hexant::app::resolve(arguments);
    return hexant::language::parse_scene_file(resolved.scene, resolved.options);
}

tr::Image render(const hexant::runtime::SceneDescription& scene, const tr::BuildOptions& build,
                 int frame, int spp, int threads = 0) {
    tr::RenderSettings settings;
    settings.mode = tr::Mode::Spacetime;
    settings.samples_per_pixel = spp;
    settings.build = build;
    settings.threads = threads;
    tr::Renderer renderer(scene, settings);
    return renderer.render_frame(frame);
}

// Pixels that differ at all (the images must be equal bit for bit).
int differing(const tr::Image& a, const tr::Image& b) {
    REQUIRE(a.rgb.size() == b.rgb.size());
    int n = 0;
    for (std::size_t i = 0; i < a.rgb.size(); i += 3)
        n += a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
    return n;
}

tr::BuildOptions options(tr::Criterion criterion, tr::BuildKind build, tr::BoundStyle bounds) {
    tr::BuildOptions o;
    o.criterion = criterion;
    o.build = build;
    o.bounds = bounds;
    return o;
}

}  // namespace

TEST_CASE("lazy and eager builds, both criteria and every bound style make the same images",
          "[tracer][build]") {
    struct Example {
        const char* name;
        int frame;
    };
    // A frame of each where things move fast or bounce.
    const Example examples[] = {{"atom", 22},   {"bounce", 4},  {"dino", 33},
                                {"twister", 5}, {"glider", 12}, {"spinner", 1}};
    for (const Example& e : examples) {
        INFO("example " << e.name << " frame " << e.frame);
        const auto scene = example(e.name, 40);
        const tr::Image reference =
            render(scene, options(tr::Criterion::Cost, tr::BuildKind::Lazy, tr::BoundStyle::Auto),
                   e.frame, 2);
        for (const auto criterion : {tr::Criterion::Cost, tr::Criterion::Paper})
            for (const auto build : {tr::BuildKind::Lazy, tr::BuildKind::Eager})
                for (const auto bounds : {tr::BoundStyle::Auto, tr::BoundStyle::Box,
                                          tr::BoundStyle::Linear, tr::BoundStyle::Slabs}) {
                    INFO("criterion " << int(criterion) << " build " << int(build) << " bounds "
                                      << int(bounds));
                    CHECK(differing(render(scene, options(criterion, build, bounds), e.frame, 2),
                                    reference) == 0);
                }
    }
}

TEST_CASE("a leaf that keeps no bins (grouped by placed ends) makes the same images",
          "[tracer][build]") {
    // Issue 43: past BuildOptions::kept_bins objects a leaf is grouped by
    // its objects' placed boxes at its ends and makes their bins at the
    // bottom; here every leaf does, on scenes whose leaves are small.
    struct Example {
        const char* name;
        int frame;
        std::vector<std::string> declares;
    };
    const Example examples[] = {{"swarm", 3, {"N=300"}}, {"atom", 22, {}}, {"bounce", 4, {}}};
    for (const Example& e : examples) {
        const auto scene = example(e.name, 40, e.declares);
        for (const auto criterion : {tr::Criterion::Cost, tr::Criterion::Paper})
            for (const auto build : {tr::BuildKind::Lazy, tr::BuildKind::Eager}) {
                INFO("example " << e.name << " criterion " << int(criterion) << " build "
                                << int(build));
                tr::BuildOptions kept = options(criterion, build, tr::BoundStyle::Auto);
                tr::BuildOptions none = kept;
                none.kept_bins = 0;
                CHECK(differing(render(scene, none, e.frame, 2), render(scene, kept, e.frame, 2)) ==
                      0);
            }
    }
}

TEST_CASE("a cold lazy hierarchy built by many threads at once gives one thread's image",
          "[tracer][lazy]") {
    // Many small moving objects, so that many cells are built while the
    // threads race through the first rays.
    const auto scene = example("swarm", 48, {"N=300"});
    const tr::Image reference = render(
        scene, options(tr::Criterion::Cost, tr::BuildKind::Eager, tr::BoundStyle::Auto), 3, 2, 1);
    for (int run = 0; run < 12; ++run) {
        INFO("run " << run);
        tr::BuildOptions lazy = options(run % 2 ? tr::Criterion::Paper : tr::Criterion::Cost,
                                        tr::BuildKind::Lazy, tr::BoundStyle::Auto);
        // Every other pair of runs treats each cell as a large one: a thread
        // that reaches one while another is under way helps that one first.
        if (run % 4 >= 2) lazy.large_build = 1;
        CHECK(differing(render(scene, lazy, 3, 2, 8), reference) == 0);
    }
}

TEST_CASE("threads racing through a cold lazy hierarchy find what one thread finds",
          "[tracer][lazy][tsan]") {
    std::string sdl;
    for (int i = 0; i < 150; ++i) {
        char line[200];
        std::snprintf(line, sizeof line,
                      "sphere { <%g, 0, 0>, 0.15 rotate y * (%d + 360 * %d * clock) "
                      "rotate <%d, 0, %d> }\n",
                      1.0 + 0.03 * i, 37 * i, 1 + i % 4, (53 * i) % 180 - 90, (29 * i) % 180 - 90);
        sdl += line;
    }
    const object_test::Parsed parsed = object_test::parse(sdl);
    const auto set = tr::ObjectSet::of(parsed.objects);
    const auto root = tr::enclosing_box(set, 0.0, 1.0);
    // Everything before the race runs on this thread alone.
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    std::vector<hexant::runtime::Ray4> rays;
    object_test::Random random(11);
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 origin = 9.0 * random.unit_vector();
        const glm::dvec3 aim(random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3));
        rays.push_back({hexant::runtime::Event(origin, random.uniform(0.0, 1.0)),
                        hexant::runtime::Event(glm::normalize(aim - origin), 0.0)});
    }
    tr::Counters counters;
    tr::BuildOptions eager;
    eager.build = tr::BuildKind::Eager;
    const auto reference = tr::make_ray_query(tr::Mode::Spacetime, set, root, eager, counters);
    std::vector<double> expected(rays.size());
    std::vector<char> blocked(rays.size());
    tr::ThreadState alone{tr::Mailbox(set.size()), {}};
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const auto hit = reference->first_hit(rays[i], 0.0, 1e30, alone);
        expected[i] = hit ? hit->s : -1.0;
        blocked[i] = reference->occluded(rays[i], 0.0, 4.0, alone);
    }
    for (int run = 0; run < 6; ++run) {
        tr::BuildOptions lazy;
        lazy.criterion = run % 2 ? tr::Criterion::Paper : tr::Criterion::Cost;
        if (run >= 2) lazy.large_build = 1;  // every cell a large one (Hierarchy::expand)
        const auto query = tr::make_ray_query(tr::Mode::Spacetime, set, root, lazy, counters);
        std::atomic<int> wrong{0};
        std::vector<std::thread> threads;
        for (int k = 0; k < 4; ++k)
            threads.emplace_back([&, k] {
                tr::ThreadState state{tr::Mailbox(set.size()), {}};
                // Each thread starts at its own place among the rays, so
                // that threads reach some cells together and some apart.
                for (std::size_t j = 0; j < rays.size(); ++j) {
                    const std::size_t i = (j + std::size_t(k) * rays.size() / 4) % rays.size();
                    const auto hit = query->first_hit(rays[i], 0.0, 1e30, state);
                    if ((hit ? hit->s : -1.0) != expected[i]) ++wrong;
                    if (query->occluded(rays[i], 0.0, 4.0, state) != bool(blocked[i])) ++wrong;
                }
            });
        for (auto& t : threads) t.join();
        INFO("run " << run);
        CHECK(wrong.load() == 0);
    }
}

TEST_CASE(
    "a renderer built for some frames' time gives the whole animation's images, and "
    "refuses other frames",
    "[tracer][build]") {
    const auto scene = example("atom", 32);
    tr::RenderSettings whole;
    whole.samples_per_pixel = 2;
    tr::RenderSettings one = whole;
    one.first_frame = one.last_frame = 22;
    tr::Renderer all_frames(scene, whole), frame_22(scene, one);
    CHECK(differing(frame_22.render_frame(22), all_frames.render_frame(22)) == 0);
    CHECK_THROWS_AS(frame_22.render_frame(23), std::out_of_range);
    tr::RenderSettings outside = whole;
    outside.first_frame = 60;
    outside.last_frame = 65;  // atom has 64
    CHECK_THROWS_AS(tr::Renderer(scene, outside), std::out_of_range);
}

TEST_CASE(
    "a lazy hierarchy lets go of the slabs of frames done: memory stays a frame's, the "
    "images stay the same, in any order of frames",
    "[tracer][lazy]") {
    // Enough spheres that nodes fill many of the arena's 64 KB blocks.
    const auto scene = example("swarm", 32, {"N=1500"});
    tr::RenderSettings settings;
    settings.samples_per_pixel = 2;
    settings.build = options(tr::Criterion::Cost, tr::BuildKind::Eager, tr::BoundStyle::Auto);
    settings.build.count_full = true;
    tr::Renderer eager(scene, settings);
    settings.build.build = tr::BuildKind::Lazy;
    tr::Renderer lazy(scene, settings);
    const int frames = scene.animation.final_frame;
    REQUIRE(frames >= 8);
    // In order, then back to frames let go of (built again when reached).
    std::vector<int> order;
    for (int f = 1; f <= frames; ++f) order.push_back(f);
    for (const int f : {3, 1, frames, 3}) order.push_back(f);
    for (const int f : order) {
        INFO("frame " << f);
        CHECK(differing(lazy.render_frame(f), eager.render_frame(f)) == 0);
    }
    eager.measure_memory();
    lazy.measure_memory();
    // The most a lazy hierarchy held at once: about a frame's slabs (two at
    // a frame's start, the next not yet let go of) out of the animation's.
    INFO("lazy " << lazy.counters().node_bytes << " B, eager " << eager.counters().node_bytes
                 << " B");
    CHECK(lazy.counters().node_bytes * 4 < eager.counters().node_bytes);
    // A full build counts each slab once, however often it was built.
    eager.count_full_hierarchy();
    lazy.count_full_hierarchy();
    CHECK(lazy.counters().cells_full == eager.counters().cells_full);
}

// Cells of more objects than the cost criterion prices one by one
// (kCostSample, tracer/hierarchy.cpp) are priced from a sample: the cells
// built may differ, the image may not.
TEST_CASE("a swarm priced from a sample makes the same images, lazy or eager, either criterion",
          "[tracer][build]") {
    const auto scene = example("swarm", 40, {"N=6000"});
    REQUIRE(scene.objects.size() > 4096);
    const tr::Image reference = render(
        scene, options(tr::Criterion::Cost, tr::BuildKind::Lazy, tr::BoundStyle::Auto), 5, 2);
    for (const auto criterion : {tr::Criterion::Cost, tr::Criterion::Paper})
        for (const auto build : {tr::BuildKind::Lazy, tr::BuildKind::Eager}) {
            INFO("criterion " << int(criterion) << " build " << int(build));
            CHECK(differing(render(scene, options(criterion, build, tr::BoundStyle::Auto), 5, 2),
                            reference) == 0);
        }
}

TEST_CASE("a leaf takes piece bounds only where they pay for their decoding", "[tracer]") {
    // Hierarchy::Builder::pieces_pay: atom's leaves hold the floor and the
    // nucleus beside small electrons, whose tighter bounds at an instant
    // save a fraction of an object test a ray: box nodes. A leaf of swarm
    // spheres, each sweeping far past its size, saves several: pieces.
    const auto count = [](const std::string& name, int size,
                          const std::vector<std::string>& declares) {
        tr::RenderSettings settings;
        settings.mode = tr::Mode::Spacetime;
        settings.samples_per_pixel = 1;
        const auto scene = example(name, size, declares);  // (the renderer keeps a reference)
        tr::Renderer renderer(scene, settings);
        renderer.render_frame(1);
        return renderer.counters();
    };
    const tr::Counters atom = count("atom", 126, {});  // (its .ini's size: the leaves it prices)
    CHECK(atom.piece_nodes == 0);
    CHECK(atom.box_nodes + atom.motion_nodes > 0);
    const tr::Counters swarm = count("swarm", 24, {"N=300"});
    CHECK(swarm.piece_nodes > 0);
}

TEST_CASE("a thread limit bounds the renderer from its construction, eager build included",
          "[build]") {
    // (Before, the limit was set only while a frame rendered: the sweeps
    // and an eager build ran on every core whatever --threads said.)
    const auto scene = example("swarm", 16, {"N=50"});
    const auto limit = [] {
        return tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
    };
    const std::size_t unlimited = limit();
    {
        tr::RenderSettings settings;
        settings.mode = tr::Mode::Spacetime;
        settings.build.build = tr::BuildKind::Eager;
        settings.threads = 1;
        tr::Renderer renderer(scene, settings);
        CHECK(limit() == 1);
        (void)renderer.render_frame(1);
        CHECK(limit() == 1);
    }
    CHECK(limit() == unlimited);
}
