#include "image/formats/png_format.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>
#include <png.h>
#include <unistd.h>

#include "image/colour_transfer.hpp"

namespace hexant::image {

namespace fs = std::filesystem;

namespace {

// Larger images are refused before memory is taken for them: wider or
// taller by libpng, more pixels than the caller's limit (a scene's
// --max-pixels, 10^8 by default) by check_declared_size.
constexpr png_uint_32 kMaxSide = 1u << 20;
// An ancillary chunk (text, an ICC profile) libpng keeps or inflates; its
// own default, stated so a build of it with none cannot take gigabytes.
constexpr png_alloc_size_t kMaxChunkBytes = 8'000'000;

// A stream of its own over a copy of the caller's descriptor (which stays
// open), for libpng's stdio writers; throws with the system's reason.
std::FILE* stream_over(int fd) {
    errno = 0;
    const int copy = ::fcntl(fd, F_DUPFD_CLOEXEC, 0);
    std::FILE* stream = copy < 0 ? nullptr : ::fdopen(copy, "wb");
    if (!stream) {
        const int system_error = errno;
        if (copy >= 0) ::close(copy);
        throw std::runtime_error(std::strerror(system_error));
    }
    return stream;
}

// Closes a stream libpng wrote to (`ok`: libpng said so; `system_error`:
// errno just after). libpng's stdio writer reports only a short fwrite
// ("Write Error"), so ferror and fclose are checked too: a full disk is an
// error, not a short file. Throws with libpng's message and the system's
// reason.
void close_written(std::FILE* stream, bool ok, int system_error, std::string message) {
    if (ok && std::ferror(stream)) ok = false;
    if (std::fclose(stream) != 0 && ok) {
        ok = false;
        system_error = errno;
    }
    if (ok) return;
    if (message.empty()) message = "libpng failed";
    const std::string reason = system_error != 0 ? std::strerror(system_error) : "";
    if (!reason.empty() && message.find(reason) == std::string::npos) message += ": " + reason;
    throw std::runtime_error(message);
}

void write_png(int fd, int width, int height, const void* pixels) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(width);
    image.height = static_cast<png_uint_32>(height);
    image.format = PNG_FORMAT_RGB;  // 8-bit, sRGB
    // (Nothing of the image's is allocated before the write: no free on
    // stream_over's throw.)
    std::FILE* stream = stream_over(fd);
    const bool ok = png_image_write_to_stdio(&image, stream, 0, pixels, 0, nullptr) != 0;
    const int system_error = errno;
    std::string message = image.message;
    png_image_free(&image);
    close_written(stream, ok, system_error, std::move(message));
}

// libpng reports an error by longjmp to the reader's (or writer's) setjmp;
// its message is kept first.
void on_error(png_structp png, png_const_charp message) {
    *static_cast<std::string*>(png_get_error_ptr(png)) = message;
    png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}

struct Reader {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~Reader() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

// Everything libpng may leave by longjmp is in here, with no object of this
// frame that has a destructor or changes after setjmp: what it fills lives
// in the caller.
// (check_declared_size's throw leaves by an exception, not a longjmp: no
// libpng frame is on the stack then.)
bool read_rows(std::FILE* file, const Reader& r, std::size_t max_pixels,
               std::vector<unsigned char>& bytes, std::vector<png_bytep>& rows, StoredImage& out,
               int& depth) {
    if (setjmp(png_jmpbuf(r.png))) return false;
    png_init_io(r.png, file);
    const auto side = static_cast<png_uint_32>(std::min<std::size_t>(kMaxSide, max_pixels));
    png_set_user_limits(r.png, side, side);
    png_set_chunk_malloc_max(r.png, kMaxChunkBytes);
    png_read_info(r.png, r.info);
    // The header's size, before any row is read or its buffer taken.
    check_declared_size(png_get_image_width(r.png, r.info), png_get_image_height(r.png, r.info),
                        max_pixels);
    // (An sRGB chunk wins over a gAMA chunk, as POV-Ray and the PNG
    // specification read them.)
    double file_gamma = 0.0;
    if (!png_get_valid(r.png, r.info, PNG_INFO_sRGB) && png_get_valid(r.png, r.info, PNG_INFO_gAMA))
        png_get_gAMA(r.png, r.info, &file_gamma);
    out.encoding_gamma = file_gamma;
    out.gamma_told =
        png_get_valid(r.png, r.info, PNG_INFO_sRGB) || png_get_valid(r.png, r.info, PNG_INFO_gAMA);
    switch (png_get_color_type(r.png, r.info)) {
        case PNG_COLOR_TYPE_GRAY:
            out.source = StoredImage::Source::Gray;
            break;
        case PNG_COLOR_TYPE_GRAY_ALPHA:
            out.source = StoredImage::Source::GrayAlpha;
            break;
        case PNG_COLOR_TYPE_PALETTE:
            out.source = StoredImage::Source::Palette;
            break;
        case PNG_COLOR_TYPE_RGB_ALPHA:
            out.source = StoredImage::Source::RgbAlpha;
            break;
        default:
            out.source = StoredImage::Source::Rgb;
            break;
    }
    out.source_bits = png_get_bit_depth(r.png, r.info);
    out.colour_key =
        out.source != StoredImage::Source::Palette && png_get_valid(r.png, r.info, PNG_INFO_tRNS);
    if (out.source == StoredImage::Source::Palette) {
        // Kept as indices, one a byte, and expanded by read_png from the
        // palette (POV-Ray reads the indices too).
        png_colorp entries = nullptr;
        int count = 0;
        if (!png_get_PLTE(r.png, r.info, &entries, &count) || count < 1)
            png_error(r.png, "a palette image without its palette");
        png_bytep alpha = nullptr;
        int alphas = 0;
        if (!png_get_tRNS(r.png, r.info, &alpha, &alphas, nullptr)) alphas = 0;
        out.palette.resize(static_cast<std::size_t>(count));
        for (int i = 0; i < count; ++i)
            out.palette[static_cast<std::size_t>(i)] = {
                float(entries[i].red / 255.0), float(entries[i].green / 255.0),
                float(entries[i].blue / 255.0), i < alphas ? float(alpha[i] / 255.0) : 1.0f};
        png_set_packing(r.png);
        png_read_update_info(r.png, r.info);
        out.channels = alphas > 0 ? 4 : 3;
    } else {
        png_set_expand(r.png);       // low-bit gray to 8 bits, tRNS to alpha
        png_set_gray_to_rgb(r.png);  // gray as RGB, so every image has 3 or 4 channels
        png_read_update_info(r.png, r.info);
        out.channels = png_get_channels(r.png, r.info);
    }
    out.width = static_cast<int>(png_get_image_width(r.png, r.info));
    out.height = static_cast<int>(png_get_image_height(r.png, r.info));
    depth = png_get_bit_depth(r.png, r.info);
    const std::size_t row_bytes = png_get_rowbytes(r.png, r.info);
    bytes.resize(row_bytes * std::size_t(out.height));
    rows.resize(std::size_t(out.height));
    for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = bytes.data() + y * row_bytes;
    png_read_image(r.png, rows.data());
    png_read_end(r.png, nullptr);
    return true;
}

StoredImage read_png(const fs::path& file, std::size_t max_pixels) {
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> stream(std::fopen(file.c_str(), "rb"),
                                                                 &std::fclose);
    if (!stream) throw std::runtime_error(std::strerror(errno));
    std::string message;
    Reader r;
    r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &message, on_error, on_warning);
    if (r.png) r.info = png_create_info_struct(r.png);
    if (!r.info) throw std::runtime_error("libpng cannot start");
    std::vector<unsigned char> bytes;
    std::vector<png_bytep> rows;
    StoredImage out;
    int depth = 8;
    if (!read_rows(stream.get(), r, max_pixels, bytes, rows, out, depth))
        throw std::runtime_error(message);
    out.linear = false;
    const std::size_t pixels = std::size_t(out.width) * std::size_t(out.height);
    out.values.resize(pixels * std::size_t(out.channels));
    if (out.source == StoredImage::Source::Palette) {
        if (bytes.size() != pixels) throw std::runtime_error("unexpected palette row size");
        const std::size_t c = std::size_t(out.channels);
        for (std::size_t i = 0; i < pixels; ++i) {
            // (An index past the palette is taken as black, opaque.)
            const std::array<float, 4> entry = bytes[i] < out.palette.size()
                                                   ? out.palette[bytes[i]]
                                                   : std::array<float, 4>{0.0f, 0.0f, 0.0f, 1.0f};
            for (std::size_t k = 0; k < c; ++k) out.values[i * c + k] = entry[k];
        }
        out.indices = std::move(bytes);
    } else if (depth == 16)  // big-endian samples
        for (std::size_t i = 0; i < out.values.size(); ++i)
            out.values[i] = float((unsigned(bytes[2 * i]) << 8 | bytes[2 * i + 1]) / 65535.0);
    else
        for (std::size_t i = 0; i < out.values.size(); ++i) out.values[i] = float(bytes[i] / 255.0);
    return out;
}

// 16-bit PNG (POV-Ray's +FN16): linear floats encoded to sRGB in 16 bits,
// with an sRGB chunk, through libpng's full interface (its simplified one
// writes 16-bit samples only as linear light).
std::uint16_t srgb16(float linear) {
    const double c = std::clamp(double(linear), 0.0, 1.0);
    return static_cast<std::uint16_t>(std::lround(srgb_encode(c) * 65535.0));
}

// Everything libpng may leave by longjmp is in here: no object with a
// destructor in this frame.
bool write_rows16(std::FILE* stream, png_structp png, png_infop info, int width, int height,
                  std::vector<png_bytep>& rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, stream);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 16, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    png_write_image(png, rows.data());
    png_write_end(png, info);
    return true;
}

