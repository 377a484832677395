#include "rigid_body_sim/core/keyed_gaussian.h"

#include <cmath>

namespace rigid_body_sim::core {
namespace {

// SplitMix64's increment and output function (Steele, Lea, Flood 2014): a
// bijection of 64-bit words whose output bits each depend on every input bit.
constexpr std::uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ULL;

std::uint64_t Mix(std::uint64_t z) {
  z += kGoldenGamma;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// The top 53 bits as a double in [0, 1).
double Unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

}  // namespace

double KeyedGaussian(const GaussianKey& key) {
  // Each part is mixed into the hash of the parts before it, so that keys
  // differing in any one part give unrelated words.
  std::uint64_t hash = Mix(key.seed);
  hash = Mix(hash ^ key.body);
  hash = Mix(hash ^ key.step);
  hash = Mix(hash ^ key.component);
  // Box–Muller with u1 in (0, 1] so that the logarithm is finite.
  const double u1 = 1.0 - Unit(Mix(hash));
  const double u2 = Unit(Mix(hash + kGoldenGamma));
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

}  // namespace rigid_body_sim::core
