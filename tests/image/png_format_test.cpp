// A palette PNG as image/formats/png_format.cpp reads it: each pixel's
// index and the palette kept beside the expanded colours (a 4-bit file
// with a tRNS chunk shorter than its palette, and an 8-bit one without),
// as POV-Ray reads an image_map's palette entries and a bump_map's
// use_index from them.
#include <cstdio>
#include <filesystem>
#include <vector>

#include <catch2/catch.hpp>
#include <png.h>
#include <unistd.h>

#include "image/image_format.hpp"

namespace fs = std::filesystem;
using hexant::image::StoredImage;

namespace {

// Writes a palette PNG of `bits` per index, rows of `indices` top first.
void write_palette_png(const fs::path& path, int w, int h, int bits,
                       const std::vector<unsigned char>& indices,
                       const std::vector<png_color>& palette,
                       const std::vector<png_byte>& alpha = {}) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    REQUIRE(f != nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), bits,
                 PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
    if (!alpha.empty())
        png_set_tRNS(png, info, alpha.data(), static_cast<int>(alpha.size()), nullptr);
    png_write_info(png, info);
    png_set_packing(png);  // one index a byte, packed by libpng
    std::vector<unsigned char> row(static_cast<std::size_t>(w));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x)
            row[static_cast<std::size_t>(x)] = indices[static_cast<std::size_t>(y * w + x)];
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

fs::path temp_folder() {
    const fs::path dir =
        fs::temp_directory_path() / ("hexant_png_palette_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

}  // namespace

TEST_CASE("a palette PNG keeps each pixel's index and its palette", "[image][png]") {
    const fs::path dir = temp_folder();
    std::vector<png_color> palette(12);
    for (int i = 0; i < 12; ++i)
        palette[static_cast<std::size_t>(i)] = {static_cast<png_byte>(20 * i),
                                                static_cast<png_byte>(255 - 20 * i), 7};
    // 4 bits an index, 3 x 2; the first two entries partly clear.
    write_palette_png(dir / "four.png", 3, 2, 4, {0, 5, 11, 1, 1, 9}, palette, {0, 128});
    const StoredImage four = hexant::image::read_stored_image(dir / "four.png");
    CHECK(four.source == StoredImage::Source::Palette);
    CHECK(four.source_bits == 4);
    REQUIRE(four.width == 3);
    REQUIRE(four.height == 2);
    CHECK(four.channels == 4);
    CHECK(four.indices == std::vector<std::uint8_t>{0, 5, 11, 1, 1, 9});
    REQUIRE(four.palette.size() == 12);
    CHECK(four.palette[5][0] == Approx(100 / 255.0));
    CHECK(four.palette[0][3] == 0.0f);
    CHECK(four.palette[1][3] == Approx(128 / 255.0));
    CHECK(four.palette[11][3] == 1.0f);  // past the tRNS chunk: opaque
    // The colours expanded as libpng would: the second pixel is entry 5.
    CHECK(four.values[4] == Approx(100 / 255.0));
    CHECK(four.values[5] == Approx(155 / 255.0));
    CHECK(four.values[7] == 1.0f);
    CHECK(four.values[3 * 4 + 3] == Approx(128 / 255.0));  // entry 1's alpha

    // 8 bits, no tRNS: RGB.
    write_palette_png(dir / "eight.png", 2, 1, 8, {3, 7}, palette);
    const StoredImage eight = hexant::image::read_stored_image(dir / "eight.png");
    CHECK(eight.channels == 3);
    CHECK(eight.indices == std::vector<std::uint8_t>{3, 7});
    CHECK(eight.values[3] == Approx(140 / 255.0));
    CHECK_FALSE(eight.gamma_told);

    fs::remove_all(dir);
}
