// The one validator: what a world and a body must be, for every caller (the
// scene's reader, a body spawned at run time, the runtime configuration,
// shards, the World's constructor and setters). Each check throws
// std::invalid_argument with one line naming the field as the World names it
// and, for a body, the entry ("bodies[2] (name 'rod'): ..."); a caller whose
// user knows the field by another name (a node's parameter) words the error
// its own way. It does not read anything, so a reader's errors about how a
// value is written (a string for a number, two numbers for three) stay the
// reader's.
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

// The settings a World takes between steps (RuntimeSettings), each alone:
// "gravity must be finite", "wrench timeout must be finite and >= 0".
void CheckIntegratorName(const std::string& name);       // IntegratorTable()
void CheckGravity(const Eigen::Vector3d& gravity_mps2);  // finite
void CheckWrenchTimeout(double timeout_s);               // finite, >= 0

// A finite mean, gust standard deviations finite and >= 0, a finite
// correlation time > 0.
void CheckWindDef(const WindDef& def);

// What a World needs: a known integrator, dt > 0, threads >= 1, a finite
// gravity, a finite wrench timeout >= 0, max_substeps >= 1, a wind that
// CheckWindDef accepts.
void CheckWorldDef(const WorldDef& def);

// The scene's rules for the name of body `index`, which names a TF frame and
// topics: at most kMaxBodyNameLength characters, a letter and then letters,
// digits or '_'. The World itself only needs a name (CheckBodyDef).
void CheckBodyName(const std::string& name, std::size_t index);

// A finite gravity scale, damping rates and drag coefficients that are
// finite and >= 0; the error names the key without the entry
// ("linear_damping must be a finite number >= 0 [1/s], got -1").
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
// actuators with names unique in the body, each at one of its sites, with
// finite thrusts min_thrust <= max_thrust, a finite torque coefficient and a
// finite time constant >= 0; properties that CheckBodyProperties accepts;
// an initial state that CheckState accepts and that a step of the world takes
// within world.max_substeps (a new body holds no wrench), else "initial state
// is spin_aliased".
void CheckBodyDef(const BodyDef& def, std::size_t index, const WorldDef& world,
                  const Integrator& integrator, const NameLookup& taken = {});

// Every body of a scene as a World of `world` built from them checks them,
// names unique across all, without building one (a shard checks the whole
// scene and keeps its part).
void CheckBodyDefs(const std::vector<BodyDef>& defs, const WorldDef& world);

}  // namespace rigid_body_sim::core
