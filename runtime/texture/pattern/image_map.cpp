#include "runtime/texture/pattern/image_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace hexant::runtime::pattern {

namespace {

constexpr double kEpsilon = 1.0e-10;  // POV-Ray's EPSILON
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// POV-Ray's wrap(): val into [0, upper).
double wrap(double val, double upper) {
    double t = std::fmod(val, upper);
    if (t < 0.0) t += upper;
    if (t >= upper) t = 0.0;
    return t;
}

// The angle about y from +x toward +z, over 2 pi (POV-Ray's way, with its
// special cases on the x axis).
double turn(double x, double z, double len) {
    double theta;
    if (z == 0.0)
        theta = x > 0.0 ? 0.0 : std::numbers::pi;
    else {
        theta = std::acos(x / len);
        if (z < 0.0) theta = kTwoPi - theta;
    }
    return theta;
}

// The size the image spans and its offset, in pixels: its own size times
// `repeat`, in single precision as POV-Ray's image->width (POV-Ray's
// Parse_Image_Map).
struct Span {
    double width, height, offset_u, offset_v;
};
Span span_of(const ImageMap& map, const ImagePixels& image) {
    return {static_cast<float>(image.width * map.repeat_u),
            static_cast<float>(image.height * map.repeat_v), map.offset_u * -image.width,
            map.offset_v * -image.height};
}

// The image coordinates (u, v) of a point by the map type; false where the
// map has none (POV-Ray's planar_image_map and its siblings).
bool map_coordinates(const ImageMap& map, const Span& span, const glm::dvec3& p, double& u,
                     double& v) {
    double x = p.x, y = p.y, z = p.z;
    switch (map.map_type) {
        case ImageMap::MapType::Planar:
            // (POV-Ray's gradient <1, -1, 0>: u along x, v along y.)
            if (map.once && (x < 0.0 || x > 1.0)) return false;
            u = std::fmod(x * span.width, span.width);
            if (map.once && (y < 0.0 || y > 1.0)) return false;
            v = std::fmod(y * span.height, span.height);
            return true;
        case ImageMap::MapType::Spherical: {
            double len = std::sqrt(x * x + y * y + z * z);
            if (len == 0.0) return false;
            x /= len;
            y /= len;
            z /= len;
            const double phi = 0.5 + std::asin(y) / std::numbers::pi;
            len = std::sqrt(x * x + z * z);
            const double theta = len == 0.0 ? 0.0 : turn(x, z, len) / kTwoPi;
            u = theta * span.width;
            v = phi * span.height;
            return true;
        }
        case ImageMap::MapType::Cylindrical: {
            if (map.once && (y < 0.0 || y > 1.0)) return false;
            v = std::fmod(y * span.height, span.height);
            double len = std::sqrt(x * x + y * y + z * z);
            if (len == 0.0) return false;
            x /= len;
            z /= len;
            len = std::sqrt(x * x + z * z);
            if (len == 0.0) return false;
            u = turn(x, z, len) / kTwoPi * span.width;
            return true;
        }
        case ImageMap::MapType::Torus: {
            // (About a major radius of 1: POV-Ray's gradient x.)
            double len = std::sqrt(x * x + z * z);
            if (len == 0.0) return false;
            const double theta = -turn(x, z, len);
            x = len - 1.0;
            len = std::sqrt(x * x + y * y);
            if (len == 0.0) return false;  // (POV-Ray divides by it)
            double phi = std::acos(-x / len);
            if (y > 0.0) phi = kTwoPi - phi;
            u = -(theta / kTwoPi) * span.width;
            v = phi / kTwoPi * span.height;
            return true;
        }
    }
    return false;
}

struct Rgbft {
    double c[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
    int index = -1;  // the palette index; -1 for an image without a palette
};

// The pixel at (x, y) (image coordinates, rows from the top): wrapped, or
// clamped to the edge for an image used once (POV-Ray's no_interpolation),
// with filter all and transmit all added.
Rgbft pixel(const ImageMap& map, const ImagePixels& image, double x, double y, double filter_all,
            double transmit_all) {
    int ix, iy;
    if (map.once) {
        ix = x < 0.0 ? 0 : x >= image.width ? image.width - 1 : static_cast<int>(x);
        iy = y < 0.0 ? 0 : y >= image.height ? image.height - 1 : static_cast<int>(y);
    } else {
        ix = static_cast<int>(wrap(x, image.width));
        iy = static_cast<int>(wrap(y, image.height));
    }
    const float* p =
        image.rgbt.data() + (static_cast<std::size_t>(iy) * static_cast<std::size_t>(image.width) +
                             static_cast<std::size_t>(ix)) *
                                4;
    Rgbft out;
    out.c[0] = p[0];
    out.c[1] = p[1];
    out.c[2] = p[2];
    out.c[3] = static_cast<float>(0.0 + filter_all);
    out.c[4] = static_cast<float>(image.palette && map.transmit_all_written ? transmit_all
                                                                            : p[3] + transmit_all);
    if (!image.indices.empty()) {
        const std::size_t k =
            image.indices[static_cast<std::size_t>(iy) * static_cast<std::size_t>(image.width) +
                          static_cast<std::size_t>(ix)];
        out.index = static_cast<int>(k);
        if (k < map.palette_entries.size()) {
            const PaletteEntryAmounts& own = map.palette_entries[k];
            if (own.has_filter) out.c[3] = own.filter;
            if (own.has_transmit) out.c[4] = own.transmit;
        }
    }
    return out;
}

// The weights of the corners (x, y), (x-1, y), (x, y-1), (x-1, y-1) for
// bilinear and normalized-distance interpolation (POV-Ray's bilinear and
// norm_dist, after Hagan); a corner the point lies on takes it all
// (POV-Ray divides by its zero distance).
void corner_weights(ImageMap::Interpolate how, double x, double y, double w[4]) {
    const double p = x - static_cast<int>(x), q = y - static_cast<int>(y);
    if (how == ImageMap::Interpolate::Bilinear) {
        w[0] = p * q;
        w[1] = (1 - p) * q;
        w[2] = p * (1 - q);
        w[3] = (1 - p) * (1 - q);
        return;
    }
    const double d[4] = {(1 - p) * (1 - p) + (1 - q) * (1 - q), p * p + (1 - q) * (1 - q),
                         (1 - p) * (1 - p) + q * q, p * p + q * q};
    for (int i = 0; i < 4; ++i)
        if (d[i] == 0.0) {
            for (int j = 0; j < 4; ++j) w[j] = i == j ? 1.0 : 0.0;
            return;
        }
    double sum = 0.0, inverse[4];
    for (int i = 0; i < 4; ++i) sum += inverse[i] = 1.0 / d[i];
    for (int i = 0; i < 4; ++i) w[i] = inverse[i] / sum;
}

// POV-Ray's cubic(): the four weights of a Catmull-Rom spline at x's
// fraction.
void cubic_weights(double x, double f[4]) {
    const double p = x - static_cast<int>(x), q = 1 - p;
    f[0] = -0.5 * p * q * q;
    f[1] = 0.5 * q * (q * (3 * p + 1) + 1);
    f[2] = 0.5 * p * (p * (3 * q + 1) + 1);
    f[3] = -0.5 * q * p * p;
}

}  // namespace

const ImagePixels& ImageMap::at(double t) const {
    // (The last piece starting at or before t.)
    const auto after = std::upper_bound(images.begin(), images.end(), t,
                                        [](double x, const Piece& p) { return x < p.time.lo; });
    return *(after == images.begin() ? images.front() : *(after - 1)).pixels;
}

namespace {

// POV-Ray's map_pos: the image coordinates (x, y) of a point, rows counted
// from the top; false outside the map's coverage.
bool map_pos(const ImageMap& map, const ImagePixels& image, const glm::dvec3& point, double& x,
             double& y) {
    const Span span = span_of(map, image);
    double u = 0.0, v = 0.0;
    if (!map_coordinates(map, span, point, u, v)) return false;
    if (!std::isfinite(u) || !std::isfinite(v)) return false;  // (a point at infinity, or NaN)
    // The offset and a nudge, then the rows counted from the top.
    x = u + span.offset_u + kEpsilon;
    y = v + span.offset_v + kEpsilon;
    if (map.once && (x >= image.width || y >= image.height || x < 0.0 || y < 0.0)) return false;
    x = wrap(x, image.width);
    y = wrap(-y, image.height);
    return true;
}

// The colour at image coordinates (x, y) by the map's interpolation, and
// the palette index interpolated likewise, then truncated (POV-Ray's
// image_colour_at, its interpolations and their *index).
Rgbft sample(const ImageMap& map, const ImagePixels& image, double x, double y, double filter_all,
             double transmit_all) {
    Rgbft sum;
    double index = 0.0;
    switch (map.interpolate) {
        case ImageMap::Interpolate::None:
            return pixel(map, image, x, y, filter_all, transmit_all);
        case ImageMap::Interpolate::Bilinear:
        case ImageMap::Interpolate::NormalizedDistance: {
            x += 0.5;
            y += 0.5;
            const int ix = static_cast<int>(x), iy = static_cast<int>(y);
            const Rgbft corners[4] = {
                pixel(map, image, ix, iy, filter_all, transmit_all),
                pixel(map, image, ix - 1.0, iy, filter_all, transmit_all),
                pixel(map, image, ix, iy - 1.0, filter_all, transmit_all),
                pixel(map, image, ix - 1.0, iy - 1.0, filter_all, transmit_all)};
            double w[4];
            corner_weights(map.interpolate, x, y, w);
            for (int i = 0; i < 4; ++i) {
                for (int c = 0; c < 5; ++c) sum.c[c] += corners[i].c[c] * w[i];
                index += corners[i].index * w[i];
            }
            break;
        }
        case ImageMap::Interpolate::Bicubic: {
            x += 0.5;
            y += 0.5;
            const int ix = static_cast<int>(x), iy = static_cast<int>(y);
            double fx[4], fy[4];
            cubic_weights(x, fx);
            cubic_weights(y, fy);
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) {
                    const Rgbft corner =
                        pixel(map, image, ix + i - 2.0, iy + j - 2.0, filter_all, transmit_all);
                    for (int c = 0; c < 5; ++c) sum.c[c] += corner.c[c] * (fx[i] * fy[j]);
                    index += corner.index * (fx[i] * fy[j]);
                }
            break;
        }
    }
    sum.index = static_cast<int>(index);
    return sum;
}

// POV-Ray's Colour::greyscale of a single-precision colour.
double grey(const Rgbft& c) {
    return static_cast<float>(0.297 * static_cast<float>(c.c[0]) +
                              0.589 * static_cast<float>(c.c[1]) +
                              0.114 * static_cast<float>(c.c[2]));
}

}  // namespace

