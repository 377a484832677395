// libFuzzer target: the bytes as the YAML text of a ~spawn_body request,
// through the node's path (ServiceFront::OnSpawnBody): XmlRpcFromYaml,
// ParseBodyEntry, then World::AddBody into a world that already has a body.
//
// A SceneError or any std::exception is a correct answer (the node sends
// its message back); a crash, a hang, a sanitizer report, an exception of
// another type, or memory beyond fuzz.sh's -rss_limit_mb / -malloc_limit_mb
// (YAML aliases can expand a short text into gigabytes) is a bug.
//
// Invariants checked on success (abort otherwise): one finite model, state
// and set of properties, unit orientation; the world takes the body with a
// finite state, and is back to its one body once the new one is removed.
//
// Build and run: scripts/fuzz.sh.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/shapes.h"
#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/yaml_value.h"

namespace {

namespace core = rigid_body_sim::core;

// The node's world before the request; built once, and every accepted body is
// removed again, so inputs do not see each other's bodies.
std::unique_ptr<core::World> world;

bool Finite(const core::BodyState& s) {
  return s.position.allFinite() && s.orientation.coeffs().allFinite() &&
         s.linear_momentum.allFinite() && s.angular_momentum.allFinite();
}

// RBS_FUZZ_VERBOSE=1 prints what the parser said (to read a reproducer).
bool Verbose() {
  static const bool verbose = std::getenv("RBS_FUZZ_VERBOSE") != nullptr;
  return verbose;
}

[[noreturn]] void Fail(const char* what) {
  std::fprintf(stderr, "service_text_fuzzer: invariant broken: %s\n", what);
  std::abort();
}

// No master: a `urdf: {param: ..}` finds no parameter.
bool NoParameters(const std::string&, XmlRpc::XmlRpcValue*) { return false; }

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const core::BodyModel box("box", core::MakeBox(1.0, Eigen::Vector3d(0.2, 0.2, 0.2), 2));
  const core::BodyState at_rest =
      core::StateFromTwist(box, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity(),
                           Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  world = std::make_unique<core::World>(core::WorldDef{},
                                        std::vector<core::BodyDef>{core::BodyDef(box, at_rest)});
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::optional<rigid_body_sim::SceneBody> entry;
  try {
    entry = rigid_body_sim::ParseBodyEntry(rigid_body_sim::XmlRpcFromYaml(text), world->size(),
                                           NoParameters);
  } catch (const std::exception& error) {  // SceneError: the node's answer
    if (Verbose()) std::fprintf(stderr, "refused: %s\n", error.what());
    return 0;
  }
  // XmlRpc::XmlRpcException or anything else escapes: libFuzzer reports it.
  const core::BodyModel& model = entry->def.model;
  const core::BodyState& state = entry->def.initial_state;
  if (!(std::isfinite(model.mass()) && model.mass() > 0.0)) Fail("finite positive total mass");
  if (!model.inertia().allFinite() || !model.inverse_inertia().allFinite()) Fail("finite inertia");
  if (!Finite(state)) Fail("finite initial state");
  if (std::abs(state.orientation.norm() - 1.0) > 1e-9) Fail("unit orientation");
  if (Verbose())
    std::fprintf(stderr, "parsed '%s', %zu particles\n", model.name().c_str(),
                 model.particle_count());

  const std::size_t before = world->size();
  try {
    world->AddBody(std::move(entry->def));
  } catch (const std::exception& error) {  // a name in use, a state out of bounds
    if (Verbose()) std::fprintf(stderr, "World: %s\n", error.what());
    if (world->size() != before) Fail("a refused body left in the world");
    return 0;
  }
  if (world->size() != before + 1 || !Finite(world->state(before)))
    Fail("finite state in the world");
  world->RemoveBody(world->id(before));
  if (world->size() != before) Fail("the world back to its bodies");
  return 0;
}
