#include "image/formats/oiio_formats.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
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

// A colour-mapped Targa's indices and map, read here as POV-Ray's targa.cpp
// reads them (OpenImageIO expands them to colours, and POV-Ray keeps each
// pixel's index: a height_field's height is index x 256, use_index, filter
// N): 8-bit indices, uncompressed (type 1) or run-length (9), a map of at
// most 256 entries of 15, 16, 24 or 32 bits (16: alpha from the top bit).
// The file was read whole by OpenImageIO first. False for another Targa.
bool read_tga_palette(const fs::path& file, StoredImage& out) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    const auto at = [&](std::size_t i) {
        if (i >= bytes.size()) throw std::runtime_error("its colour map or indices end early");
        return static_cast<unsigned char>(bytes[i]);
    };
    const auto u16 = [&](std::size_t i) { return unsigned(at(i)) | unsigned(at(i + 1)) << 8; };
    const unsigned type = at(2), map_length = u16(5), entry_bits = at(7), pixel_bits = at(16);
    if (map_length == 0 || (type != 1 && type != 9)) return false;
    if (pixel_bits != 8) throw std::runtime_error("a colour map with indices of other than 8 bits");
    if (map_length > 256) throw std::runtime_error("a colour map of more than 256 entries");
    if (entry_bits != 15 && entry_bits != 16 && entry_bits != 24 && entry_bits != 32)
        throw std::runtime_error("colour map entries of " + std::to_string(entry_bits) + " bits");
    const int width = int(u16(12)), height = int(u16(14));
    if (width != out.width || height != out.height)
        throw std::runtime_error("its header reads differently a second time");
    const bool top_first = (at(17) & 0x20) != 0;
    const std::size_t entry_bytes = (entry_bits + 7) / 8;
    std::size_t pos = 18 + std::size_t(at(0));  // after the image ID
    out.palette.assign(map_length, {0.0f, 0.0f, 0.0f, 1.0f});
    bool alpha = false;
    for (auto& entry : out.palette) {
        unsigned r = 0, g = 0, b = 0, a = 255;
        if (entry_bits <= 16) {  // (POV-Ray's ConvertColor)
            const unsigned lo = at(pos), hi = at(pos + 1);
            r = (hi & 0x7c) << 1;
            g = (((hi & 0x03) << 3) | ((lo & 0xe0) >> 5)) << 3;
            b = (lo & 0x1f) << 3;
            if (entry_bits == 16) a = (hi & 0x80) ? 255 : 0;
        } else {
            b = at(pos);
            g = at(pos + 1);
            r = at(pos + 2);
            if (entry_bits == 32) a = at(pos + 3);
        }
        alpha = alpha || entry_bits == 16 || entry_bits == 32;
        entry = {float(r / 255.0), float(g / 255.0), float(b / 255.0), float(a / 255.0)};
        pos += entry_bytes;
    }
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    out.indices.assign(pixels, 0);
    const auto put = [&](std::size_t i, unsigned index) {
        if (index >= map_length) throw std::runtime_error("an index past its colour map");
        const std::size_t row = i / std::size_t(width), x = i % std::size_t(width);
        const std::size_t line = top_first ? row : std::size_t(height) - 1 - row;
        out.indices[line * std::size_t(width) + x] = static_cast<std::uint8_t>(index);
    };
    for (std::size_t i = 0; i < pixels;) {
        if (type == 1) {
            put(i++, at(pos++));
            continue;
        }
        const unsigned header = at(pos++);
        const std::size_t count = std::min<std::size_t>((header & 0x7f) + 1, pixels - i);
        if (header & 0x80) {
            const unsigned index = at(pos++);
            for (std::size_t k = 0; k < count; ++k) put(i++, index);
        } else {
            for (std::size_t k = 0; k < count; ++k) put(i++, at(pos++));
        }
    }
    out.channels = alpha ? 4 : 3;
    out.source = StoredImage::Source::Palette;
    out.source_bits = 8;
    out.values.resize(pixels * std::size_t(out.channels));
    for (std::size_t i = 0; i < pixels; ++i)
        for (std::size_t k = 0; k < std::size_t(out.channels); ++k)
            out.values[i * std::size_t(out.channels) + k] = out.palette[out.indices[i]][k];
    return true;
}

StoredImage read_tga(const fs::path& file, std::size_t max_pixels) {
    StoredImage out = read_through(file, max_pixels, "targa", "Targa");
    if (read_tga_palette(file, out)) return out;
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