std::array<double, 5> image_colour(const ImageMap& map, const glm::dvec3& point, double t,
                                   double filter_all, double transmit_all) {
    const ImagePixels& image = map.at(t);
    double x = 0.0, y = 0.0;
    // (POV-Ray's image_map: outside the map's coverage, clear white.)
    if (!map_pos(map, image, point, x, y)) return {1.0, 1.0, 1.0, 0.0, 1.0};
    Rgbft sum = sample(map, image, x, y, filter_all, transmit_all);
    if (image.premultiplied) {
        // (POV-Ray's image_colour_at: back to straight colour, by the alpha
        // the transmit leaves, when there is any.)
        const float alpha = static_cast<float>(1.0f - static_cast<float>(sum.c[4]));
        if (alpha > 1.0e-10f)
            for (int c = 0; c < 3; ++c) sum.c[c] = static_cast<float>(sum.c[c]) / alpha;
    }
    // (POV-Ray hands on a single-precision colour.)
    std::array<double, 5> out;
    for (int c = 0; c < 5; ++c) out[static_cast<std::size_t>(c)] = static_cast<float>(sum.c[c]);
    return out;
}

int material_number(const ImageMap& map, const glm::dvec3& point, double t) {
    const ImagePixels& image = map.at(t);
    double x = 0.0, y = 0.0;
    if (!map_pos(map, image, point, x, y)) return 0;
    const Rgbft s = sample(map, image, x, y, 0.0, 0.0);
    if (s.index != -1) return s.index;
    const double red = static_cast<float>(s.c[0]) * 255.0;
    // (An OpenEXR's red may lie outside [0, 1]: no texture number below 0.)
    return std::isfinite(red) && red > 0.0 ? static_cast<int>(std::min(red, 1.0e9)) : 0;
}

