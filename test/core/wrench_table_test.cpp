#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/wrench_table.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

class WrenchTableTest : public ::testing::Test {
 protected:
  WrenchTableTest() {
    store_.Add(BodyDef{test::Diag123Body()});
    store_.Add(BodyDef{test::RodBody()});
    table_ = Table();
  }
  // A table that knows the store's bodies.
  WrenchTable Table() const {
    WrenchTable table;
    for (std::size_t i = 0; i < store_.size(); ++i) {
      table.AddBody(Id(i), store_.hot().models[i].particle_count());
    }
    return table;
  }
  BodyId Id(std::size_t index) const { return store_.id(index); }
  const BodyModel& Model(std::size_t index) const { return store_.hot().models[index]; }

  BodyStore store_;
  WrenchTable table_;
  std::vector<HeldLoads> loads_ = std::vector<HeldLoads>(2);
  std::vector<char> loaded_ = std::vector<char>(2, 0);

  Wrench Reduced(double t, double timeout, std::size_t body, const Eigen::Matrix3d& a) {
    table_.Reduce(t, timeout, 1e-9, store_, &loads_, &loaded_);
    return loaded_[body] ? loads_[body].At(0.0, a) : Wrench{};
  }
};

ParticleWrench WorldForce(BodyId body, std::size_t particle, const Eigen::Vector3d& f,
                          double start = 0.0) {
  ParticleWrench w;
  w.body = body;
  w.particle = particle;
  w.force = f;
  w.start_s = start;
  return w;
}

TEST_F(WrenchTableTest, ReducesToForceAndTorqueAboutTheCom) {
  // Random world- and body-axes forces and couples at a random orientation,
  // against the lecture's τ = Σ r_i × f_i summed directly in world axes.
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  const Eigen::Matrix3d a =
      Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), torque = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < 4; ++i) {
    ParticleWrench w = WorldForce(Id(0), i, Eigen::Vector3d(n(rng), n(rng), n(rng)));
    w.couple = Eigen::Vector3d(n(rng), n(rng), n(rng));
    w.axes = i % 2 ? WrenchAxes::kBody : WrenchAxes::kWorld;
    table_.Hold(w);
    const Eigen::Matrix3d to_world = i % 2 ? a : Eigen::Matrix3d::Identity();
    const Eigen::Vector3d r = a * Model(0).particle_offsets()[i];
    force += to_world * w.force;
    torque += r.cross(to_world * w.force) + to_world * w.couple;
  }
  const Wrench reduced = Reduced(0.0, 0.0, 0, a);
  EXPECT_TRUE(reduced.force.isApprox(force, 1e-13));
  EXPECT_TRUE(reduced.torque.isApprox(torque, 1e-13));
  EXPECT_FALSE(loaded_[1]);
}

TEST_F(WrenchTableTest, LaterWrenchForTheSameParticleReplaces) {
  table_.Hold(WorldForce(Id(0), 1, {1, 0, 0}));
  table_.Hold(WorldForce(Id(0), 2, {0, 2, 0}));
  table_.Hold(WorldForce(Id(0), 1, {0, 0, 5}));
  EXPECT_EQ(table_.size(), 2u);
  const Wrench w = Reduced(0.0, 0.0, 0, Eigen::Matrix3d::Identity());
  EXPECT_TRUE(w.force.isApprox(Eigen::Vector3d(0, 2, 5)));
}

