// A 64-bit fingerprint of the world's state as the node publishes it (doc/node.md,
// "State hash"): FNV-1a (Fowler–Noll–Vo) over the IEEE-754 little-endian bytes
// of each body's position (3), orientation (x, y, z, w), linear momentum (3)
// and angular momentum (3), in scene order. Equal runs give equal hashes, and
// a client recomputes it from the published message alone.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "rigid_body_sim/core/world.h"

namespace rigid_body_sim::core {

class Fnv1a64 {
 public:
  void AddBytes(const unsigned char* bytes, std::size_t count);
  // The value's eight IEEE-754 bytes, least significant first, on any host.
  void AddDouble(double value);
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;  // the FNV-1a 64 offset basis
};

// The values the hash covers, 13 per body in scene order.
constexpr std::size_t kStateHashValuesPerBody = 13;
void StateHashValues(const World& world, std::vector<double>* values);
std::uint64_t HashOfValues(const std::vector<double>& values);

// HashOfValues of StateHashValues (FNV-1a: one multiply per byte, in
// sequence; its cost is in bench/README.md, "State hash").
std::uint64_t StateHash(const World& world);
// 16 lower-case hexadecimal digits.
std::string HashHex(std::uint64_t hash);

}  // namespace rigid_body_sim::core
