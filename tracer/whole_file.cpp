#include "tracer/whole_file.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hexant::tracer {

namespace fs = std::filesystem;

namespace {

// The temporaries being written, for the signal handler: fixed slots of
// fixed-size names (a handler may not allocate), claimed and released with
// atomics. More temporaries at once than slots (frames are written one at
// a time per thread) are still removed on failure, only not on a signal.
constexpr int kSlots = 64;
constexpr std::size_t kNameBytes = 4096;
struct Slot {
    std::atomic<int> state{0};  // 0 free, 1 being filled, 2 registered
    char name[kNameBytes];
    // The file made there: what is at the name is removed only while it is
    // still that file (someone else's in its place is left to them).
    dev_t device = 0;
    ino_t inode = 0;
};
Slot g_slots[kSlots];

int register_temporary(const char* name, int fd) {
    const std::size_t bytes = std::strlen(name) + 1;
    struct stat st {};
    if (bytes > kNameBytes || ::fstat(fd, &st) != 0) return -1;
    for (int i = 0; i < kSlots; ++i) {
        int expected = 0;
        if (!g_slots[i].state.compare_exchange_strong(expected, 1)) continue;
        std::memcpy(g_slots[i].name, name, bytes);
        g_slots[i].device = st.st_dev;
        g_slots[i].inode = st.st_ino;
        g_slots[i].state.store(2, std::memory_order_release);
        return i;
    }
    return -1;
}

void release(int slot) {
    if (slot >= 0) g_slots[slot].state.store(0, std::memory_order_release);
}

// fsync on a descriptor; errno's reason on failure (a file system that
// cannot sync, EINVAL or EROFS, is no failure).
std::string sync_descriptor(int fd) {
    if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) return std::strerror(errno);
    return {};
}

// fsync on a folder; errno's reason on failure.
std::string sync_folder(const fs::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return std::strerror(errno);
    std::string reason = sync_descriptor(fd);
    if (::close(fd) != 0 && reason.empty()) reason = std::strerror(errno);
    return reason;
}

extern "C" void on_fatal_signal(int signal) {
    remove_registered_temporaries();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

}  // namespace

void remove_registered_temporaries() {
    // (lstat and unlink are async-signal-safe.)
    for (Slot& slot : g_slots) {
        if (slot.state.load(std::memory_order_acquire) != 2) continue;
        struct stat st {};
        if (::lstat(slot.name, &st) == 0 && st.st_dev == slot.device && st.st_ino == slot.inode)
            ::unlink(slot.name);
    }
}

void install_cleanup_on_signals() {
    static std::atomic<bool> installed{false};
    if (installed.exchange(true)) return;
    for (const int s : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction action {};
        action.sa_handler = on_fatal_signal;
        sigemptyset(&action.sa_mask);
        ::sigaction(s, &action, nullptr);
    }
    // Past a file size limit a write fails (EFBIG, reported with the file)
    // instead of killing the process.
    std::signal(SIGXFSZ, SIG_IGN);
}

TemporaryFile::TemporaryFile(const fs::path& path) : path_(path) {
    if (path.has_parent_path()) {
        std::error_code error;
        fs::create_directories(path.parent_path(), error);
        if (error)
            throw std::runtime_error(path.string() + ": cannot make its folder " +
                                     path.parent_path().string() + ": " + error.message());
    }
    // The process's number keeps two runs writing the same file apart (each
    // renames its own whole file); the name is cut so that the temporary
    // stays within a file name's 255 bytes whenever the name itself does.
    const std::string suffix = "." + std::to_string(::getpid()) + ".partial";
    std::string name = path.filename().string();
    if (name.size() + suffix.size() + 1 > 255) name.resize(255 - suffix.size() - 1);
    temporary_ = path.parent_path() / ("." + name + suffix);
    refuse_other_than_regular(path_);
    // Created here, as a new regular file of this process's own, never
    // through what sits at its name (issue 45: a link planted at a frame's
    // temporary name had the frame written into the file it pointed to):
    // O_EXCL | O_NOFOLLOW fail on a link or anything else there, which is
    // removed (unlink removes a link, not its target) and the name tried
    // once more.
    // Kept open: everything after goes through this descriptor.
    for (int attempt = 0; attempt < 2 && fd_ < 0; ++attempt) {
        fd_ = ::open(temporary_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd_ < 0 && errno == EEXIST && attempt == 0) ::unlink(temporary_.c_str());
    }
    if (fd_ < 0)
        throw std::runtime_error(path.string() + ": cannot create its temporary file " +
                                 temporary_.string() + ": " + std::strerror(errno));
    slot_ = register_temporary(temporary_.c_str(), fd_);  // (allocates nothing: cannot throw)
}

