#include "tracer/image_output.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "image/colour_transfer.hpp"
#include "image/image_format.hpp"
#include "tracer/gif_animation.hpp"
#include "tracer/whole_file.hpp"

namespace hexant::tracer {

using image::image_format_extensions;
using image::image_format_for;
using image::ImageFormat;
using image::lower_case_extension;
using image::read_stored_image;
using image::StoredImage;

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

void check_frame_pattern(const std::string& pattern, std::size_t frames, const std::string& flag) {
    const auto first = pattern.find('#');
    if (first == std::string::npos) {
        if (frames > 1)
            throw std::runtime_error(flag + " " + pattern +
                                     ": several frames need a #### in the name for the number");
        return;
    }
    const auto after = pattern.find_first_not_of('#', first);
    if (after != std::string::npos && pattern.find('#', after) != std::string::npos)
        throw std::runtime_error(flag + " " + pattern +
                                 ": one run of # is the frame number; this has more");
}

Image read_image(const fs::path& path, std::size_t max_pixels) {
    const image::StoredImage stored = image::read_stored_image(path, max_pixels);
    // (8 bits, or 16 from +FN16; Targa, PPM, BMP and TIFF frames hold sRGB
    // bytes too.)
    if (!stored.linear &&
        (stored.encoding_gamma != 0.0 || (stored.source_bits != 8 && stored.source_bits != 16)))
        throw std::runtime_error(path.string() +
                                 ": not an 8- or 16-bit sRGB image as hexant writes");
    Image image(stored.width, stored.height);
    for (int y = 0; y < stored.height; ++y)
        for (int x = 0; x < stored.width; ++x) {
            const std::size_t at = (std::size_t(y) * stored.width + x) * stored.channels;
            glm::dvec3 c(stored.values[at], stored.values[at + 1], stored.values[at + 2]);
            if (!stored.linear)
                for (int k = 0; k < 3; ++k)
                    c[k] = image::srgb_decode(c[k]);  // (to_srgb8's inverse)
            image.set(x, y, c);
        }
    return image;
}

unsigned char to_srgb8(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    const double s = image::srgb_encode(c);
    return static_cast<unsigned char>(std::lround(s * 255.0));
}

namespace {

std::vector<unsigned char> srgb_pixels(const Image& image) {
    std::vector<unsigned char> out(image.rgb.size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = to_srgb8(image.rgb[i]);
    return out;
}

// Reads the written file back whole: a write that failed quietly (a full
// disk under a library that does not check every write) leaves a file that
// does not read, or reads different. Throws with the reason.
void check_reads_back(const ImageFormat& format, const fs::path& file, const Image& image,
                      const std::vector<unsigned char>& bytes) {
    StoredImage back;
    try {
        // (Read under its own size: what was written is what is expected.)
        back = format.read(file, std::size_t(image.width) * std::size_t(image.height));
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("it does not read back whole, is the disk full? ") +
                                 e.what());
    }
    if (back.width != image.width || back.height != image.height || back.channels != 3)
        throw std::runtime_error("it reads back with the wrong size");
    bool same = true;
    if (format.reads_back_as) {
        std::array<float, 3> written{};
        for (std::size_t i = 0; i < back.values.size() && same; i += 3) {
            for (std::size_t k = 0; k < 3; ++k)
                written[k] = format.linear ? image.rgb[i + k] : float(bytes[i + k] / 255.0);
            same = format.reads_back_as(written.data(), back.values.data() + i);
        }
    } else if (format.linear)
        same = back.values == image.rgb;
    else
        for (std::size_t i = 0; i < bytes.size() && same; ++i)
            same = std::lround(back.values[i] * 255.0f) == bytes[i];
    if (!same) throw std::runtime_error("it reads back different from what was written");
}

}  // namespace

const ImageFormat& check_image_name(const fs::path& path, const std::string& variant) {
    const ImageFormat* format = image_format_for(path, variant);
    if (!format && !variant.empty() && image_format_for(path))
        throw std::runtime_error(path.string() + ": " + image_format_for(path)->name +
                                 " is not written as '" + variant + "'");
    if (!format)
        throw std::runtime_error(path.string() + ": no image format for this name (hexant writes " +
                                 image_format_extensions() + ")");
    return *format;
}

void check_image_size(const fs::path& path, int width, int height, const std::string& variant) {
    const ImageFormat& format = check_image_name(path, variant);
    if (format.max_side > 0 && std::max(width, height) > format.max_side)
        throw std::runtime_error(path.string() + ": a " + format.name + " is at most " +
                                 std::to_string(format.max_side) + " pixels a side; the image is " +
                                 std::to_string(width) + " by " + std::to_string(height));
}

void check_animation_name(const fs::path& path) {
    if (lower_case_extension(path) != ".gif")
        throw std::runtime_error(path.string() + ": an animation is written as .gif");
}

void write_image(const Image& image, const fs::path& path, const std::string& variant) {
    const ImageFormat* format = &check_image_name(path, variant);
    TemporaryFile temporary(path);
    std::vector<unsigned char> bytes;
    if (!format->linear) bytes = srgb_pixels(image);
    try {
        format->write(temporary.descriptor(), image.width, image.height,
                      format->linear ? static_cast<const void*>(image.rgb.data()) : bytes.data());
        check_reads_back(*format, temporary.reopenable_name(), image, bytes);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(path.string() + ": writing failed (" + e.what() + ")");
    }
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

std::pair<int, int> contact_sheet_size(int frames, int width, int height, int columns) {
    if (frames <= 0) return {0, 0};
    if (columns <= 0) columns = default_columns(frames);
    const long long rows = (frames + columns - 1) / columns;
    // (Past an int, as the largest int: too large for any format anyway.)
    const auto side = [](long long v) {
        return int(std::min<long long>(v, std::numeric_limits<int>::max()));
    };
    return {side(static_cast<long long>(width) * columns), side(height * rows)};
}

Image contact_sheet(const std::vector<Image>& frames, int columns) {
    if (frames.empty()) return {};
    const int n = static_cast<int>(frames.size());
    if (columns <= 0) columns = default_columns(n);
    const int w = frames.front().width, h = frames.front().height;
    const auto [sheet_width, sheet_height] = contact_sheet_size(n, w, h, columns);
    Image sheet(sheet_width, sheet_height);
    for (int k = 0; k < n; ++k) {
        const int ox = (k % columns) * w, oy = (k / columns) * h;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) sheet.set(ox + x, oy + y, frames[k].at(x, y));
    }
    return sheet;
}

void write_animation(const std::vector<Image>& frames, const fs::path& path, double fps) {
    check_animation_name(path);
    if (frames.empty()) return;
    const int width = frames.front().width, height = frames.front().height;
    std::vector<std::vector<unsigned char>> pixels;
    for (const Image& f : frames) {
        if (f.width != width || f.height != height)
            throw std::runtime_error(path.string() + ": the frames differ in size");
        pixels.push_back(srgb_pixels(f));
    }
    TemporaryFile temporary(path);
    try {
        write_gif_animation(temporary.descriptor(), width, height, pixels, fps);
        // Its colours are quantized: read back whole, not compared.
        if (count_gif_frames(temporary.descriptor(), width, height) != int(frames.size()))
            throw std::runtime_error("frames are missing when it is read back");
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(path.string() + ": writing failed (" + e.what() + ")");
    }
    temporary.commit();
}

}  // namespace hexant::tracer
