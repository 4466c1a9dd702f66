// A video of the frames: .mp4 (H.264, libx264) or .webm (VP9, libvpx-vp9),
// through FFmpeg's libraries (tracer/ffmpeg_library.hpp), frames streamed
// in one at a time as they finish, in order. Written like every file hexant
// writes (tracer/whole_file.hpp): into a temporary beside its place, read
// back and renamed only when complete.
//
// The defaults, chosen so that motion blur's smooth gradients do not band
// and any player plays the file (README, "render"): 8-bit 4:2:0 (yuv420p),
// the only layout every browser, phone and hardware decoder plays;
// H.264 at CRF 18 (x264's "visually lossless"; its default 23 flattens the
// faint gradients of a blur's tail into steps), preset slow, and
// aq-mode 3 (more bits to flat and dark areas, where banding shows first);
// VP9 at CRF 24 with no bitrate cap (constant quality), deadline good,
// cpu-used 2. sRGB bytes become Y'CbCr by BT.709's matrix in limited range
// (16-235), through libswscale, and the stream says so: BT.709 primaries
// and matrix, limited range, sRGB's transfer (IEC 61966-2-1: the bytes
// are sRGB's, which a player that ignores the tag shows as BT.709's, nearly
// the same).
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "tracer/image.hpp"

namespace hexant::tracer {

// What a name's extension asks for: its codec's FFmpeg encoder and
// container. std::runtime_error naming the file for another extension.
struct VideoKind {
    const char* extension;  // ".mp4"
    const char* encoder;    // "libx264"
    const char* container;  // "mp4"
    const char* codec;      // "H.264", for messages
};
const VideoKind& check_video_name(const std::filesystem::path& path);

// check_video_name, and that frames of width x height can be written: even
// sides for H.264's 4:2:0 (libx264 refuses odd ones; hexant does not pad
// the render), FFmpeg's libraries loaded and the encoder among theirs.
// std::runtime_error naming the file and what to do otherwise.
void check_video_output(const std::filesystem::path& path, int width, int height);

class VideoFile {
  public:
    // Opens the encoder and the temporary file for `path` (the first bytes
    // are written now); `fps` frames per second, above 0. Throws
    // std::runtime_error naming the file (check_video_output's reasons, or
    // the encoder's or the disk's).
    VideoFile(const std::filesystem::path& path, int width, int height, double fps);
    // Without finish(): the temporary is removed, nothing under `path`.
    ~VideoFile();
    VideoFile(const VideoFile&) = delete;
    VideoFile& operator=(const VideoFile&) = delete;

    // The next frame (linear RGB, written as the 8-bit sRGB of a PNG
    // frame); std::runtime_error naming the file for another size or a
    // failed write.
    void add(const Image& frame);
    // The frames added so far.
    int frames() const;
    // Flushes the encoder, finishes the container, reads the file back (its
    // frames counted) and renames it into place; std::runtime_error naming
    // the file (nothing left under its name).
    void finish();

  private:
    struct Encoder;
    std::unique_ptr<Encoder> encoder_;
};

}  // namespace hexant::tracer