void write_png16(int fd, int width, int height, const void* pixels) {
    const float* in = static_cast<const float*>(pixels);
    const std::size_t row_values = std::size_t(width) * 3;
    std::vector<unsigned char> bytes(row_values * 2 * std::size_t(height));
    for (std::size_t i = 0; i < row_values * std::size_t(height); ++i) {
        const std::uint16_t v = srgb16(in[i]);  // big-endian
        bytes[2 * i] = static_cast<unsigned char>(v >> 8);
        bytes[2 * i + 1] = static_cast<unsigned char>(v & 0xff);
    }
    std::vector<png_bytep> rows(static_cast<std::size_t>(height));
    for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = bytes.data() + y * row_values * 2;
    std::FILE* stream = stream_over(fd);
    std::string message;
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &message, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    const bool ok = info && write_rows16(stream, png, info, width, height, rows);
    const int system_error = errno;
    png_destroy_write_struct(&png, info ? &info : nullptr);
    close_written(stream, ok, system_error, std::move(message));
}

// A 16-bit frame reads back as its 16-bit values.
bool reads_back16(const float* written, const float* read) {
    for (int k = 0; k < 3; ++k)
        if (std::lround(double(read[k]) * 65535.0) != srgb16(written[k])) return false;
    return true;
}

bool is_png(const unsigned char* head, std::size_t bytes) {
    return bytes >= 8 && png_sig_cmp(head, 0, 8) == 0;
}

}  // namespace

// libpng's writer refuses an IHDR past its user limits, 10^6 pixels a
// side by default (PNG_USER_WIDTH_MAX, PNG_USER_HEIGHT_MAX).
const ImageFormat kPngFormat{"PNG", ".png", false, write_png, read_png, is_png, 1000000};
const ImageFormat kPng16Format{"PNG (16-bit)", ".png",  true, write_png16, read_png,
                               is_png,         1000000, "16", "",          reads_back16};

}  // namespace hexant::image
