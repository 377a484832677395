// The one validator: what a world, a body and the runtime settings must be,
// for every caller (the scene's reader, ~spawn_body, the runtime
// configuration, shards, the World's constructor and setters). Each check
// throws std::invalid_argument with one line naming the key and, for a body,
// the entry ("bodies[2] (name 'rod'): ..."); it does not read anything, so a
// reader's errors about how a value is written (a string for a number, two
// numbers for three) stay the reader's.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "rigid_body_sim/core/body_def.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/world_def.h"

namespace rigid_body_sim::core {

// The longest body name: a bound on what a hostile scene makes the node keep
// and send (a TF frame and topic names per body).
constexpr std::size_t kMaxBodyNameLength = 128;

// Who is told of a bad value, and so how its key is spelt. Each caller has
// always worded its errors its own way; the wording is kept, the condition is
// written once.
enum class KeyNaming {
  // The World's callers: "gravity must be finite", "wrench timeout must be
  // finite and >= 0".
  kWorld,
  // The node's private parameters at start: "~wrench_timeout must be >= 0,
  // got -1". The reader has already refused a number that is not finite.
  kParameter,
  // The runtime configuration's keys: "wrench_timeout must be finite and >=
  // 0, got -1", "gravity_y must be finite, got inf".
  kRuntime,
};

// Single keys, for the readers that check each key as they read it. The
// node's own keys (real-time factor, publish rate) have no World spelling:
// kWorld names them as kRuntime does.
void CheckIntegratorName(const std::string& name, KeyNaming naming);       // IntegratorTable()
void CheckGravity(const Eigen::Vector3d& gravity_mps2, KeyNaming naming);  // finite
void CheckWrenchTimeout(double timeout_s, KeyNaming naming);               // finite, >= 0
void CheckRealTimeFactor(double factor, KeyNaming naming);                 // finite, >= 0
// > 0 and at most the integration rate `rate_hz`.
void CheckPublishRate(double publish_rate_hz, double rate_hz, KeyNaming naming);

// What a World needs (kWorld): a known integrator, dt > 0, threads >= 1, a
// finite gravity, a finite wrench timeout >= 0, max_substeps >= 1.
void CheckWorldDef(const WorldDef& def);

// What a node stepping at `rate_hz` can take (kRuntime), in the order of the
// runtime configuration's checks: real-time factor, publish rate, gravity,
// wrench timeout, integrator.
void CheckRuntimeSettings(const RuntimeSettings& settings, double rate_hz);

// The scene's rules for the name of body `index`, which names a TF frame and
// topics: at most kMaxBodyNameLength characters, a letter and then letters,
// digits or '_'. The World itself only needs a name (CheckBodyDef).
void CheckBodyName(const std::string& name, std::size_t index);

// A finite gravity scale and damping rates that are finite and >= 0; the
// error names the key without the entry ("linear_damping must be a finite
// number >= 0 [1/s], got -1").
void CheckBodyProperties(const BodyProperties& properties);

// Who already has a frame name in a world: body `index` (its name) or one of
// its sites.
struct NameTaker {
  std::size_t index = 0;
  bool is_site = false;
};
// The taker of `name` among the bodies before the one checked, if any.
using NameLookup = std::function<std::optional<NameTaker>(const std::string& name)>;

// Body `index` of a world of `world`, stepped by `integrator` (made from
// world.integrator), in this order: a name; one that no body or site before
// it has (`taken`: who has a name; a site may share its own body's name);
// sites with names, unique among the body's own sites and free in `taken`;
// properties that CheckBodyProperties accepts; an initial state that
// CheckState accepts and that a step of the world takes within
// world.max_substeps (a new body holds no wrench), else "initial state is
// spin_aliased".
void CheckBodyDef(const BodyDef& def, std::size_t index, const WorldDef& world,
                  const Integrator& integrator, const NameLookup& taken = {});

// Every body of a scene as a World of `world` built from them checks them,
// names unique across all, without building one (a shard checks the whole
// scene and keeps its part).
void CheckBodyDefs(const std::vector<BodyDef>& defs, const WorldDef& world);

}  // namespace rigid_body_sim::core
