#include "image/formats/oiio_formats.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/oiio_library.hpp"

namespace hexant::image {

namespace fs = std::filesystem;

namespace {

float* allocate(void* context, std::size_t count) {
    try {
        auto& values = *static_cast<std::vector<float>*>(context);
        values.resize(count);
        return values.data();
    } catch (...) {
        return nullptr;
    }
}

// Reads `file` with OpenImageIO's reader `oiio` into the shape hexant keeps
// (3 or 4 channels; gray expanded).
StoredImage read_through(const fs::path& file, std::size_t max_pixels, const char* oiio,
                         const char* name) {
    const HexantOiioApi& api = oiio_module(std::string("a ") + name + " file");
    std::vector<float> raw;
    HexantOiioImage info{};
    char error[512] = "";
    const int status =
        api.read(file.c_str(), oiio, max_pixels, &info, allocate, &raw, error, sizeof error);
    if (status == 2) check_declared_size(info.width, info.height, max_pixels);
    if (status != 0) throw std::runtime_error(error);
    StoredImage out;
    out.width = info.width;
    out.height = info.height;
    out.source_bits = info.bits;
    const int in = info.channels;
    const bool gray = in <= 2;
    const bool alpha = in == 2 || in == 4;
    out.channels = alpha ? 4 : 3;
    out.source = gray ? (alpha ? StoredImage::Source::GrayAlpha : StoredImage::Source::Gray)
                      : (alpha ? StoredImage::Source::RgbAlpha : StoredImage::Source::Rgb);
    const std::size_t pixels = std::size_t(out.width) * std::size_t(out.height);
    if (raw.size() != pixels * std::size_t(in))
        throw std::runtime_error("OpenImageIO gave the wrong number of values");
    if (in == out.channels) {
        out.values = std::move(raw);
        return out;
    }
    out.values.resize(pixels * std::size_t(out.channels));
    for (std::size_t i = 0; i < pixels; ++i) {
        const float* from = raw.data() + i * std::size_t(in);
        float* to = out.values.data() + i * std::size_t(out.channels);
        to[0] = to[1] = to[2] = from[0];
        if (alpha) to[3] = from[1];
    }
    return out;
}

void write_through(int fd, int width, int height, const void* pixels, const char* oiio,
                   const char* name, const char* compression, bool linear) {
    const HexantOiioApi& api = oiio_module(std::string("a ") + name + " file");
    char error[512] = "";
    if (api.write(fd, oiio, compression, width, height, linear ? 1 : 0, pixels, error,
                  sizeof error) != 0)
        throw std::runtime_error(error);
}

// ---- Targa: no magic bytes (read by the scene's tga or the name's .tga)
StoredImage read_tga(const fs::path& file, std::size_t max_pixels) {
    StoredImage out = read_through(file, max_pixels, "targa", "Targa");
    // POV-Ray's targa.cpp keeps an 8-bit gray Targa as RGB (its
    // RGB_Int8), not as a gray image.
    if (out.source == StoredImage::Source::Gray) out.source = StoredImage::Source::Rgb;
    if (out.source == StoredImage::Source::GrayAlpha) out.source = StoredImage::Source::RgbAlpha;
    return out;
}
bool no_magic(const unsigned char*, std::size_t) {
    return false;
}
void write_tga(int fd, int width, int height, const void* pixels) {
    write_through(fd, width, height, pixels, "targa", "Targa", "none", false);
}
void write_tga_rle(int fd, int width, int height, const void* pixels) {
    write_through(fd, width, height, pixels, "targa", "Targa", "rle", false);
}

// ---- TIFF
StoredImage read_tiff(const fs::path& file, std::size_t max_pixels) {
    StoredImage out = read_through(file, max_pixels, "tiff", "TIFF");
    // POV-Ray's tiff.cpp: every TIFF an 8-bit RGBA image (TIFFReadRGBAImage;
    // 16 bits "crunched to 8"), its values as they are unless the scene
    // gives a gamma.
    // (libtiff's W2B: the high byte of a 16-bit sample.)
    if (out.source_bits > 8)
        for (float& v : out.values)
            v = float((unsigned(std::lround(std::clamp(double(v), 0.0, 1.0) * 65535.0)) >> 8) /
                      255.0);
    if (out.source == StoredImage::Source::Gray) out.source = StoredImage::Source::Rgb;
    if (out.source == StoredImage::Source::GrayAlpha) out.source = StoredImage::Source::RgbAlpha;
    out.source_bits = 8;
    out.as_stored = true;
    return out;
}
bool is_tiff(const unsigned char* head, std::size_t bytes) {
    return bytes >= 4 &&
           ((std::memcmp(head, "II*\0", 4) == 0) || (std::memcmp(head, "MM\0*", 4) == 0));
}
void write_tiff(int fd, int width, int height, const void* pixels) {
    write_through(fd, width, height, pixels, "tiff", "TIFF", "zip", false);
}

// ---- Radiance HDR: linear light, RGBE
StoredImage read_hdr(const fs::path& file, std::size_t max_pixels) {
    StoredImage out = read_through(file, max_pixels, "hdr", "Radiance HDR");
    // POV-Ray's hdr.cpp decodes a mantissa m of exponent e as Ward's
    // Radiance does, (m + 0.5) 2^(e - 136); OpenImageIO as m 2^(e - 136).
    // The half step is added back, e from the largest component (whose
    // mantissa a normalized RGBE keeps in 128 to 255).
    const std::size_t c = std::size_t(out.channels);
    for (std::size_t i = 0; i < out.values.size(); i += c) {
        float* v = out.values.data() + i;
        const float largest = std::max({v[0], v[1], v[2]});
        if (!(largest > 0.0f) || !std::isfinite(largest)) continue;
        int exponent = 0;
        (void)std::frexp(largest, &exponent);
        const float half_step = std::ldexp(0.5f, exponent - 8);
        for (int k = 0; k < 3; ++k) v[k] += half_step;
    }
    out.linear = true;
    out.gamma_told = true;
    return out;
}
bool is_hdr(const unsigned char* head, std::size_t bytes) {
    return bytes >= 2 && head[0] == '#' && head[1] == '?';
}
float rgbe_value(float v) {
    return std::isfinite(v) && v > 0.0f ? v : (v > 0.0f ? 1e30f : 0.0f);
}
void write_hdr(int fd, int width, int height, const void* pixels) {
    // RGBE holds no negative (or infinite) value: OpenImageIO's encoder
    // would wrap a negative mantissa. Such a value is written as 0 (and a
    // NaN), as a PNG clamps.
    const float* in = static_cast<const float*>(pixels);
    std::vector<float> clamped(in, in + std::size_t(width) * std::size_t(height) * 3);
    for (float& v : clamped) v = rgbe_value(v);
    write_through(fd, width, height, clamped.data(), "hdr", "Radiance HDR", nullptr, true);
}
// RGBE keeps 8 bits of a pixel's largest component, the others on its
// exponent: each reads back within 2^-7 of that component (a truncated
// mantissa), negatives as 0.
bool hdr_reads_back_as(const float* written, const float* read) {
    const double w[3] = {rgbe_value(written[0]), rgbe_value(written[1]), rgbe_value(written[2])};
    const double largest = std::max({w[0], w[1], w[2]});
    for (int k = 0; k < 3; ++k)
        if (!(std::abs(double(read[k]) - w[k]) <= largest * 0x1p-7 + 1e-30)) return false;
    return true;
}

// ---- PPM and PGM: values as they are unless the scene gives a gamma
// A PPM's or PGM's samples of more than 8 bits, read here: OpenImageIO 2.4's
// pnm reader scales each as sample * 65535 / maxval in int, which overflows
// from 32769 on (every such sample of a 16-bit file read a step low). The
// file was read whole by OpenImageIO first: its header and size are sound.
void read_deep_pnm(const fs::path& file, StoredImage& out) {
    std::ifstream in(file, std::ios::binary);
    std::string magic;
    in >> magic;
    const auto number = [&] {
        // Blanks and # comments before each number of the header.
        for (int c = in.peek(); c != EOF; c = in.peek()) {
            if (c == '#') {
                std::string comment;
                std::getline(in, comment);
            } else if (std::isspace(c)) {
                in.get();
            } else {
                break;
            }
        }
        long long value = -1;
        in >> value;
        return value;
    };
    const long long width = number(), height = number(), max = number();
    const bool gray = magic == "P2" || magic == "P5";
    const bool ascii = magic == "P2" || magic == "P3";
    if (!in || width != out.width || height != out.height || max < 256 || max > 65535)
        throw std::runtime_error("its header reads differently a second time");
    in.get();  // the one blank after maxval
    const std::size_t samples = std::size_t(width) * std::size_t(height) * (gray ? 1 : 3);
    std::vector<float> values(samples);
    for (std::size_t i = 0; i < samples; ++i) {
        long long v = 0;
        if (ascii) {
            v = number();
        } else {
            const int high = in.get(), low = in.get();
            v = (high << 8) | low;
        }
        if (!in || v < 0) throw std::runtime_error("its samples end early");
        values[i] = float(double(std::min(v, max)) / double(max));
    }
    for (std::size_t i = 0, pixels = samples / (gray ? 1 : 3); i < pixels; ++i)
        for (std::size_t k = 0; k < 3; ++k) out.values[i * 3 + k] = values[gray ? i : i * 3 + k];
}

StoredImage read_pnm(const fs::path& file, std::size_t max_pixels) {
    StoredImage out = read_through(file, max_pixels, "pnm", "PPM/PGM");
    if (out.source_bits > 8 && out.channels == 3) read_deep_pnm(file, out);
    out.as_stored = true;
    return out;
}
bool is_pnm(const unsigned char* head, std::size_t bytes) {
    return bytes >= 3 && head[0] == 'P' &&
           (head[1] == '2' || head[1] == '3' || head[1] == '5' || head[1] == '6') &&
           (head[2] == ' ' || head[2] == '\t' || head[2] == '\n' || head[2] == '\r' ||
            head[2] == '#');
}
void write_pnm(int fd, int width, int height, const void* pixels) {
    write_through(fd, width, height, pixels, "pnm", "PPM", nullptr, false);
}

// ---- BMP
StoredImage read_bmp(const fs::path& file, std::size_t max_pixels) {
    return read_through(file, max_pixels, "bmp", "BMP");
}
bool is_bmp(const unsigned char* head, std::size_t bytes) {
    return bytes >= 2 && head[0] == 'B' && head[1] == 'M';
}
void write_bmp(int fd, int width, int height, const void* pixels) {
    write_through(fd, width, height, pixels, "bmp", "BMP", nullptr, false);
}

}  // namespace

// (Targa's sides are 16-bit; BMP's and HDR's OpenImageIO writes any.)
const ImageFormat kTgaFormat{"Targa", ".tga", false, write_tga, read_tga, no_magic, 65535};
const ImageFormat kTgaRleFormat{"Targa (RLE)", ".tga",   false, write_tga_rle,
                                read_tga,      no_magic, 65535, "rle"};
const ImageFormat kTiffFormat{"TIFF",  ".tif", false, write_tiff, read_tiff,
                              is_tiff, 0,      "",    ".tiff"};
const ImageFormat kHdrFormat{"Radiance HDR", ".hdr", true, write_hdr, read_hdr,
                             is_hdr,         0,      "",   "",        hdr_reads_back_as};
const ImageFormat kPnmFormat{"PPM", ".ppm", false, write_pnm, read_pnm, is_pnm, 0, "", ".pgm"};
const ImageFormat kBmpFormat{"BMP", ".bmp", false, write_bmp, read_bmp, is_bmp, 0};

}  // namespace hexant::image
