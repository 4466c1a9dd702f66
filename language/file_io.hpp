// POV-Ray's file directives, #fopen, #read, #write and #fclose: the files a
// scene opens while it is read (never while it renders: hexant reads a
// scene once for the whole animation, so a file is written once).
//
// Confinement (issue 42): a file read is found and confined as #include's
// are (Interpreter::resolve_include), with the output folder searched too;
// a file written or appended to lies in the scene's output folder
// (ParseOptions::output_folder: the folder of the render's images) or a
// folder given with --allow-write, with `..` and symbolic links resolved
// before the check, and never a system file. Formats as POV-Ray 3.7's
// (parser_tokenizer.cpp, Parse_Write and Parse_Read_Value): strings are
// written as they are, floats with %g, vectors as "<%g,%g,%g> "; the
// binary words (uint8, sint16be, ...) write each component rounded and
// clamped to the type; #read takes floats, vectors of 2 to 5 components
// and string literals, separated by optional commas.
#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "language/value.hpp"

namespace hexant::language {

// Where a scene may write: `name` resolved against `output_folder` (when
// relative), checked to lie in it or in one of `also`. Throws ValueError
// naming what is wrong (the folders, never the file's contents).
std::filesystem::path writable_path(const std::string& name,
                                    const std::filesystem::path& output_folder,
                                    const std::vector<std::filesystem::path>& also);

// A value as #write writes it; ValueError for a value that changes with
// clock (hexant writes once for the whole animation) or of another type.
std::string written_text(const Value& value);
// The bytes of a binary #write word ("uint8", "sint16be", ...) for a
// float or vector value.
std::string written_bytes(const std::string& word, const Value& value);

class UserFiles {
  public:
    // #fopen NAME for reading, with the file's whole text.
    void open_read(const std::string& name, const std::filesystem::path& path, std::string text);
    // #fopen NAME for writing (append: at its end). ValueError if it cannot be made.
    void open_write(const std::string& name, const std::filesystem::path& path, bool append);
    void write(const std::string& name, const std::string& text);
    // The next item of a file open for reading, or nothing at its end.
    // ValueError for text that is not a float, vector or string.
    std::optional<Value> read(const std::string& name);
    void close(const std::string& name);
    bool is_open(const std::string& name) const { return files_.count(name) > 0; }

  private:
    struct File {
        std::filesystem::path path;
        bool reading = false;
        std::string text;
        std::size_t at = 0;
        struct CloseFile {
            void operator()(std::FILE* file) const;
        };
        std::unique_ptr<std::FILE, CloseFile> out;
    };
    File& find(const std::string& name);
    std::map<std::string, File> files_;
};

}  // namespace hexant::language
