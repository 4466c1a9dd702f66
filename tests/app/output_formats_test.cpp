// POV-Ray's output types through the hexant binary: +FT, +FC, +FP, +FB, +FH
// and +FN16 write their formats under POV-Ray's names (the frames read back
// as written, or the render fails), and -o's extension picks the same ones.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>
#include <unistd.h>

#include "image/image_format.hpp"

namespace fs = std::filesystem;
namespace im = hexant::image;

namespace {

fs::path fresh_folder() {
    const fs::path folder =
        fs::temp_directory_path() / ("hexant_output_formats_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

int run_hexant(const std::string& arguments, const fs::path& log) {
    const std::string atom = std::string(HEXANT_SOURCE_DIR) + "/examples/atom.pov";
    const std::string command = std::string(HEXANT_BINARY) + " " + atom + " " + arguments +
                                " +W16 +H12 -A > " + log.string() + " 2>&1";
    return std::system(command.c_str());
}

}  // namespace

TEST_CASE("POV-Ray's output types write their formats", "[app][povray][output][oiio]") {
    const fs::path folder = fresh_folder();
    const struct {
        const char* type;
        const char* file;  // POV-Ray's name for +O<folder>/f
        bool linear;
        int bits;
    } types[] = {{"+FT", "f.tga", false, 8}, {"+FC", "f.tga", false, 8},
                 {"+FP", "f.ppm", false, 8}, {"+FB", "f.bmp", false, 8},
                 {"+FH", "f.hdr", true, 32}, {"+FN16", "f.png", false, 16}};
    std::uintmax_t tga_size = 0;
    for (const auto& [type, file, linear, bits] : types) {
        INFO(type);
        const fs::path out = folder / type;
        fs::create_directories(out);
        REQUIRE(run_hexant(std::string(type) + " +O" + (out / "f").string(), folder / "log") == 0);
        REQUIRE(fs::exists(out / file));
        const im::StoredImage image = im::read_stored_image(out / file, 16 * 12);
        CHECK((image.width == 16 && image.height == 12));
        CHECK(image.linear == linear);
        if (!linear) CHECK(image.source_bits == bits);
        if (std::string(type) == "+FT") tga_size = fs::file_size(out / file);
        if (std::string(type) == "+FC") CHECK(fs::file_size(out / file) != tga_size);
    }
    // -o's extension: a TIFF.
    REQUIRE(run_hexant("-o " + (folder / "o.tif").string(), folder / "log") == 0);
    CHECK(im::read_stored_image(folder / "o.tif", 16 * 12).width == 16);
    fs::remove_all(folder);
}
