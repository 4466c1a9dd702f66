// #include reads only what a scene may read (issue 17): its own folder, the
// -L folders, the include folders of hexant and POV-Ray, and --allow-read
// folders, after `..` and symbolic links are resolved; never a device, a
// FIFO or a system file; and an error never shows a refused file's
// contents. --declare takes a value, never scene text.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <sys/stat.h>

#include "language/interpreter.hpp"

namespace fs = std::filesystem;
using hexant::language::ParseOptions;
using hexant::language::SceneError;

namespace {

struct Folders {
    fs::path root, scene, outside;
    Folders() {
        root = fs::temp_directory_path() / "hexant_confinement_test";
        fs::remove_all(root);
        scene = root / "scene";
        outside = root / "outside";
        fs::create_directories(scene / "sub");
        fs::create_directories(outside);
        std::ofstream(scene / "ok.inc") << "#declare A = 1;\n";
        std::ofstream(scene / "sub" / "deeper.inc") << "#declare B = 2;\n";
        std::ofstream(outside / "secret.inc") << "TOPSECRET line\n";
        fs::create_symlink(outside / "secret.inc", scene / "link_out.inc");
        fs::create_symlink(scene / "ok.inc", scene / "sub" / "link_in.inc");
        ::mkfifo((scene / "pipe.inc").c_str(), 0600);
    }
    ~Folders() { fs::remove_all(root); }

    // The error's message, or "" when the scene reads.
    std::string read(const std::string& text, ParseOptions options = {}) const {
        std::ofstream(scene / "main.pov") << text;
        std::ostringstream messages;
        options.messages = &messages;
        try {
            hexant::language::parse_scene_file(scene / "main.pov", options);
        } catch (const SceneError& e) {
            return e.formatted();
        }
        return "";
    }
};

}  // namespace

TEST_CASE("#include reads only from the folders a scene may read", "[language][include]") {
    const Folders f;
    // Inside: its own folder, a subfolder, a link that stays inside.
    CHECK(f.read("#include \"ok.inc\"\n") == "");
    CHECK(f.read("#include \"sub/deeper.inc\"\n") == "");
    CHECK(f.read("#include \"sub/link_in.inc\"\n") == "");
    CHECK(f.read("#include \"" + (f.scene / "ok.inc").string() + "\"\n") == "");
    // Outside: `..`, an absolute path, a link out, a system file, a
    // device, a FIFO. Each names the include, never its contents.
    for (const std::string& name :
         {std::string("../outside/secret.inc"), (f.outside / "secret.inc").string(),
          std::string("link_out.inc"), std::string("/etc/hostname"),
          std::string("/proc/self/environ"), std::string("/dev/zero"), std::string("pipe.inc")}) {
        INFO(name);
        const std::string error = f.read("#include \"" + name + "\"\n");
        CHECK(error.find("include file '" + name + "'") != std::string::npos);
        CHECK(error.find("TOPSECRET") == std::string::npos);
    }
    CHECK(f.read("#include \"pipe.inc\"\n").find("not a regular file") != std::string::npos);
    CHECK(f.read("#include \"/dev/zero\"\n").find("not a regular file") != std::string::npos);
    CHECK(f.read("#include \"/proc/self/environ\"\n").find("system file") != std::string::npos);
    // --allow-read opens a folder, and -L one to search.
    ParseOptions allowed;
    allowed.read_paths.push_back(f.outside);
    CHECK(f.read("#include \"../outside/secret.inc\"\n", allowed).find("TOPSECRET") !=
          std::string::npos);
    ParseOptions searched;
    searched.include_paths.push_back(f.outside);
    CHECK(f.read("#include \"secret.inc\"\n", searched).find("TOPSECRET") != std::string::npos);
}

TEST_CASE("declared values from the command line are values, never scene text",
          "[language][include]") {
    const auto declare = [](const std::string& name, const std::string& value) -> std::string {
        ParseOptions options;
        std::ostringstream messages;
        options.messages = &messages;
        options.declares.emplace_back(name, value);
        try {
            hexant::language::parse_scene_text("#declare Unused = 0;\n", "test.pov", options);
        } catch (const SceneError& e) {
            return e.formatted();
        }
        return "ok";
    };
    CHECK(declare("N", "100") == "ok");
    CHECK(declare("N", "-2.5e-3") == "ok");
    CHECK(declare("N", " .5 ") == "ok");
    CHECK(declare("V", "<1, 2, 3>") == "ok");
    CHECK(declare("S", "\"text\"") == "ok");
    for (const char* injected : {"1; #include \"/etc/hostname\"", "1 #declare Y = 2",
                                 "sphere { 0, 1 }", "1 /* */", "N + 1", "\"a\" #end"}) {
        INFO(injected);
        const std::string error = declare("N", injected);
        CHECK(error.find("--declare N: error: the value") == 0);
    }
    CHECK(declare("1N", "1").find("must be an identifier") != std::string::npos);
}
