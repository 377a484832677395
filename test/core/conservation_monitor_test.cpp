// ConservationMonitor's sweep (no ROS master needed): the largest drift and
// its body come from a completed pass over all bodies, spread over steps.
#include <gtest/gtest.h>

#include "rigid_body_sim/core/conservation_monitor.h"
#include "rigid_body_sim/core/shapes.h"
#include "rigid_body_sim/core/world.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

World ThreeTumblingBoxes() {
  std::vector<BodyModel> models;
  std::vector<BodyState> states(3);
  for (int i = 0; i < 3; ++i) {
    models.emplace_back("box" + std::to_string(i), MakeBox(1.0, {0.2, 0.3, 0.4}, 2));
    states[i].angular_momentum = {0.01, 0.02 * (i + 1), 0.0};
  }
  return World(WorldDef{}, test::Bodies(std::move(models), std::move(states)));
}

TEST(ConservationMonitor, SweepReportsTheLargestDriftOnceAPassIsComplete) {
  World world = ThreeTumblingBoxes();
  ConservationMonitor monitor(world);
  // Box 1's |L| grows by 10 % behind the monitor's back (no Rebase).
  BodyState pushed = world.state(1);
  pushed.angular_momentum *= 1.1;
  world.SetBodyState(world.id(1), pushed);

  monitor.Sweep(world, 2);  // bodies 0 and 1: the pass is not complete
  EXPECT_FALSE(monitor.last_sweep().measured);
  monitor.Sweep(world, 1);  // body 2 completes it
  const ConservationMonitor::Largest& largest = monitor.last_sweep();
  ASSERT_TRUE(largest.measured);
  EXPECT_EQ(largest.angular_momentum_body, 1u);
  EXPECT_NEAR(largest.angular_momentum_norm, 0.1, 1e-12);
  EXPECT_EQ(largest.rotational_energy_body, 1u);
  EXPECT_NEAR(largest.rotational_energy, 1.1 * 1.1 - 1.0, 1e-12);  // E ∝ |L|²

  // A body with a held wrench conserves nothing and is left out.
  monitor.MarkLoaded(world.id(1));
  monitor.Sweep(world, 3);
  EXPECT_NE(monitor.last_sweep().angular_momentum_body, 1u);
  EXPECT_EQ(monitor.last_sweep().angular_momentum_norm, 0.0);

  // After a rebase of all bodies the sweep starts over.
  monitor.RebaseAll(world);
  EXPECT_FALSE(monitor.last_sweep().measured);
}

}  // namespace
}  // namespace rigid_body_sim::core
