// The fuzzers whose readers open a path (FreeType, the image readers):
// each input is written to one file of the process's own, anew each time.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

namespace hexant::fuzz {

// /tmp/hexant_NAME_PID.EXTENSION, the same for the whole run.
inline std::filesystem::path input_file_path(const std::string& name,
                                             const std::string& extension) {
    return std::filesystem::temp_directory_path() /
           ("hexant_" + name + "_" + std::to_string(getpid()) + extension);
}

// False when the file could not be written whole.
inline bool write_input_file(const std::filesystem::path& path, const std::uint8_t* data,
                             std::size_t size) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(data, 1, size, f) == size;
    return std::fclose(f) == 0 && ok;
}

}  // namespace hexant::fuzz
