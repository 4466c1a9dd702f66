// Files are written whole or not at all (issue 17): past a file size limit
// (what a full disk looks like to a writer) an image or a text file is an
// error naming the file and the system's reason, with nothing left under
// its name and no temporary; a run killed by a signal removes the
// temporaries it was writing. A link planted at a temporary name is never
// written through, and an output that is a link, a FIFO or a folder is
// refused (issue 45).
#include "tracer/whole_file.hpp"

#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <catch2/catch.hpp>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tracer/image_output.hpp"

namespace fs = std::filesystem;
namespace tr = hexant::tracer;

namespace {

// A file size limit for this process while it lives (writes past it fail
// with EFBIG; SIGXFSZ ignored, as hexant does).
class FileSizeLimit {
  public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &saved_);
        previous_ = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = saved_;
        limit.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &saved_);
        std::signal(SIGXFSZ, previous_);
    }

  private:
    rlimit saved_{};
    void (*previous_)(int) = nullptr;
};

// Noise compresses badly: a 256 by 256 PNG of it is about 190 KB.
tr::Image noise(int size) {
    tr::Image image(size, size);
    unsigned state = 1;
    for (float& v : image.rgb) {
        state = state * 1103515245u + 12345u;
        v = float((state >> 8) & 0xffff) / 65535.0f;
    }
    return image;
}

}  // namespace

TEST_CASE("a write that cannot finish fails with its reason and leaves nothing",
          "[tracer][files]") {
    const fs::path folder = fs::temp_directory_path() / "hexant_file_limit_test";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const tr::Image image = noise(256);
    for (const char* name : {"frame.png", "frame.exr"}) {
        INFO(name);
        {
            const FileSizeLimit limit(16 * 1024);
            CHECK_THROWS_WITH(tr::write_image(image, folder / name),
                              Catch::Contains(name) && Catch::Contains("writing failed"));
        }
        CHECK(fs::is_empty(folder));
        // Without the limit the same write succeeds, whole.
        tr::write_image(image, folder / name);
        CHECK(fs::file_size(folder / name) > 16 * 1024);
        fs::remove(folder / name);
    }
    {
        const FileSizeLimit limit(1024);
        CHECK_THROWS_WITH(tr::write_text_file(folder / "stats.json", std::string(100000, 'x')),
                          Catch::Contains("stats.json") && Catch::Contains("File too large"));
        std::vector<tr::Image> frames(4, noise(64));
        CHECK_THROWS_WITH(tr::write_animation(frames, folder / "movie.gif", 12.0),
                          Catch::Contains("movie.gif"));
    }
    CHECK(fs::is_empty(folder));
    fs::remove_all(folder);
}

TEST_CASE("a file name as long as the system allows is written, its temporary cut to fit",
          "[tracer][files]") {
    const fs::path folder = fs::temp_directory_path() / "hexant_long_name_test";
    fs::remove_all(folder);
    const fs::path file = folder / (std::string(246, 'b') + ".png");  // 250 bytes
    tr::write_image(noise(8), file);
    CHECK(fs::file_size(file) > 0);
    tr::write_text_file(folder / (std::string(250, 's') + ".txt"), "whole");
    std::size_t entries = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
        CHECK(entry.path().filename().string().find(".partial") == std::string::npos);
        ++entries;
    }
    CHECK(entries == 2);
    fs::remove_all(folder);
}

TEST_CASE("a run ended by a signal removes the temporaries it was writing", "[tracer][files]") {
    const fs::path folder = fs::temp_directory_path() / "hexant_signal_test";
    fs::remove_all(folder);
    tr::install_cleanup_on_signals();
    {
        tr::TemporaryFile file(folder / "frame.png");
        std::ofstream(file.name()) << "half a frame";
        REQUIRE(fs::exists(file.name()));
        // A child inherits the list and the handler, and dies of SIGTERM
        // as it would have: the temporary is gone.
        const pid_t child = fork();
        if (child == 0) {
            std::raise(SIGTERM);
            _exit(0);  // not reached
        }
        int status = 0;
        REQUIRE(waitpid(child, &status, 0) == child);
        CHECK(WIFSIGNALED(status));
        CHECK(WTERMSIG(status) == SIGTERM);
        CHECK_FALSE(fs::exists(file.name()));
        CHECK_FALSE(fs::exists(folder / "frame.png"));
    }
    // Committed, the file is in its place and no longer the handler's.
    {
        tr::TemporaryFile file(folder / "kept.txt");
        std::ofstream(file.name()) << "whole";
        file.commit();
        tr::remove_registered_temporaries();
        CHECK(fs::exists(folder / "kept.txt"));
    }
    fs::remove_all(folder);
}

