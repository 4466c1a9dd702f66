// However the hierarchy is built, the image is the same: lazy or eager,
// the cost criterion or the paper's, any style of bound, with the same
// samples every ray finds the same first hit, so every pixel is equal, on
// each example. And a lazy hierarchy built by many threads at once, from
// cold, gives the image one thread gives, every time.
//
// The threaded case is the one to run under ThreadSanitizer (README.md,
// "Tests"): cmake -S . -B build-tsan -DHEXANT_SANITIZE=thread, then
// build-tsan/tests/hexant_tests "[lazy]".
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "app/command_line.hpp"
#include "language/interpreter.hpp"
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
    const Example examples[] = {{"atom", 22}, {"bounce", 4}, {"dino", 33},
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

TEST_CASE("a cold lazy hierarchy built by many threads at once gives one thread's image",
          "[tracer][lazy]") {
    // Many small moving objects, so that many cells are built while the
    // threads race through the first rays.
    const auto scene = example("swarm", 48, {"N=300"});
    const tr::Image reference =
        render(scene, options(tr::Criterion::Cost, tr::BuildKind::Eager, tr::BoundStyle::Auto), 3,
               2, 1);
    for (int run = 0; run < 12; ++run) {
        INFO("run " << run);
        const tr::Image image = render(
            scene, options(run % 2 ? tr::Criterion::Paper : tr::Criterion::Cost,
                           tr::BuildKind::Lazy, tr::BoundStyle::Auto),
            3, 2, 8);
        CHECK(differing(image, reference) == 0);
    }
}
