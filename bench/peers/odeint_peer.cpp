// Boost.Odeint (Boost 1.74, header-only) on the free body's 13-number state
// y = (x, q, p, L) of rigid_body_ode.h, the way a user of a generic ODE
// library integrates a rigid body: the quaternion is a plain state variable,
// normalised only in the states handed out, never inside the solver.
//
// Settings:
// - odeint_rkf78: runge_kutta_fehlberg78<std::array<double, 13>> used as a
//   fixed-step method (do_step with dt; its embedded error estimate unused):
//   the eighth-order solution, 13 stages per step.
// - odeint_dopri5: make_dense_output(tolerance, tolerance,
//   runge_kutta_dopri5<...>()), i.e. Dormand–Prince 5(4) with odeint's default
//   error checker (absolute and relative tolerance both `tolerance`, ratios
//   a_x = 1, a_dxdt = 1) and its step-size controller; outputs on the 1 ms
//   grid by its dense output (the Hermite interpolant of dopri5), stepping
//   as integrate_times does: steps until the output time is passed, then
//   calc_state at that time. First trial step: 1 ms. One stepper per copy,
//   so that each copy has its own step sizes.
// - Loads: the scene's wrench from the pose at the start of each step
//   (odeint_rkf78) held over the step, like the engines. odeint_dopri5
//   runs only on scenes whose wrench is constant (torque-free, the constant
//   couple): holding time-varying forces over each 1 ms output would make
//   the hold, not the tolerance, set its error.
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/numeric/odeint.hpp>

#include "engine_peers.h"
#include "peer_loads.h"
#include "rigid_body_ode.h"

namespace rigid_body_sim::bench {
namespace {

namespace odeint = boost::numeric::odeint;

class OdeintFixedStepPeer final : public Peer {
 public:
  std::string name() const override { return "odeint_rkf78"; }

  void Setup(const Scene& scene, int copies, double dt_s) override {
    run_.Start(scene, dt_s);
    ode_.emplace(*run_.model);
    states_.assign(copies, ToOdeState(scene.initial));
  }

  void Step() override {
    const double t_s = run_.step * run_.dt_s;
    const bool loaded = !run_.loads->empty();
    if (loaded) run_.loads->BeginStep(t_s);
    for (OdeState& y : states_) {
      if (loaded) {
        Eigen::Vector3d force, torque;
        run_.loads->Wrench(OdeOrientation(y).toRotationMatrix(), &force, &torque);
        ode_->set_wrench(force, torque);
      }
      stepper_.do_step(*ode_, y, t_s, run_.dt_s);
    }
    ++run_.step;
  }

  PeerState State(int copy) const override { return FromOdeState(states_[copy]); }

 private:
  PeerRun run_;
  std::optional<RigidBodyOde> ode_;
  odeint::runge_kutta_fehlberg78<OdeState> stepper_;
  std::vector<OdeState> states_;
};

class OdeintAdaptivePeer final : public Peer {
 public:
  explicit OdeintAdaptivePeer(double tolerance) : tolerance_(tolerance) {}

  std::string name() const override { return "odeint_dopri5"; }
  Stepping stepping() const override { return Stepping::kAdaptive; }
  std::optional<double> tolerance() const override { return tolerance_; }
  bool Handles(const Scene& scene) const override { return scene.forces.empty(); }

  void Setup(const Scene& scene, int copies, double dt_s) override {
    run_.Start(scene, dt_s);
    ode_.emplace(*run_.model);
    // Handles() leaves the constant couple as the only load.
    ode_->set_wrench(Eigen::Vector3d::Zero(), scene.constant_couple);
    copies_.assign(copies, Copy{odeint::make_dense_output(tolerance_, tolerance_, Dopri5()),
                                ToOdeState(scene.initial)});
    for (Copy& copy : copies_) copy.stepper.initialize(copy.output, 0.0, kOutputInterval_s);
  }

  void Step() override {
    const double t_out_s = (run_.step + 1) * run_.dt_s;
    for (Copy& copy : copies_) {
      while (copy.stepper.current_time() < t_out_s) copy.stepper.do_step(*ode_);
      copy.stepper.calc_state(t_out_s, copy.output);
    }
    ++run_.step;
  }

  PeerState State(int copy) const override { return FromOdeState(copies_[copy].output); }

 private:
  using Dopri5 = odeint::runge_kutta_dopri5<OdeState>;
  struct Copy {
    odeint::result_of::make_dense_output<Dopri5>::type stepper;
    OdeState output;  // the state at the last output time
  };

  double tolerance_;
  PeerRun run_;
  std::optional<RigidBodyOde> ode_;
  std::vector<Copy> copies_;
};

}  // namespace

std::unique_ptr<Peer> MakeOdeintPeer(const std::string& configuration) {
  if (configuration == "odeint_rkf78") return std::make_unique<OdeintFixedStepPeer>();
  throw std::invalid_argument("MakeOdeintPeer: unknown configuration " + configuration);
}

std::unique_ptr<Peer> MakeOdeintAdaptivePeer(const std::string& configuration, double tolerance) {
  if (configuration == "odeint_dopri5") return std::make_unique<OdeintAdaptivePeer>(tolerance);
  throw std::invalid_argument("MakeOdeintAdaptivePeer: unknown configuration " + configuration);
}

}  // namespace rigid_body_sim::bench
