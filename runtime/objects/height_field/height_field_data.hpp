// A height_field's grid, as POV-Ray 3.7 keeps it (hfield.cpp): one 16-bit
// height per image pixel, the image's bottom row at z = 0
// (Compute_HField: Map[z][x] = image_height_at(image, x, max_z - z - 1)),
// the per-vertex normals `smooth` blends, and a static quadtree over the
// cells (each node: its cells' rectangle and the least and greatest height
// of their corners), shared by every copy of the field.
//
// Object space (POV-Ray's Parse_HField scaling): vertex (x, z) of a
// width x depth grid is at <x / (width - 1), height / 65536, z / (depth - 1)>.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image_format.hpp"
#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::objects {

struct HeightFieldError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class HeightFieldData {
  public:
    struct Node {
        // Cells [x0, x1) x [z0, z1); the corner heights within lo..hi.
        std::uint32_t x0 = 0, z0 = 0, x1 = 0, z1 = 0;
        std::uint16_t lo = 0, hi = 0;
        // Children at [first, first + count); a leaf has count == 0.
        std::uint32_t first = 0, count = 0;
    };
    // A leaf holds at most kLeafSide x kLeafSide cells.
    static constexpr std::uint32_t kLeafSide = 4;

    // `heights`: width * depth values, row z at [z * width, (z + 1) * width),
    // z = 0 the image's bottom row. Throws HeightFieldError when the grid is
    // smaller than 2 x 2 (POV-Ray scales by 1 / (width - 1)).
    HeightFieldData(int width, int depth, std::vector<std::uint16_t> heights);

    int width() const { return width_; }  // vertices along x
    int depth() const { return depth_; }  // vertices along z
    std::uint16_t height(int x, int z) const {
        return heights_[static_cast<std::size_t>(z) * static_cast<std::size_t>(width_) +
                        static_cast<std::size_t>(x)];
    }
    std::uint16_t min_height() const { return min_; }
    std::uint16_t max_height() const { return max_; }
    double x_scale() const { return x_scale_; }  // width - 1
    double z_scale() const { return z_scale_; }  // depth - 1
    // Vertex (x, z) in object space.
    glm::dvec3 vertex(int x, int z) const {
        return {x / x_scale_, height(x, z) / 65536.0, z / z_scale_};
    }

    const std::vector<Node>& nodes() const { return nodes_; }
    // A node's box in object space, its bottom raised to `floor` (object
    // space y) when that is higher.
    geometry::Box3 node_box(const Node& node, double floor) const;

    // POV-Ray's smooth_height_field normals, per vertex in grid space
    // (x and z in cells, y in height units), stored as it stores them:
    // (short)(32767 * N). Computed on first use.
    const std::vector<std::array<std::int16_t, 3>>& smooth_normals() const;

    // Calls visit(index) for nodes from the root down while visit returns
    // true.
    template <class Visit>
    void descend(Visit&& visit) const {
        if (nodes_.empty()) return;
        std::vector<std::uint32_t> stack{0};
        while (!stack.empty()) {
            const std::uint32_t i = stack.back();
            stack.pop_back();
            if (!visit(i)) continue;
            for (std::uint32_t c = 0; c < nodes_[i].count; ++c)
                stack.push_back(nodes_[i].first + c);
        }
    }

  private:
    std::uint32_t build(std::uint32_t index);

    int width_ = 0, depth_ = 0;
    double x_scale_ = 1.0, z_scale_ = 1.0;
    std::vector<std::uint16_t> heights_;
    std::uint16_t min_ = 0, max_ = 0;
    std::vector<Node> nodes_;
    mutable std::once_flag normals_once_;
    mutable std::vector<std::array<std::int16_t, 3>> normals_;
};

// POV-Ray 3.7's image_height_at (imageutil.cpp) for an image as hexant
// reads it: 8-bit (or less) gray: (HF_VAL)(gray * 65535.0f), gray = v /
// 255.0f; 16-bit gray the same with v / 65535.0f; RGB(A) of 8 bits: red the
// high byte and green the low one, (HF_VAL)((r * 256.0 + g) * 255.0); RGB(A)
// of 16 bits: (HF_VAL)(GREY_SCALE3(r, g, b) * 65535.0f) with 0.297, 0.589,
// 0.114; OpenEXR (POV-Ray reads it as float RGBFT, whose GetMaxIntValue is
// 255) as 8-bit RGB, clamped to 0..65535; a paletted image index * 256,
// from its `indices`. Rows are turned so z = 0 is the image's bottom row.
std::vector<std::uint16_t> heights_from_image(const image::StoredImage& image);

// Reads a height field's image: `type` is the scene's type word ("png",
// "exr"), or empty when the scene gave none (then the file's extension
// says, as POV-Ray's Parse_Image infers it). Throws HeightFieldError with a
// message naming the file or the type hexant does not read, or the size
// it declares when that is more than `max_pixels` (checked before any
// pixel is read).
std::shared_ptr<const HeightFieldData> read_height_field(
    const std::filesystem::path& path, const std::string& type,
    std::size_t max_pixels = image::kMaxImagePixels);

}  // namespace hexant::runtime::objects
