#include "image/formats/gif_format.hpp"

#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gif_lib.h>

namespace hexant::image {

namespace fs = std::filesystem;

namespace {

// giflib's message for an error code (it has none for some).
std::string message(int error) {
    const char* text = GifErrorString(error);
    return text ? std::string(text) : "damaged file (giflib error " + std::to_string(error) + ")";
}

struct GifCloser {
    void operator()(GifFileType* gif) const {
        int error = 0;
        DGifCloseFile(gif, &error);
    }
};

// The first image's indices, rows top to bottom (an interlaced one's rows
// put in order), and the transparent index of the graphics control block
// before it. Not DGifSlurp: it reads every image of the file, and takes
// each one's raster (up to 2 GB) before anything can check its size.
std::vector<GifPixelType> read_first_image(GifFileType* gif, std::size_t max_pixels,
                                           int& transparent) {
    const auto fail = [&] { throw std::runtime_error(message(gif->Error)); };
    GifRecordType type = UNDEFINED_RECORD_TYPE;
    do {
        if (DGifGetRecordType(gif, &type) == GIF_ERROR) fail();
        if (type == EXTENSION_RECORD_TYPE) {
            int code = 0;
            GifByteType* block = nullptr;
            if (DGifGetExtension(gif, &code, &block) == GIF_ERROR) fail();
            GraphicsControlBlock control{};
            if (code == GRAPHICS_EXT_FUNC_CODE && block &&
                DGifExtensionToGCB(block[0], block + 1, &control) == GIF_OK)
                transparent = control.TransparentColor;
            while (block)
                if (DGifGetExtensionNext(gif, &block) == GIF_ERROR) fail();
        } else if (type == IMAGE_DESC_RECORD_TYPE) {
            if (DGifGetImageDesc(gif) == GIF_ERROR) fail();
            const int width = gif->Image.Width, height = gif->Image.Height;
            if (width < 1 || height < 1) throw std::runtime_error("an empty image");
            check_declared_size(width, height, max_pixels);
            std::vector<GifPixelType> raster(std::size_t(width) * std::size_t(height));
            const auto row = [&](int y) {
                if (DGifGetLine(gif, raster.data() + std::size_t(y) * std::size_t(width), width) ==
                    GIF_ERROR)
                    fail();
            };
            if (gif->Image.Interlace) {
                // GIF's four passes: every 8th row from 0, from 4, every 4th
                // from 2, every 2nd from 1.
                constexpr std::pair<int, int> kPasses[] = {{0, 8}, {4, 8}, {2, 4}, {1, 2}};
                for (const auto& [first, step] : kPasses)
                    for (int y = first; y < height; y += step) row(y);
            } else {
                for (int y = 0; y < height; ++y) row(y);
            }
            return raster;
        }
    } while (type != TERMINATE_RECORD_TYPE);
    throw std::runtime_error("no image in the file");
}

StoredImage read_gif(const fs::path& file, std::size_t max_pixels) {
    int error = 0;
    std::unique_ptr<GifFileType, GifCloser> gif(DGifOpenFileName(file.c_str(), &error));
    if (!gif) throw std::runtime_error(message(error));
    int transparent = NO_TRANSPARENT_COLOR;
    const std::vector<GifPixelType> raster = read_first_image(gif.get(), max_pixels, transparent);
    const GifImageDesc& desc = gif->Image;
    const std::size_t pixels = raster.size();
    const ColorMapObject* map = desc.ColorMap ? desc.ColorMap : gif->SColorMap;
    if (!map || map->ColorCount < 1) throw std::runtime_error("no colour map");

    StoredImage out;
    out.width = desc.Width;
    out.height = desc.Height;
    out.channels = 4;
    out.linear = false;
    out.encoding_gamma = 0.0;  // sRGB, unless the scene says otherwise
    out.gamma_told = false;
    out.source = StoredImage::Source::Palette;
    out.source_bits = 8;
    out.palette.resize(std::size_t(map->ColorCount));
    for (int i = 0; i < map->ColorCount; ++i) {
        const GifColorType& c = map->Colors[i];
        out.palette[std::size_t(i)] = {float(c.Red / 255.0), float(c.Green / 255.0),
                                       float(c.Blue / 255.0), i == transparent ? 0.0f : 1.0f};
    }
    out.indices.assign(raster.begin(), raster.end());
    out.values.resize(pixels * 4);
    for (std::size_t i = 0; i < pixels; ++i) {
        // (An index past the palette is taken as black, opaque, as PNG's.)
        const std::size_t k = out.indices[i];
        const std::array<float, 4> entry =
            k < out.palette.size() ? out.palette[k] : std::array<float, 4>{0.0f, 0.0f, 0.0f, 1.0f};
        std::memcpy(out.values.data() + 4 * i, entry.data(), sizeof(float) * 4);
    }
    return out;
}

bool is_gif(const unsigned char* head, std::size_t bytes) {
    return bytes >= 6 && std::memcmp(head, "GIF8", 4) == 0 && (head[4] == '7' || head[4] == '9') &&
           head[5] == 'a';
}

}  // namespace

const ImageFormat kGifFormat{"GIF", ".gif", false, nullptr, read_gif, is_gif, 0};

StoredImage pot_from_gif(const StoredImage& gif) {
    if (gif.source != StoredImage::Source::Palette ||
        gif.indices.size() != std::size_t(gif.width) * std::size_t(gif.height))
        throw std::runtime_error("a POT file is a paletted GIF");
    if (gif.width % 2 != 0 || gif.width < 2)
        throw std::runtime_error("a POT file's width (" + std::to_string(gif.width) +
                                 ") must be even: two halves");
    StoredImage out;
    out.width = gif.width / 2;
    out.height = gif.height;
    out.channels = 3;
    out.linear = false;
    out.gamma_told = true;  // no gamma: the values are heights
    out.source = StoredImage::Source::Gray;
    out.source_bits = 16;
    out.values.resize(std::size_t(out.width) * std::size_t(out.height) * 3);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            const std::size_t row = std::size_t(y) * std::size_t(gif.width);
            const unsigned value = unsigned(gif.indices[row + std::size_t(x)]) << 8 |
                                   gif.indices[row + std::size_t(x + out.width)];
            const std::size_t i = (std::size_t(y) * std::size_t(out.width) + std::size_t(x)) * 3;
            out.values[i] = out.values[i + 1] = out.values[i + 2] = float(value / 65535.0);
        }
    return out;
}

}  // namespace hexant::image
