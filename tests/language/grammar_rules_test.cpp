// The grammar rule by rule, without actions or state: what each rule accepts
// and what it rejects. (Directives and macro calls are custom rules that need
// the interpreter; they are tested through it in evaluator_test.cpp.)
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

#include <catch2/catch.hpp>
#include <tao/pegtl.hpp>
#include <tao/pegtl/contrib/analyze.hpp>

#include "language/errors.hpp"
#include "language/grammar.hpp"

namespace p = tao::pegtl;
namespace g = hexant::language::grammar;

namespace {

// Whether Rule matches the whole text.
template <typename Rule>
bool whole(const std::string& text) {
    p::memory_input in(text, "test");
    return p::parse<p::seq<Rule, p::eof>, p::nothing, hexant::language::control>(in);
}

// Whether Rule raises a parse error (a must<> that failed) on the text.
template <typename Rule>
bool raises(const std::string& text) {
    try {
        (void)whole<Rule>(text);
    } catch (const p::parse_error&) {
        return true;
    }
    return false;
}

}  // namespace

TEST_CASE("the grammar has no rule that can loop without consuming input", "[grammar]") {
    CHECK(p::analyze<g::scene_file>(-1) == 0);
}

TEST_CASE("every keyword of the grammar is a reserved word", "[grammar]") {
    // The grammar and its parts (language/grammar/).
    std::stringstream text;
    const std::filesystem::path root = std::filesystem::path(HEXANT_SOURCE_DIR) / "language";
    std::vector<std::filesystem::path> files = {root / "grammar.hpp"};
    for (const auto& entry : std::filesystem::directory_iterator(root / "grammar"))
        files.push_back(entry.path());
    REQUIRE(files.size() > 1);
    for (const auto& file : files) {
        std::ifstream in(file);
        REQUIRE(in.good());
        text << in.rdbuf();
    }
    const std::string source = text.str();
    const std::regex keyword(R"re((?:TAO_PEGTL_KEYWORD\(|HEXANT_KEYWORD\(\w+, )"(\w+)")re");
    int count = 0;
    for (auto it = std::sregex_iterator(source.begin(), source.end(), keyword);
         it != std::sregex_iterator(); ++it, ++count) {
        INFO((*it)[1].str());
        CHECK(g::is_reserved_word((*it)[1].str()));
    }
    // The tables of words matched by lookup (one_word_of).
    const auto check_table = [&](const auto& list) {
        for (const std::string_view word : list) {
            INFO(word);
            CHECK(g::is_reserved_word(word));
            ++count;
        }
    };
    check_table(g::function_words::list);
    check_table(g::builtin_constant_words::list);
    check_table(g::colour_model_words::list);
    check_table(g::colour_component_words::list);
    check_table(g::unsupported_kind_words::list);
    CHECK(count > 300);
    CHECK_FALSE(g::is_reserved_word("Radius"));
    CHECK_FALSE(g::is_reserved_word("sphere_2"));
}

TEST_CASE("a word of a table matches whole, or not at all", "[grammar]") {
    for (const char* word : {"sin", "atan", "atan2", "vaxis_rotate", "file_exists", "abs"}) {
        INFO(word);
        CHECK(whole<g::function_name>(word));
    }
    for (const char* text : {"sinx", "atan3", "Sin", "sin_", "s", "", "2sin", "_abs"}) {
        INFO(text);
        CHECK_FALSE(whole<g::function_name>(text));
    }
    CHECK(whole<g::builtin_constant_name>("clock"));
    CHECK(whole<g::builtin_constant_name>("clock_delta"));
    CHECK_FALSE(whole<g::builtin_constant_name>("clocks"));
    CHECK(whole<g::colour_model>("srgbft"));
    CHECK_FALSE(whole<g::colour_model>("rgba"));
}

TEST_CASE("blanks and comments, nested block comments included", "[grammar]") {
    CHECK(whole<g::ws>(""));
    CHECK(whole<g::ws>("  \t\n\r\n"));
    CHECK(whole<g::ws>("// to the end of the line\n"));
    CHECK(whole<g::ws>("// at the end of the file"));
    CHECK(whole<g::ws>("/* a */ /* b /* nested */ still b */ "));
    CHECK_FALSE(whole<g::ws>("/* a */ x"));
    CHECK(raises<g::ws>("/* never closed"));
    CHECK(raises<g::ws>("/* outer /* inner */ outer never closed"));
}

TEST_CASE("numbers", "[grammar]") {
    for (const char* ok : {"1", "1.5", ".5", "1.", "1e-3", "2.E+4", "0.25e2 "}) {
        INFO(ok);
        CHECK(whole<g::number>(ok));
    }
    CHECK_FALSE(whole<g::number>("e1"));
    CHECK_FALSE(whole<g::number>("-1"));  // the sign is an operator
    CHECK_FALSE(whole<g::number>("."));
    CHECK(raises<g::number>("1e"));
    CHECK(raises<g::number>("12abc"));
}

