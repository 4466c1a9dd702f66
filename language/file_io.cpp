#include "language/file_io.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "language/source_files.hpp"
#include "language/value_ops.hpp"

namespace hexant::language {

namespace fs = std::filesystem;

namespace {

// The path with `..` and every symbolic link of its existing part
// resolved (the file itself too, when it exists: a link there points
// elsewhere).
fs::path real_path(const fs::path& path) {
    std::error_code error;
    const fs::path real = fs::weakly_canonical(fs::absolute(path, error), error);
    if (error) throw ValueError("its folder cannot be reached: " + error.message());
    return real;
}

std::string format_g(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

double constant_of(const TimeFunction& f) {
    if (!f.is_constant())
        throw ValueError(
            "#write of a value that changes with clock: hexant reads a scene once for the "
            "whole animation and writes its files once (write a value of the frame's own, or "
            "render the frames one by one with --clock)");
    return f.constant();
}

}  // namespace

fs::path writable_path(const std::string& name, const fs::path& output_folder,
                       const std::vector<fs::path>& also) {
    if (name.empty()) throw ValueError("a file needs a name");
    const fs::path given(name);
    const fs::path file = real_path(given.is_absolute() ? given : output_folder / given);
    if (is_system_path(file)) throw ValueError("it is a system file: refused");
    std::vector<fs::path> allowed{output_folder};
    allowed.insert(allowed.end(), also.begin(), also.end());
    for (const auto& folder : allowed)
        if (lies_in(file, real_path(folder.empty() ? fs::path(".") : folder))) return file;
    std::string folders;
    for (const auto& folder : allowed) folders += (folders.empty() ? "" : ", ") + folder.string();
    throw ValueError("it is outside the folders a scene may write to (" + folders +
                     "; --allow-write DIR adds one)");
}

std::string written_text(const Value& value) {
    if (value.is<std::string>()) return value.as<std::string>();
    if (value.is<TimeFunction>()) return format_g(constant_of(value.as<TimeFunction>()));
    if (value.is<Vector>()) {
        const Vector& v = value.as<Vector>();
        std::string text = "<";
        for (int i = 0; i < v.size; ++i)
            text += (i ? "," : "") + format_g(constant_of(v.c[static_cast<std::size_t>(i)]));
        return text + "> ";
    }
    throw ValueError("#write writes strings, floats and vectors, not a " + type_name(value));
}

std::string written_bytes(const std::string& word, const Value& value) {
    const bool is_signed = word[0] == 's';
    const int bytes = word.find("32") != std::string::npos   ? 4
                      : word.find("16") != std::string::npos ? 2
                                                             : 1;
    const bool big_endian = word.size() > 2 && word.substr(word.size() - 2) == "be";
    const double lo = is_signed ? -std::ldexp(1.0, 8 * bytes - 1) : 0.0;
    const double hi =
        is_signed ? std::ldexp(1.0, 8 * bytes - 1) - 1 : std::ldexp(1.0, 8 * bytes) - 1;
    std::vector<double> values;
    if (value.is<TimeFunction>()) {
        values.push_back(constant_of(value.as<TimeFunction>()));
    } else if (value.is<Vector>()) {
        const Vector& v = value.as<Vector>();
        for (int i = 0; i < v.size; ++i)
            values.push_back(constant_of(v.c[static_cast<std::size_t>(i)]));
    } else {
        throw ValueError("#write " + word + " takes a float or a vector, not a " +
                         type_name(value));
    }
    std::string out;
    for (double x : values) {
        // POV-Ray clamps to the type and rounds half up; NaN is an error.
        if (std::isnan(x)) throw ValueError("#write " + word + " of NaN");
        const double clamped = x <= lo ? lo : x >= hi ? hi : std::floor(x + 0.5);
        const auto bits = static_cast<long long>(clamped);
        for (int j = 0; j < bytes; ++j) {
            const int shift = (big_endian ? bytes - 1 - j : j) * 8;
            out.push_back(static_cast<char>((bits >> shift) & 0xFF));
        }
    }
    return out;
}

UserFiles::File& UserFiles::find(const std::string& name) {
    const auto it = files_.find(name);
    if (it == files_.end())
        throw ValueError("'" + name + "' is not an open file (#fopen it first)");
    return it->second;
}

void UserFiles::open_read(const std::string& name, const fs::path& path, std::string text) {
    File f;
    f.path = path;
    f.reading = true;
    f.text = std::move(text);
    files_[name] = std::move(f);
}

void UserFiles::open_write(const std::string& name, const fs::path& path, bool append) {
    File f;
    f.path = path;
    std::error_code error;
    fs::create_directories(path.parent_path(), error);
    // The path was resolved with its links (writable_path); opened without
    // following one put at its name since, and refused unless it is a
    // regular file (a FIFO would block, a device be written into; issue
    // 45). O_NONBLOCK only for the open: a FIFO without a reader fails
    // at once instead of waiting for one.
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        throw ValueError(
            "it is not a regular file (a FIFO, a device, a link or a folder): "
            "refused");
    const int fd =
        ::open(path.c_str(), O_WRONLY | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0666);
    if (fd < 0)
        throw ValueError(std::string("it cannot be opened for writing: ") + std::strerror(errno));
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw ValueError("it is not a regular file: refused");
    }
    if ((append ? ::lseek(fd, 0, SEEK_END) < 0 : ::ftruncate(fd, 0) != 0) ||
        ::fcntl(fd, F_SETFL, append ? O_APPEND : 0) != 0) {
        const int reason = errno;
        ::close(fd);
        throw ValueError(std::string("it cannot be opened for writing: ") + std::strerror(reason));
    }
    f.out.reset(::fdopen(fd, append ? "ab" : "wb"));
    if (!f.out) {
        ::close(fd);
        throw ValueError("it cannot be opened for writing");
    }
    files_[name] = std::move(f);
}

void UserFiles::write(const std::string& name, const std::string& text) {
    File& f = find(name);
    if (f.reading) throw ValueError("'" + name + "' is open for reading, not writing");
    if (std::fwrite(text.data(), 1, text.size(), f.out.get()) != text.size() ||
        std::ferror(f.out.get()))
        throw ValueError("writing to '" + f.path.string() + "' failed: " + std::strerror(errno));
}

std::optional<Value> UserFiles::read(const std::string& name) {
    File& f = find(name);
    if (!f.reading) throw ValueError("'" + name + "' is open for writing, not reading");
    const std::string& s = f.text;
    std::size_t& i = f.at;
    const auto skip = [&] {
        // Blanks, commas between items, and comments.
        while (i < s.size()) {
            if (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == ',') {
                ++i;
            } else if (s.compare(i, 2, "//") == 0) {
                while (i < s.size() && s[i] != '\n') ++i;
            } else if (s.compare(i, 2, "/*") == 0) {
                const std::size_t end = s.find("*/", i + 2);
                i = end == std::string::npos ? s.size() : end + 2;
            } else {
                break;
            }
        }
    };
    const auto number = [&]() -> double {
        skip();
        const char* begin = s.c_str() + i;
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        if (end == begin || !std::isfinite(v))
            throw ValueError("#read of '" + f.path.filename().string() +
                             "': expected a float, vector or string at byte " + std::to_string(i));
        i += static_cast<std::size_t>(end - begin);
        return v;
    };
    skip();
    if (i >= s.size()) return std::nullopt;
    if (s[i] == '"') {
        std::string text;
        for (++i; i < s.size() && s[i] != '"'; ++i) {
            if (s[i] == '\\' && i + 1 < s.size()) {
                ++i;
                text.push_back(s[i] == 'n' ? '\n' : s[i] == 't' ? '\t' : s[i]);
            } else {
                text.push_back(s[i]);
            }
        }
        if (i >= s.size())
            throw ValueError("#read of '" + f.path.filename().string() + "': a string not closed");
        ++i;
        return Value{text};
    }
    if (s[i] == '<') {
        ++i;
        Vector v;
        v.size = 0;
        for (;;) {
            skip();
            if (i < s.size() && s[i] == '>') break;
            if (v.size == 5)
                throw ValueError("#read of '" + f.path.filename().string() +
                                 "': a vector of more than 5 components");
            v.c[static_cast<std::size_t>(v.size++)] = number();
        }
        ++i;
        if (v.size < 2)
            throw ValueError("#read of '" + f.path.filename().string() +
                             "': a vector needs 2 components or more");
        return Value{v};
    }
    return Value{TimeFunction(number())};
}

void UserFiles::close(const std::string& name) {
    const auto it = files_.find(name);
    if (it == files_.end()) return;
    // (A full disk shows in the last buffer's flush, here.)
    std::FILE* out = it->second.out.release();
    const fs::path path = it->second.path;
    files_.erase(it);
    if (out && std::fclose(out) != 0)
        throw ValueError("writing to '" + path.string() + "' failed: " + std::strerror(errno));
}

void UserFiles::File::CloseFile::operator()(std::FILE* file) const {
    if (file) std::fclose(file);
}

}  // namespace hexant::language
