#include "runtime/objects/height_field/height_field_function.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace hexant::runtime::objects {

namespace {

// POV-Ray's IntEncode(x, 65535) and IntDecode: clipped, rounded to nearest
// in single precision.
float through_16_bits(double v) {
    const float x = static_cast<float>(v);
    const float clipped = x < 0.0f ? 0.0f : x > 1.0f ? 1.0f : x;
    float q = std::floor(clipped * 65535.0f + 0.5f);
    if (!(q >= 0.0f)) q = 0.0f;  // (NaN reads as 0, as a clip of it would)
    if (q > 65535.0f) q = 65535.0f;
    return q / 65535.0f;
}

std::uint16_t height_of(float grey) {
    const float h = grey * 65535.0f;
    if (!(h > 0.0f)) return 0;
    if (h >= 65535.0f) return 65535;
    return static_cast<std::uint16_t>(h);
}

void check_size(int width, int height) {
    if (width < 2 || height < 2 || width > kMaxFunctionGridSide || height > kMaxFunctionGridSide)
        throw HeightFieldError("a height_field function's grid is 2 to " +
                               std::to_string(kMaxFunctionGridSide) + " on a side, not " +
                               std::to_string(width) + " x " + std::to_string(height));
}

template <class Grey>
std::shared_ptr<const HeightFieldData> sample(int width, int height, Grey grey) {
    check_size(width, height);
    std::vector<std::uint16_t> heights(static_cast<std::size_t>(width) *
                                       static_cast<std::size_t>(height));
    for (int z = 0; z < height; ++z) {
        // (The grid's row z is the image's row height - 1 - z.)
        const int row = height - 1 - z;
        const double y = static_cast<double>(row) / (height - 1);
        for (int i = 0; i < width; ++i) {
            const double x = static_cast<double>(i) / (width - 1);
            heights[static_cast<std::size_t>(z) * static_cast<std::size_t>(width) +
                    static_cast<std::size_t>(i)] = height_of(grey(x, y));
        }
    }
    return std::make_shared<const HeightFieldData>(width, height, std::move(heights));
}

}  // namespace

std::shared_ptr<const HeightFieldData> heights_of_function(
    int width, int height, const std::function<double(double x, double y)>& value) {
    return sample(width, height, [&](double x, double y) { return through_16_bits(value(x, y)); });
}

std::shared_ptr<const HeightFieldData> heights_of_pigment(
    int width, int height, const std::function<std::array<double, 3>(double x, double y)>& colour) {
    return sample(width, height, [&](double x, double y) {
        const std::array<double, 3> c = colour(x, y);
        // (RGBColour::Greyscale: double weights, a float result.)
        return static_cast<float>(0.297 * through_16_bits(c[0]) + 0.589 * through_16_bits(c[1]) +
                                  0.114 * through_16_bits(c[2]));
    });
}

}  // namespace hexant::runtime::objects
