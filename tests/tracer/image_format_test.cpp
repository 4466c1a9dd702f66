// Image files through their own libraries (image/image_format.hpp): what
// is written reads back exactly (PNG's bytes, EXR's floats); a name of no
// format, a damaged file and a file of no format are errors naming the file;
// an animation holds every frame; a comparison measures what OpenImageIO's
// compare did (mean, RMS, worst pixel, failing and warning pixels).
#include "image/image_format.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>
#include <fcntl.h>
#include <unistd.h>

#include "image/formats/gif_format.hpp"
#include "tracer/gif_animation.hpp"
#include "tracer/image_compare.hpp"
#include "tracer/image_output.hpp"

namespace fs = std::filesystem;
namespace tr = hexant::tracer;

namespace {

fs::path fresh_folder(const char* name) {
    const fs::path folder = fs::temp_directory_path() / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

// Values over the whole range, beyond it (clamped in PNG, kept in EXR) and
// below 8 bits' resolution.
tr::Image ramp(int width, int height) {
    tr::Image image(width, height);
    for (std::size_t i = 0; i < image.rgb.size(); ++i)
        image.rgb[i] = float(i % 97) / 80.0f - 0.1f + float(i % 7) * 1e-4f;
    return image;
}

}  // namespace

TEST_CASE("PNG and EXR frames read back as written", "[tracer][image]") {
    const fs::path folder = fresh_folder("hexant_image_format_test");
    const tr::Image image = ramp(37, 23);

    tr::write_image(image, folder / "frame.png");
    const hexant::image::StoredImage png = hexant::image::read_stored_image(folder / "frame.png");
    CHECK_FALSE(png.linear);
    REQUIRE((png.width == 37 && png.height == 23 && png.channels == 3));
    for (std::size_t i = 0; i < image.rgb.size(); ++i)
        REQUIRE(std::lround(png.values[i] * 255.0f) == tr::to_srgb8(image.rgb[i]));

    // The name's case does not matter; the format is told by the content.
    tr::write_image(image, folder / "frame.EXR");
    const hexant::image::StoredImage exr = hexant::image::read_stored_image(folder / "frame.EXR");
    CHECK(exr.linear);
    REQUIRE((exr.width == 37 && exr.height == 23 && exr.channels == 3));
    CHECK(exr.values == image.rgb);
    fs::rename(folder / "frame.EXR", folder / "misnamed.png");
    CHECK(hexant::image::read_stored_image(folder / "misnamed.png").values == image.rgb);
    fs::remove_all(folder);
}

TEST_CASE("a name of no format, a damaged file and a file of no format are errors",
          "[tracer][image]") {
    const fs::path folder = fresh_folder("hexant_image_format_errors");
    const tr::Image image = ramp(16, 16);
    CHECK_THROWS_WITH(tr::write_image(image, folder / "frame.webp"),
                      Catch::Contains("frame.webp") && Catch::Contains(".png, .exr"));
    CHECK_THROWS_WITH(tr::write_image(image, folder / "frame.exr", "rle"),
                      Catch::Contains("frame.exr") && Catch::Contains("not written as 'rle'"));
    CHECK(fs::is_empty(folder));

    tr::write_image(image, folder / "whole.png");
    tr::write_image(image, folder / "whole.exr");
    for (const char* name : {"whole.png", "whole.exr"}) {
        INFO(name);
        // The first half of the file: its pixels are cut short.
        const fs::path cut = folder / (std::string("cut_") + name);
        fs::copy_file(folder / name, cut);
        fs::resize_file(cut, fs::file_size(cut) / 2);
        CHECK_THROWS_WITH(hexant::image::read_stored_image(cut), Catch::Contains(cut.string()));
    }
    { std::ofstream(folder / "text.png") << "not an image at all"; }
    CHECK_THROWS_WITH(
        hexant::image::read_stored_image(folder / "text.png"),
        Catch::Contains("text.png") && Catch::Contains("not a PNG, OpenEXR, JPEG, GIF, TIFF"));
    CHECK_THROWS_WITH(hexant::image::read_stored_image(folder / "missing.png"),
                      Catch::Contains("missing.png"));
    fs::remove_all(folder);
}

TEST_CASE("a JPEG is read as libjpeg decodes it, and never written", "[tracer][image]") {
    namespace im = hexant::image;
    const fs::path textures =
        fs::path(HEXANT_SOURCE_DIR) / "tests" / "tracer" / "pov_reference" / "textures";
    const im::StoredImage colours = im::read_stored_image(textures / "colours.jpg");
    CHECK(colours.width == 32);
    CHECK(colours.height == 24);
    CHECK(colours.channels == 3);
    CHECK(colours.source == im::StoredImage::Source::Rgb);
    CHECK_FALSE(colours.linear);
    CHECK_FALSE(colours.gamma_told);  // sRGB unless the scene says otherwise
    REQUIRE(colours.values.size() == 32u * 24u * 3u);
    // The top-left corner is the fill's (1, 0.2, 0) plus the checker's 0,
    // within the JPEG's loss.
    CHECK(colours.values[0] == Approx(1.0).margin(0.06));
    CHECK(colours.values[2] == Approx(0.0).margin(0.06));
    const im::StoredImage heights = im::read_stored_image(textures / "heights.jpg");
    CHECK(heights.source == im::StoredImage::Source::Gray);
    REQUIRE(heights.channels == 3);
    for (std::size_t i = 0; i < heights.values.size(); i += 3) {
        CHECK(heights.values[i] == heights.values[i + 1]);
        CHECK(heights.values[i] == heights.values[i + 2]);
    }
    // Cut short, or its header damaged: an error naming the file, no crash.
    const fs::path folder = fresh_folder("hexant_jpeg_test");
    const fs::path cut = folder / "cut.jpg";
    fs::copy_file(textures / "colours.jpg", cut);
    fs::resize_file(cut, 300);  // in its tables
    CHECK_THROWS_WITH(im::read_stored_image(cut), Catch::Contains("cut.jpg"));
    fs::resize_file(cut, fs::file_size(textures / "colours.jpg") * 3 / 4);  // in its pixels
    CHECK_THROWS_WITH(im::read_stored_image(cut), Catch::Contains("cut.jpg"));
    { std::ofstream(folder / "bad.jpg", std::ios::binary) << "\xFF\xD8\xFF\xE0 not a JPEG"; }
    CHECK_THROWS_WITH(im::read_stored_image(folder / "bad.jpg"),
                      Catch::Contains("bad.jpg") && Catch::Contains("JPEG"));
    // A frame is never written as JPEG: it must read back as written.
    CHECK(im::image_format_for("frame.jpg") == nullptr);
    CHECK_THROWS(tr::write_image(ramp(4, 3), folder / "frame.jpg"));
    CHECK_FALSE(fs::exists(folder / "frame.jpg"));
    fs::remove_all(folder);
}

TEST_CASE("a GIF is read as giflib decodes it, a POT file from its halves", "[tracer][image]") {
    namespace im = hexant::image;
    const fs::path textures =
        fs::path(HEXANT_SOURCE_DIR) / "tests" / "tracer" / "pov_reference" / "textures";
    // indexed.gif (make_gifs.py): 12 x 8, pixel (x, y) index (x + 3y) % 8,
    // entry i (30i, 255 - 30i, 70i % 256), index 3 transparent.
    const im::StoredImage gif = im::read_stored_image(textures / "indexed.gif");
    CHECK(gif.width == 12);
    CHECK(gif.height == 8);
    CHECK(gif.source == im::StoredImage::Source::Palette);
    CHECK_FALSE(gif.gamma_told);  // sRGB unless the scene says otherwise
    REQUIRE(gif.channels == 4);
    REQUIRE(gif.indices.size() == 96u);
    REQUIRE(gif.palette.size() == 8u);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 12; ++x) {
            const std::size_t i = std::size_t(y * 12 + x);
            const int index = (x + 3 * y) % 8;
            INFO(x << ", " << y);
            CHECK(gif.indices[i] == index);
            CHECK(gif.values[4 * i] == Approx(30.0 * index / 255.0));
            CHECK(gif.values[4 * i + 1] == Approx((255.0 - 30.0 * index) / 255.0));
            CHECK(gif.values[4 * i + 3] == (index == 3 ? 0.0f : 1.0f));
        }
    // heights.pot: 32 x 12 as a GIF, 16 x 12 16-bit heights as a POT file.
    const im::StoredImage pot_gif = im::read_stored_image(textures / "heights.pot");
    REQUIRE(pot_gif.width == 32);
    const im::StoredImage pot = im::pot_from_gif(pot_gif);
    CHECK(pot.width == 16);
    CHECK(pot.height == 12);
    CHECK(pot.source == im::StoredImage::Source::Gray);
    CHECK(pot.source_bits == 16);
    REQUIRE(pot.values.size() == 16u * 12u * 3u);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 16; ++x) {
            const int value = int(65535 * (0.5 + 0.45 * std::sin(x * 0.5) * std::cos(y * 0.6)));
            CHECK(std::lround(pot.values[std::size_t(y * 16 + x) * 3] * 65535.0) == value);
        }
    // Not two halves, not paletted: errors.
    im::StoredImage odd = gif;
    odd.width = 3;
    odd.height = 32;
    CHECK_THROWS_WITH(im::pot_from_gif(odd), Catch::Contains("width"));
    CHECK_THROWS(im::pot_from_gif(pot));
    // Cut short, or not a GIF after its magic: an error naming the file.
    const fs::path folder = fresh_folder("hexant_gif_read_test");
    const fs::path cut = folder / "cut.gif";
    fs::copy_file(textures / "heights.pot", cut);
    fs::resize_file(cut, fs::file_size(cut) / 2);
    CHECK_THROWS_WITH(im::read_stored_image(cut), Catch::Contains("cut.gif"));
    { std::ofstream(folder / "bad.gif", std::ios::binary) << "GIF89a not a GIF at all"; }
    CHECK_THROWS_WITH(im::read_stored_image(folder / "bad.gif"),
                      Catch::Contains("bad.gif") && Catch::Contains("GIF"));
    // hexant's own animated GIF reads back: its first frame, paletted.
    std::vector<tr::Image> frames(2, ramp(10, 6));
    tr::write_animation(frames, folder / "movie.gif", 12.0);
    const im::StoredImage movie = im::read_stored_image(folder / "movie.gif");
    CHECK(movie.width == 10);
    CHECK(movie.height == 6);
    CHECK(movie.source == im::StoredImage::Source::Palette);
    // Never written as a frame.
    CHECK(im::image_format_for("frame.gif") == nullptr);
    fs::remove_all(folder);
}

