// Two image files compared pixel by pixel (the measures of OpenImageIO's
// ImageBufAlgo::compare and idiff), for golden-image tests and error
// measurements.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace hexant::tracer {

// Where differences are measured: in the files' own encoding, as values in
// [0, 1] (for PNG: 8-bit sRGB steps / 255), or in linear light (an sRGB file
// is decoded first; EXR files are linear already). Rounding shows in the
// first; a share of a pixel's samples, or an error against a reference, in
// the second.
enum class ImageSpace { Stored, Linear };

// A pixel "fails" or "warns" when any channel differs by more than the
// threshold.
struct ImageDifference {
    double mean = 0.0, rms = 0.0, max = 0.0;
    int max_x = 0, max_y = 0;
    std::size_t pixels = 0, failing = 0, warning = 0;
};

// Throws std::runtime_error naming the file when one cannot be read, or
// when the two differ in size or channels.
ImageDifference compare_images(const std::filesystem::path& a, const std::filesystem::path& b,
                               double fail_threshold, double warn_threshold,
                               ImageSpace space = ImageSpace::Stored);

// The error of an image against a reference, in linear light, averaged over
// pixels and channels: root mean squared error, and relative MSE
// ((a - r)^2 / (r^2 + epsilon), epsilon keeping dark pixels from dominating,
// 0.01 as Rousselle et al. and most denoising papers use).
struct ImageError {
    double rmse = 0.0, relative_mse = 0.0;
};
ImageError image_error(const std::filesystem::path& image, const std::filesystem::path& reference,
                       double epsilon = 0.01);

// Writes |a - b| scaled by `gain`, as a frame (write_image: the sRGB encoding
// of a PNG brightens faint differences further, which is what a person
// looking for them wants).
void write_difference_image(const std::filesystem::path& a, const std::filesystem::path& b,
                            const std::filesystem::path& out, double gain);

}  // namespace hexant::tracer
