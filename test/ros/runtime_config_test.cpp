// The runtime configuration without a master: the conversions between the
// settings and the server's configuration, the checks, and the .cfg's
// integrator enum against the core's table.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/ros/runtime_config.h"

namespace rigid_body_sim {
namespace {

NodeSettings StartSettings() {
  NodeSettings settings;
  settings.rate_hz = 500.0;
  settings.publish_rate_hz = 50.0;
  settings.real_time_factor = 2.0;
  settings.gravity_mps2 = {0.5, -1.0, -3.0};
  settings.wrench_timeout_s = 0.25;
  settings.publish_tf = false;
  settings.integrator = "rk4";
  return settings;
}

TEST(RuntimeConfig, ConfigAndSettingsConvertExactly) {
  const NodeSettings settings = StartSettings();
  const SimulationNodeConfig config = ToConfig(settings);
  EXPECT_EQ(config.real_time_factor, 2.0);
  EXPECT_EQ(config.publish_rate, 50.0);
  EXPECT_EQ(config.gravity_x, 0.5);
  EXPECT_EQ(config.gravity_y, -1.0);
  EXPECT_EQ(config.gravity_z, -3.0);
  EXPECT_EQ(config.wrench_timeout, 0.25);
  EXPECT_FALSE(config.publish_tf);
  EXPECT_EQ(config.integrator, "rk4");
  NodeSettings other;  // every runtime key different, the rest too
  other.rate_hz = 123.0;
  const NodeSettings back = WithConfig(other, config);
  EXPECT_TRUE(SameRuntimeKeys(back, settings));
  EXPECT_EQ(back.rate_hz, 123.0);  // not a runtime key
  EXPECT_FALSE(SameRuntimeKeys(other, settings));
}

TEST(RuntimeConfig, EveryValidValueIsApplicable) {
  NodeSettings settings = StartSettings();
  EXPECT_EQ(WhyNotApplicable(settings), std::nullopt);
  settings.real_time_factor = 0.0;  // unpaced
  settings.publish_rate_hz = settings.rate_hz;
  settings.wrench_timeout_s = 0.0;
  for (const std::string& name : core::IntegratorNames()) {
    settings.integrator = name;
    EXPECT_EQ(WhyNotApplicable(settings), std::nullopt) << name;
  }
}

TEST(RuntimeConfig, ABadValueIsRefusedNamingItsKey) {
  const auto why = [](void (*change)(NodeSettings*)) {
    NodeSettings settings = StartSettings();
    change(&settings);
    return WhyNotApplicable(settings).value_or("applicable");
  };
  EXPECT_EQ(why([](NodeSettings* s) { s->real_time_factor = -0.5; }),
            "real_time_factor must be finite and >= 0, got -0.5");
  EXPECT_EQ(why([](NodeSettings* s) { s->real_time_factor = std::nan(""); }),
            "real_time_factor must be finite and >= 0, got nan");
  EXPECT_EQ(why([](NodeSettings* s) { s->publish_rate_hz = 1000.0; }),
            "publish_rate must not exceed ~rate (500), got 1000");
  EXPECT_EQ(why([](NodeSettings* s) { s->publish_rate_hz = 0.0; }),
            "publish_rate must be > 0, got 0");
  EXPECT_EQ(why([](NodeSettings* s) { s->publish_rate_hz = -10.0; }),
            "publish_rate must be > 0, got -10");
  EXPECT_EQ(
      why([](NodeSettings* s) { s->gravity_mps2.y() = std::numeric_limits<double>::infinity(); }),
      "gravity_y must be finite, got inf");
  EXPECT_EQ(why([](NodeSettings* s) { s->wrench_timeout_s = -1.0; }),
            "wrench_timeout must be finite and >= 0, got -1");
  EXPECT_EQ(why([](NodeSettings* s) { s->integrator = "leapfrog"; }),
            "integrator: " + core::UnknownIntegratorMessage("leapfrog"));
}

// The .cfg's bounds must let a bad value through to the node's check rather
// than clamp it into a valid one of another meaning.
TEST(RuntimeConfig, TheCfgBoundsNeverClampABadValueIntoAValidOne) {
  const SimulationNodeConfig min = SimulationNodeConfig::__getMin__();
  const SimulationNodeConfig max = SimulationNodeConfig::__getMax__();
  const double inf = std::numeric_limits<double>::infinity();
  for (const double bound : {min.real_time_factor, min.publish_rate, min.gravity_x, min.gravity_y,
                             min.gravity_z, min.wrench_timeout}) {
    EXPECT_EQ(bound, -inf);
  }
  for (const double bound : {max.real_time_factor, max.publish_rate, max.gravity_x, max.gravity_y,
                             max.gravity_z, max.wrench_timeout}) {
    EXPECT_EQ(bound, inf);
  }
}

// The values of the integrator enum in the description the server publishes,
// in order (edit_method is the Python repr of the enum).
std::vector<std::string> EnumValues(const std::string& edit_method) {
  std::vector<std::string> values;
  const std::regex value("'value': '([^']*)'");
  for (std::sregex_iterator it(edit_method.begin(), edit_method.end(), value), end; it != end;
       ++it) {
    values.push_back((*it)[1]);
  }
  return values;
}

TEST(RuntimeConfig, TheIntegratorEnumIsTheCoresTable) {
  const dynamic_reconfigure::ConfigDescription description =
      SimulationNodeConfig::__getDescriptionMessage__();
  std::string edit_method;
  std::string default_value;
  for (const auto& group : description.groups) {
    for (const auto& param : group.parameters) {
      if (param.name == "integrator") edit_method = param.edit_method;
    }
  }
  for (const auto& entry : description.dflt.strs) {
    if (entry.name == "integrator") default_value = entry.value;
  }
  EXPECT_EQ(EnumValues(edit_method), core::IntegratorNames()) << edit_method;
  EXPECT_EQ(default_value, core::kDefaultIntegrator);
  const NodeSettings defaults;
  EXPECT_EQ(ToConfig(defaults).integrator, SimulationNodeConfig::__getDefault__().integrator);
}

TEST(RuntimeConfig, TheCfgDefaultsAreTheDocumentedParameterDefaults) {
  const NodeSettings defaults;
  const NodeSettings from_cfg = WithConfig(defaults, SimulationNodeConfig::__getDefault__());
  EXPECT_TRUE(SameRuntimeKeys(from_cfg, defaults));
}

}  // namespace
}  // namespace rigid_body_sim
