// MuJoCo 2.2.2 (Debian libmujoco-dev) stepping copies of a free body.
//
// Settings, as a MuJoCo user would write a free body, all in the generated MJCF:
// - Models of `bodies_per_model` bodies (mujoco_euler, mujoco_rk4: one model
//   with all copies; mujoco_implicit: one model per copy, because 2.2.2's
//   implicit integrator works on dense nv × nv matrices: with 1,000 bodies
//   (nv = 6,000) the model does not even fit MuJoCo's default stack, and
//   its cost would grow as nv³ instead of with the number of bodies). Models
//   of equal size are compiled once and share it, each copy with its own
//   mjData; a one-body model gets <size njmax="10" nconmax="1"/> (10 kB of
//   constraint buffers instead of 3 MB; it has no constraint). Each
//   body is a <freejoint/> and an <inertial> with
//   pos = 0 (the body frame is our body frame, origin at the COM), mass M,
//   quat = the principal axes R_BP and diaginertia = the principal moments.
//   The body frame is then the scene's body frame, so qpos is our orientation
//   directly and qvel's angular part is ω in our body axes.
// - No geoms: nothing to collide, and <flag contact="disable"/> besides.
// - gravity = 0, no joint damping, armature or frictionloss (all default 0),
//   so no passive forces; option timestep = dt.
// - Integrators (mjtIntegrator in 2.2.2 has exactly these three):
//   mujoco_euler: mjINT_EULER, "semi-implicit Euler": qvel += dt qacc, then
//     qpos integrated with the new qvel (the quaternion by the exact rotation
//     exp(dt ω)). With zero damping nothing is implicit: it is symplectic
//     Euler with the Coriolis term ω × Iω explicit.
//   mujoco_rk4: mjINT_RK4, classical Runge–Kutta on (qpos, qvel).
//   mujoco_implicit: mjINT_IMPLICIT, implicit in velocity: one linear solve
//     with M − dt ∂(qfrc_passive + qfrc_actuator − qfrc_bias)/∂qvel, which in
//     2.2.x includes the derivative of the Coriolis/centripetal term (dense
//     RNE derivatives; 2.3.3 made them sparse and added "implicitfast" without
//     them). For a free body that is a linearly implicit Euler step of ω.
// - Loads: xfrc_applied (world force and torque at the body's COM), set from
//   the pose at the start of the step and held for the whole step (RK4 too).
// - No clamp on velocities in MuJoCo's free joint.
#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "engine_peers.h"
#include "peer_loads.h"
#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::bench {
namespace {

// A double printed so that MJCF parsing gives back the same double.
std::string Exact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

class MujocoPeer final : public Peer {
 public:
  // bodies_per_model <= 0: all copies in one model.
  MujocoPeer(std::string name, mjtIntegrator integrator, int bodies_per_model)
      : name_(std::move(name)), integrator_(integrator), bodies_per_model_(bodies_per_model) {}
  ~MujocoPeer() override { Release(); }

  std::string name() const override { return name_; }

  void Setup(const Scene& scene, int copies, double dt_s) override {
    // The benchmark sets up one scene at many dt and, for every timing
    // sample, the same number of copies again: compiling 1,000 bodies takes
    // most of a second and making their data zeroes hundreds of MB, so the
    // scene's compiled models are kept (dt is a model option) and so is the
    // data of each number of copies, reset.
    const bool same_scene = run_.model && scene.name == run_.scene.name;
    if (!same_scene) Release();
    run_.Start(scene, dt_s);
    for (const Model& m : compiled_) m.model->opt.timestep = dt_s;
    const auto [kept, made] = instances_.try_emplace(copies);
    active_ = &kept->second;
    if (made) {
      MakeData(copies, active_);
    } else {
      for (const Compiled& m : active_->models) mj_resetData(m.model, m.data);
    }
    const BodyState& s = run_.scene.initial;
    const Eigen::Vector3d v = run_.model->inverse_mass() * s.linear_momentum;
    const Eigen::Vector3d omega_body = s.orientation.conjugate() * AngularVelocity(*run_.model, s);
    for (std::size_t c = 0; c < active_->copies.size(); ++c) {
      mjtNum* q = Qpos(c);
      mjtNum* u = Qvel(c);
      for (int i = 0; i < 3; ++i) {
        q[i] = s.position[i];
        u[i] = v[i];
        u[3 + i] = omega_body[i];
      }
      q[3] = s.orientation.w();
      q[4] = s.orientation.x();
      q[5] = s.orientation.y();
      q[6] = s.orientation.z();
    }
  }

