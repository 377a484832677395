// Every body's data, in scene order, and the one registry of who the bodies
// are: each has a BodyId that stays valid while it lives, its position (index)
// among the bodies, which moves down when a body before it goes, and a name.
//
// The data is split by how often it is touched. Hot columns are what every
// step reads or writes for every body: a step streams through them in index
// order, so each field is one dense array and nothing rarely used sits
// between the entries (a scene of 10⁴ bodies steps from memory, not cache).
// Cold columns are touched only on add, remove, reset or a recorded step.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "rigid_body_sim/core/body_def.h"
#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/body_id.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_properties.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/step_record.h"

namespace rigid_body_sim::core {

struct BodyHotColumns {
  // Read by every step (the inline part: mass, inverse principal moments,
  // principal axes; the rest is shared behind a pointer).
  std::vector<BodyModel> models;
  std::vector<BodyState> states;
  // This step's held wrenches, gravity and damping, summed anew only when
  // they change; loads[i] applies when loaded[i] is set.
  std::vector<HeldLoads> loads;
  std::vector<char> loaded;
  std::vector<BodyFault> faults;  // kNone while the body moves
  // The |L|² below which a free body needs no substep at the World's dt
  // (the cheap bound of the step's plan).
  std::vector<double> one_step_momentum_sq;

  template <typename F>
  void ForEach(F&& f) {
    f(models), f(states), f(loads), f(loaded), f(faults), f(one_step_momentum_sq);
  }
};

struct BodyColdColumns {
  std::vector<BodyId> ids;
  std::vector<BodyState> initial_states;  // what Reset brings each body back to
  std::vector<BodyProperties> properties;
  std::vector<BodyFrames> frames;
  // Filled only when a step is recorded (World::RecordNextStep), so they may
  // be shorter than the other columns.
  std::vector<StepRecord> step_records;
  std::vector<char> step_record_valid;  // stepped since Reset or SetBodyState

  template <typename F>
  void ForEach(F&& f) {
    f(ids), f(initial_states), f(properties), f(frames), f(step_records), f(step_record_valid);
  }
};

// A site: its body and its index among the body's sites.
struct SiteRef {
  BodyId body;
  std::size_t site = 0;
};

class BodyStore {
 public:
  std::size_t size() const { return hot_.models.size(); }

  // Appends a body (unchecked: the World checks it first) and returns its id.
  BodyId Add(BodyDef def);
  // Removes `id`'s body; the bodies after it move down by one. Throws
  // std::out_of_range for a stale id.
  void Remove(BodyId id);

  // The index of `id`'s body, or nullopt for a stale id.
  std::optional<std::size_t> IndexOf(BodyId id) const;
  // The same, throwing std::out_of_range for a stale id.
  std::size_t CheckedIndex(BodyId id) const;
  BodyId id(std::size_t index) const { return cold_.ids[index]; }
  // The body named `name`, if one lives.
  std::optional<BodyId> Find(const std::string& name) const;
  // The site named `name` (BodyFrames::sites), if one lives.
  std::optional<SiteRef> FindSite(const std::string& name) const;

  BodyHotColumns& hot() { return hot_; }
  const BodyHotColumns& hot() const { return hot_; }
  BodyColdColumns& cold() { return cold_; }
  const BodyColdColumns& cold() const { return cold_; }

 private:
  struct Slot {
    std::uint32_t generation = 0;
    std::size_t index = 0;  // valid while live
    bool live = false;
  };

  BodyHotColumns hot_;
  BodyColdColumns cold_;
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> free_slots_;
  std::unordered_map<std::string, BodyId> by_name_;
  std::unordered_map<std::string, SiteRef> sites_by_name_;
};

}  // namespace rigid_body_sim::core
