// A space split keeps cells within a factor of two of a cube (split_axes,
// tracer/hierarchy.cpp): it halves only the axes at least half as wide as
// the widest. Halving all three of a region far from a cube sliced its
// short axis ever thinner, and a ray crossing that axis crossed 2^depth
// cells (fuzz_found/flat_cells*.pov: over 100 s and gigabytes for an 8 by
// 8 frame at the default depth 24).
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "tracer/renderer.hpp"

namespace tr = hexant::tracer;

namespace {

// A ground box `width` wide and 3 high, under a camera looking across it,
// with a grid of small posts on it.
hexant::runtime::SceneDescription flat_scene(double width) {
    const std::string w = std::to_string(width);
    const std::string text =
        "camera { location <0, 1, -6> look_at <0, 2, 0> }\n"
        "light_source { <-5, 9, -7>, rgb 1 }\n"
        "box { <-" +
        w + ", 0, -" + w + ">, <" + w +
        ", 3, 0.45> pigment { rgb 0.5 } }\n"
        "#for (I, 0, 63)\n"
        "  box { <mod(I, 8) - 4, 0, div(I, 8) - 4>, <mod(I, 8) - 3.6, 3, div(I, 8) - 3.6>\n"
        "        pigment { rgb 1 } }\n"
        "#end\n";
    hexant::language::ParseOptions options;
    options.animation.width = 8;
    options.animation.height = 8;
    options.animation.final_frame = 3;
    return hexant::language::parse_scene_text(text, "flat.pov", options);
}

tr::Counters render_counters(const hexant::runtime::SceneDescription& scene, int max_depth) {
    tr::RenderSettings settings;
    settings.threads = 1;
    // The paper's criterion splits any cell of more than three objects,
    // whatever the rays (the cost criterion rightly builds little for an
    // 8 by 8 frame).
    settings.build.criterion = tr::Criterion::Paper;
    settings.build.max_depth = max_depth;
    tr::Renderer renderer(scene, settings);
    (void)renderer.render_frame(1);
    return renderer.counters();
}

}  // namespace

TEST_CASE("a ray through a flat scene crosses a few cells a level, not 2^depth",
          "[tracer][cells]") {
    // 10^12 wide and 3 high; at depth 16 halving every axis gave slices
    // 3 / 2^16 high. With cells near cubes, each of the 64 rays (and its
    // shadow ray) meets a bounded number of cells a level: allow 8 a level.
    const auto scene = flat_scene(1e12);
    const int depth = 16;
    const tr::Counters c = render_counters(scene, depth);
    const std::size_t rays = c.primary_rays + c.shadow_rays;
    INFO("cells " << c.cells << ", rays " << rays);
    CHECK(c.cells > std::size_t(depth));  // the criterion did split it
    CHECK(c.cells <= rays * std::size_t(depth) * 8);
}
