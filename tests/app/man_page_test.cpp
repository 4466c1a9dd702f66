// hexant(1) from CLI11's tables: roff escapes, hidden subcommands left
// out, nested subcommands and footers kept (app/man_page.hpp).
#include "app/man_page.hpp"

#include <regex>
#include <sstream>

#include <catch2/catch.hpp>

#include "app/version.hpp"

namespace {

std::string page_of(const CLI::App& program) {
    std::ostringstream out;
    hexant::app::write_man_page(program, out);
    return out.str();
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("the man page lists each visible subcommand with its flags", "[app][man_page]") {
    CLI::App program{"test program"};
    int width = 0;
    CLI::App* render = program.add_subcommand("render", "Render the frames");
    render->add_option("-W,--width", width, "Image width in pixels");
    render->footer("Footer line one\n.starts with a dot");
    CLI::App* bench = program.add_subcommand("merge-stats", "Merge");
    bench->add_subcommand("error-time", "Error against time");
    program.add_subcommand("man-page", "hidden")->group("");
    const std::string page = page_of(program);

    CHECK(has(page, ".TH HEXANT 1"));
    std::string version;  // as roff writes it: "-dirty" is "\-dirty"
    for (const char c : hexant::app::version_text())
        version += c == '-' ? "\\-" : std::string(1, c);
    CHECK(has(page, ".TH HEXANT 1 \"\" \"" + version + "\""));
    CHECK(has(page, ".SS \"hexant render\""));
    CHECK(has(page, ".SS \"hexant merge\\-stats\""));  // every '-' a minus sign
    CHECK(has(page, ".SS \"hexant merge\\-stats error\\-time\""));
    CHECK(has(page, "\\fB\\-W\\fR, \\fB\\-\\-width\\fR \\fIINT\\fR"));
    CHECK(has(page, "Image width in pixels"));
    CHECK(has(page, "\n\\&.starts with a dot"));  // no roff request
    CHECK_FALSE(has(page, "man\\-page"));
    CHECK_FALSE(has(page, "hidden"));
}

TEST_CASE("the man page escapes backslashes", "[app][man_page]") {
    CLI::App program{"a \\ backslash"};
    program.add_subcommand("check", "C:\\scenes");
    const std::string page = page_of(program);
    CHECK(has(page, "a \\e backslash"));
    CHECK(has(page, "C:\\escenes"));
}

TEST_CASE("the version text names the version", "[app][man_page]") {
    const std::string text = hexant::app::version_text();
    CHECK(std::regex_match(
        text, std::regex(R"(hexant [0-9]+\.[0-9]+\.[0-9]+( \(git [0-9a-f]+(-dirty)?\))?)")));
}
