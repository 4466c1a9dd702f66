#include "image/formats/jpeg_format.hpp"

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <jerror.h>  // (after jpeglib.h, which it needs)
#include <jpeglib.h>

namespace hexant::image {

namespace fs = std::filesystem;

namespace {

// Larger images are refused before memory is taken for them, as PNG's.
constexpr JDIMENSION kMaxSide = 1u << 20;

// libjpeg's default error handler exits the process; this one keeps the
// message and longjmps back to the reader's setjmp.
struct ErrorManager {
    jpeg_error_mgr pub;
    std::jmp_buf back;
    char message[JMSG_LENGTH_MAX];
};

void on_error(j_common_ptr info) {
    auto* errors = reinterpret_cast<ErrorManager*>(info->err);
    (*info->err->format_message)(info, errors->message);
    std::longjmp(errors->back, 1);
}
// Warnings pass (extraneous bytes, which cameras write), but a file cut
// short, which libjpeg would fill with gray, is an error.
void on_message(j_common_ptr info, int level) {
    if (level == -1 && info->err->msg_code == JWRN_JPEG_EOF) on_error(info);
}

// Everything libjpeg may leave by longjmp is in here, with no object of
// this frame that has a destructor: what it fills lives in the caller.
bool decode(std::FILE* file, std::size_t max_pixels, jpeg_decompress_struct& info,
            ErrorManager& errors, std::vector<unsigned char>& bytes, StoredImage& out,
            std::string& refusal) {
    if (setjmp(errors.back)) return false;
    jpeg_create_decompress(&info);
    jpeg_stdio_src(&info, file);
    jpeg_read_header(&info, TRUE);
    if (info.num_components == 1) {
        info.out_color_space = JCS_GRAYSCALE;
        out.source = StoredImage::Source::Gray;
    } else if (info.jpeg_color_space == JCS_YCbCr || info.jpeg_color_space == JCS_RGB) {
        info.out_color_space = JCS_RGB;
        out.source = StoredImage::Source::Rgb;
    } else {
        refusal = "a CMYK or YCCK JPEG (hexant reads gray and colour ones)";
        return false;
    }
    if (info.image_width > kMaxSide || info.image_height > kMaxSide) {
        refusal = "image too large";
        return false;
    }
    // (Its throw leaves by an exception, with no libjpeg frame on the
    // stack; the caller's guard destroys `info`.)
    check_declared_size(info.image_width, info.image_height, max_pixels);
    jpeg_start_decompress(&info);
    out.width = static_cast<int>(info.output_width);
    out.height = static_cast<int>(info.output_height);
    const std::size_t row = std::size_t(info.output_width) * std::size_t(info.output_components);
    bytes.resize(row * info.output_height);
    while (info.output_scanline < info.output_height) {
        JSAMPROW at = bytes.data() + row * info.output_scanline;
        jpeg_read_scanlines(&info, &at, 1);
    }
    jpeg_finish_decompress(&info);
    return true;
}

StoredImage read_jpeg(const fs::path& file, std::size_t max_pixels) {
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> stream(std::fopen(file.c_str(), "rb"),
                                                                 &std::fclose);
    if (!stream) throw std::runtime_error(std::strerror(errno));
    jpeg_decompress_struct info;
    ErrorManager errors;
    info.err = jpeg_std_error(&errors.pub);
    errors.pub.error_exit = on_error;
    errors.pub.emit_message = on_message;
    errors.message[0] = '\0';
    std::vector<unsigned char> bytes;
    StoredImage out;
    std::string refusal;
    bool read = false;
    {
        struct Destroy {
            jpeg_decompress_struct& info;
            ~Destroy() { jpeg_destroy_decompress(&info); }
        } destroy{info};
        read = decode(stream.get(), max_pixels, info, errors, bytes, out, refusal);
    }
    if (!read) throw std::runtime_error(refusal.empty() ? std::string(errors.message) : refusal);
    out.linear = false;
    out.encoding_gamma = 0.0;  // sRGB, unless the scene says otherwise
    out.gamma_told = false;
    out.source_bits = 8;
    out.channels = 3;
    const std::size_t pixels = std::size_t(out.width) * std::size_t(out.height);
    out.values.resize(pixels * 3);
    if (out.source == StoredImage::Source::Gray)
        for (std::size_t i = 0; i < pixels; ++i)
            out.values[3 * i] = out.values[3 * i + 1] = out.values[3 * i + 2] =
                float(bytes[i] / 255.0);
    else
        for (std::size_t i = 0; i < out.values.size(); ++i) out.values[i] = float(bytes[i] / 255.0);
    return out;
}

bool is_jpeg(const unsigned char* head, std::size_t bytes) {
    return bytes >= 3 && head[0] == 0xFF && head[1] == 0xD8 && head[2] == 0xFF;
}

}  // namespace

const ImageFormat kJpegFormat{"JPEG", ".jpg", false, nullptr, read_jpeg, is_jpeg, 0};

}  // namespace hexant::image
