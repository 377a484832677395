#include "rigid_body_sim/ros/recorded_input.h"

#include <stdexcept>
#include <utility>

namespace rigid_body_sim {
namespace {

std::uint8_t AxesOf(core::WrenchAxes axes) {
  return axes == core::WrenchAxes::kBody ? RecordedInput::AXES_BODY : RecordedInput::AXES_WORLD;
}

core::WrenchAxes CoreAxes(std::uint8_t axes) {
  return axes == RecordedInput::AXES_BODY ? core::WrenchAxes::kBody : core::WrenchAxes::kWorld;
}

void Append(const Eigen::Vector3d& vector, std::vector<double>* values) {
  values->insert(values->end(), vector.data(), vector.data() + 3);
}

// The recorded numbers, read in order, their count checked once.
class Values {
 public:
  Values(const RecordedInput& input, std::size_t count) : values_(input.values) {
    if (values_.size() != count) {
      throw std::invalid_argument(
          "input " + std::to_string(input.sequence) + " (kind " + std::to_string(input.kind) +
          ") has " + std::to_string(values_.size()) + " values, not " + std::to_string(count));
    }
  }
  double Next() { return values_[next_++]; }
  Eigen::Vector3d NextVector() {
    Eigen::Vector3d vector(values_[next_], values_[next_ + 1], values_[next_ + 2]);
    next_ += 3;
    return vector;
  }

