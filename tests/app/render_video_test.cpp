// `render --video`: the file decoded again with FFmpeg's own libraries
// (linked here, where hexant loads them when used) holds every frame, in
// order, at --fps, each as its PNG frame shows it; bad requests are refused
// naming the flag before anything is rendered.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include "app/render_command.hpp"
#include "image/image_format.hpp"
#include "tracer/image_output.hpp"

namespace fs = std::filesystem;
using hexant::app::RenderArguments;
using hexant::app::run_render;

namespace {

// Flat saturated colours (a red ball crossing a blue ground over a green
// bar), unlit: a wrong matrix or swapped channels move every pixel far,
// and the ball moves about 10 pixels a frame, so a frame out of order
// differs in a wide band.
const char* kScene = R"(
camera { location <0, 0, -5> look_at 0 }
background { rgb <0.02, 0.05, 0.5> }
sphere { <-2.5 + 5 * clock, 0, 0>, 0.9 pigment { rgb <1, 0.05, 0> } finish { ambient 1 diffuse 0 } }
box { <-3, -2.2, 0>, <3, -1.2, 1> pigment { rgb <0.05, 0.8, 0.1> } finish { ambient 1 diffuse 0 } }
)";

fs::path test_folder() {
    std::string name = Catch::getResultCapture().getCurrentTestName();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    const fs::path folder = fs::temp_directory_path() / "hexant_render_video_test" / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / "scene.pov") << kScene;
    return folder;
}

RenderArguments arguments_for(const fs::path& folder) {
    RenderArguments a;
    a.scene.files = {(folder / "scene.pov").string()};
    a.scene.width = 64;
    a.scene.height = 48;
    a.scene.frame_count = 6;
    a.samples_per_pixel = 4;
    a.output = (folder / "out/f_##.png").string();
    return a;
}

// A decoded video: its frames' planes (4:2:0) and what its stream says.
struct Decoded {
    int width = 0, height = 0;
    double seconds = 0.0;  // the stream's duration
    AVColorSpace matrix = AVCOL_SPC_UNSPECIFIED;
    AVColorRange range = AVCOL_RANGE_UNSPECIFIED;
    AVColorPrimaries primaries = AVCOL_PRI_UNSPECIFIED;
    AVColorTransferCharacteristic transfer = AVCOL_TRC_UNSPECIFIED;
    struct Frame {
        std::vector<std::uint8_t> y, u, v;
    };
    std::vector<Frame> frames;
};

Decoded decode(const fs::path& path) {
    AVFormatContext* input = nullptr;
    if (avformat_open_input(&input, path.c_str(), nullptr, nullptr) < 0 ||
        avformat_find_stream_info(input, nullptr) < 0)
        throw std::runtime_error("cannot open " + path.string());
    const AVStream* stream = input->streams[0];
    const AVCodec* codec = avcodec_find_decoder(stream->codecpar->codec_id);
    AVCodecContext* context = avcodec_alloc_context3(codec);
    avcodec_parameters_to_context(context, stream->codecpar);
    REQUIRE(avcodec_open2(context, codec, nullptr) == 0);
    Decoded d;
    d.width = stream->codecpar->width;
    d.height = stream->codecpar->height;
    // (WebM gives the duration of the file, not of its stream.)
    d.seconds = stream->duration != AV_NOPTS_VALUE
                    ? double(stream->duration) * av_q2d(stream->time_base)
                    : double(input->duration) / AV_TIME_BASE;
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    const auto take = [&] {
        while (avcodec_receive_frame(context, frame) == 0) {
            REQUIRE(frame->format == AV_PIX_FMT_YUV420P);
            d.matrix = frame->colorspace;
            d.range = frame->color_range;
            d.primaries = frame->color_primaries;
            d.transfer = frame->color_trc;
            Decoded::Frame f;
            const int cw = (frame->width + 1) / 2, ch = (frame->height + 1) / 2;
            for (int y = 0; y < frame->height; ++y)
                f.y.insert(f.y.end(), frame->data[0] + y * frame->linesize[0],
                           frame->data[0] + y * frame->linesize[0] + frame->width);
            for (int y = 0; y < ch; ++y) {
                f.u.insert(f.u.end(), frame->data[1] + y * frame->linesize[1],
                           frame->data[1] + y * frame->linesize[1] + cw);
                f.v.insert(f.v.end(), frame->data[2] + y * frame->linesize[2],
                           frame->data[2] + y * frame->linesize[2] + cw);
            }
            d.frames.push_back(std::move(f));
        }
    };
    while (av_read_frame(input, packet) >= 0) {
        if (packet->stream_index == 0) avcodec_send_packet(context, packet);
        av_packet_unref(packet);
        take();
    }
    avcodec_send_packet(context, nullptr);
    take();
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&context);
    avformat_close_input(&input);
    return d;
}

