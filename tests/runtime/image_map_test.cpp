// image_map's lookup (runtime/texture/pattern/image_map.cpp) on a 2 x 2 image whose
// pixels are told apart by red: which pixel a planar point reads (rows from
// the top, the image's bottom at y = 0), tiling, `once`, the interpolations
// at a pixel's centre and on a corner (where POV-Ray's normalized distance
// divides by zero), filter and transmit all, and points that are not
// finite. And an image_map file's decoding (language/image_map_file.cpp):
// sRGB, a gAMA chunk's power, the scene's gamma, assumed_gamma, alpha.
#include "runtime/texture/pattern/image_map.hpp"

#include <cmath>
#include <limits>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "language/image_map_file.hpp"

namespace pt = hexant::runtime::pattern;

namespace {

// Red 0.1, 0.2 on the top row, 0.3, 0.4 on the bottom; the bottom right
// half clear.
pt::ImageMap two_by_two() {
    auto pixels = std::make_shared<pt::ImagePixels>();
    pixels->width = pixels->height = 2;
    pixels->rgbt = {0.1f, 0, 0, 0, 0.2f, 0, 0, 0, 0.3f, 0, 0, 0, 0.4f, 0, 0, 0.5f};
    pt::ImageMap map;
    map.images.push_back({hexant::runtime::Interval(-1e300, 1e300), pixels});
    return map;
}

double red(const pt::ImageMap& map, double x, double y, double filter = 0.0,
           double transmit = 0.0) {
    return pt::image_colour(map, {x, y, 0.0}, 0.0, filter, transmit)[0];
}

}  // namespace

TEST_CASE("image_map: a planar point reads its pixel, the image tiled", "[pattern][image]") {
    const pt::ImageMap map = two_by_two();
    CHECK(red(map, 0.25, 0.75) == Approx(0.1));  // top left
    CHECK(red(map, 0.75, 0.75) == Approx(0.2));
    CHECK(red(map, 0.25, 0.25) == Approx(0.3));  // bottom left
    CHECK(red(map, 0.75, 0.25) == Approx(0.4));
    CHECK(red(map, 1.25, -0.75) == Approx(0.3));  // tiled both ways
    CHECK(red(map, -0.75, 2.75) == Approx(0.1));
    // The clear pixel's transmit, and transmit all added to it; filter all.
    const auto c = pt::image_colour(map, {0.75, 0.25, 0.0}, 0.0, 0.25, 0.125);
    CHECK(c[3] == Approx(0.25));
    CHECK(c[4] == Approx(0.625));
}

TEST_CASE("image_map: once shows the image one time and is clear outside", "[pattern][image]") {
    pt::ImageMap map = two_by_two();
    map.once = true;
    CHECK(red(map, 0.25, 0.75) == Approx(0.1));
    for (const auto& p :
         {glm::dvec3(1.5, 0.5, 0), glm::dvec3(0.5, -0.5, 0), glm::dvec3(-0.1, 0.5, 0)}) {
        const auto c = pt::image_colour(map, p, 0.0, 0.0, 0.0);
        CHECK(c[0] == 1.0);
        CHECK(c[4] == 1.0);
    }
}

TEST_CASE("image_map: interpolations agree with the pixel at its centre and stay finite",
          "[pattern][image]") {
    for (const auto how :
         {pt::ImageMap::Interpolate::Bilinear, pt::ImageMap::Interpolate::NormalizedDistance,
          pt::ImageMap::Interpolate::Bicubic}) {
        pt::ImageMap map = two_by_two();
        map.interpolate = how;
        INFO("interpolate " << static_cast<int>(how));
        // (A pixel's centre, nudged by POV-Ray's 1e-10: its own colour.)
        CHECK(red(map, 0.25, 0.75) == Approx(0.1).margin(1e-6));
        // Between pixels: between their colours.
        const double between = red(map, 0.5, 0.75);
        CHECK(between >= 0.1 - 1e-6);
        CHECK(between <= 0.2 + 1e-6);
        // On a pixel corner (normalized distance: a zero distance).
        for (double x = 0.0; x <= 1.0; x += 0.5)
            for (double y = 0.0; y <= 1.0; y += 0.5) CHECK(std::isfinite(red(map, x, y)));
    }
}