void TemporaryFile::refuse_other_than_regular(const fs::path& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return;
    const char* what = S_ISLNK(st.st_mode)                          ? "a symbolic link"
                       : S_ISDIR(st.st_mode)                        ? "a folder"
                       : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                       : S_ISFIFO(st.st_mode)                       ? "a FIFO"
                                                                    : "not a regular file";
    throw std::runtime_error(path.string() + ": is " + std::string(what) +
                             "; hexant writes a file only where nothing is or over a regular "
                             "file, never through a link or into a device");
}

int remove_leftover_temporaries(const fs::path& path) {
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    const std::string name = path.filename().string();
    std::error_code error;
    fs::directory_iterator it(folder, error);
    if (error) return 0;  // (no folder: nothing left)
    int removed = 0;
    const std::string tail = ".partial";
    for (const fs::directory_entry& entry : it) {
        const std::string f = entry.path().filename().string();
        if (f.size() < 1 + tail.size() + 2 || f[0] != '.' ||
            f.compare(f.size() - tail.size(), tail.size(), tail) != 0)
            continue;
        // ".NAME.PID.partial", NAME cut as TemporaryFile cuts it for a
        // number of that many digits.
        const std::string middle = f.substr(1, f.size() - 1 - tail.size());
        const auto dot = middle.rfind('.');
        if (dot == std::string::npos || dot + 1 == middle.size()) continue;
        const std::string pid = middle.substr(dot + 1);
        if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
        std::string expected = name;
        const std::size_t suffix = 1 + pid.size() + tail.size();
        if (expected.size() + suffix + 1 > 255) expected.resize(255 - suffix - 1);
        if (middle.substr(0, dot) != expected) continue;
        // (A process of this machine that still runs is still writing it.)
        const long number = std::strtol(pid.c_str(), nullptr, 10);
        if (number > 0 && number != ::getpid() && (::kill(pid_t(number), 0) == 0 || errno == EPERM))
            continue;
        if (fs::remove(entry.path(), error)) ++removed;
    }
    return removed;
}

TemporaryFile::~TemporaryFile() {
    if (!committed_) remove_if_ours();
    if (fd_ >= 0) ::close(fd_);
    release(slot_);
}

bool TemporaryFile::name_is_ours() const {
    struct stat mine {
    }, named{};
    return fd_ >= 0 && ::fstat(fd_, &mine) == 0 && ::lstat(temporary_.c_str(), &named) == 0 &&
           mine.st_dev == named.st_dev && mine.st_ino == named.st_ino;
}

void TemporaryFile::remove_if_ours() {
    // (What someone put at the name in its place is theirs, left alone.)
    if (name_is_ours()) ::unlink(temporary_.c_str());
}

fs::path TemporaryFile::reopenable_name() const {
    const fs::path entry = fs::path("/proc/self/fd") / std::to_string(fd_);
    std::error_code error;
    return fs::exists(entry, error) ? entry : temporary_;
}

void TemporaryFile::commit() {
    const auto fail = [&](const std::string& what) {
        remove_if_ours();
        throw std::runtime_error(path_.string() + ": " + what);
    };
    // Written data that did not fit (a full disk) shows here at the latest.
    if (const std::string reason = sync_descriptor(fd_); !reason.empty())
        fail("writing failed: " + reason);
    // Renamed by its name: the name must still be this file (not a link or
    // anything else put there since), or the rename would move that over
    // the output.
    if (!name_is_ours())
        fail("its temporary file " + temporary_.string() +
             " was replaced while it was written; nothing is renamed");
    // (Checked again: the place may have changed while the file was made.)
    try {
        refuse_other_than_regular(path_);
    } catch (const std::runtime_error& e) {
        remove_if_ours();
        throw;
    }
    std::error_code error;
    fs::rename(temporary_, path_, error);
    if (error) fail("cannot rename the finished file: " + error.message());
    committed_ = true;
    release(slot_);  // (a signal now must not remove what is at the name)
    slot_ = -1;
    const int closed = ::close(fd_);
    fd_ = -1;
    if (closed != 0)
        throw std::runtime_error(path_.string() +
                                 ": written, but closing it failed: " + std::strerror(errno));
    const fs::path folder = path_.has_parent_path() ? path_.parent_path() : fs::path(".");
    if (const std::string reason = sync_folder(folder); !reason.empty())
        throw std::runtime_error(path_.string() +
                                 ": written, but its folder could not be flushed: " + reason);
}

std::string write_all(int fd, const void* data, std::size_t bytes) {
    const auto* at = static_cast<const char*>(data);
    std::size_t done = 0;
    while (done < bytes) {
        const ssize_t n = ::write(fd, at + done, bytes - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            return std::strerror(errno);
        }
        done += std::size_t(n);
    }
    return {};
}

void write_text_file(const fs::path& path, const std::string& text) {
    TemporaryFile temporary(path);
    if (const std::string reason = write_all(temporary.descriptor(), text.data(), text.size());
        !reason.empty())
        throw std::runtime_error(path.string() + ": writing failed: " + reason);
    temporary.commit();
}

}  // namespace hexant::tracer
