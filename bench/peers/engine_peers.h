// The peer configurations of each engine, by name, and the factories that
// build them. The names are known even when an engine is not compiled in, so
// that MakePeers can report which benchmark lines are skipped.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "../peer.h"

namespace rigid_body_sim::bench {

inline constexpr std::array<const char*, 3> kMujocoConfigurations = {"mujoco_euler", "mujoco_rk4",
                                                                     "mujoco_implicit"};
inline constexpr std::array<const char*, 3> kBulletConfigurations = {
    "bullet_implicit", "bullet_explicit", "bullet_no_gyro"};
inline constexpr std::array<const char*, 3> kOdeConfigurations = {"ode_gyro", "ode_no_gyro",
                                                                  "ode_finite_rotation"};
inline constexpr std::array<const char*, 1> kSimbodyConfigurations = {"simbody_merson_fixed"};
inline constexpr std::array<const char*, 1> kDartConfigurations = {"dart_semi_implicit"};
inline constexpr std::array<const char*, 1> kOdeintConfigurations = {"odeint_rkf78"};
// Built in: the closed form of core/reference, no engine to find.
inline constexpr std::array<const char*, 1> kClosedFormConfigurations = {"reference_closed_form"};

// The adaptive configurations, each run once per tolerance of its list:
// Simbody's accuracy from loose to tight every fourth decade (each point is
// a whole-scene run of the slowest peer, and on these scenes its steps are
// the 1 ms of the output grid at every accuracy), odeint's tolerance over the
// range where dopri5 is above round-off.
inline constexpr std::array<const char*, 1> kSimbodyAdaptiveConfigurations = {
    "simbody_merson_adaptive"};
inline constexpr std::array<double, 3> kSimbodyAccuracies = {1e-4, 1e-8, 1e-12};
inline constexpr std::array<const char*, 1> kOdeintAdaptiveConfigurations = {"odeint_dopri5"};
inline constexpr std::array<double, 8> kOdeintTolerances = {1e-6,  1e-7,  1e-8,  1e-9,
                                                            1e-10, 1e-11, 1e-12, 1e-13};

// Each throws std::invalid_argument for a name not in its list above.
// Defined only when the engine was found (RBS_HAVE_MUJOCO, ...).
std::unique_ptr<Peer> MakeMujocoPeer(const std::string& configuration);
std::unique_ptr<Peer> MakeBulletPeer(const std::string& configuration);
std::unique_ptr<Peer> MakeOdePeer(const std::string& configuration);
std::unique_ptr<Peer> MakeSimbodyPeer(const std::string& configuration);
std::unique_ptr<Peer> MakeDartPeer(const std::string& configuration);
std::unique_ptr<Peer> MakeOdeintPeer(const std::string& configuration);
std::unique_ptr<Peer> MakeClosedFormPeer(const std::string& configuration);
std::unique_ptr<Peer> MakeSimbodyAdaptivePeer(const std::string& configuration, double tolerance);
std::unique_ptr<Peer> MakeOdeintAdaptivePeer(const std::string& configuration, double tolerance);

}  // namespace rigid_body_sim::bench
