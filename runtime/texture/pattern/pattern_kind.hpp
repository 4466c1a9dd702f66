// What a pattern kind provides, as runtime/objects/shape_kind.hpp says it
// for object kinds: each kind is one file under runtime/texture/pattern/kinds/,
// a struct registered once in runtime/texture/pattern/kinds.hpp. The grammar's
// keywords and setting words are derived from that list at compile time
// (PatternWords), and registry.cpp turns each struct into the Kind the
// texture evaluator reads. A kind's struct has
//
//   static constexpr std::string_view keyword;  // POV-Ray's
//   value: its evaluation, a Function (pattern.hpp): a static member
//          function, or a pointer to one in its family's file
//
// and, where it differs from the default in brackets:
//
//   static constexpr Kind::Argument argument;  // what follows the keyword [None]
//   static constexpr int colours;              // a block pattern's list [0]
//   static constexpr Wave wave;                // [Ramp]
//   static constexpr bool frequency;           // false: frequency 0 [true]
//   static constexpr bool own_turbulence;      // reads classic turbulence [false]
//   static constexpr bool single_numbers;      // numbers in floats [true]
//   static constexpr std::array settings;      // its own modifiers, Setting [none]
//   static constexpr std::array default_map;   // MapEntry [black to white]
//   static constexpr NormalFunction normal;    // in a normal { } [its slope]
//   static constexpr std::array<double, 2> number;  // the argument's default [0]
//   static constexpr std::array<double, 3> vector;  // the argument's default [0]
//   static constexpr bool average;             // averages its map [false]
//
// The rules are POV-Ray 3.7's Parse_Pattern (parstxtr.cpp) and the defaults
// its pigment.cpp's.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

#include "runtime/sorted_words.hpp"
#include "runtime/texture/pattern/pattern.hpp"

namespace hexant::runtime::pattern {

// A list of pattern kinds (the registration, kinds.hpp).
template <class... K>
struct PatternKindList {};

// POV-Ray's default colour map (pigment.cpp): black to white.
inline constexpr std::array<MapEntry, 2> kGrayMap = {MapEntry{0.0, {0, 0, 0, 0, 0}},
                                                     MapEntry{1.0, {1, 1, 1, 0, 0}}};

namespace pattern_kind_detail {

template <class K>
constexpr Kind::Argument argument_of() {
    if constexpr (requires { K::argument; })
        return K::argument;
    else
        return Kind::Argument::None;
}
template <class K>
constexpr int colours_of() {
    if constexpr (requires { K::colours; })
        return K::colours;
    else
        return 0;
}
template <class K>
constexpr Wave wave_of() {
    if constexpr (requires { K::wave; })
        return K::wave;
    else
        return Wave::Ramp;
}
template <class K>
constexpr bool frequency_of() {
    if constexpr (requires { K::frequency; })
        return K::frequency;
    else
        return true;
}
template <class K>
constexpr bool own_turbulence_of() {
    if constexpr (requires { K::own_turbulence; })
        return K::own_turbulence;
    else
        return false;
}
template <class K>
constexpr bool single_numbers_of() {
    if constexpr (requires { K::single_numbers; })
        return K::single_numbers;
    else
        return true;
}
template <class K>
constexpr bool average_of() {
    if constexpr (requires { K::average; })
        return K::average;
    else
        return false;
}
template <class K>
constexpr auto settings_of() {
    if constexpr (requires { K::settings; })
        return K::settings;
    else
        return std::array<Setting, 0>{};
}
template <class K>
constexpr auto default_map_of() {
    if constexpr (requires { K::default_map; })
        return K::default_map;
    else
        return kGrayMap;
}
template <class K>
constexpr NormalFunction normal_of() {
    if constexpr (requires { K::normal; })
        return K::normal;
    else
        return nullptr;
}
template <class K>
constexpr std::array<double, 2> number_of() {
    if constexpr (requires { K::number; })
        return K::number;
    else
        return {};
}
template <class K>
constexpr std::array<double, 3> vector_of() {
    if constexpr (requires { K::vector; })
        return K::vector;
    else
        return {};
}

// The names of a kind's settings of one shape: with one value (a number
// or a vector), with two (Pair), or none (Flag).
constexpr bool same_shape(Setting::Type a, Setting::Type b) {
    const auto shape = [](Setting::Type t) {
        return t == Setting::Type::Vector ? Setting::Type::Number : t;
    };
    return shape(a) == shape(b);
}
template <class K, Setting::Type shape>
constexpr std::size_t setting_count() {
    std::size_t n = 0;
    for (const Setting& s : settings_of<K>()) n += same_shape(s.type, shape);
    return n;
}
template <class K, Setting::Type shape>
constexpr auto setting_names() {
    constexpr auto settings = settings_of<K>();
    std::array<std::string_view, setting_count<K, shape>()> out{};
    std::size_t n = 0;
    for (const Setting& s : settings)
        if (same_shape(s.type, shape)) out[n++] = s.name;
    return out;
}

}  // namespace pattern_kind_detail

// The sorted keywords and setting words of a list of kinds (the grammar's
// tables binary-search them; the keywords are reserved words).
template <class List>
struct PatternWords;

template <class... K>
struct PatternWords<PatternKindList<K...>> {
  private:
    static constexpr auto all_keywords = sorted_words::concat(std::array{K::keyword}...);
    static constexpr auto all_settings =
        sorted_words::concat(pattern_kind_detail::setting_names<K, Setting::Type::Number>()...);
    static constexpr auto all_pairs =
        sorted_words::concat(pattern_kind_detail::setting_names<K, Setting::Type::Pair>()...);
    static constexpr auto all_flags =
        sorted_words::concat(pattern_kind_detail::setting_names<K, Setting::Type::Flag>()...);

