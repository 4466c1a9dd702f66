// Every one of POV-Ray 3.7's reserved words has a rule (issue 42: nothing
// dropped in silence), and the rule holds: a Warned word used in its place
// gives a warning at that line (an error under --strict), a Harmless one
// reads silently, a Refused one is an error wherever it is written, and a
// Rendered one is a word hexant's grammar knows.
#include "language/keyword_rules.hpp"

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/grammar.hpp"
#include "language/interpreter.hpp"

namespace lang = hexant::language;

namespace {

const std::string kWords =
    std::string(HEXANT_SOURCE_DIR) + "/tests/language/pov_reference/reserved_words_3.7.txt";

std::vector<std::string> pov_words() {
    std::ifstream in(kWords);
    std::vector<std::string> words;
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] != '#') words.push_back(line);
    return words;
}

// A use of each Warned or Harmless word in its place, written on line 2, and
// the word the warning names: the word itself, or the block it is read with
// (radiosity { }, media { }, irid { }, subsurface { }).
struct Probe {
    std::string text;
    std::string named;
};

const std::map<std::string, Probe>& probes() {
    static const std::map<std::string, Probe> kProbes = [] {
        std::map<std::string, Probe> p;
        const auto self = [&](const std::string& word, const std::string& text) {
            p[word] = {text, word};
        };
        self("confidence", "camera { location -5 look_at 0 confidence 0.9 }");
        self("variance", "camera { location -5 look_at 0 variance 0.001 }");
        self("fresnel", "sphere { 0, 1 finish { fresnel } }");
        self("subsurface", "sphere { 0, 1 finish { subsurface { translucency 0.5 } } }");
        p["translucency"] = {"sphere { 0, 1 finish { subsurface { translucency 0.5 } } }",
                             "subsurface"};
        self("adc_bailout", "global_settings { adc_bailout 0.01 }");
        self("mm_per_unit", "global_settings { mm_per_unit 10 }");
        self("hf_gray_16", "global_settings { hf_gray_16 on }");
        self("importance", "sphere { 0, 1 radiosity { importance 0.5 } }");
        self("split_union", "union { sphere { 0, 1 } sphere { x, 1 } photons { split_union on } }");
        // Harmless: no warning.
        for (const auto& [word, text] : std::map<std::string, std::string>{
                 {"sturm", "sphere { 0, 1 sturm }"},
                 {"jitter", "light_source { 0, 1 area_light x, y, 2, 2 jitter }"},
                 {"adaptive", "light_source { 0, 1 area_light x, y, 2, 2 adaptive 1 }"},
                 {"max_intersections", "global_settings { max_intersections 64 }"},
                 {"debug", "#debug \"a line\\n\""},
                 {"quick_color", "sphere { 0, 1 pigment { rgb 1 quick_color rgb 0.5 } }"},
                 {"quick_colour", "sphere { 0, 1 pigment { rgb 1 quick_colour rgb 0.5 } }"},
                 {"hierarchy",
                  "mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } hierarchy off }"},
                 {"max_gradient", "isosurface { function { x } max_gradient 2 }"},
                 {"evaluate", "isosurface { function { x } evaluate 1, 10, 0.99 }"},
                 {"max_trace", "isosurface { function { x } max_trace 2 }"},
                 {"all_intersections", "isosurface { function { x } all_intersections }"}})
            p[word] = {text, ""};
        return p;
    }();
    return kProbes;
}

struct Reading {
    std::vector<std::string> warnings;
    std::optional<lang::SceneError> error;
};

Reading read(const std::string& line2, bool strict = false) {
    lang::ParseOptions options;
    options.strict = strict;
    std::ostringstream messages;
    options.messages = &messages;
    Reading r;
    try {
        r.warnings =
            lang::parse_scene_text("#version 3.7;\n" + line2 + "\n", "probe.pov", options).warnings;
    } catch (const lang::SceneError& e) {
        r.error = e;
    }
    return r;
}

}  // namespace

TEST_CASE("every POV-Ray 3.7 reserved word has a rule, each once", "[language][keywords]") {
    const std::vector<std::string> words = pov_words();
    REQUIRE(words.size() == 503);  // the recorded list, read whole
    const auto rules = lang::keyword_rules();
    std::vector<std::string> ruled;
    for (const auto& entry : rules) ruled.emplace_back(entry.word);
    CHECK(ruled == words);
    for (const auto& word : words) {
        INFO(word);
        const lang::KeywordRuleEntry* entry = lang::find_keyword_rule(word);
        REQUIRE(entry != nullptr);
        CHECK(entry->word == word);
        // A note says what hexant does instead, where it does not render.
        if (entry->rule == lang::KeywordRule::Warned || entry->rule == lang::KeywordRule::Harmless)
            CHECK(!entry->note.empty());
    }
    CHECK(lang::find_keyword_rule("not_a_pov_word") == nullptr);
}

TEST_CASE("a rendered word is one hexant's grammar reads", "[language][keywords]") {
    for (const auto& entry : lang::keyword_rules())
        if (entry.rule == lang::KeywordRule::Rendered) {
            INFO(entry.word);
            CHECK(lang::grammar::is_reserved_word(entry.word));
        }
}