  void Step() override {
    if (!run_.loads->empty()) {
      run_.loads->BeginStep(run_.step * run_.dt_s);
      for (std::size_t c = 0; c < active_->copies.size(); ++c) {
        // qpos is the pose at the start of this step; d->xquat is not: mj_step
        // computed it before integrating.
        const Eigen::Matrix3d rotation = Orientation(c).toRotationMatrix();
        Eigen::Vector3d force, torque;
        run_.loads->Wrench(rotation, &force, &torque);
        const Copy& copy = active_->copies[c];
        mjtNum* wrench = active_->models[copy.model].data->xfrc_applied + 6 * copy.body;
        for (int i = 0; i < 3; ++i) {
          wrench[i] = force[i];
          wrench[3 + i] = torque[i];
        }
      }
    }
    for (const Compiled& m : active_->models) mj_step(m.model, m.data);
    ++run_.step;
  }

  PeerState State(int copy) const override {
    const mjtNum* q = Qpos(copy);
    const mjtNum* u = Qvel(copy);
    const Eigen::Quaterniond orientation = Orientation(copy);
    return StateFromTwist(*run_.model, Eigen::Vector3d(q[0], q[1], q[2]), orientation,
                          Eigen::Vector3d(u[0], u[1], u[2]),
                          orientation * Eigen::Vector3d(u[3], u[4], u[5]));
  }

 private:
  struct Compiled {
    const mjModel* model;
    mjData* data;
  };
  struct Model {
    int bodies;
    mjModel* model;
  };
  struct Copy {
    std::size_t model;
    int body, qpos, qvel;
  };
  // The data of one Setup's copies (each owned) and where each copy lives.
  struct Instance {
    std::vector<Compiled> models;
    std::vector<Copy> copies;
  };

  mjtNum* Qpos(std::size_t c) const {
    const Copy& copy = active_->copies[c];
    return active_->models[copy.model].data->qpos + copy.qpos;
  }
  mjtNum* Qvel(std::size_t c) const {
    const Copy& copy = active_->copies[c];
    return active_->models[copy.model].data->qvel + copy.qvel;
  }
  Eigen::Quaterniond Orientation(std::size_t c) const {
    const mjtNum* q = Qpos(c);
    return Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized();
  }

  std::string Mjcf(int bodies) const {
    static const char* const kIntegratorNames[] = {"Euler", "RK4", "implicit"};
    const Eigen::Vector3d& moments = run_.model->principal_moments();
    const Eigen::Quaterniond& axes = run_.model->principal_axes();
    std::ostringstream inertial;
    inertial << "<inertial pos=\"0 0 0\" mass=\"" << Exact(run_.model->mass()) << "\" quat=\""
             << Exact(axes.w()) << ' ' << Exact(axes.x()) << ' ' << Exact(axes.y()) << ' '
             << Exact(axes.z()) << "\" diaginertia=\"" << Exact(moments[0]) << ' '
             << Exact(moments[1]) << ' ' << Exact(moments[2]) << "\"/>";
    std::ostringstream xml;
    xml << "<mujoco model=\"rbs_bench\">\n"
        << "<option timestep=\"" << Exact(run_.dt_s) << "\" gravity=\"0 0 0\" integrator=\""
        << kIntegratorNames[integrator_] << "\">\n"
        << "<flag contact=\"disable\"/>\n</option>\n";
    // No constraint can arise (no contact, joint limit or equality), but the
    // default buffers hold 500 constraint rows (3 MB per mjData): 1,000 such
    // data cost seconds of page faults per setup.
    if (bodies == 1) xml << "<size njmax=\"10\" nconmax=\"1\"/>\n";
    xml << "<worldbody>\n";
    for (int b = 0; b < bodies; ++b) {
      xml << "<body name=\"copy" << b << "\"><freejoint/>" << inertial.str() << "</body>\n";
    }
    xml << "</worldbody>\n</mujoco>\n";
    return xml.str();
  }

