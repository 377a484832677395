// The peer configurations of each engine, by name, and the factories that
// build them. The names are known even when an engine is not compiled in, so
// that MakePeers can report which benchmark lines are skipped.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "../peer.h"

namespace rigid_body_sim::bench {

inline constexpr std::array<const char*, 3> kMujocoConfigurations = {
    "mujoco_euler", "mujoco_rk4", "mujoco_implicit"};
inline constexpr std::array<const char*, 3> kBulletConfigurations = {
    "bullet_implicit", "bullet_explicit", "bullet_no_gyro"};
inline constexpr std::array<const char*, 3> kOdeConfigurations = {
    "ode_gyro", "ode_no_gyro", "ode_finite_rotation"};

// Each throws std::invalid_argument for a name not in its list above.
// Defined only when the engine was found (RBS_HAVE_MUJOCO, ...).
std::unique_ptr<Peer> MakeMujocoPeer(const std::string& configuration);
std::unique_ptr<Peer> MakeBulletPeer(const std::string& configuration);
std::unique_ptr<Peer> MakeOdePeer(const std::string& configuration);

}  // namespace rigid_body_sim::bench
