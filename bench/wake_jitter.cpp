// The machine's floor under the node's overrun count: a bare loop paced like
// the node (sleep until the next period boundary, then busy for the node's
// step time), counting wake-ups late by more than one period, which is what
// the node counts as an overrun. Run it on the node's core with the node's
// scheduling (bench/node_load.py does), so the two counts compare.
//
// usage: wake_jitter <seconds> <busy_us> [period_us = 1000]
// prints: late_wakeups=<n> wakeups=<n> busy_us=<b> worst_late_us=<w>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: wake_jitter <seconds> <busy_us> [period_us]\n");
    return 2;
  }
  using Clock = std::chrono::steady_clock;
  const double seconds = std::atof(argv[1]);
  const std::chrono::microseconds busy(std::atol(argv[2]));
  const std::chrono::microseconds period(argc > 3 ? std::atol(argv[3]) : 1000);
  const long wakeups = static_cast<long>(seconds * 1e6 / static_cast<double>(period.count()));
  long late = 0;
  Clock::duration worst{0};
  Clock::time_point due = Clock::now();
  for (long k = 0; k < wakeups; ++k) {
    due += period;
    std::this_thread::sleep_until(due);
    const Clock::time_point woke = Clock::now();
    // As the node's pacer: the periods due by now are worked off back to
    // back (catch-up), and more than one due is an overrun.
    const long periods_due = static_cast<long>((woke - due) / period) + 1;
    if (periods_due > 1) ++late;
    worst = std::max(worst, woke - due);
    for (long p = 0; p < periods_due; ++p) {
      const Clock::time_point start = Clock::now();
      while (Clock::now() - start < busy) {
      }
    }
    due += (periods_due - 1) * period;
  }
  std::printf("late_wakeups=%ld wakeups=%ld busy_us=%ld worst_late_us=%.0f\n", late, wakeups,
              static_cast<long>(busy.count()),
              std::chrono::duration<double, std::micro>(worst).count());
  return 0;
}
