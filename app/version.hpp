// What `hexant --version` prints: the project's version from CMake and,
// when built from a git tree, the commit. Only version.cpp sees the
// generated commit header, so a new commit recompiles one file.
#pragma once

#include <string>

namespace hexant::app {

// "hexant 0.1.0 (git 70a4804)", or "hexant 0.1.0" outside a git tree.
std::string version_text();

// The project's version alone, "0.1.0" (what a frame's record keeps:
// app/frame_record.hpp).
std::string version_number();

}  // namespace hexant::app