namespace {

std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("a link planted at a temporary name is never written through", "[tracer][files]") {
    // Issue 45: a symbolic link at ".NAME.PID.partial" had the frame, then
    // the statistics, written into whatever file it pointed to.
    const fs::path folder = fs::temp_directory_path() / "hexant_planted_link_test";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const fs::path victim = folder / "victim.txt";
    std::ofstream(victim) << "not yours";
    const std::string pid = std::to_string(::getpid());
    for (const std::string name : {"f.png", "stats.json"}) {
        const fs::path temporary = folder / ("." + name + "." + pid + ".partial");
        fs::create_symlink(victim, temporary);
        if (name == "f.png")
            tr::write_image(noise(8), folder / name);
        else
            tr::write_text_file(folder / name, "{}");
        CHECK(contents(victim) == "not yours");
        CHECK(fs::is_regular_file(fs::symlink_status(folder / name)));
        CHECK_FALSE(fs::exists(fs::symlink_status(temporary)));
    }
    CHECK(contents(folder / "stats.json") == "{}");
    fs::remove_all(folder);
}

TEST_CASE("a temporary swapped for a link while it is written is never renamed or written through",
          "[tracer][files]") {
    // Issue 45: someone who can write the output folder replaces the
    // temporary by a link between its creation and the rename. The bytes
    // go through the descriptor it was created with (into the file that
    // was unlinked, not the link's target), and the rename is refused: the
    // output never becomes their link.
    const fs::path folder = fs::temp_directory_path() / "hexant_swapped_temporary_test";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const fs::path victim = folder / "victim.txt";
    std::ofstream(victim) << "not yours";
    {
        tr::TemporaryFile temporary(folder / "out.json");
        fs::remove(temporary.name());
        fs::create_symlink(victim, temporary.name());
        CHECK(tr::write_all(temporary.descriptor(), "{}", 2).empty());
        CHECK_THROWS_WITH(temporary.commit(),
                          Catch::Contains("out.json") && Catch::Contains("was replaced"));
        // Their link is theirs: left where it was.
        CHECK(fs::is_symlink(temporary.name()));
    }
    CHECK(contents(victim) == "not yours");
    CHECK_FALSE(fs::exists(fs::symlink_status(folder / "out.json")));
    // Unswapped, the same steps write the file whole, and the descriptor
    // reads back what was written under a name nobody can swap.
    {
        tr::TemporaryFile temporary(folder / "out.json");
        CHECK(tr::write_all(temporary.descriptor(), "{}", 2).empty());
        CHECK(contents(temporary.reopenable_name()) == "{}");
        temporary.commit();
    }
    CHECK(contents(folder / "out.json") == "{}");
    fs::remove_all(folder);
}

TEST_CASE("an output that is a link, a FIFO or a folder is refused and left as it was",
          "[tracer][files]") {
    const fs::path folder = fs::temp_directory_path() / "hexant_special_output_test";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const fs::path victim = folder / "victim.png";
    std::ofstream(victim) << "not yours";
    fs::create_symlink(victim, folder / "link.png");
    REQUIRE(::mkfifo((folder / "fifo.json").c_str(), 0600) == 0);
    fs::create_directories(folder / "folder.png");
    const auto refused = [&](const std::function<void()>& write, const std::string& what) {
        try {
            write();
            FAIL("written over " << what);
        } catch (const std::runtime_error& e) {
            INFO(e.what());
            CHECK(std::string(e.what()).find(what) != std::string::npos);
        }
    };
    refused([&] { tr::write_image(noise(8), folder / "link.png"); }, "a symbolic link");
    refused([&] { tr::write_text_file(folder / "fifo.json", "{}"); }, "a FIFO");
    refused([&] { tr::write_image(noise(8), folder / "folder.png"); }, "a folder");
    CHECK(contents(victim) == "not yours");
    CHECK(fs::is_symlink(folder / "link.png"));
    CHECK(fs::is_fifo(folder / "fifo.json"));
    // Nothing of theirs left behind.
    for (const auto& entry : fs::directory_iterator(folder))
        CHECK(entry.path().filename().string().find(".partial") == std::string::npos);
    fs::remove_all(folder);
}
