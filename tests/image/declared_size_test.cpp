// An image that declares more pixels than its reader may take is refused
// from its header, before any row is decoded or its buffer taken (issue
// 45): a PNG of 61 bytes declaring 2^30 gray pixels took 3 to 6 GB and 20 to
// 48 s before std::bad_alloc.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <sys/stat.h>
#include <unistd.h>

#include "image/image_format.hpp"
#include "tests/image/declared_size_files.hpp"

namespace fs = std::filesystem;
namespace im = hexant::image;

namespace {

fs::path temp_folder() {
    const fs::path dir =
        fs::temp_directory_path() / ("hexant_declared_size_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

void write_bytes(const fs::path& path, const std::vector<unsigned char>& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

}  // namespace

TEST_CASE("a PNG declaring more pixels than the limit is refused from its header",
          "[image][png][limits]") {
    const fs::path dir = temp_folder();
    const fs::path huge = dir / "huge.png";
    hexant::test::write_png_header(huge, 32768, 32768);
    // Without the check, libpng would go on to the rows: 3 GB of buffer for
    // 2^30 pixels expanded to RGB, then "Not enough image data".
    CHECK(fs::file_size(huge) < 100);
    REQUIRE_THROWS_AS(im::read_stored_image(huge, 100'000'000), im::ImageTooLarge);
    REQUIRE_THROWS_WITH(im::read_stored_image(huge, 100'000'000),
                        Catch::Contains("huge.png: cannot read PNG image: it declares 32768 by "
                                        "32768 pixels, more than the limit of 100000000 pixels"));
    // The same file under a limit it fits is read as far as its rows: the
    // refusal above came from the header, not from the missing data.
    REQUIRE_THROWS_AS(im::read_stored_image(huge, std::size_t(1) << 30), std::runtime_error);
    try {
        (void)im::read_stored_image(dir / "huge.png", std::size_t(1) << 30);
    } catch (const im::ImageTooLarge&) {
        FAIL("refused as too large under a limit it fits");
    } catch (const std::exception&) {
    }
    fs::remove_all(dir);
}

TEST_CASE("an image's limit is width times height, to the pixel", "[image][png][limits]") {
    const fs::path tiles =
        fs::path(HEXANT_SOURCE_DIR) / "tests/tracer/pov_reference/textures/tiles.png";
    const im::StoredImage image = im::read_stored_image(tiles);
    const auto pixels = std::size_t(image.width) * std::size_t(image.height);
    CHECK(im::read_stored_image(tiles, pixels).width == image.width);
    CHECK_THROWS_AS(im::read_stored_image(tiles, pixels - 1), im::ImageTooLarge);
}

TEST_CASE("an OpenEXR data window larger than the limit is refused before its pixels",
          "[image][exr][limits]") {
    const fs::path dir = temp_folder();
    const fs::path huge = dir / "huge.exr";
    // Its header alone: the pixels' chunks and their offsets are absent.
    write_bytes(huge, hexant::test::exr_header_bytes(0, 0, 32767, 32767));
    CHECK(fs::file_size(huge) < 1024);
    REQUIRE_THROWS_AS(im::read_stored_image(huge, 100'000'000), im::ImageTooLarge);
    REQUIRE_THROWS_WITH(im::read_stored_image(huge, 100'000'000),
                        Catch::Contains("huge.exr: cannot read OpenEXR image: it declares 32768 "
                                        "by 32768 pixels, more than the limit of 100000000"));
    // A data window of 2^31 by 2^31 (min -2^30, max 2^30 - 1 on each
    // axis: its width overflowed an int) is refused by the header check.
    const fs::path wide = dir / "wide.exr";
    {
        std::vector<unsigned char> bytes =
            hexant::test::exr_header_bytes(-(1 << 30), -(1 << 30), (1 << 30) - 1, (1 << 30) - 1);
        std::ofstream(wide, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    }
    REQUIRE_THROWS_AS(im::read_stored_image(wide, 100'000'000), std::runtime_error);
    fs::remove_all(dir);
}

TEST_CASE("a GIF image larger than the limit is refused from its descriptor, not its screen",
          "[image][gif][limits]") {
    // A screen of 16 by 16 and an image of 40000 by 40000: giflib's
    // DGifSlurp took 1.6 GB for its raster before anything saw the size.
    const fs::path dir = temp_folder();
    const fs::path huge = dir / "huge.gif";
    hexant::test::write_gif_header(huge, 40000, 40000);
    REQUIRE_THROWS_AS(im::read_stored_image(huge, 100'000'000), im::ImageTooLarge);
    REQUIRE_THROWS_WITH(im::read_stored_image(huge, 100'000'000),
                        Catch::Contains("huge.gif: cannot read GIF image: it declares 40000 by "
                                        "40000 pixels, more than the limit of 100000000"));
    fs::remove_all(dir);
}

TEST_CASE("an OpenEXR attribute that declares more than the file holds is refused first",
          "[image][exr][limits]") {
    // The image fuzzer's finds (tests/fuzz/image_found/): the C++ reader
    // took 1.6 and 1.9 GB for an attribute of an unknown type, the second
    // after a box2i declared 0 bytes and the reader went on from the wrong
    // place.
    const fs::path found = fs::path(HEXANT_SOURCE_DIR) / "tests/fuzz/image_found";
    for (const char* name : {"exr_attribute_of_1.6_GB.exr", "exr_box2i_of_size_0.exr"}) {
        INFO(name);
        REQUIRE_THROWS_WITH(im::read_stored_image(found / name, 100'000'000),
                            Catch::Contains("is damaged"));
    }
}

TEST_CASE("an image reader refuses a FIFO or a folder at once", "[image][limits]") {
    // Issue 45: every reader refuses special files. A FIFO at a frame's
    // name (--resume) or at error-time's cached reference blocked the
    // image reader for good, waiting for a writer.
    const fs::path dir = temp_folder();
    const fs::path fifo = dir / "frame.png";
    fs::remove(fifo);
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    CHECK_THROWS_WITH(im::read_stored_image(fifo),
                      Catch::Contains("frame.png") && Catch::Contains("not a regular file"));
    CHECK_THROWS_WITH(im::read_stored_image(dir),
                      Catch::Contains("not a regular file") || Catch::Contains("directory"));
    fs::remove_all(dir);
}
