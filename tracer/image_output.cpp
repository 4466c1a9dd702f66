#include "tracer/image_output.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "tracer/whole_file.hpp"

namespace hexant::tracer {

namespace fs = std::filesystem;

std::string frame_path(const std::string& pattern, int frame) {
    const auto first = pattern.find('#');
    if (first == std::string::npos) return pattern;
    auto last = first;
    while (last < pattern.size() && pattern[last] == '#') ++last;
    std::string number = std::to_string(frame);
    const std::size_t width = last - first;
    if (number.size() < width) number.insert(0, width - number.size(), '0');
    return pattern.substr(0, first) + number + pattern.substr(last);
}

unsigned char to_srgb8(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return static_cast<unsigned char>(std::lround(s * 255.0));
}

namespace {

bool is_float_format(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".exr" || ext == ".hdr";
}

std::vector<unsigned char> srgb_pixels(const Image& image) {
    std::vector<unsigned char> out(image.rgb.size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = to_srgb8(image.rgb[i]);
    return out;
}

}  // namespace

namespace {

// Reads the written file back whole: a write that failed quietly (a full
// disk under a library that does not check fwrite) leaves a file that does
// not read. With `expected`, its pixels must also be exactly those written.
bool reads_back(const fs::path& file, int width, int height, int subimages, OIIO::TypeDesc type,
                const void* expected, std::size_t expected_bytes, std::string& reason) {
    // The reader's first line says why (a library may add several).
    const auto first_line = [](std::string text) { return text.substr(0, text.find('\n')); };
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) {
        reason = "it does not read back: " + first_line(OIIO::geterror());
        return false;
    }
    for (int s = 0; s < subimages; ++s) {
        if (s > 0 && !in->seek_subimage(s, 0)) {
            reason = "frame " + std::to_string(s + 1) + " is missing";
            return false;
        }
        const OIIO::ImageSpec& spec = in->spec();
        if (spec.width != width || spec.height != height) {
            reason = "it reads back with the wrong size";
            return false;
        }
        std::vector<unsigned char> data(std::size_t(width) * std::size_t(height) *
                                        std::size_t(spec.nchannels) * type.size());
        if (!in->read_image(0, 0, 0, spec.nchannels, type, data.data())) {
            reason = "it does not read back whole, is the disk full? " + first_line(in->geterror());
            return false;
        }
        if (expected && (spec.nchannels != 3 || data.size() != expected_bytes ||
                         std::memcmp(data.data(), expected, expected_bytes) != 0)) {
            reason = "it reads back different from what was written";
            return false;
        }
    }
    return true;
}

}  // namespace

void write_image(const Image& image, const fs::path& path) {
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out)
        throw std::runtime_error(path.string() + ": no image format for this name (" +
                                 OIIO::geterror() + ")");
    TemporaryFile temporary(path);
    const bool linear = is_float_format(path);
    const OIIO::TypeDesc type = linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(image.width, image.height, 3, type);
    spec.attribute("oiio:ColorSpace", linear ? "Linear" : "sRGB");
    if (!out->open(temporary.name().string(), spec))
        throw std::runtime_error(path.string() + ": cannot write: " + out->geterror());
    std::vector<unsigned char> bytes;
    const void* data = nullptr;
    std::size_t size = 0;
    if (linear) {
        data = image.rgb.data();
        size = image.rgb.size() * sizeof(float);
    } else {
        bytes = srgb_pixels(image);
        data = bytes.data();
        size = bytes.size();
    }
    bool ok = out->write_image(type, data);
    ok = out->close() && ok;
    if (!ok) throw std::runtime_error(path.string() + ": writing failed: " + out->geterror());
    // Half-precision formats (.hdr) do not give back the floats written.
    const bool exact = !linear || path.extension() == ".exr" || path.extension() == ".EXR";
    std::string reason;
    if (!reads_back(temporary.name(), image.width, image.height, 1, type, exact ? data : nullptr,
                    size, reason))
        throw std::runtime_error(path.string() + ": writing failed (" + reason + ")");
    temporary.commit();
}

// A full grid when one is nearly square (32 frames: 8 by 4, not 6 by 6 with
// four holes); otherwise the smallest square that holds them all.
static int default_columns(int n) {
    const int square = static_cast<int>(std::ceil(std::sqrt(double(n))));
    for (int columns = square; columns <= 2 * square; ++columns)
        if (n % columns == 0) return columns;
    return square;
}

Image contact_sheet(const std::vector<Image>& frames, int columns) {
    if (frames.empty()) return {};
    const int n = static_cast<int>(frames.size());
    if (columns <= 0) columns = default_columns(n);
    const int rows = (n + columns - 1) / columns;
    const int w = frames.front().width, h = frames.front().height;
    Image sheet(w * columns, h * rows);
    for (int k = 0; k < n; ++k) {
        const int ox = (k % columns) * w, oy = (k / columns) * h;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) sheet.set(ox + x, oy + y, frames[k].at(x, y));
    }
    return sheet;
}

void write_animation(const std::vector<Image>& frames, const fs::path& path, double fps) {
    if (frames.empty()) return;
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out || !out->supports("multiimage"))
        throw std::runtime_error(path.string() + ": this format cannot hold an animation");
    TemporaryFile temporary(path);
    std::vector<OIIO::ImageSpec> specs;
    for (const Image& f : frames) {
        OIIO::ImageSpec spec(f.width, f.height, 3, OIIO::TypeDesc::UINT8);
        spec.attribute("FramesPerSecond", OIIO::TypeDesc::TypeRational,
                       std::vector<int>{int(std::lround(fps)), 1}.data());
        spec.attribute("oiio:LoopCount", 0);
        specs.push_back(spec);
    }
    if (!out->open(temporary.name().string(), int(specs.size()), specs.data()))
        throw std::runtime_error(path.string() + ": cannot write: " + out->geterror());
    bool ok = true;
    for (std::size_t i = 0; i < frames.size() && ok; ++i) {
        if (i > 0)
            ok = out->open(temporary.name().string(), specs[i], OIIO::ImageOutput::AppendSubimage);
        const auto pixels = srgb_pixels(frames[i]);
        ok = ok && out->write_image(OIIO::TypeDesc::UINT8, pixels.data());
    }
    ok = out->close() && ok;
    if (!ok) throw std::runtime_error(path.string() + ": writing failed: " + out->geterror());
    // Its colours are quantized (GIF): read back whole, not compared.
    std::string reason;
    if (!reads_back(temporary.name(), frames.front().width, frames.front().height,
                    int(frames.size()), OIIO::TypeDesc::UINT8, nullptr, 0, reason))
        throw std::runtime_error(path.string() + ": writing failed (" + reason + ")");
    temporary.commit();
}

}  // namespace hexant::tracer