glm::dvec3 bump_map_normal(const ImageMap& map, const glm::dvec3& point, double t, double amount,
                           const glm::dvec3& normal) {
    const ImagePixels& image = map.at(t);
    double x = 0.0, y = 0.0;
    // (Off the image: the normal as it was.)
    if (!map_pos(map, image, point, x, y)) return normal;
    // Three samples: here, one pixel left and down, one right and down
    // (POV-Ray's bump_map, its coordinates wrapped by one image).
    const auto wrap_once = [](double c, int size) {
        return c < 0.0 ? c + size : c >= size ? c - size : c;
    };
    const Rgbft s1 = sample(map, image, x, y, 0.0, 0.0);
    x = wrap_once(x - 1.0, image.width);
    y = wrap_once(y + 1.0, image.height);
    const Rgbft s2 = sample(map, image, x, y, 0.0, 0.0);
    x = wrap_once(x + 2.0, image.width);
    const Rgbft s3 = sample(map, image, x, y, 0.0, 0.0);
    const bool colour = !map.use_index || s1.index == -1 || s2.index == -1 || s3.index == -1;
    const auto height = [&](const Rgbft& s) { return amount * (colour ? grey(s) : s.index); };
    const glm::dvec3 p1(0.0, height(s1), 0.0), p2(-1.0, height(s2), 1.0), p3(1.0, height(s3), 1.0);
    // The triangle's normal, in a frame about the surface's normal.
    glm::dvec3 bump = glm::cross(p3 - p2, p1 - p2);
    bump /= glm::length(bump);
    glm::dvec3 yprime = normal;
    glm::dvec3 xprime = glm::cross(yprime, glm::dvec3(0.0, 1.0, 0.0));
    double length = glm::length(xprime);
    if (length < kEpsilon) {
        yprime = std::fabs(normal.y - 1.0) < kEpsilon ? glm::dvec3(0.0, 1.0, 0.0)
                                                      : glm::dvec3(0.0, -1.0, 0.0);
        xprime = glm::dvec3(1.0, 0.0, 0.0);
        length = 1.0;
    }
    xprime /= length;
    glm::dvec3 zprime = glm::cross(xprime, yprime);
    zprime /= glm::length(zprime);
    return xprime * bump.x + yprime * bump.y - zprime * bump.z;
}

}  // namespace hexant::runtime::pattern
