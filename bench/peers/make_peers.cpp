// Collects the peer configurations of the engines this build found
// (RBS_HAVE_* from cmake/bench_peers.cmake) and names the rest as missing,
// so that the benchmark can say which lines it skipped and why.
#include <string>
#include <utility>
#include <vector>

#include "engine_peers.h"

namespace rigid_body_sim::bench {
namespace {

template <typename Names, typename Make>
void AddAll(const Names& names, Make make, std::vector<std::unique_ptr<Peer>>* peers) {
  for (const char* name : names) peers->push_back(make(name));
}

template <typename Names, typename Tolerances, typename Make>
void AddAtEachTolerance(const Names& names, const Tolerances& tolerances, Make make,
                        std::vector<std::unique_ptr<Peer>>* peers) {
  for (const char* name : names) {
    for (double tolerance : tolerances) peers->push_back(make(name, tolerance));
  }
}

template <typename Names>
void MarkMissing(const Names& names, std::vector<std::string>* missing) {
  if (missing == nullptr) return;
  for (const char* name : names) missing->emplace_back(name);
}

}  // namespace

std::vector<std::unique_ptr<Peer>> MakePeers(std::vector<std::string>* missing) {
  std::vector<std::unique_ptr<Peer>> peers;
  (void)missing;  // unused when every engine was found
#ifdef RBS_HAVE_MUJOCO
  AddAll(kMujocoConfigurations, MakeMujocoPeer, &peers);
#else
  MarkMissing(kMujocoConfigurations, missing);
#endif
#ifdef RBS_HAVE_BULLET
  AddAll(kBulletConfigurations, MakeBulletPeer, &peers);
#else
  MarkMissing(kBulletConfigurations, missing);
#endif
#ifdef RBS_HAVE_ODE
  AddAll(kOdeConfigurations, MakeOdePeer, &peers);
#else
  MarkMissing(kOdeConfigurations, missing);
#endif
#ifdef RBS_HAVE_SIMBODY
  AddAll(kSimbodyConfigurations, MakeSimbodyPeer, &peers);
  AddAtEachTolerance(kSimbodyAdaptiveConfigurations, kSimbodyAccuracies, MakeSimbodyAdaptivePeer,
                     &peers);
#else
  MarkMissing(kSimbodyConfigurations, missing);
  MarkMissing(kSimbodyAdaptiveConfigurations, missing);
#endif
#ifdef RBS_HAVE_DART
  AddAll(kDartConfigurations, MakeDartPeer, &peers);
#else
  MarkMissing(kDartConfigurations, missing);
#endif
#ifdef RBS_HAVE_ODEINT
  AddAll(kOdeintConfigurations, MakeOdeintPeer, &peers);
  AddAtEachTolerance(kOdeintAdaptiveConfigurations, kOdeintTolerances, MakeOdeintAdaptivePeer,
                     &peers);
#else
  MarkMissing(kOdeintConfigurations, missing);
  MarkMissing(kOdeintAdaptiveConfigurations, missing);
#endif
  AddAll(kClosedFormConfigurations, MakeClosedFormPeer, &peers);
  return peers;
}

}  // namespace rigid_body_sim::bench
