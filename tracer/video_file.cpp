#include "tracer/video_file.hpp"

#include <cerrno>
#include <cmath>
#include <functional>
#include <new>
#include <stdexcept>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "image/image_format.hpp"
#include "tracer/ffmpeg_library.hpp"
#include "tracer/image_output.hpp"
#include "tracer/whole_file.hpp"

namespace hexant::tracer {

namespace fs = std::filesystem;

namespace {

const VideoKind kKinds[] = {{".mp4", "libx264", "mp4", "H.264"},
                            {".webm", "libvpx-vp9", "webm", "VP9"}};

constexpr int kIoBuffer = 1 << 16;

// (FFmpeg 7 made the written bytes const.)
#if LIBAVFORMAT_VERSION_MAJOR >= 61
using WrittenBytes = const std::uint8_t*;
#else
using WrittenBytes = std::uint8_t*;
#endif

// The temporary's descriptor as FFmpeg's output: written in order, with
// seeks back (MP4's box sizes, WebM's duration and cues), the first failed
// write's reason kept for the message.
struct Sink {
    int fd = -1;
    std::string error;
};

int write_sink(void* opaque, WrittenBytes data, int size) {
    Sink& sink = *static_cast<Sink*>(opaque);
    const std::string why = write_all(sink.fd, data, std::size_t(size));
    if (why.empty()) return size;
    if (sink.error.empty()) sink.error = why;
    return AVERROR(EIO);
}

std::int64_t size_of(int fd) {
    struct stat status {};
    return ::fstat(fd, &status) == 0 ? std::int64_t(status.st_size) : AVERROR(errno);
}

std::int64_t seek_sink(void* opaque, std::int64_t offset, int whence) {
    const int fd = static_cast<Sink*>(opaque)->fd;
    if (whence & AVSEEK_SIZE) return size_of(fd);
    const off_t at = ::lseek(fd, offset, whence & ~AVSEEK_FORCE);
    return at < 0 ? AVERROR(errno) : std::int64_t(at);
}

// The same descriptor read back from its start (pread: its own position).
struct Source {
    int fd = -1;
    std::int64_t at = 0;
};

int read_source(void* opaque, std::uint8_t* data, int size) {
    Source& source = *static_cast<Source*>(opaque);
    ssize_t got;
    do got = ::pread(source.fd, data, std::size_t(size), source.at);
    while (got < 0 && errno == EINTR);
    if (got < 0) return AVERROR(errno);
    if (got == 0) return AVERROR_EOF;
    source.at += got;
    return int(got);
}

std::int64_t seek_source(void* opaque, std::int64_t offset, int whence) {
    Source& source = *static_cast<Source*>(opaque);
    const std::int64_t size = size_of(source.fd);
    if (whence & AVSEEK_SIZE) return size;
    switch (whence & ~AVSEEK_FORCE) {
        case SEEK_SET:
            source.at = offset;
            break;
        case SEEK_CUR:
            source.at += offset;
            break;
        case SEEK_END:
            source.at = size + offset;
            break;
        default:
            return AVERROR(EINVAL);
    }
    return source.at;
}

// Runs `undo` when the scope ends.
struct Finally {
    std::function<void()> undo;
    ~Finally() { undo(); }
};

// The video packets the file at `fd` holds, read through FFmpeg's demuxer
// (no decoding: a file cut short, or with frames missing, shows here);
// its size in `width` and `height`. Throws with FFmpeg's reason.
int count_packets(const FFmpeg& f, int fd, int& width, int& height) {
    Source source{fd, 0};
    auto* buffer = static_cast<unsigned char*>(f.av_malloc(kIoBuffer));
    if (!buffer) throw std::bad_alloc();
    AVIOContext* io =
        f.avio_alloc_context(buffer, kIoBuffer, 0, &source, read_source, nullptr, seek_source);
    if (!io) {
        f.av_free(buffer);
        throw std::bad_alloc();
    }
    AVFormatContext* input = f.avformat_alloc_context();
    const Finally free_all{[&] {
        f.avformat_close_input(&input);  // (null after a failed open)
        f.av_free(io->buffer);
        f.avio_context_free(&io);
    }};
    if (!input) throw std::bad_alloc();
    input->pb = io;
    input->flags |= AVFMT_FLAG_CUSTOM_IO;
    int r = f.avformat_open_input(&input, nullptr, nullptr, nullptr);
    if (r < 0) throw std::runtime_error("it does not read back: " + f.error_text(r));
    if (input->nb_streams != 1 || input->streams[0]->codecpar->codec_type != AVMEDIA_TYPE_VIDEO)
        throw std::runtime_error("it reads back without its one video stream");
    width = input->streams[0]->codecpar->width;
    height = input->streams[0]->codecpar->height;
    AVPacket* packet = f.av_packet_alloc();
    if (!packet) throw std::bad_alloc();
    const Finally free_packet{[&] { f.av_packet_free(&packet); }};
    int packets = 0;
    while ((r = f.av_read_frame(input, packet)) >= 0) {
        packets += packet->stream_index == 0;
        f.av_packet_unref(packet);
    }
    if (r != AVERROR_EOF) throw std::runtime_error("it does not read back: " + f.error_text(r));
    return packets;
}

const FFmpeg& ffmpeg_for(const fs::path& path) {
    try {
        return ffmpeg();
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(path.string() + ": " + e.what());
    }
}

}  // namespace

const VideoKind& check_video_name(const fs::path& path) {
    const std::string extension = image::lower_case_extension(path);
    for (const VideoKind& kind : kKinds)
        if (extension == kind.extension) return kind;
    throw std::runtime_error(path.string() + ": a video is written as .mp4 (H.264) or .webm (VP9)");
}

void check_video_output(const fs::path& path, int width, int height) {
    const VideoKind& kind = check_video_name(path);
    // (libvpx codes odd sides in 4:2:0, the last chroma sample covering one
    // pixel; libx264 refuses them.)
    if (kind.encoder == std::string("libx264") && (width % 2 != 0 || height % 2 != 0))
        throw std::runtime_error(path.string() + ": H.264 in 4:2:0 needs an even width and " +
                                 "height; the frames are " + std::to_string(width) + " by " +
                                 std::to_string(height) +
                                 " (render at even sides, or write .webm)");
    const FFmpeg& f = ffmpeg_for(path);
    if (!f.avcodec_find_encoder_by_name(kind.encoder))
        throw std::runtime_error(path.string() + ": FFmpeg's libavcodec here has no " +
                                 kind.encoder + " encoder (" + kind.codec + "); Debian's has it");
}

struct VideoFile::Encoder {
    Encoder(const fs::path& p, const VideoKind& k, int w, int h)
        : f(ffmpeg_for(p)), path(p), kind(k), width(w), height(h), temporary(p) {
        sink.fd = temporary.descriptor();
    }
    ~Encoder() {
        f.sws_freeContext(scale);
        f.av_frame_free(&frame);
        f.av_packet_free(&packet);
        f.avcodec_free_context(&codec);
        f.avformat_free_context(format);  // (not the custom io)
        if (io) {
            f.av_free(io->buffer);
            f.avio_context_free(&io);
        }
    }

