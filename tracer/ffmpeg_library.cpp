#include "tracer/ffmpeg_library.hpp"

#include <cstdarg>
#include <mutex>
#include <stdexcept>

#include <dlfcn.h>

namespace hexant::tracer {

namespace {

#define HEXANT_STRING(x) #x
#define HEXANT_SONAME(library, major) "lib" library ".so." HEXANT_STRING(major)

std::mutex log_mutex;
std::string logged_error;                                // (guarded by log_mutex)
decltype(&::av_log_format_line2) format_line = nullptr;  // (set before the callback)

// FFmpeg's log, kept: errors remembered for the message hexant throws,
// the rest (x264's statistics, warnings) dropped.
void keep_errors(void* context, int level, const char* format, va_list arguments) {
    if (level > AV_LOG_ERROR) return;
    char line[512];
    int prefix = 1;
    // (Its component by name, not "[libx264 @ 0x55d0...]".)
    format_line(nullptr, level, format, arguments, line, sizeof line, &prefix);
    const AVClass* component = context ? *static_cast<const AVClass* const*>(context) : nullptr;
    std::string text = component && component->item_name
                           ? std::string(component->item_name(context)) + ": " + line
                           : std::string(line);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    const std::lock_guard lock(log_mutex);
    logged_error = text;
}

// dlopen's handle of one library, with its package's name for the message.
void* open_library(const char* soname, const char* package) {
    void* handle = ::dlopen(soname, RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* why = ::dlerror();
        throw std::runtime_error(std::string("cannot load FFmpeg's ") + soname +
                                 " (Debian's package " + package + "): " + (why ? why : "?"));
    }
    return handle;
}

template <typename Function>
void look_up(void* handle, const char* soname, const char* name, Function& function) {
    function = reinterpret_cast<Function>(::dlsym(handle, name));
    if (!function)
        throw std::runtime_error(std::string("FFmpeg's ") + soname + " has no function " + name +
                                 " (another version than hexant was built with?)");
}

FFmpeg load() {
    FFmpeg f;
    // (avutil first: the others need it. A handle is never closed: FFmpeg
    // keeps threads and tables for the process's life.)
    const char* avutil = HEXANT_SONAME("avutil", LIBAVUTIL_VERSION_MAJOR);
    const char* swscale = HEXANT_SONAME("swscale", LIBSWSCALE_VERSION_MAJOR);
    const char* avcodec = HEXANT_SONAME("avcodec", LIBAVCODEC_VERSION_MAJOR);
    const char* avformat = HEXANT_SONAME("avformat", LIBAVFORMAT_VERSION_MAJOR);
    void* h = open_library(avutil, "libavutil" HEXANT_STRING(LIBAVUTIL_VERSION_MAJOR));
#define HEXANT_LOOK_UP(name) look_up(h, soname, #name, f.name);
    const char* soname = avutil;
    HEXANT_AVUTIL_FUNCTIONS(HEXANT_LOOK_UP)
    h = open_library(swscale, "libswscale" HEXANT_STRING(LIBSWSCALE_VERSION_MAJOR));
    soname = swscale;
    HEXANT_SWSCALE_FUNCTIONS(HEXANT_LOOK_UP)
    h = open_library(avcodec, "libavcodec" HEXANT_STRING(LIBAVCODEC_VERSION_MAJOR));
    soname = avcodec;
    HEXANT_AVCODEC_FUNCTIONS(HEXANT_LOOK_UP)
    h = open_library(avformat, "libavformat" HEXANT_STRING(LIBAVFORMAT_VERSION_MAJOR));
    soname = avformat;
    HEXANT_AVFORMAT_FUNCTIONS(HEXANT_LOOK_UP)
#undef HEXANT_LOOK_UP
    return f;
}

}  // namespace

std::string FFmpeg::error_text(int code) const {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    if (av_strerror(code, text, sizeof text) < 0) return "FFmpeg error " + std::to_string(code);
    return text;
}

std::string FFmpeg::take_logged_error() const {
    const std::lock_guard lock(log_mutex);
    std::string text;
    text.swap(logged_error);
    return text;
}

const FFmpeg& ffmpeg() {
    static std::mutex mutex;
    static FFmpeg loaded;
    static bool done = false;
    const std::lock_guard lock(mutex);
    if (!done) {
        loaded = load();
        done = true;
        format_line = loaded.av_log_format_line2;
        loaded.av_log_set_callback(keep_errors);
    }
    return loaded;
}

}  // namespace hexant::tracer
