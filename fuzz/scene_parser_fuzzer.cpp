// libFuzzer target: an arbitrary XmlRpcValue tree (what rosparam hands the
// node for ~bodies) through rigid_body_sim::ParseBodies.
//
// The bytes drive a small generator of nested arrays / structs / strings /
// ints / doubles / bools whose struct keys come mostly from the scene's own
// vocabulary, so that the parser gets past its first checks. A SceneError or
// any std::exception from the parser is a correct answer; a crash, a hang, a
// sanitizer report or an exception of another type (e.g. XmlRpc's
// XmlRpcException, which is not a std::exception) is a bug.
//
// Invariant checked on success (abort otherwise): one finite model and one
// finite initial state per entry, unit orientation.
//
// Build and run: scripts/fuzz.sh.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/scene_params.h"

#include "byte_reader.h"

namespace {

using XmlRpc::XmlRpcValue;

const char* const kKeys[] = {
    "name",
    "particles",
    "mass",
    "position",
    "orientation",
    "linear_velocity",
    "angular_velocity",
    "shape",
    "size",
    "radius",
    "length",
    "resolution",
    "gravity_scale",
    "linear_damping",
    "angular_damping",
};
const char* const kStrings[] = {"box", "sphere", "cylinder",  "rod",  "a",    "b_1",
                                "",    "1x",     "has space", "cube", "Body", "x"};

double Number(ByteReader* in) {
  switch (in->Byte() % 16) {
    case 0:
      return 0.0;
    case 1:
      return 1.0;
    case 2:
      return -1.0;
    case 3:
      return 0.5;
    case 4:
      return 1e-300;
    case 5:
      return 1e300;
    case 6:
      return -1e300;
    case 7:
      return std::numeric_limits<double>::quiet_NaN();
    case 8:
      return std::numeric_limits<double>::infinity();
    case 9:
      return -std::numeric_limits<double>::infinity();
    case 10:
      return std::numeric_limits<double>::denorm_min();
    case 11:
      return std::numeric_limits<double>::max();
    case 12:
      return std::numeric_limits<double>::epsilon();
    case 13:
      return static_cast<double>(static_cast<std::int8_t>(in->Byte())) / 8.0;
    default:
      return in->RawDouble();
  }
}

int Int(ByteReader* in) {
  switch (in->Byte() % 8) {
    case 0:
      return 0;
    case 1:
      return 1;
    case 2:
      return -1;
    case 3:
      return 40;
    case 4:
      return 41;
    case 5:
      return std::numeric_limits<int>::max();
    case 6:
      return std::numeric_limits<int>::min();
    default:
      return static_cast<int>(in->U32());
  }
}

std::string Key(ByteReader* in) {
  const std::uint8_t b = in->Byte();
  constexpr std::size_t kKnown = sizeof(kKeys) / sizeof(kKeys[0]);
  if (b % 16 < kKnown) return kKeys[b % 16];
  return in->String(12);
}

XmlRpcValue Value(ByteReader* in, int depth);

XmlRpcValue Array(ByteReader* in, int depth, std::size_t max_len) {
  XmlRpcValue array;
  const int len = static_cast<int>(in->Byte() % (max_len + 1));
  array.setSize(len);
  for (int i = 0; i < len; ++i) array[i] = Value(in, depth + 1);
  return array;
}

XmlRpcValue Struct(ByteReader* in, int depth) {
  XmlRpcValue map;
  map.begin();  // makes it an (empty) struct
  const int members = in->Byte() % 9;
  for (int i = 0; i < members; ++i) {
    const std::string key = Key(in);
    map[key] = Value(in, depth + 1);
  }
  return map;
}

// A vector of numbers, the most common kind of value in a scene.
XmlRpcValue NumberList(ByteReader* in) {
  XmlRpcValue list;
  const int len = static_cast<int>(in->Byte() % 6);
  list.setSize(len);
  for (int i = 0; i < len; ++i) {
    if (in->Byte() % 4 == 0)
      list[i] = Int(in);
    else
      list[i] = Number(in);
  }
  return list;
}

XmlRpcValue Value(ByteReader* in, int depth) {
  if (in->empty()) return XmlRpcValue(1.0);
  const std::uint8_t kind = in->Byte() % (depth >= 6 ? 6 : 10);
  switch (kind) {
    case 0:
      return XmlRpcValue(Number(in));
    case 1:
      return XmlRpcValue(Int(in));
    case 2:
      return XmlRpcValue(static_cast<bool>(in->Byte() & 1));
    case 3:
      return XmlRpcValue(
          std::string(kStrings[in->Byte() % (sizeof(kStrings) / sizeof(kStrings[0]))]));
    case 4:
      return XmlRpcValue(in->String(140));
    case 5:
      return NumberList(in);
    case 6:
    case 7:
      return Struct(in, depth);
    case 8:
      return Array(in, depth, 8);
    default:
      return XmlRpcValue();  // TypeInvalid
  }
}

bool Finite(const rigid_body_sim::core::BodyState& s) {
  return s.position.allFinite() && s.orientation.coeffs().allFinite() &&
         s.linear_momentum.allFinite() && s.angular_momentum.allFinite();
}

// RBS_FUZZ_VERBOSE=1 prints what the parser said (to read a reproducer).
bool Verbose() {
  static const bool verbose = std::getenv("RBS_FUZZ_VERBOSE") != nullptr;
  return verbose;
}

void Fail(const char* what, std::size_t body) {
  std::fprintf(stderr, "scene_parser_fuzzer: invariant broken: %s (body %zu)\n", what, body);
  std::abort();
}

// No master: a `urdf: {param: ..}` finds no parameter.
bool NoParameters(const std::string&, XmlRpc::XmlRpcValue*) { return false; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  // The top level is mostly a list of structs, so most inputs reach ParseBody.
  XmlRpcValue bodies;
  switch (in.Byte() % 8) {
    case 0:
      bodies = Value(&in, 0);
      break;
    default: {
      const int len = 1 + in.Byte() % 4;
      bodies.setSize(len);
      for (int i = 0; i < len; ++i) bodies[i] = Struct(&in, 1);
    }
  }

  std::vector<rigid_body_sim::SceneBody> scene_bodies;
  try {
    scene_bodies = rigid_body_sim::ParseBodies(bodies, NoParameters);
  } catch (const rigid_body_sim::SceneError& error) {
    if (Verbose()) std::fprintf(stderr, "SceneError: %s\n", error.what());
    return 0;
  } catch (const std::exception& error) {
    if (Verbose()) std::fprintf(stderr, "std::exception: %s\n", error.what());
    return 0;
  }
  if (Verbose()) std::fprintf(stderr, "parsed %zu bodies\n", scene_bodies.size());
  // XmlRpc::XmlRpcException or anything else escapes: libFuzzer reports it.

  if (scene_bodies.size() != static_cast<std::size_t>(bodies.size())) {
    Fail("one body per entry", 0);
  }
  // The node's scene path ends in the World, which checks names and states.
  std::optional<rigid_body_sim::core::World> world;
  try {
    world.emplace(rigid_body_sim::core::WorldDef{},
                  rigid_body_sim::CoreDefs(std::move(scene_bodies)));
  } catch (const std::invalid_argument& error) {
    if (Verbose()) std::fprintf(stderr, "World: %s\n", error.what());
    return 0;
  }
  const std::vector<rigid_body_sim::core::BodyState>& states = world->states();
  for (std::size_t i = 0; i < world->size(); ++i) {
    const auto& m = world->model(i);
    if (!(std::isfinite(m.mass()) && m.mass() > 0.0)) Fail("finite positive total mass", i);
    if (!m.inertia().allFinite() || !m.inverse_inertia().allFinite()) Fail("finite inertia", i);
    if (!Finite(states[i])) Fail("finite initial state", i);
    if (std::abs(states[i].orientation.norm() - 1.0) > 1e-9) Fail("unit orientation", i);
  }
  return 0;
}
