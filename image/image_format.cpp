#include "image/image_format.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "image/formats/exr_format.hpp"
#include "image/formats/gif_format.hpp"
#include "image/formats/jpeg_format.hpp"
#include "image/formats/oiio_formats.hpp"
#include "image/formats/png_format.hpp"

namespace hexant::image {

namespace fs = std::filesystem;

namespace {

// The registration: a new format is its own file and one line here. (The
// first of an extension is its default when written; a format with no
// magic bytes, Targa, is last: read only when no other recognizes a file.)
constexpr std::array<const ImageFormat*, 11> kFormats{
    &kPngFormat, &kPng16Format, &kExrFormat, &kJpegFormat, &kGifFormat,   &kTiffFormat,
    &kHdrFormat, &kPnmFormat,   &kBmpFormat, &kTgaFormat,  &kTgaRleFormat};

bool has_extension(const ImageFormat& format, const std::string& ext) {
    return ext == format.extension || (*format.other_extension && ext == format.other_extension);
}

}  // namespace

std::string lower_case_extension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

const ImageFormat* image_format_for(const fs::path& path, const std::string& variant) {
    const std::string ext = lower_case_extension(path);
    for (const ImageFormat* format : kFormats)
        if (format->write && has_extension(*format, ext) && variant == format->variant)
            return format;
    return nullptr;
}

std::string image_format_extensions() {
    std::string names;
    for (const ImageFormat* format : kFormats)
        if (format->write && !*format->variant) {
            names += (names.empty() ? "" : ", ") + std::string(format->extension);
            if (*format->other_extension) names += std::string(", ") + format->other_extension;
        }
    return names;
}

void check_declared_size(long long width, long long height, std::size_t max_pixels) {
    // (An empty image is its reader's error. Sides of up to 2^32 each: the
    // product fits an unsigned long long.)
    if (width <= 0 || height <= 0) return;
    const auto pixels =
        static_cast<unsigned long long>(width) * static_cast<unsigned long long>(height);
    if (pixels <= max_pixels) return;
    throw ImageTooLarge("it declares " + std::to_string(width) + " by " + std::to_string(height) +
                        " pixels, more than the limit of " + std::to_string(max_pixels) +
                        " pixels (width times height)");
}

StoredImage read_stored_image(const fs::path& path, std::size_t max_pixels,
                              const std::string& type_word) {
    // Only a regular file (issue 45: a FIFO at a frame's or a reference's
    // name blocked the reader for good): opened without waiting for a
    // writer, checked, and kept open, so that the format's reader opens
    // this very file (/proc/self/fd/N) and not whatever is at the name by
    // then.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        throw std::runtime_error(path.string() + ": cannot read image: " + std::strerror(errno));
    struct Closing {
        int fd;
        ~Closing() { ::close(fd); }
    } closing{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0)
        throw std::runtime_error(path.string() + ": cannot read image: " + std::strerror(errno));
    if (!S_ISREG(st.st_mode))
        throw std::runtime_error(path.string() +
                                 ": cannot read image: not a regular file (a FIFO, a device or "
                                 "a folder)");
    std::array<unsigned char, 8> head{};
    ssize_t n = 0;
    do {
        n = ::pread(fd, head.data(), head.size(), 0);
    } while (n < 0 && errno == EINTR);
    if (n < 0)
        throw std::runtime_error(path.string() + ": cannot read image: " + std::strerror(errno));
    const std::size_t got = static_cast<std::size_t>(n);
    std::error_code error;
    const fs::path entry = fs::path("/proc/self/fd") / std::to_string(fd);
    const fs::path opened = fs::exists(entry, error) ? entry : path;
    const auto read = [&](const ImageFormat& format) {
        const std::string what = path.string() + ": cannot read " + format.name + " image: ";
        try {
            return format.read(opened, max_pixels);
        } catch (const ImageTooLarge& e) {
            throw ImageTooLarge(what + e.what());
        } catch (const std::runtime_error& e) {
            throw std::runtime_error(what + e.what());
        }
    };
    for (const ImageFormat* format : kFormats)
        if (format->recognizes(head.data(), got)) return read(*format);
    // Targa has no magic bytes: the scene's word or the name says it.
    if (type_word == "tga" || (type_word.empty() && lower_case_extension(path) == ".tga"))
        return read(kTgaFormat);
    throw std::runtime_error(path.string() +
                             ": cannot read image: not a PNG, OpenEXR, JPEG, GIF, TIFF, Radiance "
                             "HDR, PPM, PGM or BMP file, nor a Targa file named .tga");
}

}  // namespace hexant::image
