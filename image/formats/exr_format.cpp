#include "image/formats/exr_format.hpp"

#include <exception>
#include <stdexcept>
#include <string>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

namespace hexant::image {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxPixels = std::size_t(1) << 30;
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

StoredImage read_exr(const fs::path& file) {
    try {
        Imf::InputFile in(file.c_str());
        const Imath::Box2i window = in.header().dataWindow();
        const Imf::ChannelList& list = in.header().channels();
        StoredImage out;
        out.linear = true;
        out.width = window.max.x - window.min.x + 1;
        out.height = window.max.y - window.min.y + 1;
        if (out.width <= 0 || out.height <= 0 ||
            std::size_t(out.width) * std::size_t(out.height) > kMaxPixels)
            throw std::runtime_error("its data window is empty or too large");
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
