// Floods the node's wrench topics from another process for `duration_s`
// seconds: `arrays_per_s` ParticleWrenchArray messages of `entries` entries
// each, round-robin over the particles of ARRAY_BODY, and `singles_per_s`
// single ParticleWrench messages over the particles of SINGLE_BODY (two
// bodies, so each body is fed by one connection, whose order is kept). Every
// wrench carries a sequence number in force.x, so afterwards each particle's
// held force can be checked against the last one sent, printed as
// "last <body> <particle> <force_x>" lines.
//
// usage: wrench_flood ARRAY_BODY ARRAY_PARTICLES ARRAYS_PER_S ENTRIES
//                     SINGLE_BODY SINGLE_PARTICLES SINGLES_PER_S DURATION_S
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <rigid_body_sim/ParticleWrench.h>
#include <rigid_body_sim/ParticleWrenchArray.h>
#include <ros/ros.h>

namespace {

// Sequence numbers scaled so the forces stay small: a few mN.
constexpr double kNewtonsPerSequence = 1e-9;

struct Target {
  std::string body;
  std::uint32_t particles;
  std::vector<double> last_force;  // force.x of the last wrench sent per particle
  std::uint32_t next_particle = 0;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "wrench_flood", ros::init_options::AnonymousName);
  if (argc != 9) {
    std::fprintf(stderr,
                 "usage: wrench_flood ARRAY_BODY ARRAY_PARTICLES ARRAYS_PER_S ENTRIES "
                 "SINGLE_BODY SINGLE_PARTICLES SINGLES_PER_S DURATION_S\n");
    return 2;
  }
  const double arrays_per_s = std::atof(argv[3]);
  const std::uint32_t entries = std::atoi(argv[4]);
  const double singles_per_s = std::atof(argv[7]);
  const double duration_s = std::atof(argv[8]);

  ros::NodeHandle nh;
  ros::Publisher arrays =
      nh.advertise<rigid_body_sim::ParticleWrenchArray>("/rigid_body_sim/particle_wrenches", 1000);
  ros::Publisher singles =
      nh.advertise<rigid_body_sim::ParticleWrench>("/rigid_body_sim/particle_wrench", 100000);
  const auto connect_deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while ((arrays.getNumSubscribers() == 0 || singles.getNumSubscribers() == 0) &&
         std::chrono::steady_clock::now() < connect_deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }

  const auto array_particles = static_cast<std::uint32_t>(std::atoi(argv[2]));
  const auto single_particles = static_cast<std::uint32_t>(std::atoi(argv[6]));
  Target array_target{argv[1], array_particles, std::vector<double>(array_particles, 0.0)};
  Target single_target{argv[5], single_particles, std::vector<double>(single_particles, 0.0)};
  std::uint64_t sequence = 0, sent_wrenches = 0;
  auto next = [&](Target& target, rigid_body_sim::ParticleWrench* wrench) {
    wrench->body = target.body;
    wrench->particle = target.next_particle;
    wrench->wrench.force.x = kNewtonsPerSequence * static_cast<double>(++sequence);
    target.last_force[target.next_particle] = wrench->wrench.force.x;
    target.next_particle = (target.next_particle + 1) % target.particles;
    ++sent_wrenches;
  };

  // 1 ms ticks; each sends the messages due by then, so the rates hold on average.
  const auto start = std::chrono::steady_clock::now();
  double arrays_sent = 0, singles_sent = 0;
  for (auto tick = start; ros::ok(); tick += std::chrono::milliseconds(1)) {
    const double elapsed = std::chrono::duration<double>(tick - start).count();
    if (elapsed >= duration_s) break;
    for (; arrays_sent < arrays_per_s * elapsed; ++arrays_sent) {
      rigid_body_sim::ParticleWrenchArray message;
      message.wrenches.resize(entries);
      for (auto& wrench : message.wrenches) next(array_target, &wrench);
      arrays.publish(message);
    }
    for (; singles_sent < singles_per_s * elapsed; ++singles_sent) {
      rigid_body_sim::ParticleWrench message;
      next(single_target, &message);
      singles.publish(message);
    }
    std::this_thread::sleep_until(tick + std::chrono::milliseconds(1));
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // let the queues drain
  std::printf("sent %llu wrenches in %.3f s: %.0f per s (%.0f arrays, %.0f singles)\n",
              static_cast<unsigned long long>(sent_wrenches), wall_s, sent_wrenches / wall_s,
              arrays_sent, singles_sent);
  for (const Target* target : {&array_target, &single_target}) {
    for (std::uint32_t p = 0; p < target->particles; ++p) {
      std::printf("last %s %u %.17g\n", target->body.c_str(), p, target->last_force[p]);
    }
  }
  return 0;
}
