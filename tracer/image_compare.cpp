#include "tracer/image_compare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "image/colour_transfer.hpp"
#include "image/image_format.hpp"
#include "tracer/image.hpp"
#include "tracer/image_output.hpp"

namespace hexant::tracer {

using image::read_stored_image;
using image::StoredImage;
namespace {

namespace fs = std::filesystem;

// `max_pixels`: the second image of a pair is read under the first's size
// (a different size is refused anyway), so a reference or golden file
// that declares a huge size is refused from its header.
StoredImage read(const fs::path& path, ImageSpace space = ImageSpace::Stored,
                 std::size_t max_pixels = image::kMaxImagePixels) {
    StoredImage image = read_stored_image(path, max_pixels);
    if (space == ImageSpace::Linear && !image.linear) {
        // Colour channels only: an alpha channel is not encoded.
        for (std::size_t i = 0; i < image.values.size(); ++i)
            if (int(i % std::size_t(image.channels)) < 3)
                image.values[i] = float(image::srgb_decode(image.values[i]));
        image.linear = true;
    }
    return image;
}

std::size_t pixels_of(const StoredImage& image) {
    return std::size_t(image.width) * std::size_t(image.height);
}

// The second image of a pair, read under the first's size.
StoredImage read_second(const fs::path& path, ImageSpace space, const StoredImage& first,
                        const fs::path& first_path) {
    try {
        return read(path, space, pixels_of(first));
    } catch (const image::ImageTooLarge& e) {
        throw std::runtime_error(first_path.string() + " is " + std::to_string(first.width) + "x" +
                                 std::to_string(first.height) + "x" +
                                 std::to_string(first.channels) + " but " + e.what());
    }
}

void check_same_shape(const StoredImage& a, const fs::path& pa, const StoredImage& b,
                      const fs::path& pb) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels)
        throw std::runtime_error(pa.string() + " is " + std::to_string(a.width) + "x" +
                                 std::to_string(a.height) + "x" + std::to_string(a.channels) +
                                 " but " + pb.string() + " is " + std::to_string(b.width) + "x" +
                                 std::to_string(b.height) + "x" + std::to_string(b.channels));
}

}  // namespace

ImageDifference compare_images(const fs::path& a, const fs::path& b, double fail_threshold,
                               double warn_threshold, ImageSpace space) {
    const StoredImage ia = read(a, space);
    const StoredImage ib = read_second(b, space, ia, a);
    check_same_shape(ia, a, ib, b);
    ImageDifference d;
    d.pixels = std::size_t(ia.width) * std::size_t(ia.height);
    const std::size_t channels = std::size_t(ia.channels);
    double sum = 0.0, squares = 0.0;
    for (std::size_t p = 0; p < d.pixels; ++p) {
        bool fails = false, warns = false;
        for (std::size_t c = 0; c < channels; ++c) {
            const double e =
                std::abs(double(ia.values[p * channels + c]) - double(ib.values[p * channels + c]));
            sum += e;
            squares += e * e;
            // A NaN on either side counts as the worst difference.
            if (!(e <= d.max)) {
                d.max = std::isnan(e) ? std::numeric_limits<double>::infinity() : e;
                d.max_x = int(p % std::size_t(ia.width));
                d.max_y = int(p / std::size_t(ia.width));
            }
            fails = fails || !(e <= fail_threshold);
            warns = warns || !(e <= warn_threshold);
        }
        d.failing += fails;
        d.warning += warns;
    }
    const double values = double(d.pixels * channels);
    d.mean = values > 0 ? sum / values : 0.0;
    d.rms = values > 0 ? std::sqrt(squares / values) : 0.0;
    return d;
}

ImageError image_error(const fs::path& image, const fs::path& reference, double epsilon) {
    const StoredImage a = read(image, ImageSpace::Linear);
    const StoredImage r = read_second(reference, ImageSpace::Linear, a, image);
    check_same_shape(a, image, r, reference);
    double squares = 0.0, relative = 0.0;
    for (std::size_t i = 0; i < a.values.size(); ++i) {
        const double e = double(a.values[i]) - double(r.values[i]);
        const double ref = r.values[i];
        squares += e * e;
        relative += e * e / (ref * ref + epsilon);
    }
    const double n = double(std::max<std::size_t>(a.values.size(), 1));
    return {std::sqrt(squares / n), relative / n};
}

void write_difference_image(const fs::path& a, const fs::path& b, const fs::path& out,
                            double gain) {
    const StoredImage ia = read(a);
    const StoredImage ib = read_second(b, ImageSpace::Stored, ia, a);
    check_same_shape(ia, a, ib, b);
    Image image(ia.width, ia.height);
    const std::size_t channels = std::size_t(ia.channels);
    for (std::size_t p = 0; p < std::size_t(ia.width) * std::size_t(ia.height); ++p)
        for (std::size_t c = 0; c < 3; ++c)
            image.rgb[p * 3 + c] = float(gain * std::abs(double(ia.values[p * channels + c]) -
                                                         double(ib.values[p * channels + c])));
    write_image(image, out);
}

}  // namespace hexant::tracer
