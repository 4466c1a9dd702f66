// The formats read and written through hexant's OpenImageIO module
// (image/formats/oiio_formats.hpp): each reads as POV-Ray 3.7 reads it
// (its shape, its default decoding), each written frame reads back as
// written, a Targa is told by the scene's word or its name, a file that
// declares too many pixels is refused from its header, and a damaged file of
// each format is an error naming it. The fixtures are
// tests/tracer/pov_reference/textures/colours.{tga,ppm,bmp,tif}, glow.hdr and
// heights16.pgm, made by oiiotool (pov_reference/README.md): the four 8-bit
// colour files hold the same bytes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <unistd.h>

#include "image/colour_transfer.hpp"
#include "image/image_format.hpp"
#include "image/oiio_library.hpp"
#include "language/image_map_file.hpp"
#include "runtime/objects/height_field/height_field_data.hpp"
#include "tracer/image_output.hpp"

namespace fs = std::filesystem;
namespace im = hexant::image;
namespace tr = hexant::tracer;

namespace {

const fs::path kTextures =
    fs::path(HEXANT_SOURCE_DIR) / "tests" / "tracer" / "pov_reference" / "textures";

fs::path fresh_folder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

// Values over the whole range, beyond it and below 8 bits' resolution.
tr::Image ramp(int width, int height) {
    tr::Image image(width, height);
    for (std::size_t i = 0; i < image.rgb.size(); ++i)
        image.rgb[i] = float(i % 97) / 80.0f - 0.1f + float(i % 7) * 1e-4f;
    return image;
}

}  // namespace

TEST_CASE("Targa, PPM, BMP and TIFF read the same bytes, each as POV-Ray decodes it",
          "[image][oiio]") {
    const im::StoredImage ppm = im::read_stored_image(kTextures / "colours.ppm");
    REQUIRE((ppm.width == 32 && ppm.height == 24 && ppm.channels == 3));
    CHECK(ppm.source == im::StoredImage::Source::Rgb);
    CHECK(ppm.as_stored);  // no gamma unless the scene gives one
    CHECK_FALSE(ppm.linear);
    const struct {
        const char* name;
        bool as_stored;
    } same[] = {{"colours.tga", false}, {"colours.bmp", false}, {"colours.tif", true}};
    for (const auto& [name, as_stored] : same) {
        INFO(name);
        const im::StoredImage other = im::read_stored_image(kTextures / name);
        REQUIRE((other.width == 32 && other.height == 24 && other.channels == 3));
        CHECK(other.as_stored == as_stored);  // Targa and BMP: sRGB by default
        CHECK_FALSE(other.linear);
        CHECK(other.source_bits == 8);
        REQUIRE(other.values.size() == ppm.values.size());
        for (std::size_t i = 0; i < ppm.values.size(); ++i)
            REQUIRE(std::lround(other.values[i] * 255.0f) == std::lround(ppm.values[i] * 255.0f));
    }
    // The top-left pixel is the fill's corner, (1, 0.2, 0).
    CHECK(std::lround(ppm.values[0] * 255.0f) == 255);
    CHECK(std::lround(ppm.values[1] * 255.0f) == 51);
    CHECK(std::lround(ppm.values[2] * 255.0f) == 0);
}

TEST_CASE("a PPM's values go to the working space as they are, a Targa's are sRGB",
          "[image][oiio]") {
    // POV-Ray 3.7's ppm.cpp applies a gamma only when the scene gives one;
    // targa.cpp decodes sRGB by default.
    const im::StoredImage ppm = im::read_stored_image(kTextures / "colours.ppm");
    const im::StoredImage tga = im::read_stored_image(kTextures / "colours.tga");
    const hexant::language::ImageGamma by_default;
    const auto raw = hexant::language::image_pixels(ppm, by_default, 1.0);
    const auto srgb = hexant::language::image_pixels(tga, by_default, 1.0);
    CHECK(raw.rgbt[1] == Approx(0.2f));                   // 51 / 255, as it is
    CHECK(srgb.rgbt[1] == Approx(im::srgb_decode(0.2)));  // decoded
    // The scene's gamma applies to a PPM too.
    hexant::language::ImageGamma told;
    told.power = 2.2;
    CHECK(hexant::language::image_pixels(ppm, told, 1.0).rgbt[1] == Approx(std::pow(0.2, 2.2)));
}

