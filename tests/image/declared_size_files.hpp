// Tiny image files that declare a size their bytes do not hold, built byte
// by byte: what a hostile scene may bring as an image_map or height_field
// (tests/image/declared_size_test.cpp, tests/language/limits_test.cpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace hexant::test {

inline void put32_be(std::vector<unsigned char>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(static_cast<unsigned char>(v >> shift));
}
inline void put32_le(std::vector<unsigned char>& out, std::uint32_t v) {
    for (int shift = 0; shift < 32; shift += 8)
        out.push_back(static_cast<unsigned char>(v >> shift));
}

// One PNG chunk: length, type, data and the CRC of type and data.
inline void png_chunk(std::vector<unsigned char>& out, const char* type,
                      const std::vector<unsigned char>& data) {
    put32_be(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t from = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = from; i < out.size(); ++i) {
        crc ^= out[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    put32_be(out, crc ^ 0xffffffffu);
}

// A PNG of 8-bit gray whose IHDR says `width` by `height` and whose IDAT
// holds a few bytes of nothing: 61 bytes.
inline void write_png_header(const std::filesystem::path& path, std::uint32_t width,
                             std::uint32_t height) {
    std::vector<unsigned char> bytes = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<unsigned char> ihdr;
    put32_be(ihdr, width);
    put32_be(ihdr, height);
    ihdr.insert(ihdr.end(), {8, 0, 0, 0, 0});  // 8 bits, gray, deflate, filter 0, no interlace
    png_chunk(bytes, "IHDR", ihdr);
    png_chunk(bytes, "IDAT", {0x78, 0x9c, 0x03, 0x00});
    png_chunk(bytes, "IEND", {});
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// A GIF whose screen is 16 by 16 and whose first image says `width` by
// `height` (GIF's sides are 16-bit), with no pixel data: 32 bytes.
inline void write_gif_header(const std::filesystem::path& path, std::uint16_t width,
                             std::uint16_t height) {
    std::vector<unsigned char> bytes = {'G',  'I', 'F', '8',  '9', 'a', 16,
                                        0,    16,  0,   0x80, 0,   0,    // a global palette of 2
                                        0,    0,   0,   255,  255, 255,  // black, white
                                        0x2c, 0,   0,   0,    0};        // an image at 0, 0
    for (const std::uint16_t side : {width, height}) {
        bytes.push_back(static_cast<unsigned char>(side & 0xff));
        bytes.push_back(static_cast<unsigned char>(side >> 8));
    }
    bytes.insert(bytes.end(), {0, 2, 0, 0x3b});  // no local palette, LZW of 2 bits, the end
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// An OpenEXR scanline file's header alone (float R, G, B; no compression;
// the data window given, the display window the same) and no offset table.
inline std::vector<unsigned char> exr_header_bytes(int min_x, int min_y, int max_x, int max_y) {
    std::vector<unsigned char> out = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0};
    const auto attribute = [&](const std::string& name, const std::string& type,
                               const std::vector<unsigned char>& value) {
        out.insert(out.end(), name.begin(), name.end());
        out.push_back(0);
        out.insert(out.end(), type.begin(), type.end());
        out.push_back(0);
        put32_le(out, static_cast<std::uint32_t>(value.size()));
        out.insert(out.end(), value.begin(), value.end());
    };
    std::vector<unsigned char> channels;
    for (const char* c : {"B", "G", "R"}) {
        channels.push_back(static_cast<unsigned char>(c[0]));
        channels.push_back(0);
        put32_le(channels, 2);  // FLOAT
        put32_le(channels, 0);  // pLinear and reserved
        put32_le(channels, 1);
        put32_le(channels, 1);
    }
    channels.push_back(0);
    std::vector<unsigned char> box;
    for (int v : {min_x, min_y, max_x, max_y}) put32_le(box, static_cast<std::uint32_t>(v));
    std::vector<unsigned char> one;  // 1.0f
    put32_le(one, 0x3f800000u);
    std::vector<unsigned char> centre(8, 0);
    attribute("channels", "chlist", channels);
    attribute("compression", "compression", {0});
    attribute("dataWindow", "box2i", box);
    attribute("displayWindow", "box2i", box);
    attribute("lineOrder", "lineOrder", {0});
    attribute("pixelAspectRatio", "float", one);
    attribute("screenWindowCenter", "v2f", centre);
    attribute("screenWindowWidth", "float", one);
    out.push_back(0);
    return out;
}

}  // namespace hexant::test
