// libFuzzer over the image files a scene may name (image_map, bump_map,
// material_map, height_field; README, "Fuzzing"): the bytes are a file, read
// by image::read_stored_image (PNG through libpng, OpenEXR, JPEG, GIF; TIFF,
// Radiance HDR, PPM/PGM and BMP through the OpenImageIO module; its format
// told by its first bytes, and a file of none read as a Targa, as a scene's
// word `tga` asks) under a limit of pixels, then made into
// what a scene keeps of it: an image map's pixels, looked up and
// interpolated, and a height field's heights (a POT file's too). A damaged
// or hostile file must end in a std::runtime_error: a crash, a sanitizer
// report, a leak, a hang or an allocation past -malloc_limit_mb is a bug.
// Seeds: tests/fuzz/image_corpus/.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>

#include <unistd.h>

#include "image/formats/gif_format.hpp"
#include "image/image_format.hpp"
#include "language/image_map_file.hpp"
#include "runtime/objects/height_field/height_field_data.hpp"
#include "runtime/texture/pattern/image_map.hpp"
#include "tests/fuzz/input_file.hpp"

namespace pat = hexant::runtime::pattern;

namespace {

// The readers open a file by its path: the input is written to one file
// per process, anew for each input.
const std::filesystem::path& image_file() {
    static const std::filesystem::path path = hexant::fuzz::input_file_path("image_fuzz", ".img");
    return path;
}

// Lower than a scene's 10^8 so that one input stays within the fuzzer's
// memory (a float RGBA copy of 2^20 pixels is 16 MB); what the limit
// guards is the same at any value.
constexpr std::size_t kMaxPixels = std::size_t(1) << 20;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::filesystem::path& path = image_file();
    if (!hexant::fuzz::write_input_file(path, data, size)) return 0;
    hexant::image::StoredImage stored;
    try {
        stored = hexant::image::read_stored_image(path, kMaxPixels, "tga");
    } catch (const std::runtime_error&) {
        return 0;  // a refused file: what the fuzzer wants to see
    }
    // An image_map of it, in each interpolation, as a pigment and a bump_map
    // look it up.
    for (const bool undecoded : {false, true}) {
        hexant::language::ImageGamma gamma;
        gamma.undecoded = undecoded;
        auto pixels = std::make_shared<const pat::ImagePixels>(
            hexant::language::image_pixels(stored, gamma, 2.2));
        pat::ImageMap map;
        map.images.push_back({hexant::runtime::Interval(-1e30, 1e30), pixels});
        map.use_index = undecoded && pixels->palette;
        for (const auto mode :
             {pat::ImageMap::Interpolate::None, pat::ImageMap::Interpolate::Bilinear,
              pat::ImageMap::Interpolate::Bicubic,
              pat::ImageMap::Interpolate::NormalizedDistance}) {
            map.interpolate = mode;
            for (const double u : {0.0, 0.37, 0.999999})
                (void)pat::image_colour(map, {u, 1.0 - u, 0.0}, 0.0, 0.0, 0.0);
            (void)pat::bump_map_normal(map, {0.5, 0.5, 0.0}, 0.0, 1.0, {0.0, 0.0, -1.0});
        }
    }
    // A height field of it (a POT file when it is a GIF).
    try {
        if (stored.source == hexant::image::StoredImage::Source::Palette)
            (void)hexant::image::pot_from_gif(stored);
    } catch (const std::runtime_error&) {
    }
    (void)hexant::runtime::objects::heights_from_image(stored);
    return 0;
}
