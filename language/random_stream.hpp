// POV-Ray 3.7's seed()/rand(): one stream per seed() call, each a 32-bit
// linear congruential generator.
#pragma once

#include <cstdint>

namespace hexant::language {

class RandomStream {
  public:
    // seed(seed_value): the value is truncated to an int as C++ does; a value
    // outside int's range (or NaN) becomes INT_MIN, as x86 conversion gives in
    // POV-Ray. The int's bits are the generator's starting state.
    explicit RandomStream(double seed_value);

    // rand(stream): state = state * 1812433253 + 12345 (mod 2^32), then
    // state / (2^32 - 1), a value in [0, 1].
    double next();

  private:
    std::uint32_t state_;
};

}  // namespace hexant::language
