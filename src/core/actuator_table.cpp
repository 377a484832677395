#include "rigid_body_sim/core/actuator_table.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace rigid_body_sim::core {

void ActuatorTable::AddBody(BodyId id, std::size_t index, const BodyModel& model,
                            const BodyFrames& frames, std::vector<ThrusterDef> thrusters,
                            double step_s) {
  if (thrusters.empty()) return;
  ActuatedBody body;
  body.id = id;
  body.index = index;
  for (const ThrusterDef& def : thrusters) {
    const auto site = std::find_if(frames.sites.begin(), frames.sites.end(),
                                   [&def](const Site& s) { return s.name == def.site; });
    assert(site != frames.sites.end());
    Thruster thruster;
    thruster.offset_m = BodyOffset(model, site->position_m);
    thruster.axis = site->orientation * Eigen::Vector3d::UnitZ();
    thruster.torque_per_n =
        thruster.offset_m.cross(thruster.axis) + def.torque_coefficient_m * thruster.axis;
    thruster.min_thrust_n = def.min_thrust_n;
    thruster.max_thrust_n = def.max_thrust_n;
    thruster.lag = ThrusterLag(def.time_constant_s, step_s);
    body.thrusters.push_back(thruster);
  }
  body.defs = std::move(thrusters);
  index_.Insert(id, bodies_.size());
  bodies_.push_back(std::move(body));
}

void ActuatorTable::RemoveBody(BodyId id, std::size_t index) {
  if (Find(id) != nullptr) {
    const std::size_t i = index_.at(id);
    index_.Erase(id);
    if (i + 1 != bodies_.size()) {
      bodies_[i] = std::move(bodies_.back());
      index_.at(bodies_[i].id) = i;
    }
    bodies_.pop_back();
  }
  for (ActuatedBody& body : bodies_) {
    if (body.index > index) --body.index;
  }
}

ActuatorTable::ActuatedBody* ActuatorTable::Find(BodyId id) {
  return const_cast<ActuatedBody*>(static_cast<const ActuatorTable*>(this)->Find(id));
}

const ActuatorTable::ActuatedBody* ActuatorTable::Find(BodyId id) const {
  return index_.Contains(id) ? &bodies_[index_.at(id)] : nullptr;
}

const std::vector<ThrusterDef>* ActuatorTable::thrusters(BodyId id) const {
  const ActuatedBody* body = Find(id);
  return body != nullptr ? &body->defs : nullptr;
}

std::vector<double> ActuatorTable::thrusts(BodyId id) const {
  std::vector<double> thrusts;
  if (const ActuatedBody* body = Find(id)) {
    for (const Thruster& thruster : body->thrusters) thrusts.push_back(thruster.thrust_n);
  }
  return thrusts;
}

void ActuatorTable::Hold(BodyId id, std::size_t thruster, double command_n, double start_s) {
  ActuatedBody* body = Find(id);
  assert(body != nullptr && thruster < body->thrusters.size());
  assert(std::isfinite(command_n) && std::isfinite(start_s));
  Thruster& held = body->thrusters[thruster];
  held.held = true;
  held.command_n = std::clamp(command_n, held.min_thrust_n, held.max_thrust_n);
  held.start_s = start_s;
}

void ActuatorTable::Zero(Thruster* thruster) {
  thruster->held = false;
  thruster->command_n = 0.0;
  thruster->thrust_n = 0.0;
}

void ActuatorTable::Clear() {
  for (ActuatedBody& body : bodies_) {
    for (Thruster& thruster : body.thrusters) Zero(&thruster);
  }
}

void ActuatorTable::ClearBody(BodyId id) {
  if (ActuatedBody* body = Find(id)) {
    for (Thruster& thruster : body->thrusters) Zero(&thruster);
  }
}

bool ActuatorTable::StartStep(double t_s, double timeout_s, double tolerance_s) {
  bool changed = false;
  for (ActuatedBody& body : bodies_) {
    body.thrust_changed = false;
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();
    bool thrusts = false;
    for (Thruster& thruster : body.thrusters) {
      // The comparisons of WrenchTable::Reduce, so that a command and a
      // wrench with the same stamp start and expire at the same step.
      if (thruster.held && timeout_s > 0.0 && t_s > thruster.start_s + timeout_s - tolerance_s) {
        thruster.held = false;
      }
      const double command_n =
          thruster.held && !(thruster.start_s > t_s + tolerance_s) ? thruster.command_n : 0.0;
      const double mean_n = thruster.lag.Mean(thruster.thrust_n, command_n);
      body.thrust_changed = body.thrust_changed || mean_n != thruster.mean_thrust_n;
      thruster.mean_thrust_n = mean_n;
      thruster.thrust_n = thruster.lag.End(thruster.thrust_n, command_n);
      if (mean_n == 0.0) continue;
      force += mean_n * thruster.axis;
      torque += mean_n * thruster.torque_per_n;
      thrusts = true;
    }
    body.force_n = force;
    body.torque_nm = torque;
    body.thrusts = thrusts;
    changed = changed || body.thrust_changed;
  }
  return changed;
}

void ActuatorTable::AddThrust(const ActuatedBody& body, HeldLoads* loads, char* loaded) {
  if (!body.thrusts) return;
  loads->AddBodyForce(body.force_n, Eigen::Vector3d::Zero());
  loads->AddBodyCouple(body.torque_nm);
  *loaded = 1;
}

void ActuatorTable::AddLoads(std::vector<HeldLoads>* loads, std::vector<char>* loaded) {
  for (ActuatedBody& body : bodies_) {
    HeldLoads& body_loads = (*loads)[body.index];
    body.other_loads = body_loads.body_axes_sum();
    body.other_loaded = (*loaded)[body.index] != 0;
    AddThrust(body, &body_loads, &(*loaded)[body.index]);
  }
}

void ActuatorTable::UpdateLoads(std::vector<HeldLoads>* loads, std::vector<char>* loaded) const {
  for (const ActuatedBody& body : bodies_) {
    if (!body.thrust_changed) continue;
    HeldLoads& body_loads = (*loads)[body.index];
    body_loads.RestoreBodyAxesSum(body.other_loads);
    (*loaded)[body.index] = body.other_loaded ? 1 : 0;
    AddThrust(body, &body_loads, &(*loaded)[body.index]);
  }
}

}  // namespace rigid_body_sim::core