TEST_CASE("image_map: a point that is not finite reads clear, never NaN", "[pattern][image]") {
    const double inf = std::numeric_limits<double>::infinity(),
                 nan = std::numeric_limits<double>::quiet_NaN();
    for (const auto type : {pt::ImageMap::MapType::Planar, pt::ImageMap::MapType::Spherical,
                            pt::ImageMap::MapType::Cylindrical, pt::ImageMap::MapType::Torus}) {
        pt::ImageMap map = two_by_two();
        map.map_type = type;
        for (const glm::dvec3 p :
             {glm::dvec3(inf, 0, 0), glm::dvec3(nan, 0.5, 0), glm::dvec3(0, 0, 0),
              glm::dvec3(1e300, -1e300, 1e300), glm::dvec3(1, 0, 0)}) {
            const auto c = pt::image_colour(map, p, 0.0, 0.0, 0.0);
            for (const double v : c) CHECK(std::isfinite(v));
        }
    }
}

TEST_CASE("image_map: an image sequence shows the image of each piece of time",
          "[pattern][image]") {
    pt::ImageMap map = two_by_two();
    auto other = std::make_shared<pt::ImagePixels>(*map.images[0].pixels);
    other->rgbt[0] = 0.9f;
    map.images = {{hexant::runtime::Interval(0.0, 0.5), map.images[0].pixels},
                  {hexant::runtime::Interval(0.5 + 1e-12, 1.0), other}};
    const auto top_left = [&](double t) {
        return pt::image_colour(map, {0.25, 0.75, 0.0}, t, 0.0, 0.0)[0];
    };
    CHECK(top_left(0.25) == Approx(0.1));
    CHECK(top_left(0.75) == Approx(0.9));
    CHECK(top_left(-1.0) == Approx(0.1));  // before the first piece: the first
    CHECK(top_left(2.0) == Approx(0.9));   // after the last: the last
}

TEST_CASE("image_map's file: decoded as POV-Ray 3.7 decodes it", "[pattern][image]") {
    hexant::image::StoredImage stored;
    stored.width = 2;
    stored.height = 1;
    stored.channels = 4;
    stored.values = {0.5f, 0.04f, 1.0f, 0.25f, 0.0f, 0.2f, 0.8f, 1.0f};
    using hexant::language::image_pixels;
    using hexant::language::ImageGamma;
    const auto srgb = [](double x) {
        return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
    };
    // No word from the file: sRGB; alpha 0.25 is transmit 0.75.
    auto p = image_pixels(stored, ImageGamma{}, 1.0);
    CHECK(p.rgbt[0] == Approx(srgb(0.5)));
    CHECK(p.rgbt[1] == Approx(0.04 / 12.92));
    CHECK(p.rgbt[3] == Approx(0.75));
    CHECK(p.rgbt[7] == Approx(0.0));
    // A gAMA chunk of 1/1.8: value^1.8; the scene's gamma wins over it.
    stored.encoding_gamma = 1.0 / 1.8;
    p = image_pixels(stored, ImageGamma{}, 1.0);
    CHECK(p.rgbt[0] == Approx(std::pow(0.5, 1.8)));
    p = image_pixels(stored, ImageGamma{2.2, false}, 1.0);
    CHECK(p.rgbt[0] == Approx(std::pow(0.5, 2.2)));
    p = image_pixels(stored, ImageGamma{std::nullopt, true}, 1.0);
    CHECK(p.rgbt[0] == Approx(srgb(0.5)));
    // assumed_gamma 2.2: the linear value encoded into the working space.
    p = image_pixels(stored, ImageGamma{2.2, false}, 2.2);
    CHECK(p.rgbt[0] == Approx(0.5));
    // A #version below 3.7 that set assumed_gamma (POV-Ray's
    // AssumedGamma36): a file that says nothing is in the working space;
    // one that says is decoded as in 3.7.
    ImageGamma legacy;
    legacy.legacy_default = true;
    p = image_pixels(stored, legacy, 1.0);
    CHECK(p.rgbt[0] == Approx(std::pow(0.5, 1.8)));
    stored.encoding_gamma = 0.0;
    p = image_pixels(stored, legacy, 1.0);
    CHECK(p.rgbt[0] == Approx(0.5));
    p = image_pixels(stored, legacy, 2.2);
    CHECK(p.rgbt[0] == Approx(0.5));
    stored.gamma_told = true;  // an sRGB chunk
    p = image_pixels(stored, legacy, 1.0);
    CHECK(p.rgbt[0] == Approx(srgb(0.5)));
    // OpenEXR: linear as it is.
    stored.linear = true;
    stored.encoding_gamma = 0.0;
    p = image_pixels(stored, ImageGamma{}, 1.0);
    CHECK(p.rgbt[0] == Approx(0.5));
}

