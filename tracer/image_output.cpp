#include "tracer/image_output.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <OpenImageIO/imageio.h>

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

void write_image(const Image& image, const fs::path& path) {
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out)
        throw std::runtime_error(path.string() + ": no image format for this name (" +
                                 OIIO::geterror() + ")");
    const fs::path temporary = temporary_beside(path);
    const bool linear = is_float_format(path);
    OIIO::ImageSpec spec(image.width, image.height, 3,
                         linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", linear ? "Linear" : "sRGB");
    if (!out->open(temporary.string(), spec))
        throw std::runtime_error(path.string() + ": cannot write: " + out->geterror());
    bool ok;
    if (linear) {
        ok = out->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data());
    } else {
        const auto pixels = srgb_pixels(image);
        ok = out->write_image(OIIO::TypeDesc::UINT8, pixels.data());
    }
    ok = out->close() && ok;
    if (!ok) {
        fs::remove(temporary);
        throw std::runtime_error(path.string() + ": writing failed: " + out->geterror());
    }
    replace_with(temporary, path);
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
    const fs::path temporary = temporary_beside(path);
    std::vector<OIIO::ImageSpec> specs;
    for (const Image& f : frames) {
        OIIO::ImageSpec spec(f.width, f.height, 3, OIIO::TypeDesc::UINT8);
        spec.attribute("FramesPerSecond", OIIO::TypeDesc::TypeRational,
                       std::vector<int>{int(std::lround(fps)), 1}.data());
        spec.attribute("oiio:LoopCount", 0);
        specs.push_back(spec);
    }
    if (!out->open(temporary.string(), int(specs.size()), specs.data()))
        throw std::runtime_error(path.string() + ": cannot write: " + out->geterror());
    bool ok = true;
    for (std::size_t i = 0; i < frames.size() && ok; ++i) {
        if (i > 0) ok = out->open(temporary.string(), specs[i], OIIO::ImageOutput::AppendSubimage);
        const auto pixels = srgb_pixels(frames[i]);
        ok = ok && out->write_image(OIIO::TypeDesc::UINT8, pixels.data());
    }
    ok = out->close() && ok;
    if (!ok) {
        fs::remove(temporary);
        throw std::runtime_error(path.string() + ": writing failed: " + out->geterror());
    }
    replace_with(temporary, path);
}

}  // namespace hexant::tracer
