#include "language/image_map_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "image/colour_transfer.hpp"

namespace hexant::language {

runtime::pattern::ImagePixels image_pixels(const image::StoredImage& stored,
                                           const ImageGamma& gamma, double assumed_gamma) {
    if (stored.channels != 3 && stored.channels != 4)
        throw std::logic_error("image_pixels: an image of " + std::to_string(stored.channels) +
                               " channels");
    // POV-Ray's PPM, PGM and TIFF readers apply no gamma unless the scene
    // gives one: the values are the working space's as they are.
    const bool as_stored = stored.as_stored && !gamma.srgb && !gamma.power;
    // Decoding: the scene's gamma, else the file's (OpenEXR is linear; a
    // PNG's gAMA chunk gives its encoding gamma; else sRGB).
    const auto decode = [&](double x) {
        if (gamma.srgb) return image::srgb_decode(x);
        if (gamma.power) return std::pow(x, *gamma.power);
        if (stored.linear || gamma.undecoded || as_stored) return x;
        if (stored.encoding_gamma > 0.0) return std::pow(x, 1.0 / stored.encoding_gamma);
        if (gamma.legacy_default && !stored.gamma_told) return std::pow(x, assumed_gamma);
        return image::srgb_decode(x);
    };
    const bool working_linear = assumed_gamma == 1.0 || gamma.undecoded || as_stored;
    using Source = image::StoredImage::Source;
    // POV-Ray 3.7 keeps a gray image of 8 bits or fewer as 8-bit integers
    // after decoding (its Gray_Int8), truncated: dark tones are coarse
    // there, and so here.
    const bool coarse = stored.source == Source::Gray && stored.source_bits <= 8 &&
                        !stored.linear && !gamma.undecoded && !as_stored;
    // It ignores an RGB image's colour key (tRNS); a gray one's it does not
    // read well (it crashes): hexant keeps that one as alpha.
    const bool keyed_rgb = stored.colour_key && stored.source == Source::Rgb;
    runtime::pattern::ImagePixels out;
    out.premultiplied = stored.linear && stored.channels == 4;
    out.palette = stored.source == Source::Palette;
    out.indices = stored.indices;
    out.palette_size = static_cast<int>(stored.palette.size());
    out.width = stored.width;
    out.height = stored.height;
    const std::size_t n =
        static_cast<std::size_t>(stored.width) * static_cast<std::size_t>(stored.height);
    out.rgbt.resize(n * 4);
    for (std::size_t i = 0; i < n; ++i) {
        const float* in = stored.values.data() + i * static_cast<std::size_t>(stored.channels);
        for (std::size_t c = 0; c < 3; ++c) {
            double v = decode(in[c]);
            if (!working_linear && v > 0.0) v = std::pow(v, 1.0 / assumed_gamma);
            // (A NaN or infinite value in an OpenEXR file is taken as 0.)
            if (!std::isfinite(v)) v = 0.0;
            if (coarse) v = std::floor(std::clamp(v, 0.0, 1.0) * 255.0) / 255.0;
            out.rgbt[i * 4 + c] = static_cast<float>(v);
        }
        const double alpha = stored.channels == 4 && !keyed_rgb ? in[3] : 1.0;
        out.rgbt[i * 4 + 3] = std::isfinite(alpha) ? static_cast<float>(1.0 - alpha) : 0.0f;
    }
    return out;
}

}  // namespace hexant::language
