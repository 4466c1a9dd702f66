#include "app/povray_words.hpp"

#include <algorithm>
#include <cctype>

#include "language/ini_file.hpp"
#include "language/povray_options.hpp"

namespace hexant::app {

namespace {

// Put before a marked switch: a control character no one types, so that
// the word is no flag to CLI11 and no file name to anyone.
constexpr char kMark = '\x1f';

bool ends_with_pov(const std::string& word) {
    if (word.size() <= 4) return false;
    std::string tail = word.substr(word.size() - 4);
    std::transform(tail.begin(), tail.end(), tail.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return tail == ".pov";
}

bool is_option_word(const std::string& word) {
    const auto eq = word.find('=');
    return eq != std::string::npos && eq > 0 && language::is_povray_option_key(word.substr(0, eq));
}

// -W, -H (alone or with a number), -L, -o and -h: hexant's own.
bool is_own_short_flag(const std::string& word) {
    const std::string body = word.substr(1);
    const char c = body[0];
    if (c == 'W' || c == 'H')
        return body.size() == 1 || body[1] == '=' ||
               body.find_first_not_of("0123456789", 1) == std::string::npos;
    return c == 'L' || c == 'o' || body == "h";
}

bool is_minus_switch(const std::string& word) {
    return word.size() >= 2 && word[0] == '-' && word[1] != '-' && !is_own_short_flag(word) &&
           language::is_povray_switch(word.substr(1));
}

}  // namespace

void mark_minus_switches(std::vector<std::string>& words) {
    for (auto& word : words)
        if (is_minus_switch(word)) word.insert(word.begin(), kMark);
}

std::optional<std::string> minus_switch(const std::string& word) {
    if (word.size() < 3 || word[0] != kMark) return std::nullopt;
    return word.substr(1);
}

std::vector<std::string> command_line_words(int argc, const char* const* argv) {
    std::vector<std::string> words(argv + std::min(argc, 1), argv + argc);
    if (words.empty()) return words;
    const std::string& first = words.front();
    static const char* const kSubcommands[] = {"check", "dump",        "render",
                                               "farm",  "merge-stats", "bench"};
    const bool subcommand = std::any_of(std::begin(kSubcommands), std::end(kSubcommands),
                                        [&](const char* name) { return first == name; });
    if (!subcommand &&
        (ends_with_pov(first) || language::ini_reference(first) ||
         (first.size() >= 2 && first[0] == '+') || is_option_word(first) || is_minus_switch(first)))
        words.insert(words.begin(), "render");
    // The subcommands that read a scene with add_scene_arguments.
    const std::string& command = words.front();
    std::size_t from = 0;
    if (command == "check" || command == "dump" || command == "render") from = 1;
    if (command == "bench" && words.size() > 1 && words[1] == "error-time") from = 2;
    if (from > 0) {
        std::vector<std::string> rest(words.begin() + static_cast<std::ptrdiff_t>(from),
                                      words.end());
        mark_minus_switches(rest);
        std::copy(rest.begin(), rest.end(), words.begin() + static_cast<std::ptrdiff_t>(from));
    }
    return words;
}

}  // namespace hexant::app
