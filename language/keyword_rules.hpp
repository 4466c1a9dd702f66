// What hexant does with each of POV-Ray 3.7's reserved words: renders it as
// POV-Ray does, reads it and warns at its place that it does not, accepts it
// silently where ignoring it cannot change the image, or refuses it with an
// error at its place. The list is POV-Ray 3.7.0.10's
// (source/backend/parser/reswords.cpp, its words only);
// tests/language/keyword_rules_test.cpp walks it and asserts each rule.
#pragma once

#include <span>
#include <string_view>

namespace hexant::language {

enum class KeywordRule {
    Rendered,  // read and rendered as POV-Ray renders it
    Warned,    // read, not rendered as POV-Ray renders it: a warning at its place
    Harmless,  // read silently: ignoring it cannot change the image
    Refused,   // an error at its place
};

struct KeywordRuleEntry {
    std::string_view word;
    KeywordRule rule;
    // For Warned and Harmless: what hexant does instead, and why.
    std::string_view note;
};

// Every entry, sorted by word.
std::span<const KeywordRuleEntry> keyword_rules();
// The entry for `word`; null when it is not one of POV-Ray 3.7's words.
const KeywordRuleEntry* find_keyword_rule(std::string_view word);

}  // namespace hexant::language