// A decoded frame as 8-bit R'G'B', by the limited-range equations of a
// matrix with luma weights kr, kb (BT.709: 0.2126, 0.0722), written out
// here rather than through libswscale, so that the test does not share the
// writer's conversion. Chroma taken from the nearest sample. `swap` swaps
// red and blue.
std::vector<double> to_rgb(const Decoded& d, const Decoded::Frame& f, double kr, double kb,
                           bool swap = false) {
    std::vector<double> rgb;
    const int cw = (d.width + 1) / 2;
    const double kg = 1.0 - kr - kb;
    for (int y = 0; y < d.height; ++y)
        for (int x = 0; x < d.width; ++x) {
            const double luma = (f.y[std::size_t(y) * d.width + x] - 16.0) / 219.0;
            const std::size_t c = std::size_t(y / 2) * cw + x / 2;
            const double pb = (f.u[c] - 128.0) / 224.0, pr = (f.v[c] - 128.0) / 224.0;
            const double r = luma + 2.0 * (1.0 - kr) * pr, b = luma + 2.0 * (1.0 - kb) * pb;
            const double g = (luma - kr * r - kb * b) / kg;
            for (const double v : {swap ? b : r, g, swap ? r : b})
                rgb.push_back(std::clamp(v, 0.0, 1.0) * 255.0);
        }
    return rgb;
}

// The mean absolute difference, in 8-bit steps, from the PNG's bytes, of
// the means of 2 by 2 blocks (`width` even): 4:2:0 keeps one chroma
// sample a block, so a sharp red-on-blue edge inside a block cannot come
// back pixel by pixel (6 to 7 steps a frame, all at edges, pixel by pixel
// here), but the block's mean colour does.
double mean_difference(const std::vector<double>& rgb, const fs::path& png, int width) {
    const auto stored = hexant::image::read_stored_image(png, 1 << 20);
    REQUIRE(stored.values.size() == rgb.size());
    const int height = int(rgb.size() / 3) / width;
    double sum = 0.0;
    for (int y = 0; y + 1 < height; y += 2)
        for (int x = 0; x + 1 < width; x += 2)
            for (int c = 0; c < 3; ++c) {
                double block = 0.0;
                for (const int dy : {0, 1})
                    for (const int dx : {0, 1}) {
                        const std::size_t i = (std::size_t(y + dy) * width + x + dx) * 3 + c;
                        block += rgb[i] - std::round(stored.values[i] * 255.0f);
                    }
                sum += std::fabs(block / 4.0);
            }
    return sum / double(rgb.size() / 4);
}

// What a right frame may differ from its PNG by, on average over its 2 by
// 2 blocks and channels, in 8-bit steps: lossy coding at CRF 18 / 24 moves
// flat areas by about 1 step, and at sharp saturated edges the encoder's
// chroma filter reaches past a block (measured: 2.4 to 3.2 on these 64 by
// 48 frames, H.264 and VP9 alike). A frame out of order (a band of ball
// against sky: 11 to 20), BT.601's matrix instead of BT.709's (8.3 to 8.9:
// the saturated red and blue move) or red and blue swapped (~67) each
// give at least twice this.
constexpr double kTolerance = 4.0;

fs::path frame_png(const fs::path& folder, int k) {
    return folder / hexant::tracer::frame_path("out/f_##.png", k);
}

}  // namespace

