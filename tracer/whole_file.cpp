#include "tracer/whole_file.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace hexant::tracer {

namespace fs = std::filesystem;

fs::path temporary_beside(const fs::path& path) {
    if (path.has_parent_path()) fs::create_directories(path.parent_path());
    return path.parent_path() / ("." + path.filename().string() + ".partial");
}

void replace_with(const fs::path& temporary, const fs::path& path) {
    std::error_code error;
    fs::rename(temporary, path, error);
    if (error) {
        fs::remove(temporary);
        throw std::runtime_error(path.string() + ": cannot rename the finished file: " +
                                 error.message());
    }
}

void write_text_file(const fs::path& path, const std::string& text) {
    const fs::path temporary = temporary_beside(path);
    {
        std::ofstream file(temporary, std::ios::binary);
        file << text;
        file.flush();
        if (!file) {
            file.close();
            fs::remove(temporary);
            throw std::runtime_error(path.string() + ": cannot write");
        }
    }
    replace_with(temporary, path);
}

}  // namespace hexant::tracer
