#include "tracer/gif_animation.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <gif_lib.h>
#include <unistd.h>

namespace hexant::tracer {

namespace fs = std::filesystem;

namespace {

std::string reason(int code) {
    // (giflib leaves the code 0 when its first allocation fails.)
    if (code == 0) return "giflib failed (out of memory?)";
    const char* text = GifErrorString(code);
    return text ? text : "giflib error " + std::to_string(code);
}

struct MapDeleter {
    void operator()(ColorMapObject* map) const { GifFreeMapObject(map); }
};

// Writes every block after the screen; false on the first failure, whose
// code giflib keeps in gif->Error.
bool write_blocks(GifFileType* gif, int width, int height,
                  const std::vector<std::vector<unsigned char>>& frames, double fps) {
    if (EGifPutScreenDesc(gif, width, height, 8, 0, nullptr) == GIF_ERROR) return false;
    // The NETSCAPE2.0 application block: loop forever.
    static const GifByteType kApplication[] = {'N', 'E', 'T', 'S', 'C', 'A',
                                               'P', 'E', '2', '.', '0'};
    static const GifByteType kLoop[] = {1, 0, 0};
    if (EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
        EGifPutExtensionBlock(gif, sizeof kApplication, kApplication) == GIF_ERROR ||
        EGifPutExtensionBlock(gif, sizeof kLoop, kLoop) == GIF_ERROR ||
        EGifPutExtensionTrailer(gif) == GIF_ERROR)
        return false;
    GraphicsControlBlock control{};
    control.DisposalMode = DISPOSE_DO_NOT;
    control.DelayTime = static_cast<int>(std::lround(100.0 / fps));
    control.TransparentColor = NO_TRANSPARENT_COLOR;
    GifByteType control_bytes[4];
    EGifGCBToExtension(&control, control_bytes);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    std::vector<GifByteType> red(pixels), green(pixels), blue(pixels), index(pixels);
    for (const auto& frame : frames) {
        for (std::size_t i = 0; i < pixels; ++i) {
            red[i] = frame[3 * i];
            green[i] = frame[3 * i + 1];
            blue[i] = frame[3 * i + 2];
        }
        int colours = 256;
        const std::unique_ptr<ColorMapObject, MapDeleter> map(GifMakeMapObject(256, nullptr));
        if (!map) throw std::bad_alloc();
        if (GifQuantizeBuffer(unsigned(width), unsigned(height), &colours, red.data(), green.data(),
                              blue.data(), index.data(), map->Colors) == GIF_ERROR)
            throw std::runtime_error("giflib cannot quantize a frame");
        if (EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, 4, control_bytes) == GIF_ERROR ||
            EGifPutImageDesc(gif, 0, 0, width, height, false, map.get()) == GIF_ERROR)
            return false;
        for (int y = 0; y < height; ++y)
            if (EGifPutLine(gif, index.data() + std::size_t(y) * std::size_t(width), width) ==
                GIF_ERROR)
                return false;
    }
    return true;
}

}  // namespace

void write_gif_animation(int fd, int width, int height,
                         const std::vector<std::vector<unsigned char>>& frames, double fps) {
    if (width > kGifMaxSide || height > kGifMaxSide)
        throw std::runtime_error("a GIF is at most " + std::to_string(kGifMaxSide) +
                                 " pixels a side");
    // giflib closes the descriptor it is given: a copy of the caller's.
    const int descriptor = ::fcntl(fd, F_DUPFD_CLOEXEC, 0);
    if (descriptor < 0) throw std::runtime_error(std::strerror(errno));
    int error = 0;
    GifFileType* gif = EGifOpenFileHandle(descriptor, &error);
    if (!gif) {
        ::close(descriptor);
        throw std::runtime_error(reason(error));
    }
    EGifSetGifVersion(gif, true);  // GIF89a: delays and looping
    bool ok = false;
    try {
        ok = write_blocks(gif, width, height, frames, fps);
    } catch (...) {
        EGifCloseFile(gif, &error);
        throw;
    }
    const int block_error = ok ? 0 : gif->Error;
    // Closing writes the trailer and checks fclose; it frees `gif` either way.
    const bool closed = EGifCloseFile(gif, &error) != GIF_ERROR;
    if (!ok) throw std::runtime_error(reason(block_error));
    if (!closed) throw std::runtime_error(reason(error));
}

int count_gif_frames(int fd, int width, int height) {
    int error = 0;
    // (A copy shares the caller's position: both are rewound to the
    // start; giflib closes the copy.)
    const int descriptor = ::fcntl(fd, F_DUPFD_CLOEXEC, 0);
    if (descriptor < 0 || ::lseek(descriptor, 0, SEEK_SET) != 0) {
        const int system_error = errno;
        if (descriptor >= 0) ::close(descriptor);
        throw std::runtime_error(std::strerror(system_error));
    }
    GifFileType* gif = DGifOpenFileHandle(descriptor, &error);
    if (!gif) throw std::runtime_error(reason(error));
    const bool read = DGifSlurp(gif) != GIF_ERROR;
    const int read_error = gif->Error;
    int frames = gif->ImageCount;
    bool sizes = true;
    for (int i = 0; read && i < frames; ++i)
        sizes = sizes && gif->SavedImages[i].ImageDesc.Width == width &&
                gif->SavedImages[i].ImageDesc.Height == height;
    DGifCloseFile(gif, &error);
    if (!read) throw std::runtime_error("it does not read back whole: " + reason(read_error));
    if (!sizes) throw std::runtime_error("it reads back with the wrong size");
    return frames;
}

}  // namespace hexant::tracer
