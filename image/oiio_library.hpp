// hexant's OpenImageIO module (image/oiio/oiio_module.h), loaded with dlopen
// the first time a file needs it, never at start-up: linked into hexant,
// OpenImageIO and its plugins' libraries cost every process ~0.35 s and
// ~120 MB before main (docs/benchmarks.md, "Start-up and the OpenImageIO
// module"). As tracer/ffmpeg_library.hpp loads FFmpeg.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/oiio/oiio_module.h"

namespace hexant::image {

// The module's file name, and the folders it is looked for in, in order:
// the executable's own (a build folder), then the installed place
// (${CMAKE_INSTALL_LIBDIR}/hexant/, relative to the executable's folder as
// installed), then the build folder hexant was built in (for the tests'
// executables, which live in a folder of their own).
inline constexpr const char* kOiioModuleName = "libhexant_oiio.so";
std::vector<std::filesystem::path> oiio_module_folders();

// The module's table, loaded once per process (thread-safe). Throws
// std::runtime_error saying what is missing (the module, by the folders
// looked in; or OpenImageIO's library, Debian's package libopenimageio2.4)
// and what `needed_for` needs it ("reading x.tga (Targa)"); the next call
// tries again.
const HexantOiioApi& oiio_module(const std::string& needed_for);

// Whether the module was loaded in this process (for tests and benchmarks).
bool oiio_module_loaded();

}  // namespace hexant::image
