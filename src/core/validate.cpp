#include "rigid_body_sim/core/validate.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <unordered_map>

#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/check.h"
#include "rigid_body_sim/core/format_number.h"
#include "step_policy.h"

namespace rigid_body_sim::core {
namespace {

std::string Entry(std::size_t index, const std::string& name) {
  return "bodies[" + std::to_string(index) + "] (name '" + name + "')";
}

// A valid TF frame and ROS graph name.
bool IsValidBodyName(const std::string& name) {
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

// Why `properties` cannot be simulated, or "".
std::string PropertiesError(const BodyProperties& properties) {
  if (!std::isfinite(properties.gravity_scale)) {
    return "gravity_scale must be a finite number, got " + FormatNumber(properties.gravity_scale);
  }
  const auto damping_error = [](const char* key, double value) -> std::string {
    if (std::isfinite(value) && value >= 0.0) return "";
    return std::string(key) + " must be a finite number >= 0 [1/s], got " + FormatNumber(value);
  };
  std::string error = damping_error("linear_damping", properties.linear_damping_per_s);
  if (error.empty()) error = damping_error("angular_damping", properties.angular_damping_per_s);
  const Drag& drag = properties.drag;
  const auto drag_error = [](const char* key, const Eigen::Vector3d& value,
                             const char* unit) -> std::string {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(value[k]) || value[k] < 0.0) {
        return std::string("drag.") + key + " must be 3 finite numbers >= 0 [" + unit + "], got " +
               FormatNumber(value[k]);
      }
    }
    return "";
  };
  if (error.empty()) error = drag_error("linear", drag.linear_Nspm, "N s/m");
  if (error.empty()) error = drag_error("quadratic", drag.quadratic_Ns2pm2, "N s^2/m^2");
  if (error.empty()) error = drag_error("angular.linear", drag.angular_linear_Nms, "N m s");
  if (error.empty()) {
    error = drag_error("angular.quadratic", drag.angular_quadratic_Nms2, "N m s^2");
  }
  return error;
}

// Why thruster `def` cannot act on a body with `sites`, or "": the error
// names the key as the scene does.
std::string ThrusterError(const ThrusterDef& def, const std::vector<Site>& sites) {
  if (def.name.empty()) return "name must not be empty";
  if (std::none_of(sites.begin(), sites.end(),
                   [&def](const Site& site) { return site.name == def.site; })) {
    return "site '" + def.site + "' is not a site of the body";
  }
  const auto finite = [](const char* key, double value) -> std::string {
    if (std::isfinite(value)) return "";
    return std::string(key) + " must be a finite number, got " + FormatNumber(value);
  };
  for (const std::string& error :
       {finite("max_thrust", def.max_thrust_n), finite("min_thrust", def.min_thrust_n),
        finite("torque_coefficient", def.torque_coefficient_m)}) {
    if (!error.empty()) return error;
  }
  if (!(def.min_thrust_n <= def.max_thrust_n)) {
    return "min_thrust (" + FormatNumber(def.min_thrust_n) + ") must be <= max_thrust (" +
           FormatNumber(def.max_thrust_n) + ")";
  }
  if (!std::isfinite(def.time_constant_s) || def.time_constant_s < 0.0) {
    return "time_constant must be a finite number >= 0 [s], got " +
           FormatNumber(def.time_constant_s);
  }
  return "";
}

}  // namespace

void CheckIntegratorName(const std::string& name) {
  RBS_CHECK(FindIntegrator(name) != nullptr, UnknownIntegratorMessage(name));
}

void CheckGravity(const Eigen::Vector3d& gravity_mps2) {
  RBS_CHECK(gravity_mps2.allFinite(), "gravity must be finite");
}

void CheckWrenchTimeout(double timeout_s) {
  RBS_CHECK(std::isfinite(timeout_s) && timeout_s >= 0.0, "wrench timeout must be finite and >= 0");
}

void CheckWindDef(const WindDef& def) {
  RBS_CHECK(def.velocity_mps.allFinite(), "wind.velocity must be finite");
  RBS_CHECK(def.gust_stddev_mps.allFinite() && (def.gust_stddev_mps.array() >= 0.0).all(),
            "wind.gust_stddev must be 3 finite numbers >= 0 [m/s]");
  RBS_CHECK(std::isfinite(def.gust_time_constant_s) && def.gust_time_constant_s > 0.0,
            "wind.gust_time_constant must be a finite number > 0 [s], got " +
                FormatNumber(def.gust_time_constant_s));
}