  void MakeData(int copies, Instance* instance) {
    const int per_model = bodies_per_model_ > 0 ? bodies_per_model_ : copies;
    for (int first = 0; first < copies; first += per_model) {
      // Chunks of the same size share one compiled model, each with its own data.
      const int bodies = std::min(per_model, copies - first);
      const mjModel* model = CompiledFor(bodies);
      instance->models.push_back({model, mj_makeData(model)});
    }
    // Where each copy lives: its model, body and qpos/qvel addresses, read
    // from the model so that nothing depends on MuJoCo's layout.
    for (std::size_t m = 0; m < instance->models.size(); ++m) {
      const mjModel* model = instance->models[m].model;
      for (int body = 1; body < model->nbody; ++body) {  // body 0 is the world
        const int joint = model->body_jntadr[body];
        instance->copies.push_back({m, body, model->jnt_qposadr[joint], model->jnt_dofadr[joint]});
      }
    }
  }

  const mjModel* CompiledFor(int bodies) {
    for (const Model& m : compiled_) {
      if (m.bodies == bodies) return m.model;
    }
    compiled_.push_back({bodies, Compile(bodies)});
    return compiled_.back().model;
  }

  // Compiles the MJCF from memory through MuJoCo's virtual file system.
  mjModel* Compile(int bodies) {
    const std::string xml = Mjcf(bodies);
    auto vfs = std::make_unique<mjVFS>();  // ~2 MB: not on the stack
    mj_defaultVFS(vfs.get());
    const char* const kFile = "rbs_bench.xml";
    if (mj_makeEmptyFileVFS(vfs.get(), kFile, static_cast<int>(xml.size())) != 0) {
      throw std::runtime_error(name_ + ": MuJoCo VFS refused the model");
    }
    const int index = mj_findFileVFS(vfs.get(), kFile);
    std::copy(xml.begin(), xml.end(), static_cast<char*>(vfs->filedata[index]));
    char error[1000] = "";
    mjModel* model = mj_loadXML(kFile, vfs.get(), error, sizeof error);
    mj_deleteVFS(vfs.get());
    if (model == nullptr) {
      throw std::runtime_error(name_ + ": MuJoCo rejected the model: " + error);
    }
    return model;
  }

  void Release() {
    for (const auto& [copies, instance] : instances_) {
      for (const Compiled& m : instance.models) mj_deleteData(m.data);
    }
    instances_.clear();
    active_ = nullptr;
    for (const Model& m : compiled_) mj_deleteModel(m.model);
    compiled_.clear();
  }

  std::string name_;
  mjtIntegrator integrator_;
  int bodies_per_model_;
  PeerRun run_;
  std::vector<Model> compiled_;        // owned: the scene's, by number of bodies
  std::map<int, Instance> instances_;  // by number of copies
  Instance* active_ = nullptr;         // the last Setup's
};

}  // namespace

std::unique_ptr<Peer> MakeMujocoPeer(const std::string& configuration) {
  if (configuration == "mujoco_euler")
    return std::make_unique<MujocoPeer>(configuration, mjINT_EULER, 0);
  if (configuration == "mujoco_rk4")
    return std::make_unique<MujocoPeer>(configuration, mjINT_RK4, 0);
  if (configuration == "mujoco_implicit") {
    return std::make_unique<MujocoPeer>(configuration, mjINT_IMPLICIT, 1);
  }
  throw std::invalid_argument("MakeMujocoPeer: unknown configuration " + configuration);
}

}  // namespace rigid_body_sim::bench