TEST_CASE("a Radiance HDR is linear, a 16-bit PGM gray in 16 bits", "[image][oiio]") {
    const im::StoredImage hdr = im::read_stored_image(kTextures / "glow.hdr");
    REQUIRE((hdr.width == 32 && hdr.height == 24 && hdr.channels == 3));
    CHECK(hdr.linear);
    // 3 x the colours' fill: its top-left red is 3 (within RGBE's 2^-7).
    CHECK(hdr.values[0] == Approx(3.0f).epsilon(1.0 / 128));
    const im::StoredImage pgm = im::read_stored_image(kTextures / "heights16.pgm");
    REQUIRE((pgm.width == 24 && pgm.height == 24 && pgm.channels == 3));
    CHECK(pgm.source == im::StoredImage::Source::Gray);
    CHECK(pgm.source_bits == 16);
    // Its heights are its 16-bit values (POV-Ray's Gray_Int16), the bottom
    // row first: the file's big-endian samples, read here on their own, as
    // POV-Ray's GetGrayValue hands them on (sample / 65535 in single
    // precision, times 65535, truncated: a step below for some).
    std::ifstream in(kTextures / "heights16.pgm", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    const std::size_t start = bytes.find("65535\n") + 6;
    REQUIRE(bytes.size() == start + 24u * 24u * 2u);
    const std::vector<std::uint16_t> heights = hexant::runtime::objects::heights_from_image(pgm);
    REQUIRE(heights.size() == 24u * 24u);
    for (std::size_t row = 0; row < 24; ++row)
        for (std::size_t x = 0; x < 24; ++x) {
            const std::size_t at = start + 2 * (row * 24 + x);
            const unsigned sample = unsigned(static_cast<unsigned char>(bytes[at])) << 8 |
                                    static_cast<unsigned char>(bytes[at + 1]);
            const float gray = float(sample) / 65535.0f;
            REQUIRE(heights[(23 - row) * 24 + x] == std::uint16_t(gray * 65535.0f));
        }
    // Values no 8-bit file holds.
    bool deep = false;
    for (const std::uint16_t h : heights) deep = deep || h % 257 != 0;
    CHECK(deep);
}

TEST_CASE("a Targa is told by the scene's word or by its name", "[image][oiio]") {
    const fs::path folder = fresh_folder("hexant_tga_name");
    fs::copy_file(kTextures / "colours.tga", folder / "colours.dat");
    CHECK_THROWS_WITH(im::read_stored_image(folder / "colours.dat"),
                      Catch::Contains("colours.dat") && Catch::Contains("Targa file named .tga"));
    CHECK(im::read_stored_image(folder / "colours.dat", im::kMaxImagePixels, "tga").width == 32);
    fs::copy_file(kTextures / "colours.tga", folder / "COLOURS.TGA");
    CHECK(im::read_stored_image(folder / "COLOURS.TGA").width == 32);
    fs::remove_all(folder);
}

TEST_CASE("a file through OpenImageIO declaring more pixels than the limit is refused",
          "[image][oiio][limits]") {
    for (const char* name :
         {"colours.tga", "colours.ppm", "colours.bmp", "colours.tif", "glow.hdr"}) {
        INFO(name);
        REQUIRE_THROWS_AS(im::read_stored_image(kTextures / name, 32 * 24 - 1), im::ImageTooLarge);
        REQUIRE_THROWS_WITH(im::read_stored_image(kTextures / name, 32 * 24 - 1),
                            Catch::Contains(name) && Catch::Contains("it declares 32 by 24"));
        CHECK(im::read_stored_image(kTextures / name, 32 * 24).width == 32);
    }
    // A header that declares 60000 x 60000 in a file of 18 bytes.
    const fs::path folder = fresh_folder("hexant_tga_huge");
    const unsigned char header[18] = {0, 0, 2, 0,    0,    0,    0,    0,  0,
                                      0, 0, 0, 0x60, 0xEA, 0x60, 0xEA, 24, 0x20};
    std::ofstream(folder / "huge.tga", std::ios::binary)
        .write(reinterpret_cast<const char*>(header), sizeof header);
    CHECK_THROWS_AS(im::read_stored_image(folder / "huge.tga", 100'000'000), im::ImageTooLarge);
    // A run-length BMP, which OpenImageIO decodes whole when it opens it:
    // refused from hexant's own look at its header first.
    std::vector<unsigned char> bmp(54 + 1024, 0);
    const auto put32 = [&](std::size_t at, std::uint32_t v) {
        for (int k = 0; k < 4; ++k) bmp[at + k] = static_cast<unsigned char>(v >> (8 * k));
    };
    bmp[0] = 'B';
    bmp[1] = 'M';
    put32(2, std::uint32_t(bmp.size()));
    put32(10, 54 + 1024);
    put32(14, 40);
    put32(18, 60000);
    put32(22, 60000);
    bmp[26] = 1;  // planes
    bmp[28] = 8;  // bits per pixel
    bmp[30] = 1;  // BI_RLE8
    std::ofstream(folder / "huge.bmp", std::ios::binary)
        .write(reinterpret_cast<const char*>(bmp.data()), std::streamsize(bmp.size()));
    CHECK_THROWS_WITH(im::read_stored_image(folder / "huge.bmp", 100'000'000),
                      Catch::Contains("huge.bmp") && Catch::Contains("60000 by 60000"));
    fs::remove_all(folder);
}

TEST_CASE("a damaged file of each format is an error naming it, never a crash", "[image][oiio]") {
    const fs::path folder = fresh_folder("hexant_oiio_damaged");
    for (const char* name : {"colours.tga", "colours.ppm", "colours.bmp", "colours.tif", "glow.hdr",
                             "heights16.pgm"}) {
        const std::uintmax_t size = fs::file_size(kTextures / name);
        for (const std::uintmax_t keep : {std::uintmax_t(1), std::uintmax_t(12), size / 2}) {
            INFO(name << " cut to " << keep << " bytes");
            const fs::path cut = folder / (std::string("cut_") + name);
            fs::remove(cut);
            fs::copy_file(kTextures / name, cut);
            fs::resize_file(cut, keep);
            CHECK_THROWS_WITH(im::read_stored_image(cut), Catch::Contains(cut.string()));
        }
    }
    fs::remove_all(folder);
}

TEST_CASE("frames written in each format read back as written", "[image][oiio][tracer]") {
    const fs::path folder = fresh_folder("hexant_oiio_frames");
    const tr::Image image = ramp(37, 23);
    const struct {
        const char* name;
        const char* variant;
    } frames[] = {{"frame.tga", ""}, {"rle.tga", "rle"}, {"frame.ppm", ""}, {"frame.bmp", ""},
                  {"frame.tif", ""}, {"frame.tiff", ""}, {"frame.hdr", ""}, {"deep.png", "16"}};
    for (const auto& [name, variant] : frames) {
        INFO(name << " " << variant);
        tr::write_image(image, folder / name, variant);
        const im::StoredImage back = im::read_stored_image(folder / name);
        REQUIRE((back.width == 37 && back.height == 23 && back.channels == 3));
        const im::ImageFormat& format = *im::image_format_for(folder / name, variant);
        for (std::size_t i = 0; i < image.rgb.size(); ++i) {
            const double written = image.rgb[i];
            if (format.linear && std::string(variant) == "16")
                REQUIRE(std::lround(back.values[i] * 65535.0) ==
                        std::lround(im::srgb_encode(std::clamp(written, 0.0, 1.0)) * 65535.0));
            else if (format.linear)  // RGBE: within 2^-7 of the pixel's largest
                REQUIRE(back.values[i] == Approx(std::max(written, 0.0)).margin(1.3 / 128));
            else
                REQUIRE(std::lround(back.values[i] * 255.0f) == tr::to_srgb8(written));
        }
    }
    // A run-length Targa is smaller than the uncompressed one for a flat
    // image, and both read alike.
    const tr::Image flat(64, 64);
    tr::write_image(flat, folder / "flat.tga");
    tr::write_image(flat, folder / "flat_rle.tga", "rle");
    CHECK(fs::file_size(folder / "flat_rle.tga") < fs::file_size(folder / "flat.tga") / 4);
    CHECK(im::read_stored_image(folder / "flat_rle.tga").values ==
          im::read_stored_image(folder / "flat.tga").values);
    // A 16-bit PNG says so, and sRGB.
    const im::StoredImage deep = im::read_stored_image(folder / "deep.png");
    CHECK(deep.source_bits == 16);
    CHECK(deep.gamma_told);
    CHECK(deep.encoding_gamma == 0.0);
    fs::remove_all(folder);
}

TEST_CASE("the OpenImageIO module is found beside the executable or in the build folder",
          "[image][oiio]") {
    const std::vector<fs::path> folders = im::oiio_module_folders();
    REQUIRE(folders.size() == 3u);
    bool found = false;
    for (const fs::path& folder : folders)
        found = found || fs::exists(folder / im::kOiioModuleName);
    CHECK(found);
    (void)im::read_stored_image(kTextures / "colours.tga");
    CHECK(im::oiio_module_loaded());
}

TEST_CASE("mutated files of each format read whole or fail with an error", "[image][oiio]") {
    // The fuzzer's seeds with bytes changed and cut short, 400 of each, in a
    // fixed order (a cheap stand-in for hexant_image_fuzz, which needs a
    // sanitizer build): each reads into a whole image or throws
    // std::runtime_error naming the file; nothing else.
    const fs::path seeds = fs::path(HEXANT_SOURCE_DIR) / "tests" / "fuzz" / "image_corpus";
    const fs::path folder = fresh_folder("hexant_oiio_mutated");
    std::uint64_t state = 0x9E3779B97F4A7C15u;
    const auto next = [&] {
        state = state * 6364136223846793005u + 1442695040888963407u;
        return std::uint32_t(state >> 33);
    };
    for (const char* name :
         {"seed_rle.tga", "seed.ppm", "seed.bmp", "seed.tif", "seed.hdr", "seed16.pgm"}) {
        std::ifstream in(seeds / name, std::ios::binary);
        const std::string original((std::istreambuf_iterator<char>(in)), {});
        REQUIRE(original.size() > 16u);
        const fs::path file = folder / (std::string("m_") + name);
        int read = 0;
        for (int k = 0; k < 400; ++k) {
            std::string bytes = original;
            const int changes = 1 + int(next() % 4);
            for (int c = 0; c < changes; ++c)
                bytes[next() % bytes.size()] = static_cast<char>(next() & 0xff);
            if (next() % 4 == 0) bytes.resize(next() % bytes.size());
            std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
            try {
                const im::StoredImage image = im::read_stored_image(file, 1 << 16, "tga");
                REQUIRE(image.values.size() == std::size_t(image.width) *
                                                   std::size_t(image.height) *
                                                   std::size_t(image.channels));
                ++read;
            } catch (const std::runtime_error& e) {
                REQUIRE_THAT(e.what(), Catch::Contains(file.string()));
            }
        }
        INFO(name << ": " << read << " of 400 read");
        CHECK(read < 400);  // (some mutations must have been refused)
    }
    fs::remove_all(folder);
}

TEST_CASE("a colour-mapped Targa keeps its indices, as POV-Ray reads it", "[image][oiio]") {
    // 4 x 2 pixels, indices 0..4 of a 5-entry 24-bit map (entry i: blue
    // 10i, green 20i, red 40i), stored bottom row first; uncompressed
    // (type 1) and run-length (type 9: a run of 3, then 5 literals).
    const std::vector<unsigned char> indices_in_file = {4, 4, 4, 3, 0, 1, 2, 3};
    std::vector<unsigned char> map;
    for (unsigned i = 0; i < 5; ++i)
        map.insert(map.end(),
                   {(unsigned char)(10 * i), (unsigned char)(20 * i), (unsigned char)(40 * i)});
    const auto targa = [&](unsigned char type, const std::vector<unsigned char>& data) {
        std::vector<unsigned char> bytes = {0, 1, type, 0, 0, 5, 0, 24, 0,
                                            0, 0, 0,    4, 0, 2, 0, 8,  0};
        bytes.insert(bytes.end(), map.begin(), map.end());
        bytes.insert(bytes.end(), data.begin(), data.end());
        return bytes;
    };
    const fs::path folder = fresh_folder("hexant_tga_palette");
    const auto write = [&](const char* name, const std::vector<unsigned char>& bytes) {
        std::ofstream(folder / name, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        return folder / name;
    };
    const fs::path raw = write("raw.tga", targa(1, indices_in_file));
    const fs::path rle = write("rle.tga", targa(9, {0x82, 4, 0x04, 3, 0, 1, 2, 3}));
    for (const fs::path& file : {raw, rle}) {
        INFO(file);
        const im::StoredImage image = im::read_stored_image(file);
        REQUIRE(image.source == im::StoredImage::Source::Palette);
        REQUIRE((image.width == 4 && image.height == 2 && image.channels == 3));
        REQUIRE(image.palette.size() == 5u);
        CHECK(image.palette[2][0] == Approx(80 / 255.0));  // red
        CHECK(image.palette[2][2] == Approx(20 / 255.0));  // blue
        // Rows top first: the file's second row, then its first.
        CHECK(image.indices == std::vector<std::uint8_t>{0, 1, 2, 3, 4, 4, 4, 3});
        CHECK(image.values[3 * 5] == Approx(160 / 255.0));  // pixel 5's red: entry 4
        // A height field of it: index x 256, its bottom row the file's first.
        const auto heights = hexant::runtime::objects::heights_from_image(image);
        CHECK(heights == std::vector<std::uint16_t>{1024, 1024, 1024, 768, 0, 256, 512, 768});
    }
    // An index past the map: an error naming the file, as POV-Ray's.
    const fs::path bad = write("bad.tga", targa(1, {0, 1, 2, 3, 4, 5, 0, 0}));
    CHECK_THROWS_WITH(im::read_stored_image(bad),
                      Catch::Contains("bad.tga") && Catch::Contains("past its colour map"));
    fs::remove_all(folder);
}
