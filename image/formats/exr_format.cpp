#include "image/formats/exr_format.hpp"

#include <exception>
#include <stdexcept>
#include <string>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/openexr.h>

namespace hexant::image {

namespace fs = std::filesystem;

namespace {

// Wider or taller is refused by the header's own check, as PNG's; and a
// file of more chunks (line blocks or tiles: 1 by 1 tiles over 2^20 by
// 2^20 pixels would be 2^40) before the C++ reader takes its offset table.
constexpr int kMaxSide = 1 << 20;
constexpr int kMaxChunks = 1 << 22;

// The C library's message for the error it reports (by default it prints
// it on stderr).
thread_local std::string t_core_message;
void on_core_error(exr_const_context_t, exr_result_t, const char* message) {
    t_core_message = message ? message : "";
}

// The first part's header as the C library reads it, alone (no offsets,
// no pixels): its data window against `max_pixels` and its chunks.
void check_header(const fs::path& file, std::size_t max_pixels) {
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_core_error;
    init.max_image_width = init.max_image_height = kMaxSide;
    init.max_tile_width = init.max_tile_height = kMaxSide;
    exr_context_t context = nullptr;
    t_core_message.clear();
    const exr_result_t started = exr_start_read(&context, file.c_str(), &init);
    const auto finish = [&] { exr_finish(&context); };
    if (started != EXR_ERR_SUCCESS) {
        finish();
        throw std::runtime_error(t_core_message.empty() ? exr_get_default_error_message(started)
                                                        : t_core_message);
    }
    exr_attr_box2i_t window{};
    int32_t chunks = 0;
    if (exr_get_data_window(context, 0, &window) != EXR_ERR_SUCCESS ||
        exr_get_chunk_count(context, 0, &chunks) != EXR_ERR_SUCCESS) {
        finish();
        throw std::runtime_error(t_core_message.empty() ? "a damaged header" : t_core_message);
    }
    finish();
    const long long width = (long long)window.max.x - window.min.x + 1;
    const long long height = (long long)window.max.y - window.min.y + 1;
    if (width <= 0 || height <= 0) throw std::runtime_error("its data window is empty");
    check_declared_size(width, height, max_pixels);
    if (chunks < 0 || chunks > kMaxChunks)
        throw std::runtime_error("it has " + std::to_string(chunks) + " chunks, more than " +
                                 std::to_string(kMaxChunks));
}

constexpr const char* kChannels[] = {"R", "G", "B", "A"};

void write_exr(const fs::path& file, int width, int height, const void* pixels) {
    try {
        Imf::Header header(width, height);
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::FrameBuffer frame;
        const std::size_t x_stride = 3 * sizeof(float), y_stride = x_stride * std::size_t(width);
        char* base = static_cast<char*>(const_cast<void*>(pixels));
        for (int c = 0; c < 3; ++c) {
            header.channels().insert(kChannels[c], Imf::Channel(Imf::FLOAT));
            frame.insert(kChannels[c],
                         Imf::Slice(Imf::FLOAT, base + c * sizeof(float), x_stride, y_stride));
        }
        // The file's destructor writes the line offsets and swallows its
        // errors: the caller reads the file back to catch a short one.
        Imf::OutputFile out(file.c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(height);
    } catch (const std::exception& e) {
        throw std::runtime_error(e.what());
    }
}

StoredImage read_exr(const fs::path& file, std::size_t max_pixels) {
    check_header(file, max_pixels);
    try {
        Imf::InputFile in(file.c_str());
        const Imath::Box2i window = in.header().dataWindow();
        const Imf::ChannelList& list = in.header().channels();
        StoredImage out;
        out.linear = true;
        // (The C++ reader reads the header again: the window it will use
        // is the one checked here.)
        const long long width = (long long)window.max.x - window.min.x + 1;
        const long long height = (long long)window.max.y - window.min.y + 1;
        if (width <= 0 || height <= 0) throw std::runtime_error("its data window is empty");
        check_declared_size(width, height, max_pixels);
        out.width = static_cast<int>(width);
        out.height = static_cast<int>(height);
        for (int c = 0; c < 3; ++c)
            if (!list.findChannel(kChannels[c]))
                throw std::runtime_error(std::string("it has no ") + kChannels[c] + " channel");
        out.channels = list.findChannel("A") ? 4 : 3;
        out.values.resize(std::size_t(out.width) * std::size_t(out.height) *
                          std::size_t(out.channels));
        Imf::FrameBuffer frame;
        const std::size_t x_stride = std::size_t(out.channels) * sizeof(float);
        const std::size_t y_stride = x_stride * std::size_t(out.width);
        for (int c = 0; c < out.channels; ++c)
            frame.insert(kChannels[c], Imf::Slice::Make(Imf::FLOAT, out.values.data() + c, window,
                                                        x_stride, y_stride));
        in.setFrameBuffer(frame);
        in.readPixels(window.min.y, window.max.y);
        return out;
    } catch (const std::runtime_error&) {
        throw;
    } catch (const std::exception& e) {
        throw std::runtime_error(e.what());
    }
}

bool is_exr(const unsigned char* head, std::size_t bytes) {
    return bytes >= 4 && head[0] == 0x76 && head[1] == 0x2f && head[2] == 0x31 && head[3] == 0x01;
}

}  // namespace

const ImageFormat kExrFormat{"OpenEXR", ".exr", true, write_exr, read_exr, is_exr, 0};

}  // namespace hexant::image
