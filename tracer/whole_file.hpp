// Files written whole or not at all: each goes under a temporary name beside
// its place and is renamed over it once complete, so an interrupted or
// failing run never leaves a half-written file under the real name (frames,
// statistics, benchmark tables and plots alike).
#pragma once

#include <filesystem>
#include <string>

namespace hexant::tracer {

// The temporary name beside `path` (".NAME.partial"); creates the folder.
std::filesystem::path temporary_beside(const std::filesystem::path& path);

// Renames the finished temporary over `path`; removes it and throws
// std::runtime_error naming `path` when that fails.
void replace_with(const std::filesystem::path& temporary, const std::filesystem::path& path);

// Writes `text` to `path` whole; throws std::runtime_error naming the file.
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace hexant::tracer
