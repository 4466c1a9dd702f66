#include "image/formats/gif_format.hpp"

#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

#include <gif_lib.h>

namespace hexant::image {

namespace fs = std::filesystem;

namespace {

// Larger images are refused before memory is taken for them, as PNG's.
constexpr std::size_t kMaxPixels = std::size_t(1) << 30;

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

StoredImage read_gif(const fs::path& file) {
    int error = 0;
    std::unique_ptr<GifFileType, GifCloser> gif(DGifOpenFileName(file.c_str(), &error));
    if (!gif) throw std::runtime_error(message(error));
    // (DGifSlurp reads every image, de-interlacing each, and checks the
    // sizes against the data it finds.)
    if (DGifSlurp(gif.get()) != GIF_OK) throw std::runtime_error(message(gif->Error));
    if (gif->ImageCount < 1) throw std::runtime_error("no image in the file");
    const SavedImage& first = gif->SavedImages[0];
    const GifImageDesc& desc = first.ImageDesc;
    if (desc.Width < 1 || desc.Height < 1) throw std::runtime_error("an empty image");
    const std::size_t pixels = std::size_t(desc.Width) * std::size_t(desc.Height);
    if (pixels > kMaxPixels) throw std::runtime_error("image too large");
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
    GraphicsControlBlock control{};
    int transparent = NO_TRANSPARENT_COLOR;
    if (DGifSavedExtensionToGCB(gif.get(), 0, &control) == GIF_OK)
        transparent = control.TransparentColor;
    out.palette.resize(std::size_t(map->ColorCount));
    for (int i = 0; i < map->ColorCount; ++i) {
        const GifColorType& c = map->Colors[i];
        out.palette[std::size_t(i)] = {float(c.Red / 255.0), float(c.Green / 255.0),
                                       float(c.Blue / 255.0), i == transparent ? 0.0f : 1.0f};
    }
    out.indices.assign(first.RasterBits, first.RasterBits + pixels);
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