    // Throws naming the file: `what`, with FFmpeg's reason for `code` and
    // what it logged, or the disk's.
    [[noreturn]] void fail(const std::string& what, int code = 0) const {
        std::string why = sink.error;
        if (why.empty()) why = f.take_logged_error();
        if (why.empty() && code < 0) why = f.error_text(code);
        throw std::runtime_error(path.string() + ": " + what +
                                 (why.empty() ? "" : " (" + why + ")"));
    }
    void check(int code, const std::string& what) const {
        if (code < 0) fail(what, code);
    }

    void open(double fps);
    // Sends `next` (null: the end) and writes every packet the encoder
    // gives back.
    void send(const AVFrame* next);

    const FFmpeg& f;
    fs::path path;
    const VideoKind& kind;
    int width, height;
    TemporaryFile temporary;
    Sink sink;
    AVFormatContext* format = nullptr;
    AVIOContext* io = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    SwsContext* scale = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    std::vector<unsigned char> srgb;
    int added = 0;
};

void VideoFile::Encoder::open(double fps) {
    f.take_logged_error();  // (an earlier file's)
    const AVCodec* encoder = f.avcodec_find_encoder_by_name(kind.encoder);
    if (!encoder) fail(std::string("FFmpeg's libavcodec here has no ") + kind.encoder + " encoder");
    // The temporary's /proc/self/fd name: MP4's faststart reads the file
    // back by it to move the index to the front (web players start sooner).
    const std::string url = temporary.reopenable_name().string();
    check(f.avformat_alloc_output_context2(&format, nullptr, kind.container, url.c_str()),
          "cannot set up the container");
    stream = f.avformat_new_stream(format, nullptr);
    codec = f.avcodec_alloc_context3(encoder);
    if (!stream || !codec) throw std::bad_alloc();
    // Frame k at time k / fps: one tick of the time base a frame.
    const AVRational rate = f.av_d2q(fps, 100000);
    codec->width = width;
    codec->height = height;
    codec->pix_fmt = AV_PIX_FMT_YUV420P;
    codec->time_base = av_inv_q(rate);
    codec->framerate = rate;
    codec->color_primaries = AVCOL_PRI_BT709;
    codec->color_trc = AVCOL_TRC_IEC61966_2_1;
    codec->colorspace = AVCOL_SPC_BT709;
    codec->color_range = AVCOL_RANGE_MPEG;
    if (format->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    // The quality defaults (video_file.hpp says why).
    AVDictionary* options = nullptr;
    const Finally free_options{[&] { f.av_dict_free(&options); }};
    if (kind.encoder == std::string("libx264")) {
        f.av_dict_set(&options, "crf", "18", 0);
        f.av_dict_set(&options, "preset", "slow", 0);
        f.av_dict_set(&options, "x264-params", "aq-mode=3", 0);
    } else {
        codec->bit_rate = 0;  // (constant quality, no bitrate target)
        f.av_dict_set(&options, "crf", "24", 0);
        f.av_dict_set(&options, "deadline", "good", 0);
        f.av_dict_set(&options, "cpu-used", "2", 0);
        f.av_dict_set(&options, "row-mt", "1", 0);
    }
    check(f.avcodec_open2(codec, encoder, &options),
          std::string("the ") + kind.encoder + " encoder refuses the frames");
    check(f.avcodec_parameters_from_context(stream->codecpar, codec), "cannot set up the stream");
    stream->time_base = codec->time_base;
    stream->avg_frame_rate = rate;
    auto* buffer = static_cast<unsigned char*>(f.av_malloc(kIoBuffer));
    if (!buffer) throw std::bad_alloc();
    io = f.avio_alloc_context(buffer, kIoBuffer, 1, &sink, nullptr, write_sink, seek_sink);
    if (!io) {
        f.av_free(buffer);
        throw std::bad_alloc();
    }
    format->pb = io;
    format->flags |= AVFMT_FLAG_CUSTOM_IO;
    AVDictionary* muxer = nullptr;
    const Finally free_muxer{[&] { f.av_dict_free(&muxer); }};
    if (kind.container == std::string("mp4")) f.av_dict_set(&muxer, "movflags", "+faststart", 0);
    check(f.avformat_write_header(format, &muxer), "writing failed");
    // sRGB bytes (full range) to BT.709 Y'CbCr in limited range; chroma
    // filtered from every pixel (FULL_CHR_H_INP), rounded exactly.
    scale = f.sws_getContext(width, height, AV_PIX_FMT_RGB24, width, height, AV_PIX_FMT_YUV420P,
                             SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr, nullptr,
                             nullptr);
    if (!scale) fail("libswscale cannot convert the frames");
    const int* bt709 = f.sws_getCoefficients(SWS_CS_ITU709);
    if (f.sws_setColorspaceDetails(scale, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16) < 0)
        fail("libswscale cannot convert to BT.709");
    frame = f.av_frame_alloc();
    packet = f.av_packet_alloc();
    if (!frame || !packet) throw std::bad_alloc();
    frame->format = AV_PIX_FMT_YUV420P;
    frame->width = width;
    frame->height = height;
    frame->color_primaries = codec->color_primaries;
    frame->color_trc = codec->color_trc;
    frame->colorspace = codec->colorspace;
    frame->color_range = codec->color_range;
    check(f.av_frame_get_buffer(frame, 0), "cannot hold a frame");
}

void VideoFile::Encoder::send(const AVFrame* next) {
    check(f.avcodec_send_frame(codec, next),
          std::string("the ") + kind.encoder + " encoder failed");
    for (;;) {
        const int r = f.avcodec_receive_packet(codec, packet);
        if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
        check(r, std::string("the ") + kind.encoder + " encoder failed");
        // Each frame lasts one tick: the last one too, so the file lasts
        // frames / fps (a cyclic animation loops without a pause).
        packet->duration = 1;
        f.av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
        packet->stream_index = stream->index;
        check(f.av_interleaved_write_frame(format, packet), "writing failed");
    }
}

VideoFile::VideoFile(const fs::path& path, int width, int height, double fps) {
    check_video_output(path, width, height);
    if (!(fps > 0.0) || !std::isfinite(fps))
        throw std::runtime_error(path.string() + ": the frame rate must be a number above 0");
    encoder_ = std::make_unique<Encoder>(path, check_video_name(path), width, height);
    encoder_->open(fps);
}

VideoFile::~VideoFile() = default;

int VideoFile::frames() const {
    return encoder_->added;
}

void VideoFile::add(const Image& image) {
    Encoder& e = *encoder_;
    if (image.width != e.width || image.height != e.height)
        throw std::runtime_error(e.path.string() + ": a frame of " + std::to_string(image.width) +
                                 " by " + std::to_string(image.height) + " pixels, not " +
                                 std::to_string(e.width) + " by " + std::to_string(e.height));
    // The bytes a PNG frame holds (write_image's).
    e.srgb.resize(image.rgb.size());
    for (std::size_t i = 0; i < e.srgb.size(); ++i) e.srgb[i] = to_srgb8(image.rgb[i]);
    e.check(e.f.av_frame_make_writable(e.frame), "cannot hold a frame");
    const std::uint8_t* planes[1] = {e.srgb.data()};
    const int strides[1] = {3 * e.width};
    e.f.sws_scale(e.scale, planes, strides, 0, e.height, e.frame->data, e.frame->linesize);
    e.frame->pts = e.added;
    e.send(e.frame);
    ++e.added;
}

void VideoFile::finish() {
    Encoder& e = *encoder_;
    e.send(nullptr);
    e.check(e.f.av_write_trailer(e.format), "writing failed");
    e.f.avio_flush(e.io);
    if (!e.sink.error.empty() || e.io->error < 0) e.fail("writing failed", e.io->error);
    int width = 0, height = 0, frames = 0;
    try {
        frames = count_packets(e.f, e.temporary.descriptor(), width, height);
    } catch (const std::runtime_error& error) {
        e.fail(error.what());
    }
    if (width != e.width || height != e.height) e.fail("it reads back with the wrong size");
    if (frames != e.added)
        e.fail("it reads back with " + std::to_string(frames) + " frames, not " +
               std::to_string(e.added));
    e.temporary.commit();
}

}  // namespace hexant::tracer
