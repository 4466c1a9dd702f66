#include "runtime/objects/height_field/height_field_data.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "image/formats/gif_format.hpp"

namespace hexant::runtime::objects {

namespace {

// POV-Ray's EPSILON (its normalize() and the ray/plane test).
constexpr double kPovEpsilon = 1.0e-10;

// (HF_VAL)(x): a conversion to unsigned short, clamped (POV-Ray's cast is
// undefined outside 0..65535; only OpenEXR values reach there).
std::uint16_t to_height(double x) {
    if (!(x > 0.0)) return 0;
    if (x >= 65535.0) return 65535;
    return static_cast<std::uint16_t>(x);
}

}  // namespace

HeightFieldData::HeightFieldData(int width, int depth, std::vector<std::uint16_t> heights)
    : width_(width), depth_(depth), heights_(std::move(heights)) {
    if (width < 2 || depth < 2)
        throw HeightFieldError("a height_field's image must be at least 2 x 2 pixels, not " +
                               std::to_string(width) + " x " + std::to_string(depth));
    if (heights_.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(depth))
        throw HeightFieldError("height_field: the heights do not fill the grid");
    x_scale_ = width - 1.0;
    z_scale_ = depth - 1.0;
    const auto [lo, hi] = std::minmax_element(heights_.begin(), heights_.end());
    min_ = *lo;
    max_ = *hi;
    nodes_.push_back({0, 0, static_cast<std::uint32_t>(width - 1),
                      static_cast<std::uint32_t>(depth - 1), 0, 0, 0, 0});
    build(0);
}

// Fills node `index` (its rectangle set) and its subtree: split in half
// along each side longer than kLeafSide.
std::uint32_t HeightFieldData::build(std::uint32_t index) {
    Node node = nodes_[index];
    const std::uint32_t wx = node.x1 - node.x0, wz = node.z1 - node.z0;
    if (wx <= kLeafSide && wz <= kLeafSide) {
        std::uint16_t lo = 65535, hi = 0;
        for (std::uint32_t z = node.z0; z <= node.z1; ++z)
            for (std::uint32_t x = node.x0; x <= node.x1; ++x) {
                const std::uint16_t h = height(static_cast<int>(x), static_cast<int>(z));
                lo = std::min(lo, h);
                hi = std::max(hi, h);
            }
        nodes_[index].lo = lo;
        nodes_[index].hi = hi;
        nodes_[index].count = 0;
        return index;
    }
    const std::uint32_t mx = wx > kLeafSide ? node.x0 + wx / 2 : node.x1;
    const std::uint32_t mz = wz > kLeafSide ? node.z0 + wz / 2 : node.z1;
    std::vector<Node> children;
    for (int i = 0; i < 2; ++i)
        for (int k = 0; k < 2; ++k) {
            Node c;
            c.x0 = k == 0 ? node.x0 : mx;
            c.x1 = k == 0 ? mx : node.x1;
            c.z0 = i == 0 ? node.z0 : mz;
            c.z1 = i == 0 ? mz : node.z1;
            if (c.x0 < c.x1 && c.z0 < c.z1) children.push_back(c);
        }
    const auto first = static_cast<std::uint32_t>(nodes_.size());
    nodes_.insert(nodes_.end(), children.begin(), children.end());
    nodes_[index].first = first;
    nodes_[index].count = static_cast<std::uint32_t>(children.size());
    std::uint16_t lo = 65535, hi = 0;
    for (std::uint32_t c = 0; c < children.size(); ++c) {
        build(first + c);
        lo = std::min(lo, nodes_[first + c].lo);
        hi = std::max(hi, nodes_[first + c].hi);
    }
    nodes_[index].lo = lo;
    nodes_[index].hi = hi;
    return index;
}

geometry::Box3 HeightFieldData::node_box(const Node& node, double floor) const {
    return {{node.x0 / x_scale_, std::max(node.lo / 65536.0, floor), node.z0 / z_scale_},
            {node.x1 / x_scale_, node.hi / 65536.0, node.z1 / z_scale_}};
}

const std::vector<std::array<std::int16_t, 3>>& HeightFieldData::smooth_normals() const {
    std::call_once(normals_once_, [this] {
        // hfield.cpp smooth_height_field and add_single_normal: the four
        // triangles around each vertex, each face normal t0 x t1 (t0 = v2 -
        // v0, t1 = v1 - v0) normalized and turned upward, summed,
        // normalized, stored as (short)(32767 * N).
        const int xsize = width_ - 1, zsize = depth_ - 1;
        const auto add = [&](int x0, int z0, int x1, int z1, int x2, int z2, glm::dvec3& n) {
            if (x0 < 0 || z0 < 0 || x1 < 0 || z1 < 0 || x2 < 0 || z2 < 0 || x0 > xsize ||
                z0 > zsize || x1 > xsize || z1 > zsize || x2 > xsize || z2 > zsize)
                return 0;
            const glm::dvec3 v0(x0, height(x0, z0), z0), v1(x1, height(x1, z1), z1),
                v2(x2, height(x2, z2), z2);
            glm::dvec3 nt = glm::cross(v2 - v0, v1 - v0);
            const double length = glm::length(nt);
            nt = std::fabs(length) > kPovEpsilon ? nt / length : glm::dvec3(0.0, 1.0, 0.0);
            if (nt.y < 0.0) nt = -nt;
            n += nt;
            return 1;
        };
        normals_.resize(heights_.size());
        for (int i = 0; i <= zsize; ++i)
            for (int j = 0; j <= xsize; ++j) {
                glm::dvec3 n(0.0);
                add(j, i, j + 1, i, j, i + 1, n);
                add(j, i, j, i + 1, j - 1, i, n);
                add(j, i, j - 1, i, j, i - 1, n);
                add(j, i, j, i - 1, j + 1, i, n);
                const double length = glm::length(n);
                n = std::fabs(length) > kPovEpsilon ? n / length : glm::dvec3(0.0, 1.0, 0.0);
                normals_[static_cast<std::size_t>(i) * static_cast<std::size_t>(width_) +
                         static_cast<std::size_t>(j)] = {static_cast<std::int16_t>(32767 * n.x),
                                                         static_cast<std::int16_t>(32767 * n.y),
                                                         static_cast<std::int16_t>(32767 * n.z)};
            }
    });
    return normals_;
}

std::vector<std::uint16_t> heights_from_image(const image::StoredImage& image) {
    using Source = image::StoredImage::Source;
    const int w = image.width, h = image.height;
    const auto c = static_cast<std::size_t>(image.channels);
    std::vector<std::uint16_t> out(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    const bool palette = image.source == Source::Palette && !image.linear;
    if (palette && image.indices.size() != out.size())
        throw HeightFieldError("height_field: a paletted image's indices are missing");
    const bool gray =
        !image.linear && (image.source == Source::Gray || image.source == Source::GrayAlpha);
    const bool deep = !image.linear && image.source_bits > 8;
    for (int row = 0; row < h; ++row) {
        // POV-Ray's z = 0 is the image's bottom row.
        const int z = h - 1 - row;
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(row) * static_cast<std::size_t>(w) +
                                  static_cast<std::size_t>(x);
            const float* v = image.values.data() + i * c;
            std::uint16_t height = 0;
            if (palette) {
                height = static_cast<std::uint16_t>(image.indices[i] * 256);
            } else if (gray) {
                // GrayImage::GetGrayValue: float(stored) / float(max).
                const float max = deep ? 65535.0f : 255.0f;
                const float g = float(std::lround(double(v[0]) * max)) / max;
                height = to_height(g * 65535.0f);
            } else if (deep) {
                const float r = float(std::lround(double(v[0]) * 65535.0)) / 65535.0f;
                const float g = float(std::lround(double(v[1]) * 65535.0)) / 65535.0f;
                const float b = float(std::lround(double(v[2]) * 65535.0)) / 65535.0f;
                height = to_height((0.297 * r + 0.589 * g + 0.114 * b) * 65535.0f);
            } else {
                float r = v[0], g = v[1];
                if (!image.linear) {
                    r = float(std::lround(double(v[0]) * 255.0)) / 255.0f;
                    g = float(std::lround(double(v[1]) * 255.0)) / 255.0f;
                }
                const double value = (double(r) * 256.0 + double(g)) * 255.0;
                height = std::isfinite(value) ? to_height(value) : 0;
            }
            out[static_cast<std::size_t>(z) * static_cast<std::size_t>(w) +
                static_cast<std::size_t>(x)] = height;
        }
    }
    return out;
}

std::shared_ptr<const HeightFieldData> read_height_field(const std::filesystem::path& path,
                                                         const std::string& type,
                                                         std::size_t max_pixels) {
    std::string kind = type;
    if (kind.empty()) {
        // POV-Ray's InferFileTypeFromExt (and .pot, a POT file).
        static const std::pair<const char*, const char*> kExtensions[] = {
            {".png", "png"}, {".exr", "exr"}, {".jpg", "jpeg"}, {".jpeg", "jpeg"}, {".gif", "gif"},
            {".pot", "pot"}, {".tga", "tga"}, {".tif", "tiff"}, {".tiff", "tiff"}, {".ppm", "ppm"},
            {".pgm", "pgm"}, {".bmp", "bmp"}, {".hdr", "hdr"},  {".iff", "iff"}};
        const std::string ext = image::lower_case_extension(path);
        for (const auto& [extension, word] : kExtensions)
            if (ext == extension) kind = word;
        if (kind.empty())
            throw HeightFieldError(
                "height_field: no image type for '" + path.filename().string() + "' (" +
                (ext.empty() ? std::string("no extension") : ext) +
                "): name it, as png \"FILE\" (hexant reads png, exr, jpeg, gif, pot, tga, tiff, "
                "ppm, pgm, bmp and hdr)");
    }
    if (kind == "sys")
        throw HeightFieldError(
            "height_field: sys images: POV-Ray 3.7 on Unix defines no system format ('This "
            "platform has not defined a SYS file type'); name the file's format (png, tga, ...)");
    if (kind == "iff")
        throw HeightFieldError(
            "height_field: iff images (Amiga ILBM) are not read: POV-Ray 3.7's reader fails on "
            "every file ('Unexpected EOF while reading IFF file', after the last chunk); convert "
            "the file to png");
    image::StoredImage stored;
    try {
        stored = image::read_stored_image(path, max_pixels, kind);
    } catch (const image::ImageTooLarge& e) {
        throw HeightFieldError(std::string(e.what()) + "; --max-pixels N raises it");
    } catch (const std::runtime_error& e) {
        throw HeightFieldError(e.what());
    }
    // (The file's bytes say its format: it must be one like the one named.
    // A POT file is a GIF, and a GIF is paletted.)
    const bool paletted = stored.source == image::StoredImage::Source::Palette;
    const bool linear_kind = kind == "exr" || kind == "hdr";
    if (linear_kind != stored.linear || ((kind == "gif" || kind == "pot") && !paletted))
        throw HeightFieldError("height_field: '" + path.filename().string() + "' is not " +
                               (kind == "exr"    ? "an OpenEXR"
                                : kind == "hdr"  ? "a Radiance HDR"
                                : kind == "jpeg" ? "a JPEG"
                                : kind == "gif"  ? "a GIF"
                                : kind == "pot"  ? "a POT (GIF)"
                                                 : "an 8- or 16-bit") +
                               " file");
    if (kind == "pot") {
        try {
            stored = image::pot_from_gif(stored);
        } catch (const std::runtime_error& e) {
            throw HeightFieldError("height_field: '" + path.filename().string() + "': " + e.what());
        }
    }
    return std::make_shared<const HeightFieldData>(stored.width, stored.height,
                                                   heights_from_image(stored));
}

}  // namespace hexant::runtime::objects
