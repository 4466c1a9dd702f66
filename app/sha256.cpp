#include "app/sha256.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hexant::app {

Sha256::Sha256() {
    sha256_init(&context_);
}

void Sha256::add(const void* data, std::size_t bytes) {
    sha256_update(&context_, bytes, static_cast<const std::uint8_t*>(data));
}

std::string Sha256::hex() {
    std::uint8_t digest[SHA256_DIGEST_SIZE];
    sha256_digest(&context_, sizeof digest, digest);
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string text;
    for (const std::uint8_t byte : digest) {
        text += kDigits[byte >> 4];
        text += kDigits[byte & 15];
    }
    return text;
}

FileHash hash_file(const std::filesystem::path& path) {
    // (Without waiting for a writer, and only a regular file: a FIFO at a
    // frame's name would block the resume for good, issue 45.)
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        throw std::runtime_error(path.string() + ": cannot read it: " + std::strerror(errno));
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw std::runtime_error(path.string() + ": cannot read it: not a regular file");
    }
    Sha256 sha;
    FileHash hash;
    std::vector<unsigned char> chunk(1 << 20);
    for (;;) {
        const ssize_t got = ::read(fd, chunk.data(), chunk.size());
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) {
            const int error = errno;
            ::close(fd);
            throw std::runtime_error(path.string() + ": cannot read it: " + std::strerror(error));
        }
        if (got == 0) break;
        sha.add(chunk.data(), std::size_t(got));
        hash.bytes += std::uintmax_t(got);
    }
    ::close(fd);
    hash.sha256 = sha.hex();
    return hash;
}

}  // namespace hexant::app