TEST_CASE("strings", "[grammar]") {
    CHECK(whole<g::string_literal>(R"("plain")"));
    CHECK(whole<g::string_literal>(R"("with \"escapes\" and \\ ")"));
    CHECK(whole<g::string_literal>(R"("")"));
    CHECK_FALSE(whole<g::string_literal>("'single'"));
    CHECK(raises<g::string_literal>("\"no end"));
    CHECK(raises<g::string_literal>("\"no end\non this line\""));
}

TEST_CASE("names are identifiers that are not keywords", "[grammar]") {
    for (const char* ok : {"Radius", "_tmp", "Foo_1", "spheres", "xx", "clock2"}) {
        INFO(ok);
        CHECK(whole<g::identifier>(ok));
    }
    for (const char* bad : {"sphere", "x", "clock", "rgb", "declare", "1abc", ""}) {
        INFO(bad);
        CHECK_FALSE(whole<g::identifier>(bad));
    }
}

TEST_CASE("expressions of every shape", "[grammar]") {
    for (const char* ok : {"1+2*3",
                           "-x.y",
                           "(1 < 2) & (3 >= 2) | !0",
                           "a ? b : c",
                           "<1, 2, 3>.x",
                           "<1,2>",
                           "<1,2,3,4,5>",
                           "vrotate(x, <0, 90, 0>)",
                           "max(1, 2, 3)",
                           "pi * clock",
                           "A[1][2]",
                           "S(0.5).y",
                           "1 = 1 != 0",
                           "2 * -3",
                           "+1",
                           "rgb <1, 0, 0>",
                           "rgbft 1",
                           "srgb <.5, .5, .5> + rgb 1",
                           "color red 1 green .5",
                           "colour Red blue 1",
                           "defined(Foo)",
                           "\"a\"",
                           "str(1, 0, 2)",
                           "a.red + b.filter * c.u"}) {
        INFO(ok);
        CHECK(whole<g::expression>(ok));
    }
    for (const char* bad : {"", "*1", "sphere", "1 1", ")", "a ? b"}) {
        INFO(bad);
        bool accepted = false;
        try {
            accepted = whole<g::expression>(bad);
        } catch (const p::parse_error&) {
        }
        CHECK_FALSE(accepted);
    }
    CHECK(raises<g::expression>("1 +"));
    CHECK(raises<g::expression>("<1, 2"));
    CHECK(raises<g::expression>("sin 1"));
    CHECK(raises<g::expression>("(1"));
    CHECK(raises<g::expression>("a ? b :"));
}

TEST_CASE("skipped text steps over nested directives, strings and comments", "[grammar]") {
    // Stops at a divider at its own depth only.
    CHECK(whole<g::skip::text>("sphere { 0, 1 } #if (1) #else #end /* #end */ \"#end\""));
    {
        const std::string text = "a #if (1) b #else c #end d #else e";
        p::memory_input in(text, "test");
        REQUIRE(p::parse<g::skip::text>(in));
        CHECK(std::string(in.current()) == "#else e");
    }
    CHECK(whole<g::skip::braced>("{ a { b } \"}\" /* } */ c }"));
    CHECK(raises<g::skip::braced>("{ a { b }"));
    CHECK(raises<g::skip::text>("#while (1) never ends"));
}

TEST_CASE("scene items that need no directives", "[grammar]") {
    for (const char* ok :
         {"sphere { <0, 0, 0>, 1 translate x }", "box { <0,0,0> <1,1,1> }",
          "plane { y, 0 pigment { checker rgb 1, rgb 0 } }",
          "camera { location <0, 1, -5> look_at 0 angle 60 }",
          "light_source { <1, 2, 3>, rgb 1 shadowless }", "union { sphere { 0, 1 } box { 0, 1 } }",
          "global_settings { assumed_gamma 1 radiosity { count 10 } }",
          "background { rgb <0, 0, 0.1> }", "object { sphere { 0, 1 } scale 2 }",
          "torus { 1, 0.25 twist y, 30 }", "isosurface { function { x } }", ""}) {
        INFO(ok);
        CHECK(whole<g::scene_file>(ok));
    }
    CHECK(raises<g::scene_file>("sphere { 0, 1"));
    CHECK(raises<g::scene_file>("sphere { 0, 1 location 0 }"));
    CHECK(raises<g::scene_file>("}"));
    CHECK(raises<g::scene_file>("sphere 0, 1"));
    CHECK(raises<g::scene_file>("box { 0, 1 matrix 1 }"));
}