TEST_CASE("render --video holds every frame in order, at --fps, as its PNG", "[app][video]") {
    for (const char* name : {"v.mp4", "v.webm"}) {
        INFO(name);
        const fs::path folder = test_folder();
        RenderArguments a = arguments_for(folder);
        a.video = (folder / "out" / name).string();
        a.fps = 12;
        std::ostringstream out, err;
        REQUIRE(run_render(a, out, err) == 0);
        INFO(err.str());
        CHECK(out.str().find("6 frames at 12 per second") != std::string::npos);
        const Decoded d = decode(*a.video);
        CHECK(d.width == 64);
        CHECK(d.height == 48);
        // Exactly the frames rendered: none repeated at the end, so a
        // cyclic animation loops cleanly, and it lasts frames / fps.
        REQUIRE(d.frames.size() == 6);
        CHECK(d.seconds == Approx(6.0 / 12.0).margin(1e-3));
        CHECK(d.matrix == AVCOL_SPC_BT709);
        CHECK(d.range == AVCOL_RANGE_MPEG);
        CHECK(d.primaries == AVCOL_PRI_BT709);
        CHECK(d.transfer == AVCOL_TRC_IEC61966_2_1);
        for (int k = 1; k <= 6; ++k) {
            INFO("frame " << k);
            const Decoded::Frame& f = d.frames[std::size_t(k - 1)];
            const double right =
                mean_difference(to_rgb(d, f, 0.2126, 0.0722), frame_png(folder, k), 64);
            CHECK(right <= kTolerance);
            // The same comparison fails where it should: the next frame's
            // PNG, another matrix, red and blue swapped.
            CHECK(mean_difference(to_rgb(d, f, 0.2126, 0.0722), frame_png(folder, k % 6 + 1), 64) >
                  kTolerance);
            CHECK(mean_difference(to_rgb(d, f, 0.299, 0.114), frame_png(folder, k), 64) >
                  kTolerance);
            CHECK(mean_difference(to_rgb(d, f, 0.2126, 0.0722, true), frame_png(folder, k), 64) >
                  kTolerance);
        }
        // Nothing but the frames, their records' folder and the video in the
        // folder (no temporary).
        int files = 0;
        for (const auto& entry : fs::directory_iterator(folder / "out")) {
            if (entry.path().filename() == ".hexant") continue;
            CHECK(entry.path().filename().string().front() != '.');
            ++files;
        }
        CHECK(files == 7);
    }
}

TEST_CASE("render --video after --resume adds the frames on disk in their turn", "[app][video]") {
    const fs::path folder = test_folder();
    RenderArguments a = arguments_for(folder);
    std::ostringstream out, err;
    REQUIRE(run_render(a, out, err) == 0);
    // Frames 2 and 5 are rendered again, the others read back.
    fs::remove(frame_png(folder, 2));
    fs::remove(frame_png(folder, 5));
    a.resume = true;
    a.video = (folder / "out/v.mp4").string();
    REQUIRE(run_render(a, out, err) == 0);
    INFO(err.str());
    const Decoded d = decode(*a.video);
    REQUIRE(d.frames.size() == 6);
    for (int k = 1; k <= 6; ++k) {
        INFO("frame " << k);
        const auto rgb = to_rgb(d, d.frames[std::size_t(k - 1)], 0.2126, 0.0722);
        CHECK(mean_difference(rgb, frame_png(folder, k), 64) <= kTolerance);
    }
}

TEST_CASE("render --video refuses what it cannot write, naming the flag, before rendering",
          "[app][video]") {
    const fs::path folder = test_folder();
    const auto refused = [&](const auto& change, const std::string& says) {
        RenderArguments a = arguments_for(folder);
        change(a);
        std::ostringstream o, e;
        CHECK(run_render(a, o, e) != 0);
        INFO(e.str());
        CHECK(e.str().find("--video") != std::string::npos);
        CHECK(e.str().find(says) != std::string::npos);
        CHECK_FALSE(fs::exists(folder / "out"));  // not a frame, not a temporary
    };
    refused([&](RenderArguments& a) { a.video = (folder / "out/v.avi").string(); },
            "v.avi: a video is written as .mp4 (H.264) or .webm (VP9)");
    refused([&](RenderArguments& a) { a.video = (folder / "out/v").string(); },
            "a video is written as .mp4");
    // H.264 in 4:2:0 codes pairs of rows and columns: an odd side is
    // refused (hexant neither pads nor crops the render).
    refused(
        [&](RenderArguments& a) {
            a.scene.width = 63;
            a.video = (folder / "out/v.mp4").string();
        },
        "needs an even width and height; the frames are 63 by 48");
    refused(
        [&](RenderArguments& a) {
            a.window = "0/2";
            a.video = (folder / "out/v.mp4").string();
        },
        "--window renders part of the frames");
    // VP9 codes odd sides.
    RenderArguments a = arguments_for(folder);
    a.scene.width = 63;
    a.scene.height = 47;
    a.scene.frame_count = 2;
    a.video = (folder / "out/odd.webm").string();
    std::ostringstream o, e;
    REQUIRE(run_render(a, o, e) == 0);
    const Decoded d = decode(*a.video);
    CHECK(d.width == 63);
    CHECK(d.height == 47);
    CHECK(d.frames.size() == 2);
}

TEST_CASE("render takes --fps as a frame rate above 0", "[app][video]") {
    for (const char* bad : {"0", "x", "24fps", "1e9", "nan"}) {
        CLI::App app;
        RenderArguments a;
        hexant::app::add_render_arguments(app, a);
        INFO(bad);
        CHECK_THROWS_WITH(app.parse(std::vector<std::string>{bad, "--fps", "s.pov"}),
                          Catch::Contains("not a frame rate"));
    }
}
