// The thrusters of the bodies that have any (doc/physics.md, "Thrusters"):
// each thruster's held command u with its start time, its thrust T and the
// mean thrust of the step under way. Bodies without thrusters are not in the
// table, so a world without any costs a step nothing here.
//
// A command is held as a wrench is (wrench_table.h): it replaces the one held
// for the same thruster, acts from its start time and, with a timeout, until
// start + timeout; while none acts u = 0. T follows u with its lag whatever
// u is, so at a timeout T decays from where it is.
//
// The mean thrusts change in most steps while the held wrenches do not, so
// a thrust is added to its body's loads on top of the sum of the rest, kept
// per body: a step whose thrusts alone changed adds the new ones to that sum
// for the bodies whose thrust changed, without summing any other load anew.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/body_id.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/thruster.h"

namespace rigid_body_sim::core {

class ActuatorTable {
 public:
  // Body `id` at `index` in the store with `thrusters` (checked:
  // CheckBodyDef), whose sites are in `frames`, stepped by `step_s`; a body
  // without thrusters is not kept.
  void AddBody(BodyId id, std::size_t index, const BodyModel& model, const BodyFrames& frames,
               std::vector<ThrusterDef> thrusters, double step_s);
  // Body `id`, at `index`, is gone; the bodies after it moved down by one.
  void RemoveBody(BodyId id, std::size_t index);
  bool empty() const { return bodies_.empty(); }

  // The thrusters of `id` in their order, or nullptr for a body without any.
  const std::vector<ThrusterDef>* thrusters(BodyId id) const;
  // T of each of `id`'s thrusters at the world's time [N] (empty for a body
  // without any).
  std::vector<double> thrusts(BodyId id) const;

  // Holds `command_n` for thruster `thruster` of `id` from `start_s`, clipped
  // to the thruster's range. The caller has checked it: a body with that
  // thruster, finite numbers.
  void Hold(BodyId id, std::size_t thruster, double command_n, double start_s);
  // Every command dropped, every T back to 0.
  void Clear();
  // The same for `id`'s thrusters (nothing for a body without any).
  void ClearBody(BodyId id);

  // Starts the step at t_s: drops the commands that expired (start + timeout
  // − tolerance < t_s, for timeout_s > 0), takes each thruster's u (its
  // command if it started by t_s + tolerance, else 0), sets the step's mean
  // thrust and moves T to the end of the step. Returns whether any mean
  // thrust differs from the last step's (then UpdateLoads).
  bool StartStep(double t_s, double timeout_s, double tolerance_s);
  // After every other load of the step was summed anew into `loads` and
  // `loaded` (the store's columns): keeps each body's sum and adds the mean
  // thrusts and their couples of this step to it, setting loaded[i] for a
  // body with a thrust.
  void AddLoads(std::vector<HeldLoads>* loads, std::vector<char>* loaded);
  // The other loads kept since AddLoads: the sum AddLoads kept, plus the
  // step's mean thrusts, for each body whose mean thrust changed.
  void UpdateLoads(std::vector<HeldLoads>* loads, std::vector<char>* loaded) const;

 private:
  struct Thruster {
    // From the COM to the site's origin and the site's +z, body axes.
    Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    // The body-axes torque about the COM per newton of thrust: the force's
    // moment offset × axis plus the couple torque_coefficient · axis.
    Eigen::Vector3d torque_per_n = Eigen::Vector3d::Zero();
    double min_thrust_n = 0.0;
    double max_thrust_n = 0.0;
    ThrusterLag lag;
    bool held = false;  // a command is held
    double command_n = 0.0;
    double start_s = 0.0;
    double thrust_n = 0.0;       // T at the world's time
    double mean_thrust_n = 0.0;  // over the step under way (the last started)
  };
  struct ActuatedBody {
    BodyId id;
    std::size_t index = 0;  // in the store
    std::vector<ThrusterDef> defs;
    std::vector<Thruster> thrusters;
    // The step's mean thrusts as a body-axes force at the COM and a couple;
    // `thrusts`: some mean thrust is not 0.
    Eigen::Vector3d force_n = Eigen::Vector3d::Zero();
    Eigen::Vector3d torque_nm = Eigen::Vector3d::Zero();
    bool thrusts = false;
    bool thrust_changed = false;  // in the step under way
    // The body's other loads, as AddLoads found them.
    HeldLoads::BodyAxesSum other_loads{};
    bool other_loaded = false;
  };
  ActuatedBody* Find(BodyId id);
  const ActuatedBody* Find(BodyId id) const;
  static void Zero(Thruster* thruster);
  // Adds `body`'s mean thrusts to `loads`, setting `loaded` if it has any.
  static void AddThrust(const ActuatedBody& body, HeldLoads* loads, char* loaded);

  std::vector<ActuatedBody> bodies_;  // in no particular order
  BodyMap<std::size_t> index_;        // id → position in bodies_
};

}  // namespace rigid_body_sim::core