TEST_CASE("image_map: a palette entry's own filter and transmit", "[pattern][image]") {
    // Entries 0 to 3 on a 2 x 2 image; the file gives entry 3 transmit 0.5.
    auto pixels = std::make_shared<pt::ImagePixels>();
    pixels->width = pixels->height = 2;
    pixels->rgbt = {0.1f, 0, 0, 0, 0.2f, 0, 0, 0, 0.3f, 0, 0, 0, 0.4f, 0, 0, 0.5f};
    pixels->palette = true;
    pixels->indices = {0, 1, 2, 3};
    pixels->palette_size = 4;
    pt::ImageMap map;
    map.images.push_back({hexant::runtime::Interval(-1e300, 1e300), pixels});
    // transmit 1, 1 and filter 2, 0.25: those entries only.
    map.palette_entries.resize(3);
    map.palette_entries[1].has_transmit = true;
    map.palette_entries[1].transmit = 1.0f;
    map.palette_entries[2].has_filter = true;
    map.palette_entries[2].filter = 0.25f;
    const auto at = [&](double x, double y) {
        return pt::image_colour(map, {x, y, 0.0}, 0.0, 0.0, 0.0);
    };
    CHECK(at(0.25, 0.75)[4] == 0.0);  // entry 0: the file's
    CHECK(at(0.75, 0.75)[4] == 1.0);  // entry 1
    CHECK(at(0.75, 0.75)[0] == Approx(0.2));
    CHECK(at(0.25, 0.25)[3] == 0.25);  // entry 2's filter
    CHECK(at(0.25, 0.25)[4] == 0.0);
    CHECK(at(0.75, 0.25)[4] == 0.5);  // entry 3: the file's
    // After `transmit all 0.125` (set before the entries'): every other
    // entry's transmit is all's, entry 1 keeps its own.
    map.transmit_all_written = true;
    CHECK(pt::image_colour(map, {0.75, 0.25, 0.0}, 0.0, 0.0, 0.125)[4] == 0.125);
    CHECK(pt::image_colour(map, {0.75, 0.75, 0.0}, 0.0, 0.0, 0.125)[4] == 1.0);
    // Bilinear: the corners' own amounts blended.
    map.interpolate = pt::ImageMap::Interpolate::Bilinear;
    CHECK(pt::image_colour(map, {0.5, 0.75, 0.0}, 0.0, 0.0, 0.0)[4] == Approx(0.5));
}

TEST_CASE("bump_map: three samples' heights tilt the normal", "[pattern][image]") {
    // 3 x 2: the top row index 5, the bottom 0, 1, 2; grey 0.5 everywhere.
    auto pixels = std::make_shared<pt::ImagePixels>();
    pixels->width = 3;
    pixels->height = 2;
    pixels->rgbt.assign(6 * 4, 0.5f);
    for (std::size_t i = 3; i < pixels->rgbt.size(); i += 4) pixels->rgbt[i] = 0.0f;
    pixels->palette = true;
    pixels->indices = {5, 5, 5, 0, 1, 2};
    pixels->palette_size = 6;
    pt::ImageMap map;
    map.images.push_back({hexant::runtime::Interval(-1e300, 1e300), pixels});
    const glm::dvec3 up(0.0, 1.0, 0.0), wall(0.0, 0.0, -1.0);
    // The colours are flat: the normal unchanged, whatever it is.
    for (const glm::dvec3& n : {up, wall, glm::normalize(glm::dvec3(1.0, 2.0, -3.0))}) {
        const glm::dvec3 b = pt::bump_map_normal(map, {0.5, 0.75, 0.0}, 0.0, 0.5, n);
        CHECK(b.x == Approx(n.x).margin(1e-12));
        CHECK(b.y == Approx(n.y).margin(1e-12));
        CHECK(b.z == Approx(n.z).margin(1e-12));
    }
    // use_index at the top middle pixel: heights 0.5 * (5, 0, 2) here, one
    // down to the left and one down to the right; about +y the triangle's
    // normal (h2 - h3, 2, 2 h1 - h2 - h3) with z turned.
    map.use_index = true;
    const glm::dvec3 b = pt::bump_map_normal(map, {0.5, 0.75, 0.0}, 0.0, 0.5, up);
    const double l = std::sqrt(21.0);
    CHECK(b.x == Approx(-1.0 / l));
    CHECK(b.y == Approx(2.0 / l));
    CHECK(b.z == Approx(-4.0 / l));
    // Off an image used once: unchanged.
    map.once = true;
    const glm::dvec3 off = pt::bump_map_normal(map, {1.5, 0.5, 0.0}, 0.0, 0.5, wall);
    CHECK(off == wall);
    // An image without a palette has no index: its greys (flat here).
    map.once = false;
    pixels->indices.clear();
    pixels->palette = false;
    const glm::dvec3 grey = pt::bump_map_normal(map, {0.5, 0.75, 0.0}, 0.0, 0.5, up);
    CHECK(grey.y == Approx(1.0));
}
