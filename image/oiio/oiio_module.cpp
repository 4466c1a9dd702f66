// hexant's OpenImageIO module (image/oiio/oiio_module.h): the table of
// functions hexant calls through dlopen. Everything OpenImageIO throws or
// reports is caught here and returned as text.
#include "image/oiio/oiio_module.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <string>

#include <OpenImageIO/imageio.h>

namespace {

void set_error(char* error, std::size_t size, const std::string& text) {
    if (!error || size == 0) return;
    std::snprintf(error, size, "%s", text.empty() ? "OpenImageIO failed" : text.c_str());
}

const char* library_version() {
    return OIIO_VERSION_STRING;
}

// A BMP's declared size from its own header: OpenImageIO's reader decodes a
// run-length BMP whole when it opens it (width x height bytes taken before
// its caller sees the header). False when the header is too short to say.
bool bmp_declared_size(const char* path, long long& width, long long& height) {
    unsigned char h[26] = {};
    std::FILE* file = std::fopen(path, "rb");
    if (!file) return false;
    const std::size_t got = std::fread(h, 1, sizeof h, file);
    std::fclose(file);
    const auto u16 = [&](int at) { return (unsigned(h[at]) | unsigned(h[at + 1]) << 8); };
    const auto s32 = [&](int at) {
        return static_cast<long long>(static_cast<std::int32_t>(
            std::uint32_t(h[at]) | std::uint32_t(h[at + 1]) << 8 | std::uint32_t(h[at + 2]) << 16 |
            std::uint32_t(h[at + 3]) << 24));
    };
    if (got < 22) return false;
    if (u16(14) == 12) {  // OS/2 1.x: 16-bit sides
        width = u16(18);
        height = u16(20);
        return true;
    }
    if (got < 26) return false;
    width = s32(18);
    height = s32(22);
    if (height < 0) height = -height;  // (a top-down BMP)
    return true;
}

int read(const char* path, const char* format, std::size_t max_pixels, HexantOiioImage* image,
         HexantOiioAllocate allocate, void* context, char* error, std::size_t error_size) {
    try {
        long long declared_width = 0, declared_height = 0;
        if (std::strcmp(format, "bmp") == 0 &&
            bmp_declared_size(path, declared_width, declared_height) &&
            (declared_width < 0 || static_cast<unsigned long long>(declared_width) *
                                           static_cast<unsigned long long>(declared_height) >
                                       max_pixels)) {
            *image = HexantOiioImage{};
            image->width = int(std::clamp<long long>(declared_width, 0, (1LL << 31) - 1));
            image->height = int(std::clamp<long long>(declared_height, 0, (1LL << 31) - 1));
            if (declared_width < 0) {
                set_error(error, error_size, "a negative width");
                return 1;
            }
            return 2;
        }
        // The reader of the format named, whatever the file's name says.
        auto in = OIIO::ImageInput::create(format);
        if (!in) {
            set_error(error, error_size,
                      "no OpenImageIO reader for " + std::string(format) + ": " + OIIO::geterror());
            return 1;
        }
        // Alpha as the file holds it (POV-Ray's TGA, BMP: not premultiplied).
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        OIIO::ImageSpec spec;
        if (!in->open(path, spec, config)) {
            set_error(error, error_size, in->geterror());
            return 1;
        }
        const long long width = spec.width, height = spec.height;
        if (width <= 0 || height <= 0 || spec.nchannels <= 0) {
            set_error(error, error_size, "an empty image");
            return 1;
        }
        *image = HexantOiioImage{};
        image->width = spec.width;
        image->height = spec.height;
        image->channels = std::min(spec.nchannels, 4);
        image->bits = spec.get_int_attribute("oiio:BitsPerSample", int(spec.format.size() * 8));
        image->is_float = spec.format.is_floating_point() ? 1 : 0;
        image->has_palette = spec.get_string_attribute("tiff:ColorSpace") == "palette" ||
                             (std::strcmp(format, "bmp") == 0 &&
                              spec.get_int_attribute("bmp:bitsperpixel", 24) <= 8);
        std::snprintf(image->format, sizeof image->format, "%s", in->format_name());
        // The header's size, before any pixel is decoded.
        if (static_cast<unsigned long long>(width) * static_cast<unsigned long long>(height) >
            max_pixels)
            return 2;
        const std::size_t count =
            std::size_t(width) * std::size_t(height) * std::size_t(image->channels);
        float* values = allocate(context, count);
        if (!values) {
            set_error(error, error_size, "out of memory for the pixels");
            return 1;
        }
        // (A reader that went on past an error it logged: a failure too.)
        if (!in->read_image(0, 0, 0, image->channels, OIIO::TypeDesc::FLOAT, values) ||
            in->has_error()) {
            set_error(error, error_size, in->geterror());
            return 1;
        }
        in->close();
        return 0;
    } catch (const std::exception& e) {
        set_error(error, error_size, e.what());
    } catch (...) {
        set_error(error, error_size, "OpenImageIO failed");
    }
    return 1;
}

int write(int fd, const char* format, const char* compression, int width, int height, int is_float,
          const void* pixels, char* error, std::size_t error_size) {
    try {
        auto out = OIIO::ImageOutput::create(format);
        if (!out) {
            set_error(error, error_size,
                      "no OpenImageIO writer for " + std::string(format) + ": " + OIIO::geterror());
            return 1;
        }
        const OIIO::TypeDesc type = is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
        OIIO::ImageSpec spec(width, height, 3, type);
        if (compression) spec.attribute("compression", compression);
        // The descriptor's own file (a temporary hexant created), not a name.
        const std::string name = "/proc/self/fd/" + std::to_string(fd);
        if (!out->open(name, spec) || !out->write_image(type, pixels) || !out->close()) {
            set_error(error, error_size, out->geterror());
            return 1;
        }
        return 0;
    } catch (const std::exception& e) {
        set_error(error, error_size, e.what());
    } catch (...) {
        set_error(error, error_size, "OpenImageIO failed");
    }
    return 1;
}

const HexantOiioApi kApi{HEXANT_OIIO_API_VERSION, library_version, read, write};

}  // namespace

extern "C" __attribute__((visibility("default"))) const HexantOiioApi* hexant_oiio_api(
    int version) {
    return version == HEXANT_OIIO_API_VERSION ? &kApi : nullptr;
}