TEST_CASE("a warned word warns at its line, and --strict refuses it", "[language][keywords]") {
    std::size_t probed = 0;
    for (const auto& entry : lang::keyword_rules()) {
        if (entry.rule != lang::KeywordRule::Warned) continue;
        INFO(entry.word);
        const auto found = probes().find(std::string(entry.word));
        REQUIRE(found != probes().end());  // every warned word has its probe
        const Probe& probe = found->second;
        INFO(probe.text);
        const Reading r = read(probe.text);
        REQUIRE_FALSE(r.error);
        bool named = false;
        for (const auto& w : r.warnings)
            named = named ||
                    (w.rfind("probe.pov:2:", 0) == 0 &&
                     w.find("'" + probe.named + "' is read but not rendered") != std::string::npos);
        CHECK(named);
        const Reading strict = read(probe.text, true);
        REQUIRE(strict.error);
        CHECK(strict.error->places().front().line == 2);
        ++probed;
    }
    // (The table still warns many words: 39 once media were rendered, 20
    // once radiosity was, 11 once photons were, 9 once dispersion was. A
    // table emptied by mistake would probe none.)
    CHECK(probed >= 9);
}

TEST_CASE("a harmless word reads silently", "[language][keywords]") {
    for (const auto& entry : lang::keyword_rules()) {
        if (entry.rule != lang::KeywordRule::Harmless) continue;
        INFO(entry.word);
        const auto found = probes().find(std::string(entry.word));
        REQUIRE(found != probes().end());
        const Reading r = read(found->second.text, true);
        CHECK_FALSE(r.error);
        CHECK(r.warnings.empty());
    }
}

TEST_CASE("a refused word is an error wherever it is written", "[language][keywords]") {
    // At the top level, in an object, in its pigment, finish and interior,
    // in a camera, in global_settings and as a value: each an error, none
    // read in silence.
    const std::vector<std::string> places = {
        "WORD",
        "sphere { 0, 1 WORD }",
        "sphere { 0, 1 pigment { WORD } }",
        "sphere { 0, 1 finish { WORD } }",
        "sphere { 0, 1 interior { WORD } }",
        "camera { WORD }",
        "global_settings { WORD 1 }",
        "#declare V = WORD;",
    };
    std::size_t refused = 0;
    for (const auto& entry : lang::keyword_rules()) {
        if (entry.rule != lang::KeywordRule::Refused) continue;
        ++refused;
        for (std::string text : places) {
            text.replace(text.find("WORD"), 4, entry.word);
            INFO(text);
            const Reading r = read(text);
            CHECK(r.error);
        }
    }
    // (60 once density_file, df3 and bump_map were rendered: the count
    // falls as hexant reads more; a table emptied by mistake refuses none.)
    CHECK(refused > 40);
}

TEST_CASE("a declaration hexant cannot render warns only where it is used",
          "[language][keywords]") {
    // An include file's declared texture (a finish's fresnel) says
    // nothing until an object uses it; then the warning names the
    // declaration's line and the object's.
    const std::string declared = "#declare T = texture { finish { fresnel } }";
    CHECK(read(declared).warnings.empty());
    const Reading used = read(declared +
                              "\nsphere { 0, 1 texture { T } }\n"
                              "sphere { 2, 1 texture { T } }");
    REQUIRE(used.warnings.size() == 1);  // once, however many use it
    CHECK(used.warnings[0].rfind("probe.pov:2:", 0) == 0);
    CHECK(used.warnings[0].find("(used by the object at probe.pov:3)") != std::string::npos);
    // A mesh face's own texture is used by the mesh.
    const Reading face = read(
        "#declare T = texture { pigment { rgb 1 } finish { fresnel } }\n"
        "mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> texture { T } } }");
    REQUIRE(face.warnings.size() == 1);
    CHECK(face.warnings[0].find("'fresnel'") != std::string::npos);
}

TEST_CASE("a scene POV-Ray reads with its legacy gamma rule is rendered so",
          "[language][keywords]") {
    // POV-Ray 3.7 renders a scene whose #version ends below 3.7 (3.62 when
    // there is none) and that sets no assumed_gamma without gamma
    // correction (parser.cpp); so does hexant, silently.
    const auto read_scene = [](const std::string& text) {
        lang::ParseOptions options;
        std::ostringstream messages;
        options.messages = &messages;
        return lang::parse_scene_text(text, "legacy.pov", options);
    };
    const std::string object = "sphere { 0, 1 pigment { rgb 0.5 } }\n";
    const auto legacy = [&](const std::string& text) {
        const auto scene = read_scene(text);
        CHECK(scene.warnings.empty());
        return !scene.global.gamma_correction;
    };
    CHECK(legacy(object));
    CHECK(legacy("#version 3.6;\n" + object));
    CHECK_FALSE(legacy("#version 3.7;\n" + object));
    CHECK_FALSE(legacy("global_settings { assumed_gamma 1 }\n" + object));
    CHECK_FALSE(legacy("#version 3.6;\nglobal_settings { assumed_gamma 2.2 }\n" + object));
    // A version changed and restored, as colors.inc does, leaves 3.7.
    CHECK_FALSE(legacy("#declare V = version; #version 3.5; #version V;\n" + object));
}