TEST_CASE("an animated GIF holds every frame", "[tracer][image]") {
    const fs::path folder = fresh_folder("hexant_gif_test");
    std::vector<tr::Image> frames;
    for (int k = 0; k < 5; ++k) {
        tr::Image frame(20, 12);
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 20; ++x) frame.set(x, y, {x == 4 * k ? 1.0 : 0.1, 0.5, y / 12.0});
        frames.push_back(frame);
    }
    tr::write_animation(frames, folder / "movie.gif", 12.0);
    const int fd = ::open((folder / "movie.gif").c_str(), O_RDONLY | O_CLOEXEC);
    REQUIRE(fd >= 0);
    CHECK(tr::count_gif_frames(fd, 20, 12) == 5);
    CHECK_THROWS_WITH(tr::count_gif_frames(fd, 21, 12), Catch::Contains("wrong size"));
    ::close(fd);
    CHECK_THROWS_WITH(tr::write_animation(frames, folder / "movie.png", 12.0),
                      Catch::Contains("movie.png"));
    frames.back() = tr::Image(8, 8);
    CHECK_THROWS_WITH(tr::write_animation(frames, folder / "other.gif", 12.0),
                      Catch::Contains("differ in size"));
    CHECK_FALSE(fs::exists(folder / "other.gif"));
    fs::remove_all(folder);
}

