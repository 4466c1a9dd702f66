// Files written whole or not at all: each goes under a temporary name beside
// its place, is flushed to the disk (fsync) and checked, and is renamed over
// its place once complete (then the folder is flushed too), so a failing
// run (a full disk, a file size limit, an I/O error) never leaves a
// half-written file under the real name, and says why. A run stopped by
// SIGINT, SIGTERM or SIGHUP removes the temporaries it was writing before
// it dies (install_cleanup_on_signals), so none is left behind either.
// Frames, statistics, benchmark tables and plots alike.
#pragma once

#include <filesystem>
#include <string>

namespace hexant::tracer {

// A temporary file being written: named beside `path` (".NAME.PID.partial",
// the folder created; NAME cut to fit 255 bytes), created empty as a new
// regular file (O_EXCL | O_NOFOLLOW: never through a link planted at its
// name), registered for removal on a signal, and removed when the object
// goes away unless commit() renamed it over `path`. It is written and read
// back through the descriptor it was created with, never reopened by its
// name (which someone who can write the folder could swap for a link or a
// FIFO meanwhile), and renamed only while its name is still that file. A
// `path` that is a link, a device, a FIFO or a folder is refused
// (std::runtime_error naming it), here and again before the rename: only
// nothing or a regular file is replaced.
class TemporaryFile {
  public:
    explicit TemporaryFile(const std::filesystem::path& path);
    ~TemporaryFile();
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    const std::filesystem::path& name() const { return temporary_; }

    // The open descriptor of the temporary, for writing (at its start, as
    // created) and reading back; it stays this object's, closed by
    // commit() or the destructor. A writer that needs a FILE* or a library
    // that closes what it is given takes a dup() of it.
    int descriptor() const { return fd_; }

    // A name that opens this very file whatever is at name() by now (the
    // process's /proc/self/fd entry), for a reader that takes a path;
    // name() itself where /proc is not mounted.
    std::filesystem::path reopenable_name() const;

    // Flushes the temporary to the disk, checks that its name is still the
    // file this object created, renames it over the path and flushes the
    // folder; throws std::runtime_error naming the path and the system's
    // reason (the temporary is removed).
    void commit();

    // Throws std::runtime_error if `path` exists and is not a regular file.
    static void refuse_other_than_regular(const std::filesystem::path& path);

  private:
    // Whether name() is still the file fd_ holds (same device and inode,
    // not followed through a link).
    bool name_is_ours() const;
    void remove_if_ours();

    std::filesystem::path path_, temporary_;
    int fd_ = -1;
    int slot_ = -1;  // in the signal handler's list
    bool committed_ = false;
};

// Removes what a killed run left of its temporaries for `path` (the
// ".NAME.PID.partial" files beside it, of any process); returns how many.
// For a run that resumes (render --resume): nothing else writes `path`.
int remove_leftover_temporaries(const std::filesystem::path& path);

// Writes `bytes` bytes at `data` to `fd` whole (again after EINTR and short
// writes); the system's reason on failure, empty on success.
std::string write_all(int fd, const void* data, std::size_t bytes);

// Writes `text` to `path` whole; throws std::runtime_error naming the file.
void write_text_file(const std::filesystem::path& path, const std::string& text);

// From now on SIGINT, SIGTERM and SIGHUP remove every temporary being
// written, then end the process as the signal would have. Once per process
// (the app calls it); harmless to repeat.
void install_cleanup_on_signals();

// What the signal handler does, callable directly (tests): removes every
// registered temporary. Async-signal-safe.
void remove_registered_temporaries();

}  // namespace hexant::tracer
