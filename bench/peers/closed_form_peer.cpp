// The exact torque-free motion evaluated on the output grid: what the states
// cost when they are read off the closed form (Jacobi elliptic functions and
// the precession angle, core/reference/torque_free.h, the formula of the
// references) instead of integrated. A cost line, not an engine: its error is
// round-off.
//
// Settings:
// - reference_closed_form: one TorqueFreeMotion per copy, built at set-up
//   from the initial state (not timed, as no engine's set-up is); Step()
//   evaluates R(t) at the next output, t = step · 1 ms, and the COM at
//   x0 + t p / M; L and p are constant.
// - Torque-free scenes only: the forced scene has no closed form, and the
//   constant-couple scene's (core/reference/constant_load.h) holds for a body
//   spinning about the couple's principal axis only.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine_peers.h"
#include "peer_loads.h"
#include "rigid_body_sim/core/reference/torque_free.h"

namespace rigid_body_sim::bench {
namespace {

class ClosedFormPeer final : public Peer {
 public:
  std::string name() const override { return "reference_closed_form"; }
  Stepping stepping() const override { return Stepping::kClosedForm; }
  bool Handles(const Scene& scene) const override {
    return scene.closed_form && scene.forces.empty() && scene.constant_couple.isZero(0.0);
  }

  void Setup(const Scene& scene, int copies, double dt_s) override {
    run_.Start(scene, dt_s);
    const BodyModel& model = *run_.model;
    const Eigen::Quaterniond principal = scene.initial.orientation * model.principal_axes();
    motions_.assign(copies, TorqueFreeMotion(model.principal_moments(),
                                             principal.conjugate() * scene.initial.angular_momentum,
                                             principal));
    states_.assign(copies, scene.initial);
  }

  void Step() override {
    ++run_.step;
    const double t_s = run_.step * run_.dt_s;
    const BodyModel& model = *run_.model;
    const BodyState& initial = run_.scene.initial;
    const Eigen::Vector3d position =
        initial.position + t_s * model.inverse_mass() * initial.linear_momentum;
    const Eigen::Quaterniond principal_to_body = model.principal_axes().conjugate();
    for (std::size_t c = 0; c < motions_.size(); ++c) {
      states_[c].position = position;
      states_[c].orientation = (motions_[c].Orientation(t_s) * principal_to_body).normalized();
    }
  }

  PeerState State(int copy) const override { return states_[copy]; }

 private:
  PeerRun run_;
  std::vector<TorqueFreeMotion> motions_;
  std::vector<BodyState> states_;  // L and p stay the initial ones
};

}  // namespace

std::unique_ptr<Peer> MakeClosedFormPeer(const std::string& configuration) {
  if (configuration == "reference_closed_form") return std::make_unique<ClosedFormPeer>();
  throw std::invalid_argument("MakeClosedFormPeer: unknown configuration " + configuration);
}

}  // namespace rigid_body_sim::bench