TEST_CASE("a comparison measures mean, RMS, worst pixel, failing and warning pixels",
          "[tracer][image]") {
    const fs::path folder = fresh_folder("hexant_image_compare_test");
    tr::Image a(4, 2), b(4, 2);
    for (float& v : a.rgb) v = 0.25f;
    b = a;
    // Pixel (3, 1): one channel off by 0.5; pixel (1, 0): all three by 0.125.
    b.rgb[(1 * 4 + 3) * 3 + 2] = 0.75f;
    for (int c = 0; c < 3; ++c) b.rgb[(0 * 4 + 1) * 3 + c] = 0.375f;
    tr::write_image(a, folder / "a.exr");
    tr::write_image(b, folder / "b.exr");
    const tr::ImageDifference d = tr::compare_images(folder / "a.exr", folder / "b.exr", 0.25, 0.1);
    CHECK(d.pixels == 8);
    CHECK(d.failing == 1);
    CHECK(d.warning == 2);
    CHECK(d.max == Approx(0.5));
    CHECK((d.max_x == 3 && d.max_y == 1));
    CHECK(d.mean == Approx((0.5 + 3 * 0.125) / 24.0));
    CHECK(d.rms == Approx(std::sqrt((0.25 + 3 * 0.015625) / 24.0)));
    const tr::ImageError e = tr::image_error(folder / "b.exr", folder / "a.exr");
    CHECK(e.rmse == Approx(d.rms));
    CHECK(e.relative_mse == Approx((0.25 + 3 * 0.015625) / (0.0625 + 0.01) / 24.0));

    // In linear light a PNG is decoded first: mid-grey's byte 188 is 0.5.
    tr::Image grey(2, 2), white(2, 2);
    for (float& v : grey.rgb) v = 0.5f;
    for (float& v : white.rgb) v = 1.0f;
    tr::write_image(grey, folder / "grey.png");
    tr::write_image(white, folder / "white.png");
    const double stored = tr::compare_images(folder / "grey.png", folder / "white.png", 1, 1).max;
    const double linear =
        tr::compare_images(folder / "grey.png", folder / "white.png", 1, 1, tr::ImageSpace::Linear)
            .max;
    CHECK(stored == Approx(1.0 - 188.0 / 255.0));
    // Rounding to a byte moves grey by at most half a step, 0.003 in linear
    // light near 0.5 (a step there is 0.006).
    CHECK(linear == Approx(0.5).margin(0.004));
    CHECK_THROWS_WITH(tr::compare_images(folder / "grey.png", folder / "a.exr", 1, 1),
                      Catch::Contains("2x2x3 but"));
    fs::remove_all(folder);
}
