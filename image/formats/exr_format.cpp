#include "image/formats/exr_format.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <string>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/openexr.h>
#include <unistd.h>

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

// The bytes the C++ reader reads for an attribute of a fixed size,
// whatever its declared size says (0: a type of variable size).
int fixed_size(const std::string& type) {
    static const std::pair<const char*, int> kSizes[] = {{"box2i", 16},
                                                         {"box2f", 16},
                                                         {"v2i", 8},
                                                         {"v2f", 8},
                                                         {"v2d", 16},
                                                         {"v3i", 12},
                                                         {"v3f", 12},
                                                         {"v3d", 24},
                                                         {"int", 4},
                                                         {"float", 4},
                                                         {"double", 8},
                                                         {"rational", 8},
                                                         {"compression", 1},
                                                         {"lineOrder", 1},
                                                         {"envmap", 1},
                                                         {"deepImageState", 1},
                                                         {"m33f", 36},
                                                         {"m33d", 72},
                                                         {"m44f", 64},
                                                         {"m44d", 128},
                                                         {"chromaticities", 32},
                                                         {"keycode", 28},
                                                         {"timecode", 8},
                                                         {"tiledesc", 9}};
    for (const auto& [name, size] : kSizes)
        if (type == name) return size;
    return 0;
}

// Every attribute of every header as the C++ reader will read it: each
// holds no more bytes than the file has, and one of a fixed size, a
// channel list or a preview holds exactly what it declares. The C++ reader
// takes an attribute's declared size (or a preview's width by height)
// before it reads, and reads a fixed-size one whatever its size says, so a
// wrong size sets it reading the next attribute from the wrong place: an
// attribute of an unknown type then declared 1.6 GB in a file of 340
// bytes (found by the image fuzzer; the C library passed the file).
void check_attributes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    in.seekg(0, std::ios::end);
    const long long file_size = in.tellg();
    in.seekg(4);
    unsigned char version[4] = {};
    in.read(reinterpret_cast<char*>(version), 4);
    const bool multipart = (version[1] & 0x10) != 0;  // bit 12
    const auto word = [&](std::string& out) {         // a name or a type, NUL-ended
        out.clear();
        for (char c = 0; in.get(c) && c != '\0';)
            if (out.size() < 256) out += c;
        return bool(in);
    };
    const auto int32 = [&] {
        unsigned char b[4] = {};
        in.read(reinterpret_cast<char*>(b), 4);
        return static_cast<long long>(
            static_cast<std::int32_t>(std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 |
                                      std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24));
    };
    const auto refuse = [](const std::string& name, long long size) {
        throw std::runtime_error("its attribute '" + name + "' is damaged (" +
                                 std::to_string(size) + " bytes declared)");
    };
    std::string name, type, channel;
    do {
        while (word(name) && !name.empty()) {
            if (!word(type)) return;
            const long long size = int32();
            const long long start = in.tellg();
            if (!in || size < 0 || size > file_size - start) refuse(name, size);
            const int fixed = fixed_size(type);
            if (fixed != 0 && size != fixed) refuse(name, size);
            if (type == "chlist") {  // read up to its empty name
                while (word(channel) && !channel.empty()) in.seekg(16, std::ios::cur);
                if (!in || static_cast<long long>(in.tellg()) - start != size) refuse(name, size);
            } else if (type == "preview") {
                const long long width = int32(), height = int32();
                if (!in || width < 0 || height < 0 || 8 + 4 * width * height != size)
                    refuse(name, size);
            }
            in.seekg(start + size);
        }
        // (A multi-part file's headers end with an empty one.)
    } while (multipart && in && in.peek() != 0 && in.peek() != EOF);
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

// An OpenEXR output stream over a descriptor the caller keeps (a file
// created for this write, never reopened by its name): positioned writes,
// so the line offsets it writes last go where the library says.
class DescriptorStream : public Imf::OStream {
  public:
    explicit DescriptorStream(int fd) : Imf::OStream("(descriptor)"), fd_(fd) {}
    void write(const char c[], int n) override {
        std::size_t done = 0;
        while (done < std::size_t(n)) {
            const ssize_t wrote = ::pwrite(fd_, c + done, std::size_t(n) - done, off_t(at_ + done));
            if (wrote < 0 && errno == EINTR) continue;
            if (wrote <= 0) throw std::runtime_error(std::strerror(wrote < 0 ? errno : EIO));
            done += std::size_t(wrote);
        }
        at_ += std::uint64_t(n);
    }
    std::uint64_t tellp() override { return at_; }
    void seekp(std::uint64_t pos) override { at_ = pos; }

  private:
    int fd_;
    std::uint64_t at_ = 0;
};

void write_exr(int fd, int width, int height, const void* pixels) {
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
        DescriptorStream stream(fd);
        Imf::OutputFile out(stream, header);
        out.setFrameBuffer(frame);
        out.writePixels(height);
    } catch (const std::exception& e) {
        throw std::runtime_error(e.what());
    }
}

StoredImage read_exr(const fs::path& file, std::size_t max_pixels) {
    check_header(file, max_pixels);
    check_attributes(file);
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
