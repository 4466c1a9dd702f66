// SHA-256 (FIPS 180-4) of bytes and of files, by GNU Nettle (nettle-dev):
// the content hash a frame's record keeps of the frame and of every file
// its scene read (app/frame_record.hpp). In hex it is what `sha256sum FILE`
// prints, so a user can check a record by hand.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include <nettle/sha2.h>

namespace hexant::app {

class Sha256 {
  public:
    Sha256();
    void add(const void* data, std::size_t bytes);
    void add(std::string_view text) { add(text.data(), text.size()); }
    // The digest in lower-case hex (64 characters); the object is spent.
    std::string hex();

  private:
    sha256_ctx context_;
};

// A file's size in bytes and its SHA-256 in hex. std::runtime_error naming
// the file and the system's reason when it cannot be read.
struct FileHash {
    std::uintmax_t bytes = 0;
    std::string sha256;
};
FileHash hash_file(const std::filesystem::path& path);

}  // namespace hexant::app
