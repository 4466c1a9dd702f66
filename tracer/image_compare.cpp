#include "tracer/image_compare.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "tracer/image.hpp"
#include "tracer/image_output.hpp"

namespace hexant::tracer {
namespace {

namespace fs = std::filesystem;

OIIO::ImageBuf read(const fs::path& path, ImageSpace space = ImageSpace::Stored) {
    OIIO::ImageBuf image(path.string());
    if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT))
        throw std::runtime_error(path.string() + ": cannot read image: " + image.geterror());
    if (space == ImageSpace::Linear &&
        image.spec().get_string_attribute("oiio:ColorSpace") == "sRGB") {
        OIIO::ImageBuf linear = OIIO::ImageBufAlgo::colorconvert(image, "sRGB", "linear");
        if (linear.has_error())
            throw std::runtime_error(path.string() + ": cannot decode sRGB: " + linear.geterror());
        return linear;
    }
    return image;
}

void check_same_shape(const OIIO::ImageBuf& a, const fs::path& pa, const OIIO::ImageBuf& b,
                      const fs::path& pb) {
    const auto& sa = a.spec();
    const auto& sb = b.spec();
    if (sa.width != sb.width || sa.height != sb.height || sa.nchannels != sb.nchannels)
        throw std::runtime_error(pa.string() + " is " + std::to_string(sa.width) + "x" +
                                 std::to_string(sa.height) + "x" + std::to_string(sa.nchannels) +
                                 " but " + pb.string() + " is " + std::to_string(sb.width) + "x" +
                                 std::to_string(sb.height) + "x" + std::to_string(sb.nchannels));
}

}  // namespace

ImageDifference compare_images(const fs::path& a, const fs::path& b, double fail_threshold,
                               double warn_threshold, ImageSpace space) {
    const OIIO::ImageBuf ia = read(a, space), ib = read(b, space);
    check_same_shape(ia, a, ib, b);
    const OIIO::ImageBufAlgo::CompareResults r = OIIO::ImageBufAlgo::compare(
        ia, ib, static_cast<float>(fail_threshold), static_cast<float>(warn_threshold));
    // r.error is also set when pixels exceed failthresh; only a message
    // means the comparison itself went wrong.
    if (const std::string message = OIIO::geterror(); r.error && !message.empty())
        throw std::runtime_error(a.string() + " against " + b.string() + ": " + message);
    ImageDifference d;
    d.mean = r.meanerror;
    d.rms = r.rms_error;
    d.max = r.maxerror;
    d.max_x = r.maxx;
    d.max_y = r.maxy;
    d.pixels = std::size_t(ia.spec().width) * std::size_t(ia.spec().height);
    d.failing = r.nfail;
    d.warning = r.nwarn;
    return d;
}

ImageError image_error(const fs::path& image, const fs::path& reference, double epsilon) {
    namespace algo = OIIO::ImageBufAlgo;
    const OIIO::ImageBuf a = read(image, ImageSpace::Linear);
    const OIIO::ImageBuf r = read(reference, ImageSpace::Linear);
    check_same_shape(a, image, r, reference);
    const OIIO::ImageBuf difference = algo::sub(a, r);
    const OIIO::ImageBuf squared = algo::mul(difference, difference);
    const OIIO::ImageBuf relative =
        algo::div(squared, algo::add(algo::mul(r, r), static_cast<float>(epsilon)));
    const auto mean_of = [](const OIIO::ImageBuf& buffer) {
        const algo::PixelStats stats = algo::computePixelStats(buffer);
        double sum = 0.0;
        for (const double v : stats.avg) sum += v;
        return stats.avg.empty() ? 0.0 : sum / double(stats.avg.size());
    };
    return {std::sqrt(mean_of(squared)), mean_of(relative)};
}

void write_difference_image(const fs::path& a, const fs::path& b, const fs::path& out,
                            double gain) {
    const OIIO::ImageBuf ia = read(a), ib = read(b);
    check_same_shape(ia, a, ib, b);
    const OIIO::ImageBuf difference =
        OIIO::ImageBufAlgo::mul(OIIO::ImageBufAlgo::absdiff(ia, ib), static_cast<float>(gain));
    Image image(difference.spec().width, difference.spec().height);
    const int channels = std::min(difference.spec().nchannels, 3);
    for (OIIO::ImageBuf::ConstIterator<float> p(difference); !p.done(); ++p)
        for (int c = 0; c < 3; ++c)
            image.rgb[(std::size_t(p.y()) * image.width + p.x()) * 3 + c] = p[std::min(c, channels - 1)];
    write_image(image, out);
}

}  // namespace hexant::tracer
