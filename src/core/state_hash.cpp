#include "rigid_body_sim/core/state_hash.h"

#include <cstdio>
#include <cstring>

namespace rigid_body_sim::core {
namespace {

constexpr std::uint64_t kFnvPrime = 0x100000001b3ULL;

}  // namespace

void Fnv1a64::AddBytes(const unsigned char* bytes, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    hash_ ^= bytes[i];
    hash_ *= kFnvPrime;
  }
}

void Fnv1a64::AddDouble(double value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  unsigned char bytes[sizeof bits];
  for (std::size_t i = 0; i < sizeof bits; ++i)
    bytes[i] = static_cast<unsigned char>(bits >> (8 * i));
  AddBytes(bytes, sizeof bytes);
}

void StateHashValues(const World& world, std::vector<double>* values) {
  values->resize(kStateHashValuesPerBody * world.size());
  double* out = values->data();
  for (std::size_t body = 0; body < world.size(); ++body) {
    const BodyState& state = world.state(body);
    for (int i = 0; i < 3; ++i) *out++ = state.position[i];
    *out++ = state.orientation.x();
    *out++ = state.orientation.y();
    *out++ = state.orientation.z();
    *out++ = state.orientation.w();
    for (int i = 0; i < 3; ++i) *out++ = state.linear_momentum[i];
    for (int i = 0; i < 3; ++i) *out++ = state.angular_momentum[i];
  }
}

std::uint64_t HashOfValues(const std::vector<double>& values) {
  Fnv1a64 hash;
  for (double value : values) hash.AddDouble(value);
  return hash.value();
}

std::uint64_t StateHash(const World& world) {
  std::vector<double> values;
  StateHashValues(world, &values);
  return HashOfValues(values);
}

std::string HashHex(std::uint64_t hash) {
  char digits[17];
  std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(hash));
  return digits;
}

}  // namespace rigid_body_sim::core
