// Image files as hexant reads and writes them, one format per file under
// formats/ and one line in image_format.cpp's table: PNG (8- and 16-bit,
// libpng) and OpenEXR (linear float, the OpenEXR library), and JPEG and
// GIF read only (libjpeg, giflib), each linked directly; Targa, TIFF,
// Radiance HDR, PPM/PGM and BMP through OpenImageIO, in a module of its
// own loaded the first time a file needs it (formats/oiio_formats.hpp,
// oiio_library.hpp): linked into hexant, OpenImageIO's plugins and their
// libraries would cost every process about 120 MB of resident memory and a
// third of a second before main() (docs/benchmarks.md; issue 21).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace hexant::image {

// An image as its file holds it, channel values interleaved, rows top to
// bottom: `linear` values are linear light (EXR); otherwise they are the
// file's encoding scaled to [0, 1] (an 8-bit PNG's byte / 255, sRGB).
// `channels` is 3 (RGB) or 4 (RGBA; gray and palette files are expanded).
// A palette file also keeps each pixel's index and its palette, which
// POV-Ray reads for a height_field, a bump_map's use_index and an
// image_map's filter and transmit of one palette entry.
struct StoredImage {
    int width = 0, height = 0, channels = 0;
    bool linear = false;
    std::vector<float> values;
    // How a non-linear file says its values are encoded: a PNG's gAMA
    // chunk (its encoding gamma, as 0.45455 for 2.2), or 0 when the file
    // says sRGB (an sRGB chunk) or nothing (then sRGB, as PNG and W3C
    // recommend).
    double encoding_gamma = 0.0;
    // Whether the file says how it is encoded (a PNG's sRGB or gAMA
    // chunk): POV-Ray decodes one that does not by the scene's default.
    bool gamma_told = false;
    // POV-Ray takes the values as they are, in the scene's working space,
    // unless the scene gives a gamma (its PPM, PGM and TIFF readers: "may
    // or may not be gamma-encoded").
    bool as_stored = false;
    // What the file held before it was expanded to RGB or RGBA: its colour
    // type, its bits per sample, and whether its alpha came from a colour
    // key (a PNG tRNS chunk on an RGB or gray image).
    enum class Source { Rgb, RgbAlpha, Gray, GrayAlpha, Palette };
    Source source = Source::Rgb;
    int source_bits = 8;
    bool colour_key = false;
    // Source::Palette: each pixel's index (rows top to bottom) and the
    // palette's entries, red, green, blue and alpha as `values` holds them
    // (alpha 1 where a tRNS chunk gives none).
    std::vector<std::uint8_t> indices;
    std::vector<std::array<float, 4>> palette;
};

// The pixels a reader takes when its caller gives no limit (a scene gives
// its own, Limits::image_pixels): the rows of a larger one would not fit
// hexant's int sizes.
constexpr std::size_t kMaxImagePixels = std::size_t(1) << 30;

// A file that declares more pixels than the reader was allowed: a small
// file may declare 2^30 (a PNG's rows took 3 to 6 GB and 20 to 48 s before
// std::bad_alloc, issue 45).
struct ImageTooLarge : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws ImageTooLarge, saying the declared size and the limit, when
// `width` x `height` is more than `max_pixels`.
void check_declared_size(long long width, long long height, std::size_t max_pixels);

// One file format. `write` writes `width` x `height` RGB pixels: bytes in
// sRGB for an 8-bit format, floats in linear light for a `linear` one, to
// an open descriptor from its start (a new file's, which the caller keeps
// and closes: tracer::TemporaryFile); both throw std::runtime_error with
// the reason (not the path: the caller names the file it meant, not the
// temporary it wrote).
struct ImageFormat {
    const char* name;       // "PNG"
    const char* extension;  // ".png", lower case
    bool linear;            // stores linear float
    // (null: a format hexant reads only)
    void (*write)(int fd, int width, int height, const void* pixels);
    // Refuses (ImageTooLarge) a file that declares more than `max_pixels`
    // before any pixel is decoded or any buffer for them is taken.
    StoredImage (*read)(const std::filesystem::path& file, std::size_t max_pixels);
    bool (*recognizes)(const unsigned char* head, std::size_t bytes);  // the file's magic
    // The widest and tallest image it writes (0: no limit of its own), so
    // that a command can refuse a size before it renders anything.
    int max_side = 0;
    // Another way of writing the same extension, asked for by name
    // (image_format_for's `variant`): "rle" (Targa), "16" (PNG); "" for the
    // extension's own.
    const char* variant = "";
    // A second extension it is written and known by (".tiff"), or "".
    const char* other_extension = "";
    // Whether a pixel written (RGB, as `write` took it; floats for a
    // `linear` format) read back (as `read` gives it) is what was written,
    // for a format that does not store its input exactly (16-bit PNG, RGBE);
    // null: exactly (bytes, floats).
    bool (*reads_back_as)(const float* written, const float* read) = nullptr;
};

// A name's extension in lower case (".PNG" and ".png" ask for one format).
std::string lower_case_extension(const std::filesystem::path& path);

// The format a file name asks hexant to write, by its extension (any case)
// and `variant` ("": the extension's own; "rle", "16": ImageFormat::variant);
// nullptr for an unknown one or one hexant only reads.
const ImageFormat* image_format_for(const std::filesystem::path& path,
                                    const std::string& variant = "");

// The extensions hexant writes, for messages: ".png, .exr".
std::string image_format_extensions();

// Reads an image, its format told by its first bytes, else (Targa has no
// magic bytes) by `type_word` (a scene's image type, "tga") or the name's
// extension; throws std::runtime_error naming the file when it cannot be
// opened, is not a regular file, is of no format hexant reads, or is
// damaged, and ImageTooLarge (naming it too) when it declares more than
// `max_pixels`.
StoredImage read_stored_image(const std::filesystem::path& path,
                              std::size_t max_pixels = kMaxImagePixels,
                              const std::string& type_word = "");

}  // namespace hexant::image
