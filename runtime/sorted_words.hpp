// Compile-time word tables: the registered object and pattern kinds'
// keywords and settings, merged and sorted, that the grammar's tables
// binary-search (runtime/objects/shape_kind.hpp's KindWords,
// runtime/texture/pattern/pattern_kind.hpp's PatternWords).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <string_view>
#include <tuple>

namespace hexant::runtime::sorted_words {

// The words of every array, in one sorted array (repeats kept).
template <class... A>
constexpr auto concat(const A&... arrays) {
    std::array<std::string_view, (0 + ... + std::tuple_size_v<A>)> out{};
    std::size_t at = 0;
    ((std::copy(arrays.begin(), arrays.end(), out.begin() + at), at += arrays.size()), ...);
    std::sort(out.begin(), out.end());
    return out;
}

// How many different words a sorted array holds.
template <std::size_t N>
constexpr std::size_t count_unique(const std::array<std::string_view, N>& sorted) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < N; ++i)
        if (i == 0 || sorted[i] != sorted[i - 1]) ++n;
    return n;
}

// A sorted array's M different words (M = count_unique(sorted)).
template <std::size_t M, std::size_t N>
constexpr std::array<std::string_view, M> unique(const std::array<std::string_view, N>& sorted) {
    std::array<std::string_view, M> out{};
    std::size_t n = 0;
    for (std::size_t i = 0; i < N; ++i)
        if (i == 0 || sorted[i] != sorted[i - 1]) out[n++] = sorted[i];
    return out;
}

}  // namespace hexant::runtime::sorted_words
