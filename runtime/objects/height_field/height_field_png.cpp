// A paletted PNG's indices for height_field (POV-Ray takes a palette
// image's heights from its indices, not its colours, which
// image::read_stored_image expands to). libpng directly.
#include <csetjmp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <png.h>

#include "runtime/objects/height_field/height_field_data.hpp"

namespace hexant::runtime::objects {

namespace {

void on_error(png_structp png, png_const_charp message) {
    auto* text = static_cast<std::string*>(png_get_error_ptr(png));
    if (text) *text = message;
    png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

struct Reader {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~Reader() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

// Nothing with a destructor lives in this frame (setjmp).
bool read_indices(std::FILE* file, const Reader& r, std::vector<std::uint8_t>& bytes,
                  std::vector<png_bytep>& rows, int& width, int& height) {
    if (setjmp(png_jmpbuf(r.png))) return false;
    png_init_io(r.png, file);
    png_set_user_limits(r.png, 1u << 16, 1u << 16);
    png_read_info(r.png, r.info);
    if (png_get_color_type(r.png, r.info) != PNG_COLOR_TYPE_PALETTE)
        png_error(r.png, "not a paletted PNG");
    png_set_packing(r.png);  // 1, 2 and 4-bit indices one to a byte
    png_read_update_info(r.png, r.info);
    width = static_cast<int>(png_get_image_width(r.png, r.info));
    height = static_cast<int>(png_get_image_height(r.png, r.info));
    const std::size_t row_bytes = png_get_rowbytes(r.png, r.info);
    if (row_bytes != static_cast<std::size_t>(width)) png_error(r.png, "unexpected row size");
    bytes.resize(row_bytes * static_cast<std::size_t>(height));
    rows.resize(static_cast<std::size_t>(height));
    for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = bytes.data() + y * row_bytes;
    png_read_image(r.png, rows.data());
    png_read_end(r.png, nullptr);
    return true;
}

}  // namespace

std::vector<std::uint8_t> read_png_palette_indices(const std::filesystem::path& path, int& width,
                                                   int& height) {
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> stream(std::fopen(path.c_str(), "rb"),
                                                                 &std::fclose);
    if (!stream) throw HeightFieldError("height_field: cannot open '" + path.string() + "'");
    std::string message;
    Reader r;
    r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &message, on_error, on_warning);
    if (r.png) r.info = png_create_info_struct(r.png);
    if (!r.info) throw HeightFieldError("height_field: libpng cannot start");
    std::vector<std::uint8_t> bytes;
    std::vector<png_bytep> rows;
    if (!read_indices(stream.get(), r, bytes, rows, width, height))
        throw HeightFieldError("height_field: '" + path.string() + "': " + message);
    return bytes;
}

}  // namespace hexant::runtime::objects