TEST_F(WrenchTableTest, ActiveFromStartUntilTimeout) {
  table_.Hold(WorldForce(Id(1), 0, {1, 0, 0}, 0.5));
  const Eigen::Matrix3d id = Eigen::Matrix3d::Identity();
  EXPECT_TRUE(Reduced(0.499, 0.25, 1, id).force.isZero());  // not yet started
  EXPECT_FALSE(loaded_[1]);
  EXPECT_TRUE(Reduced(0.5, 0.25, 1, id).force.isApprox(Eigen::Vector3d(1, 0, 0)));  // start <= t
  EXPECT_TRUE(Reduced(0.7, 0.25, 1, id).force.isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(Reduced(0.75, 0.25, 1, id).force.isZero());  // t < start + timeout fails
  EXPECT_EQ(table_.size(), 0u);                            // and it is dropped for good
}

TEST_F(WrenchTableTest, WithoutTimeoutHeldUntilCleared) {
  table_.Hold(WorldForce(Id(1), 2, {0, 1, 0}));
  const Eigen::Matrix3d id = Eigen::Matrix3d::Identity();
  EXPECT_FALSE(Reduced(1e6, 0.0, 1, id).force.isZero());
  table_.Clear();
  EXPECT_TRUE(Reduced(1e6, 0.0, 1, id).force.isZero());
  EXPECT_FALSE(loaded_[1]);
}

TEST_F(WrenchTableTest, KeptSumsEqualSumsFromScratchAtEveryStep) {
  // Wrenches starting and expiring at random steps, some replaced on the
  // way: at every step the table that keeps its sums between changes gives
  // the same loads, bit for bit, as a table summing from scratch, and it sums
  // anew only when a wrench starts, expires or is held.
  const double dt = 1e-3, timeout = 0.02;
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> step_of(0, 60);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<ParticleWrench> wrenches;
  for (int k = 0; k < 7; ++k) {  // one per particle of the two bodies
    ParticleWrench w = WorldForce(Id(k < 4 ? 0 : 1), k < 4 ? k : k - 4,
                                  Eigen::Vector3d(n(rng), n(rng), n(rng)), step_of(rng) * dt);
    w.axes = k % 4 < 2 ? WrenchAxes::kWorld : WrenchAxes::kBody;
    w.couple = Eigen::Vector3d(n(rng), n(rng), n(rng));
    wrenches.push_back(w);
  }
  const int hold_again_at = 30;  // wrenches[0] once more, from then on
  for (const ParticleWrench& w : wrenches) table_.Hold(w);
  const Eigen::Matrix3d a =
      Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
  int sums = 0;
  for (int step = 0; step <= 100; ++step) {
    const double t = step * dt;
    ParticleWrench again = wrenches[0];
    again.start_s = hold_again_at * dt;
    if (step == hold_again_at) table_.Hold(again);
    sums += table_.Reduce(t, timeout, 1e-9, store_, &loads_, &loaded_);

    WrenchTable scratch = Table();
    // What the table still holds: every wrench until it expires (the same
    // comparison as Reduce's), wrenches[0] replaced by `again` from its hold.
    const auto held = [&](const ParticleWrench& w) { return !(t > w.start_s + timeout - 1e-9); };
    for (std::size_t k = step >= hold_again_at ? 1 : 0; k < wrenches.size(); ++k) {
      if (held(wrenches[k])) scratch.Hold(wrenches[k]);
    }
    if (step >= hold_again_at && held(again)) scratch.Hold(again);
    std::vector<HeldLoads> expected(2);
    std::vector<char> expected_loaded(2, 0);
    scratch.Reduce(t, timeout, 1e-9, store_, &expected, &expected_loaded);
    for (std::size_t body = 0; body < 2; ++body) {
      SCOPED_TRACE("step " + std::to_string(step) + ", body " + std::to_string(body));
      ASSERT_EQ(loaded_[body], expected_loaded[body]);
      if (!loaded_[body]) continue;
      const Wrench kept = loads_[body].At(0.0, a), fresh = expected[body].At(0.0, a);
      EXPECT_EQ(kept.force, fresh.force);
      EXPECT_EQ(kept.torque, fresh.torque);
    }
  }
  // Once per change at most: 8 starts, 8 expiries, the second hold and the first call.
  EXPECT_LE(sums, 18);
}

TEST_F(WrenchTableTest, BodyWrenchActsAtTheComAddsToParticleWrenchesAndReplacesItself) {
  const Eigen::Matrix3d a =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  table_.Hold(WorldForce(Id(0), 1, {1, 0, 0}));
  BodyWrench body_wrench;
  body_wrench.body = Id(0);
  body_wrench.axes = WrenchAxes::kBody;
  body_wrench.force = {0.0, 5.0, 0.0};
  body_wrench.couple = {0.0, 0.0, 2.0};
  table_.HoldBodyWrench(body_wrench);
  body_wrench.force = {0.0, 3.0, 0.0};  // replaces the first
  table_.HoldBodyWrench(body_wrench);
  const Wrench reduced = Reduced(0.0, 0.0, 0, a);
  const Eigen::Vector3d particle_force(1, 0, 0);
  const Eigen::Vector3d r = a * Model(0).particle_offsets()[1];
  EXPECT_TRUE(reduced.force.isApprox(particle_force + a * body_wrench.force, 1e-14));
  EXPECT_TRUE(reduced.torque.isApprox(r.cross(particle_force) + a * body_wrench.couple, 1e-14));
  EXPECT_EQ(table_.size(), 2u);
}

TEST_F(WrenchTableTest, WorldBodyWrenchWithoutCoupleLeavesTheBodyTorqueFree) {
  BodyWrench push;
  push.body = Id(1);
  push.force = {0.0, 0.0, 4.0};
  table_.HoldBodyWrench(push);
  Reduced(0.0, 0.0, 1, Eigen::Matrix3d::Identity());
  EXPECT_FALSE(loads_[1].has_torque());
}

TEST_F(WrenchTableTest, JobActsAtItsPointOverItsWindowAndIsThenForgotten) {
  // As a particle at the job's point would: τ = (A r̄) × f.
  const Eigen::Matrix3d a =
      Eigen::AngleAxisd(-1.1, Eigen::Vector3d(0, 1, 1).normalized()).toRotationMatrix();
  WrenchJob job;
  job.body = Id(1);
  job.force = {0.0, 2.0, 0.0};
  job.point_m = {0.5, 0.0, 0.0};
  job.start_s = 0.1;
  job.end_s = 0.3;
  ASSERT_EQ(table_.AddJob(job, 0.0), JobRefusal::kNone);
  ASSERT_EQ(table_.AddJob(job, 0.0), JobRefusal::kNone);  // jobs add up
  EXPECT_EQ(Reduced(0.09, 0.0, 1, a).force, Eigen::Vector3d::Zero());
  for (double t : {0.1, 0.2, 0.29}) {
    const Wrench w = Reduced(t, 0.0, 1, a);
    EXPECT_TRUE(w.force.isApprox(2.0 * job.force, 1e-15)) << t;
    EXPECT_TRUE(w.torque.isApprox(2.0 * (a * job.point_m).cross(job.force), 1e-14)) << t;
  }
  // The wrench timeout does not apply to jobs.
  EXPECT_TRUE(Reduced(0.2, 0.05, 1, a).force.isApprox(2.0 * job.force, 1e-15));
  EXPECT_EQ(Reduced(0.3, 0.0, 1, a).force, Eigen::Vector3d::Zero());
  EXPECT_EQ(table_.job_count(), 0u);
  EXPECT_EQ(table_.size(), 0u);
}

TEST_F(WrenchTableTest, JobsAreCappedPerBodyCountingOnlyLiveOnes) {
  WrenchJob job;
  job.body = Id(0);
  job.force = {1.0, 0.0, 0.0};
  job.end_s = 1.0;
  for (std::size_t k = 0; k < WrenchTable::kMaxJobsPerBody; ++k) {
    ASSERT_EQ(table_.AddJob(job, 0.0), JobRefusal::kNone);
  }
  EXPECT_EQ(table_.AddJob(job, 0.0), JobRefusal::kBodyFull);
  job.body = Id(1);
  EXPECT_EQ(table_.AddJob(job, 0.0), JobRefusal::kNone);  // another body has room
  job.body = Id(0);
  EXPECT_EQ(table_.AddJob(job, 1.0), JobRefusal::kNone);  // the others ended at 1.0
  EXPECT_EQ(table_.job_count(Id(0)), 1u);
  EXPECT_EQ(table_.job_count(), 1u);  // body 1's ended at 1.0 too
}

TEST_F(WrenchTableTest, ClearBodyDropsOneBodysWrenchesOnly) {
  table_.Hold(WorldForce(Id(0), 1, {1, 0, 0}));
  table_.Hold(WorldForce(Id(1), 0, {0, 1, 0}));
  BodyWrench push;
  push.body = Id(0);
  push.force = {0, 0, 1};
  table_.HoldBodyWrench(push);
  WrenchJob job;
  job.body = Id(0);
  job.end_s = std::numeric_limits<double>::infinity();
  table_.AddJob(job, 0.0);
  table_.ClearBody(Id(0));
  EXPECT_EQ(table_.size(), 1u);
  EXPECT_EQ(table_.job_count(Id(0)), 0u);
  Reduced(0.0, 0.0, 0, Eigen::Matrix3d::Identity());
  EXPECT_FALSE(loaded_[0]);
  EXPECT_TRUE(loaded_[1]);
}

TEST_F(WrenchTableTest, RemovedBodysWrenchesGoAndTheOthersKeepTheirsAfterMovingDown) {
  const BodyId third =
      store_.Add(BodyDef{BodyModel("third", {{1.0, {0, 0, 0}}, {1.0, {1, 0, 0}}})});
  table_.AddBody(third, 2);
  const BodyId first = Id(0);
  table_.Hold(WorldForce(first, 1, {1, 0, 0}));
  table_.Hold(WorldForce(third, 1, {0, 7, 0}));
  table_.RemoveBody(first);
  store_.Remove(first);                          // the rod is now at index 0, the third body at 1
  table_.Hold(WorldForce(third, 0, {0, 0, 3}));  // adds to its own, on another particle
  const Wrench w = Reduced(0.0, 0.0, 1, Eigen::Matrix3d::Identity());
  EXPECT_EQ(w.force, Eigen::Vector3d(0, 7, 3));
  EXPECT_FALSE(loaded_[0]);
  EXPECT_EQ(table_.size(), 2u);
}

TEST_F(WrenchTableTest, AStaleIdIsCaught) {
  const BodyId rod = Id(1);
  table_.RemoveBody(rod);
  store_.Remove(rod);
  const BodyId reused = store_.Add(BodyDef{test::RodBody()});
  ASSERT_EQ(reused.slot, rod.slot);  // the slot is reused, under a new generation
  EXPECT_NE(reused, rod);
  EXPECT_FALSE(store_.IndexOf(rod).has_value());
  EXPECT_THROW(table_.job_count(rod), std::out_of_range);
  EXPECT_THROW(store_.CheckedIndex(rod), std::out_of_range);
}

}  // namespace
}  // namespace rigid_body_sim::core
