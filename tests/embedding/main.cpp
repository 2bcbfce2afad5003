// Runs one program on one machine with nothing but the kernel-side
// libraries (nck::sim, and through it nck::prep and nck::kernel): load the
// lists, prepare, tick cycle by cycle to the program end. Prints the
// simulated time at the end, as `nck run` reports it.
//   embedding MACHINE_FOLDER PROGRAM
#include <cstdio>

#include "nck/config/load.hpp"
#include "nck/sim/dry_run.hpp"

int main(int argc, char** argv) {
  if (argc != 3) return std::fprintf(stderr, "usage: embedding MACHINE_FOLDER PROGRAM\n"), 2;
  const nck::config::LoadResult loaded = nck::config::load_machine(argv[1]);
  if (!loaded.ok()) return std::fprintf(stderr, "the machine's lists have errors (nck check)\n"), 1;
  auto run = nck::sim::DryRun::create(*loaded.machine, {argv[2]});
  if (!run) return std::fprintf(stderr, "%s\n", nck::format(run.error()).c_str()), 1;
  // A TickOutput is large (every channel, spindle and event of a cycle):
  // one, kept outside the loop, never on a real-time thread's stack.
  static nck::kernel::TickOutput out;
  double end_s = -1;
  for (long cycle = 0; end_s < 0 && cycle < 100'000'000; ++cycle) {
    run->step(out);  // prepare what fits, then one cycle: tick() inside
    for (const nck::kernel::Event& e : out.events)
      if (e.kind() == nck::kernel::EventKind::end) end_s = out.t_s;
      else if (e.kind() == nck::kernel::EventKind::error) return std::fprintf(stderr, "NC error\n"), 1;
  }
  std::printf("end %.3f s\n", end_s);
  return end_s < 0;
}
