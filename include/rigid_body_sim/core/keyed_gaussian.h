// Standard normal numbers as a pure function of a key instead of a stream
// position: a noise sample is the same whoever asks for it and in whatever
// order, so a seeded run repeats exactly.
#pragma once

#include <cstdint>

namespace rigid_body_sim::core {

// The key of one draw: the run's seed, then what the number is for.
struct GaussianKey {
  std::uint64_t seed = 0;
  std::uint64_t body = 0;
  std::uint64_t step = 0;       // steps since start
  std::uint64_t component = 0;  // which scalar of the sample
};

// N(0, 1), the same for the same key on every platform with IEEE doubles.
double KeyedGaussian(const GaussianKey& key);

}  // namespace rigid_body_sim::core
