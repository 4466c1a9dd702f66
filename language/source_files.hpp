// The files a scene reads as source (the scene, its includes): where
// POV-Ray's own include files and fonts are on Debian, and the checked
// reading of one file (language/interpreter_symbols.cpp).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace hexant::language {

// POV-Ray's own include folder (Debian's povray-includes), readable too.
extern const char* const kPovRayIncludeDir;
// Debian's fonts-povray: POV-Ray's fonts (timrom.ttf, cyrvetic.ttf, ...),
// which its include folder links to.
extern const char* const kPovRayFontDir;

// The text of a scene or include file, checked before it is read: a
// regular file (`hexant check /dev/zero` read until memory ran out), of at
// most max_bytes (what is left of Limits::text_read). Throws ValueError
// saying what is wrong with it.
std::string read_source_text(const std::filesystem::path& path, std::size_t max_bytes);

// Is `file` inside `folder` (both absolute, with `..` and symbolic links
// resolved)? The confinement of every file a scene reads or writes.
bool lies_in(const std::filesystem::path& file, const std::filesystem::path& folder);
// Is `file` (resolved) under /proc, /sys or /dev, which a scene never
// reads or writes?
bool is_system_path(const std::filesystem::path& file);

}  // namespace hexant::language
