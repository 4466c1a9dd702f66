// FFmpeg's libraries (libavformat, libavcodec, libswscale, libavutil), loaded
// with dlopen the first time a video is written, never at start-up: linked
// into hexant, Debian's libavcodec brings about 160 shared libraries (every
// codec's) that each run would load before main, for a flag few runs use
// (start-up is kept fast: see image/image_format.hpp on OpenImageIO). The
// headers give each function's type; the sonames are the headers' major
// versions, so hexant loads the libraries it was built against.
#pragma once

#include <string>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
#include <libavutil/error.h>
#include <libavutil/frame.h>
#include <libavutil/log.h>
#include <libavutil/mem.h>
#include <libavutil/rational.h>
#include <libswscale/swscale.h>
}

namespace hexant::tracer {

// The functions hexant calls, by library (an X-macro: F(name) each).
// clang-format off
#define HEXANT_AVUTIL_FUNCTIONS(F) \
    F(av_frame_alloc)              \
    F(av_frame_free)               \
    F(av_frame_get_buffer)         \
    F(av_frame_make_writable)      \
    F(av_malloc)                   \
    F(av_free)                     \
    F(av_strerror)                 \
    F(av_dict_set)                 \
    F(av_dict_free)                \
    F(av_d2q)                      \
    F(av_log_set_callback)         \
    F(av_log_format_line2)
#define HEXANT_SWSCALE_FUNCTIONS(F) \
    F(sws_getContext)               \
    F(sws_setColorspaceDetails)     \
    F(sws_getCoefficients)          \
    F(sws_scale)                    \
    F(sws_freeContext)
#define HEXANT_AVCODEC_FUNCTIONS(F)    \
    F(avcodec_find_encoder_by_name)    \
    F(avcodec_alloc_context3)          \
    F(avcodec_open2)                   \
    F(avcodec_free_context)            \
    F(avcodec_parameters_from_context) \
    F(avcodec_send_frame)              \
    F(avcodec_receive_packet)          \
    F(av_packet_alloc)                 \
    F(av_packet_free)                  \
    F(av_packet_unref)                 \
    F(av_packet_rescale_ts)
#define HEXANT_AVFORMAT_FUNCTIONS(F)  \
    F(avformat_alloc_output_context2) \
    F(avformat_free_context)          \
    F(avformat_new_stream)            \
    F(avformat_write_header)          \
    F(av_interleaved_write_frame)     \
    F(av_write_trailer)               \
    F(avio_alloc_context)             \
    F(avio_context_free)              \
    F(avio_flush)                     \
    F(avformat_alloc_context)         \
    F(avformat_open_input)            \
    F(avformat_find_stream_info)      \
    F(avformat_close_input)           \
    F(av_read_frame)
// clang-format on

struct FFmpeg {
#define HEXANT_FFMPEG_MEMBER(name) decltype(&::name) name = nullptr;
    HEXANT_AVUTIL_FUNCTIONS(HEXANT_FFMPEG_MEMBER)
    HEXANT_SWSCALE_FUNCTIONS(HEXANT_FFMPEG_MEMBER)
    HEXANT_AVCODEC_FUNCTIONS(HEXANT_FFMPEG_MEMBER)
    HEXANT_AVFORMAT_FUNCTIONS(HEXANT_FFMPEG_MEMBER)
#undef HEXANT_FFMPEG_MEMBER

    // FFmpeg's text for an error code ("Invalid argument").
    std::string error_text(int code) const;
    // The last error FFmpeg logged (its own log is kept off the terminal:
    // the messages hexant throws carry it), then forgotten; empty if none.
    std::string take_logged_error() const;
};

// The libraries, loaded once per process (thread-safe); std::runtime_error
// naming the library and the Debian package to install when one does not
// load or lacks a function (then the next call tries again).
const FFmpeg& ffmpeg();

}  // namespace hexant::tracer