void CheckWorldDef(const WorldDef& def) {
  CheckIntegratorName(def.integrator);
  RBS_CHECK(def.dt_s > 0.0, "dt must be > 0");
  RBS_CHECK(def.threads >= 1, "threads must be >= 1");
  // What the setters check too, after the checks above: a def that breaks
  // one of those and one of these is named by the first.
  CheckGravity(def.gravity);
  CheckWrenchTimeout(def.wrench_timeout_s);
  RBS_CHECK(def.max_substeps >= 1, "max_substeps must be >= 1");
  CheckWindDef(def.wind);
}

void CheckBodyName(const std::string& name, std::size_t index) {
  RBS_CHECK(name.size() <= kMaxBodyNameLength, Entry(index, name) + ": name is longer than " +
                                                   std::to_string(kMaxBodyNameLength) +
                                                   " characters");
  RBS_CHECK(IsValidBodyName(name), Entry(index, name) +
                                       ": name must be a letter then letters, digits or '_' "
                                       "(it names a TF frame and topics)");
}

void CheckBodyProperties(const BodyProperties& properties) {
  const std::string error = PropertiesError(properties);
  RBS_CHECK(error.empty(), error);
}

namespace {

std::string TakerName(const NameTaker& taker) {
  return std::string(taker.is_site ? "a site of " : "") + "bodies[" + std::to_string(taker.index) +
         "]";
}

}  // namespace

void CheckBodyDef(const BodyDef& def, std::size_t index, const WorldDef& world,
                  const Integrator& integrator, const NameLookup& taken) {
  RBS_DCHECK(world.integrator == integrator.name());
  const std::string& name = def.model.name();
  RBS_CHECK(!name.empty(), Entry(index, name) + ": name must not be empty");
  const auto taker = [&](const std::string& frame) {
    return taken ? taken(frame) : std::optional<NameTaker>();
  };
  if (const std::optional<NameTaker> owner = taker(name)) {
    RBS_CHECK(owner->index == index, Entry(index, name) + ": name duplicates " + TakerName(*owner));
  }
  const std::vector<Site>& sites = def.frames.sites;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const std::string site = Entry(index, name) + ": sites[" + std::to_string(k) + "]";
    RBS_CHECK(!sites[k].name.empty(), site + ": name must not be empty");
    for (std::size_t j = 0; j < k; ++j) {
      RBS_CHECK(
          sites[j].name != sites[k].name,
          site + ": name '" + sites[k].name + "' duplicates sites[" + std::to_string(j) + "]");
    }
    if (const std::optional<NameTaker> owner = taker(sites[k].name)) {
      RBS_CHECK(owner->index == index,
                site + ": name '" + sites[k].name + "' duplicates " + TakerName(*owner));
    }
  }
  const std::vector<ThrusterDef>& thrusters = def.actuators;
  for (std::size_t k = 0; k < thrusters.size(); ++k) {
    const std::string thruster = Entry(index, name) + ": actuators[" + std::to_string(k) +
                                 "] (name '" + thrusters[k].name + "')";
    const std::string error = ThrusterError(thrusters[k], sites);
    RBS_CHECK(error.empty(), thruster + ": " + error);
    for (std::size_t j = 0; j < k; ++j) {
      RBS_CHECK(thrusters[j].name != thrusters[k].name,
                thruster + ": name duplicates actuators[" + std::to_string(j) + "]");
    }
  }
  const std::string properties_error = PropertiesError(def.properties);
  RBS_CHECK(properties_error.empty(), Entry(index, name) + ": " + properties_error);
  BodyFault fault = CheckState(def.model, def.initial_state);
  // A new body holds no wrench yet: World::Step's count of a free body's substeps.
  if (fault == BodyFault::kNone && SubstepsFor(integrator, def.model, def.initial_state, nullptr,
                                               world.dt_s, world.max_substeps) == 0) {
    fault = BodyFault::kSpinAliased;
  }
  RBS_CHECK(fault == BodyFault::kNone,
            Entry(index, name) + ": initial state is " + ToString(fault));
}

void CheckBodyDefs(const std::vector<BodyDef>& defs, const WorldDef& world) {
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(world.integrator);
  std::unordered_map<std::string, NameTaker> takers;
  const NameLookup taken = [&takers](const std::string& name) -> std::optional<NameTaker> {
    const auto found = takers.find(name);
    if (found == takers.end()) return std::nullopt;
    return found->second;
  };
  for (std::size_t i = 0; i < defs.size(); ++i) {
    CheckBodyDef(defs[i], i, world, *integrator, taken);
    takers.emplace(defs[i].model.name(), NameTaker{i, false});
    for (const Site& site : defs[i].frames.sites) takers.emplace(site.name, NameTaker{i, true});
  }
}

}  // namespace rigid_body_sim::core
