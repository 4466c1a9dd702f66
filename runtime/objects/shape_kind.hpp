// What an object kind is: one record type in its own folder
// (runtime/objects/<kind>/), registered once in runtime/objects/kinds.hpp,
// from which the language, the factory, the checks and the dump take what
// they need (pbrt-v4 keeps each shape's parameter reading beside the shape;
// Mitsuba registers its plugins in one place). A kind's record provides
//
//   static constexpr std::string_view keyword;   POV-Ray's word ("sphere")
//   using Model = objects::SphereModel;          its time functions, which the
//                                                factory wraps as Primitive<Model>
//   static Sphere read(const ShapeArguments&);   from the values in its block
//   template <class F> void parameters(F&& f) const;
//       calls f(name, phrase, value) for each parameter: name as the dump
//       and "which parameters move" print it ("center"), phrase as error
//       messages say it ("centre"), value one of the Parameter types below
//
// and, where it has them,
//
//   static constexpr std::array<std::string_view, N> options;
//       words written before its values (prism's linear_sweep)
//   static constexpr std::array<std::string_view, N> settings;
//   void set(std::string_view setting, const ShapeArguments& value);
//       words written among its modifiers (open), with their values
//   static constexpr bool kOwnSyntax = true;
//       its blocks are read by a rule of its own in the grammar (mesh),
//       not the generic "keyword { values modifiers }", and it has no read()
//   std::optional<std::string> standalone_error() const;
//       set when the block holds what belongs only inside another object (a
//       triangle's uv_vectors, read only in a mesh): the factory refuses
//       the object on its own, naming its place
//   std::optional<std::string> unsupported() const;
//       set when the block asked for a variant hexant lacks: kept
//       unevaluated, an error only where used.
#pragma once

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "runtime/objects/shape_arguments.hpp"
#include "runtime/sorted_words.hpp"
#include "runtime/time/time_ops.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime::objects {

// A parameter that is neither a number nor a vector (a font's name, a
// mesh's triangles): never a time function; the dump prints `text`.
struct DescribedParameter {
    std::string text;
};

template <class... Kinds>
struct KindList {};

// The index in a list of kinds of the kind whose keyword is `keyword`, or
// the list's size when none has it.
template <class... K>
constexpr std::size_t kind_index(KindList<K...>, std::string_view keyword) {
    constexpr std::array<std::string_view, sizeof...(K)> keywords{K::keyword...};
    for (std::size_t i = 0; i < keywords.size(); ++i)
        if (keywords[i] == keyword) return i;
    return keywords.size();
}

template <class... K>
constexpr std::size_t kind_count(KindList<K...>) {
    return sizeof...(K);
}

// The keyword of the kind at `index` of a list of kinds.
template <class... K>
constexpr std::string_view kind_keyword(KindList<K...>, std::size_t index) {
    constexpr std::array<std::string_view, sizeof...(K)> keywords{K::keyword...};
    return keywords.at(index);
}

// A setting that is a flag (`open`, `open off`, `open 0`): on unless its
// value is POV-Ray's false.
inline bool flag(const ShapeArguments& value) {
    return value.size() == 0 || pov_true(value.constant(0, "'" + value.keyword() + "'"));
}

// A triangle's uv_vectors setting: three <u, v> (POV-Ray's
// Parse_Three_UVCoords).
inline std::array<Vector2Function, 3> read_uv_vectors(const ShapeArguments& value) {
    value.need(3, 3, "three <u, v> vectors, one a corner");
    return {value.vector2(0, "first uv vector"), value.vector2(1, "second uv vector"),
            value.vector2(2, "third uv vector")};
}

namespace kind_detail {

template <class K>
constexpr bool own_syntax() {
    if constexpr (requires { K::kOwnSyntax; })
        return K::kOwnSyntax;
    else
        return false;
}

template <class K>
constexpr std::array<std::string_view, 1> keyword_of() {
    return {K::keyword};
}

// Kinds the generic shape block reads (not those with a rule of their own).
template <class K>
constexpr auto block_keyword_of() {
    if constexpr (own_syntax<K>())
        return std::array<std::string_view, 0>{};
    else
        return std::array<std::string_view, 1>{K::keyword};
}

template <class K>
constexpr auto options_of() {
    if constexpr (requires { K::options; })
        return K::options;
    else
        return std::array<std::string_view, 0>{};
}

template <class K>
constexpr auto settings_of() {
    if constexpr (requires { K::settings; })
        return K::settings;
    else
        return std::array<std::string_view, 0>{};
}

}  // namespace kind_detail

// The sorted keywords, option words and setting words of a list of kinds
// (grammar tables binary-search them).
template <class List>
struct KindWords;

template <class... K>
struct KindWords<KindList<K...>> {
  private:
    static constexpr auto all_keywords = sorted_words::concat(kind_detail::keyword_of<K>()...);
    static constexpr auto all_block_keywords =
        sorted_words::concat(kind_detail::block_keyword_of<K>()...);
    static constexpr auto all_options = sorted_words::concat(kind_detail::options_of<K>()...);
    static constexpr auto all_settings = sorted_words::concat(kind_detail::settings_of<K>()...);

  public:
    // Every kind's keyword (reserved words), and those of the kinds the
    // generic shape block reads.
    static constexpr auto keywords =
        sorted_words::unique<sorted_words::count_unique(all_keywords)>(all_keywords);
    static constexpr auto block_keywords =
        sorted_words::unique<sorted_words::count_unique(all_block_keywords)>(all_block_keywords);
    static constexpr auto options =
        sorted_words::unique<sorted_words::count_unique(all_options)>(all_options);
    static constexpr auto settings =
        sorted_words::unique<sorted_words::count_unique(all_settings)>(all_settings);
};

template <class K>
constexpr bool takes_setting(std::string_view word) {
    for (const auto w : kind_detail::settings_of<K>())
        if (w == word) return true;
    return false;
}

template <class K>
std::optional<std::string> unsupported_variant(const K& record) {
    if constexpr (requires { record.unsupported(); })
        return record.unsupported();
    else
        return std::nullopt;
}

}  // namespace hexant::runtime::objects
