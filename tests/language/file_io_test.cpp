// #fopen, #write, #read and #fclose (language/file_io.hpp): POV-Ray's
// formats, reading to a file's end, and confinement: writes only into the
// output folder and the --allow-write folders, with `..` and symbolic
// links resolved; reads as #include's.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <sys/stat.h>

#include "language/interpreter.hpp"
#include "language/scene_error.hpp"

namespace fs = std::filesystem;
namespace lang = hexant::language;

namespace {

// A fresh folder for one test's output.
fs::path fresh_folder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / ("hexant_file_io_" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

std::string file_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Reading {
    std::string debug;  // what #debug printed
    std::string error;  // the first error's message, or empty
};

Reading read(const std::string& text, const fs::path& output, std::vector<fs::path> also = {},
             bool animated = false) {
    lang::ParseOptions options;
    options.output_folder = output;
    options.write_paths = std::move(also);
    if (animated) {
        options.animation.initial_frame = 1;
        options.animation.final_frame = 4;
    }
    std::ostringstream messages;
    options.messages = &messages;
    Reading r;
    try {
        (void)lang::parse_scene_text("#version 3.7;\n" + text, "io.pov", options);
    } catch (const lang::SceneError& e) {
        r.error = e.what();
    }
    r.debug = messages.str();
    return r;
}

}  // namespace

TEST_CASE("#write and #read round-trip POV-Ray's formats", "[language][file_io]") {
    const fs::path out = fresh_folder("roundtrip");
    // POV-Ray's own fileio.pov sample, and its reading back.
    const Reading r = read(
        "#fopen MyFile \"FILEIO.TXT\" write\n"
        "#write (MyFile,\"\\\"Testing 123\\\",\",5,\",\",<1,2,3>,\"\\n\")\n"
        "#fclose MyFile\n"
        "#fopen MyFile \"FILEIO.TXT\" read\n"
        "#read (MyFile,MyString,MyFloat,MyVect)\n"
        "#fclose MyFile\n"
        "#debug concat(MyString, \"|\", str(MyFloat, 0, 1), \"|\", vstr(3, MyVect, \",\", 0, 0))\n",
        out);
    REQUIRE(r.error.empty());
    // POV-Ray writes floats with %g and vectors as "<%g,%g,%g> ".
    CHECK(file_text(out / "FILEIO.TXT") == "\"Testing 123\",5,<1,2,3> \n");
    CHECK(r.debug.find("Testing 123|5.0|1,2,3") != std::string::npos);
}

TEST_CASE("#read to a file's end undefines its name", "[language][file_io]") {
    const fs::path out = fresh_folder("loop");
    const Reading r = read(
        "#fopen F \"list.txt\" write\n"
        "#write (F, 1.5, \",\", -2, \",\", 1e3)\n"
        "#fclose F\n"
        "#fopen F \"list.txt\" read\n"
        "#declare Sum = 0; #declare N = 0;\n"
        "#while (defined(F)) #read (F, V) #if (defined(F)) #declare Sum = Sum + V; "
        "#declare N = N + 1; #end #end\n"
        "#debug concat(str(N, 0, 0), \" \", str(Sum, 0, 1))\n",
        out);
    REQUIRE(r.error.empty());
    CHECK(r.debug.find("3 999.5") != std::string::npos);
}

TEST_CASE("#write's binary words write POV-Ray's bytes", "[language][file_io]") {
    const fs::path out = fresh_folder("binary");
    const Reading r = read(
        "#fopen B \"b.bin\" write\n"
        "#write (B, uint8 255.6, uint8 -3, sint16be -2, uint16le 258, sint8 <1, 300>)\n"
        "#fclose B\n",
        out);
    REQUIRE(r.error.empty());
    // Clamped to the type, rounded half up.
    CHECK(file_text(out / "b.bin") == std::string("\xFF\x00\xFF\xFE\x02\x01\x01\x7F", 8));
}

TEST_CASE("a scene writes only into its output folder and --allow-write",
          "[language][file_io][confinement]") {
    const fs::path out = fresh_folder("confined");
    const fs::path other = fresh_folder("confined_other");
    const auto refused = [&](const std::string& name, std::vector<fs::path> also = {}) {
        const Reading r = read("#fopen F \"" + name + "\" write\n", out, also);
        INFO(name << ": " << r.error);
        return r.error.find("outside the folders a scene may write to") != std::string::npos ||
               r.error.find("system file") != std::string::npos;
    };
    CHECK(refused((other / "x.txt").string()));
    CHECK(refused("../hexant_file_io_confined_other/x.txt"));
    CHECK(refused("sub/../../x.txt"));
    CHECK(refused("/proc/self/x"));
    // A symbolic link inside the folder to a folder outside it.
    fs::create_directory_symlink(other, out / "link");
    CHECK(refused("link/x.txt"));
    CHECK_FALSE(fs::exists(other / "x.txt"));
    // Allowed: the folder itself, a folder under it, and --allow-write.
    CHECK(read("#fopen F \"sub/y.txt\" write #fclose F\n", out).error.empty());
    CHECK(fs::exists(out / "sub" / "y.txt"));
    CHECK(read("#fopen F \"" + (other / "z.txt").string() + "\" write #fclose F\n", out, {other})
              .error.empty());
    CHECK(fs::exists(other / "z.txt"));
    // Text read from memory with no output folder may not write at all.
    CHECK(read("#fopen F \"w.txt\" write\n", fs::path()).error.find("no output folder") !=
          std::string::npos);
}

TEST_CASE("#fopen writes only into a regular file, appends at its end",
          "[language][file_io][confinement]") {
    // Issue 45: a FIFO in the output folder blocked #fopen for good, a
    // device was written into; both are refused at once now.
    const fs::path out = fresh_folder("special");
    REQUIRE(::mkfifo((out / "fifo.txt").c_str(), 0600) == 0);
    const Reading fifo = read("#fopen F \"fifo.txt\" write\n", out);
    INFO(fifo.error);
    CHECK(fifo.error.find("fifo.txt") != std::string::npos);
    CHECK(fs::is_fifo(out / "fifo.txt"));
    // Write, then append: the second text after the first.
    CHECK(read("#fopen F \"a.txt\" write #write (F, \"one\") #fclose F\n"
               "#fopen F \"a.txt\" append #write (F, \"two\") #fclose F\n",
               out)
              .error.empty());
    CHECK(file_text(out / "a.txt") == "onetwo");
    // Writing again starts it anew.
    CHECK(read("#fopen F \"a.txt\" write #write (F, \"3\") #fclose F\n", out).error.empty());
    CHECK(file_text(out / "a.txt") == "3");
}

TEST_CASE("a scene reads files only where #include may", "[language][file_io][confinement]") {
    const fs::path out = fresh_folder("reads");
    const Reading r = read("#fopen F \"/etc/passwd\" read\n", out);
    CHECK(r.error.find("outside the folders a scene may read") != std::string::npos);
    CHECK(read("#fopen F \"/proc/self/status\" read\n", out).error.find("system file") !=
          std::string::npos);
}

TEST_CASE("file_exists() answers only inside the folders a scene may read",
          "[language][file_io][confinement]") {
    // (issue 45) file_exists("/etc/shadow") answered for any path, and the
    // answer could steer the image.
    const fs::path folder = fresh_folder("exists");
    const fs::path other = fresh_folder("exists_other");
    std::ofstream(folder / "here.inc") << "// here\n";
    std::ofstream(other / "there.inc") << "// there\n";
    fs::create_directory_symlink(other, folder / "link");
    const auto probe = [](const std::string& name) {
        return "str(file_exists(\"" + name + "\"), 0, 0)";
    };
    std::ofstream(folder / "scene.pov")
        << "#version 3.7;\n#include \"here.inc\"\n#debug concat(" << probe("here.inc") << ", "
        << probe((other / "there.inc").string()) << ", " << probe("link/there.inc") << ", "
        << probe("/etc/passwd") << ", " << probe("missing.inc") << ", " << probe("")
        << ", \"\\n\")\n";
    lang::ParseOptions options;
    std::ostringstream messages;
    options.messages = &messages;
    const auto scene = lang::parse_scene_file(folder / "scene.pov", options);
    CHECK(messages.str() == "100000\n");
    // The files it read are its inputs (outputs never replace one).
    REQUIRE(scene.inputs.size() == 2);
    CHECK(scene.inputs[0] == fs::canonical(folder / "scene.pov"));
    CHECK(scene.inputs[1] == fs::canonical(folder / "here.inc"));
    // --allow-read opens the other folder, through the link too.
    options.read_paths = {other};
    messages.str("");
    (void)lang::parse_scene_file(folder / "scene.pov", options);
    CHECK(messages.str() == "111000\n");
}

TEST_CASE("file directives refuse what they cannot do", "[language][file_io]") {
    const fs::path out = fresh_folder("refusals");
    CHECK(read("#write (F, 1)\n", out).error.find("not an open file") != std::string::npos);
    CHECK(read("#fopen F \"a.txt\" write #read (F, V)\n", out).error.find("open for writing") !=
          std::string::npos);
    CHECK(read("#fopen F \"a.txt\" write #write (F, sphere { 0, 1 })\n", out)
              .error.find("expected ')' or another item") != std::string::npos);
    CHECK(read("#fopen F \"a.txt\" wrote\n", out).error.find("expected read, write or append") !=
          std::string::npos);
    // A value of clock, written once for the whole animation, is refused.
    CHECK(read("#fopen F \"a.txt\" write #write (F, clock)\n", out, {}, true)
              .error.find("changes with clock") != std::string::npos);
    CHECK(read("#if (clock < 0.5) #fopen F \"a.txt\" write #end\n", out, {}, true)
              .error.find("depends on clock") != std::string::npos);
}
