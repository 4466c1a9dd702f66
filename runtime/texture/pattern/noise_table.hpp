// POV-Ray 3.7's noise table (noise_table.cpp says where it comes from).
#pragma once

#include <array>
#include <cstddef>

namespace hexant::runtime::pattern {

inline constexpr std::size_t kNoiseTableSize = 267;
extern const std::array<double, kNoiseTableSize> kNoiseTable;

}  // namespace hexant::runtime::pattern