  public:
    static constexpr auto keywords = all_keywords;
    // The settings with one value, and those with two (exterior TYPE, FACTOR).
    static constexpr auto settings =
        sorted_words::unique<sorted_words::count_unique(all_settings)>(all_settings);
    static constexpr auto pair_settings =
        sorted_words::unique<sorted_words::count_unique(all_pairs)>(all_pairs);
    // The settings that are a word alone (crackle's solid).
    static constexpr auto flag_settings =
        sorted_words::unique<sorted_words::count_unique(all_flags)>(all_flags);
    static_assert(sorted_words::count_unique(all_keywords) == all_keywords.size(),
                  "two pattern kinds share a keyword");
};

// The Kind the texture evaluator reads, from a kind's struct.
template <class K>
Kind make_kind() {
    using namespace pattern_kind_detail;
    Kind kind;
    kind.name = K::keyword;
    kind.value = K::value;
    kind.argument = argument_of<K>();
    kind.colours = colours_of<K>();
    kind.wave = wave_of<K>();
    kind.frequency = frequency_of<K>();
    kind.own_turbulence = own_turbulence_of<K>();
    constexpr auto map = default_map_of<K>();
    kind.default_map.assign(map.begin(), map.end());
    constexpr auto settings = settings_of<K>();
    kind.settings.assign(settings.begin(), settings.end());
    kind.number = number_of<K>();
    kind.more = {};
    const std::array<double, 3> v = vector_of<K>();
    kind.vector = glm::dvec3(v[0], v[1], v[2]);
    const auto number_at = [&kind](int slot) -> double& {
        return slot < Setting::kMoreSlot
                   ? kind.number[static_cast<std::size_t>(slot)]
                   : kind.more[static_cast<std::size_t>(slot - Setting::kMoreSlot)];
    };
    for (const Setting& s : kind.settings) {
        if (s.type == Setting::Type::Vector) {
            kind.vector = glm::dvec3(s.vector[0], s.vector[1], s.vector[2]);
            continue;
        }
        number_at(s.slot) = s.number;
        if (s.type == Setting::Type::Pair) number_at(s.slot + 1) = s.second;
    }
    kind.normal = normal_of<K>();
    kind.single_numbers = single_numbers_of<K>();
    kind.average = average_of<K>();
    return kind;
}

}  // namespace hexant::runtime::pattern