 private:
  const std::vector<double>& values_;
  std::size_t next_ = 0;
};

core::BodyId FindRecordedBody(const RecordedInput& input, const core::World& world) {
  const std::optional<core::BodyId> body = world.FindBody(input.body);
  if (!body) {
    throw std::invalid_argument("input " + std::to_string(input.sequence) + " names body '" +
                                input.body + "', which the world does not have");
  }
  return *body;
}

}  // namespace

RecordedInput RecordedOfKind(std::uint8_t kind, std::string body) {
  RecordedInput input;
  input.kind = kind;
  input.body = std::move(body);
  return input;
}

RecordedInput RecordedParticleWrench(const core::World& world, const core::ParticleWrench& wrench) {
  RecordedInput input =
      RecordedOfKind(RecordedInput::PARTICLE_WRENCH, world.model(wrench.body).name());
  input.particle = static_cast<std::uint32_t>(wrench.particle);
  input.axes = AxesOf(wrench.axes);
  Append(wrench.force, &input.values);
  Append(wrench.couple, &input.values);
  input.values.push_back(wrench.start_s);
  return input;
}

RecordedInput RecordedBodyWrench(const core::World& world, const core::BodyWrench& wrench) {
  RecordedInput input = RecordedOfKind(RecordedInput::BODY_WRENCH, world.model(wrench.body).name());
  input.axes = AxesOf(wrench.axes);
  Append(wrench.force, &input.values);
  Append(wrench.couple, &input.values);
  input.values.push_back(wrench.start_s);
  return input;
}

RecordedInput RecordedActuatorCommands(const core::World& world, core::BodyId body,
                                       const std::vector<std::size_t>& actuators,
                                       const std::vector<double>& commands_n, double start_s) {
  RecordedInput input = RecordedOfKind(RecordedInput::ACTUATOR_COMMANDS, world.model(body).name());
  input.indices.assign(actuators.begin(), actuators.end());
  input.values.assign(commands_n.begin(), commands_n.end());
  input.values.push_back(start_s);
  return input;
}

RecordedInput RecordedWrenchJob(const core::World& world, const core::WrenchJob& job) {
  RecordedInput input = RecordedOfKind(RecordedInput::WRENCH_JOB, world.model(job.body).name());
  input.axes = AxesOf(job.axes);
  Append(job.force, &input.values);
  Append(job.couple, &input.values);
  Append(job.point_m, &input.values);
  input.values.push_back(job.start_s);
  input.values.push_back(job.end_s);
  return input;
}

RecordedInput RecordedBodyState(const core::World& world, core::BodyId body,
                                const core::BodyState& state) {
  RecordedInput input = RecordedOfKind(RecordedInput::BODY_STATE, world.model(body).name());
  Append(state.position, &input.values);
  const Eigen::Quaterniond& q = state.orientation;
  input.values.insert(input.values.end(), {q.w(), q.x(), q.y(), q.z()});
  Append(state.linear_momentum, &input.values);
  Append(state.angular_momentum, &input.values);
  return input;
}

RecordedInput RecordedReconfiguration(const NodeSettings& in_force, const NodeSettings& next) {
  RecordedInput input = RecordedOfKind(RecordedInput::RECONFIGURE);
  Append(next.gravity_mps2, &input.values);
  Append(next.wind_mps, &input.values);
  input.values.push_back(next.wrench_timeout_s);
  input.text = next.integrator;
  // As SimulationNode::ApplyRuntimeSettings sets them: what changed only.
  if (next.gravity_mps2 != in_force.gravity_mps2) {
    input.indices.push_back(RecordedInput::CHANGED_GRAVITY);
  }
  if (next.wind_mps != in_force.wind_mps) input.indices.push_back(RecordedInput::CHANGED_WIND);
  if (next.wrench_timeout_s != in_force.wrench_timeout_s) {
    input.indices.push_back(RecordedInput::CHANGED_WRENCH_TIMEOUT);
  }
  if (next.integrator != in_force.integrator) {
    input.indices.push_back(RecordedInput::CHANGED_INTEGRATOR);
  }
  return input;
}

void ApplyRecordedInput(const RecordedInput& input, core::World* world) {
  switch (input.kind) {
    case RecordedInput::PARTICLE_WRENCH: {
      Values values(input, 7);
      core::ParticleWrench wrench;
      wrench.body = FindRecordedBody(input, *world);
      wrench.particle = input.particle;
      wrench.axes = CoreAxes(input.axes);
      wrench.force = values.NextVector();
      wrench.couple = values.NextVector();
      wrench.start_s = values.Next();
      world->HoldWrench(wrench);
      return;
    }
    case RecordedInput::BODY_WRENCH: {
      Values values(input, 7);
      core::BodyWrench wrench;
      wrench.body = FindRecordedBody(input, *world);
      wrench.axes = CoreAxes(input.axes);
      wrench.force = values.NextVector();
      wrench.couple = values.NextVector();
      wrench.start_s = values.Next();
      world->HoldBodyWrench(wrench);
      return;
    }
    case RecordedInput::ACTUATOR_COMMANDS: {
      const core::BodyId body = FindRecordedBody(input, *world);
      Values values(input, input.indices.size() + 1);
      std::vector<double> commands_n;
      for (std::size_t i = 0; i < input.indices.size(); ++i) commands_n.push_back(values.Next());
      const double start_s = values.Next();
      for (std::size_t i = 0; i < input.indices.size(); ++i) {
        world->HoldActuatorCommand(body, input.indices[i], commands_n[i], start_s);
      }
      return;
    }
    case RecordedInput::WRENCH_JOB: {
      Values values(input, 11);
      core::WrenchJob job;
      job.body = FindRecordedBody(input, *world);
      job.axes = CoreAxes(input.axes);
      job.force = values.NextVector();
      job.couple = values.NextVector();
      job.point_m = values.NextVector();
      job.start_s = values.Next();
      job.end_s = values.Next();
      world->AddWrenchJob(job);
      return;
    }
    case RecordedInput::CLEAR_WRENCHES:
      world->ClearWrenches();
      return;
    case RecordedInput::CLEAR_BODY_WRENCHES:
      world->ClearBodyWrenches(FindRecordedBody(input, *world));
      return;
    case RecordedInput::BODY_STATE: {
      Values values(input, 13);
      core::BodyState state;
      state.position = values.NextVector();
      const double w = values.Next();
      const Eigen::Vector3d xyz = values.NextVector();
      state.orientation = Eigen::Quaterniond(w, xyz.x(), xyz.y(), xyz.z());
      state.linear_momentum = values.NextVector();
      state.angular_momentum = values.NextVector();
      world->SetBodyState(FindRecordedBody(input, *world), state);
      return;
    }
    case RecordedInput::RESET:
      world->Reset();
      return;
    case RecordedInput::DELETE:
      world->RemoveBody(FindRecordedBody(input, *world));
      return;
    case RecordedInput::RECONFIGURE: {
      Values values(input, 7);
      const Eigen::Vector3d gravity_mps2 = values.NextVector();
      const Eigen::Vector3d wind_mps = values.NextVector();
      const double wrench_timeout_s = values.Next();
      // Only what changed was set, as the node sets it.
      for (const std::uint32_t changed : input.indices) {
        switch (changed) {
          case RecordedInput::CHANGED_GRAVITY:
            world->SetGravity(gravity_mps2);
            break;
          case RecordedInput::CHANGED_WIND:
            world->SetWindVelocity(wind_mps);
            break;
          case RecordedInput::CHANGED_WRENCH_TIMEOUT:
            world->SetWrenchTimeout(wrench_timeout_s);
            break;
          case RecordedInput::CHANGED_INTEGRATOR:
            world->SetIntegrator(input.text);
            break;
          default:
            throw std::invalid_argument("input " + std::to_string(input.sequence) +
                                        " changes setting " + std::to_string(changed) +
                                        ", which is not one of the world's");
        }
      }
      return;
    }
    default:
      throw std::invalid_argument("input " + std::to_string(input.sequence) + " has kind " +
                                  std::to_string(input.kind) + ", which acts on no world");
  }
}

}  // namespace rigid_body_sim
