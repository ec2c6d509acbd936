// cosph-bench: particle-steps per second of the fluid solver alone on the dam
// break at three resolutions, and of the solid alone on the oscillating plate
// at two, on one thread and on all. Not a test: run
//   build/bin/cosph-bench [--steps N] [--quick]
// It prints a table; scripts/benchmark.py turns it into docs/results/benchmark.md.
#include <omp.h>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "fluid_parameters.hpp"
#include "fluid_solver.hpp"
#include "jaumann_solver.hpp"
#include "solid_parameters.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/solver_cli.hpp"

namespace {

using cosph::fluid::FluidSolver;

struct Measurement {
  long particles;
  int threads;
  double seconds_per_step;
  // Pairs (i, j) within 2h summed over the particles the passes visit, in the
  // last step: the work of a step. Per particle it is lower for small scenes, where
  // more of the particles lie near a surface or a wall.
  long pairs = 0;
  long sorts = 0;  // fluid: neighbour re-sorts during the timed steps
  long water = 0;  // fluid: the water particles, the ones the integrator moves
};

// The pairs a fluid step visits: every water particle's neighbours within 2h.
long fluid_pairs(const FluidSolver& solver) {
  long pairs = 0;
  for (long i = 0; i < static_cast<long>(solver.particles().size()); ++i)
    pairs += static_cast<long>(solver.pairs().neighbours(i).size());
  return pairs;
}

// With --cpu the clock is CPU time: on a shared machine one thread's CPU time
// is its wall time without the slices the neighbours took. On several threads
// it is the CPU time of the busiest thread, an estimate of the wall time on
// cores of one's own if the idle threads do not spin (OMP_WAIT_POLICY=passive).
bool cpu_clock = false;

// Each OpenMP thread's CPU time, or the wall time once, in seconds.
std::vector<double> clock_seconds() {
  if (!cpu_clock)
    return {
        std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count()};
  std::vector<double> seconds(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel
  {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    seconds[static_cast<std::size_t>(omp_get_thread_num())] =
        static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  }
  return seconds;
}

double seconds_since(const std::vector<double>& start) {
  const std::vector<double> now = clock_seconds();
  double longest = 0.0;
  for (std::size_t k = 0; k < start.size() && k < now.size(); ++k)
    longest = std::max(longest, now[k] - start[k]);
  return longest;
}

// Case settings (--set FIELD=VALUE) for the fluid's runs, after its spacing.
std::vector<std::string> fluid_settings;

Measurement time_fluid(const std::string& case_path, double spacing, int threads, int steps) {
  omp_set_num_threads(threads);
  std::vector<std::string> settings{"fluid.spacing=" + std::to_string(spacing)};
  settings.insert(settings.end(), fluid_settings.begin(), fluid_settings.end());
  const sph::CaseFile case_file = sph::load_case(case_path, settings);
  FluidSolver solver(case_file, cosph::fluid::read_fluid_parameters(case_file));
  // Warm up (first touch, the collapse starting), then time a fixed number of steps.
  for (int s = 0; s < steps / 10 + 1; ++s) solver.step(solver.step_limits().smallest());
  const long sorts_before = solver.sorts();
  const std::vector<double> start = clock_seconds();
  for (int s = 0; s < steps; ++s) solver.step(solver.step_limits().smallest());
  const double elapsed = seconds_since(start);
  const auto& kind = solver.particles().kind;
  return {static_cast<long>(solver.particles().size()),
          threads,
          elapsed / steps,
          fluid_pairs(solver),
          solver.sorts() - sorts_before,
          std::count(kind.begin(), kind.end(), cosph::fluid::Kind::water)};
}

// The pairs a solid step visits: those within 2h of each particle that is not
// inert, counted once (the rates pass works each pair out once; its momentum
// pass lists fewer, none of two clamped particles).
long solid_pairs(const cosph::solid::jaumann::JaumannSolver& solver) {
  const cosph::solid::jaumann::JaumannParticles& P = solver.particles();
  const double support = sph::kernel::kSupport * solver.parameters().h;
  long pairs = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    for (std::size_t j = i + 1; j < P.size(); ++j)
      pairs +=
          static_cast<long>(!P.inert[i] && (P.x[i] - P.x[j]).squaredNorm() < support * support);
  return pairs;
}

// The solid on the oscillating plate (Gray et al. 2001) at a given spacing.
Measurement time_solid(const std::string& case_path, double spacing, int threads, int steps) {
  omp_set_num_threads(threads);
  const sph::CaseFile case_file =
      sph::load_case(case_path, {"solid.spacing=" + std::to_string(spacing)});
  cosph::solid::jaumann::JaumannSolver solver(case_file,
                                              cosph::solid::read_solid_parameters(case_file));
  for (int s = 0; s < steps / 10 + 1; ++s) solver.step(solver.step_limits().smallest());
  const std::vector<double> start = clock_seconds();
  for (int s = 0; s < steps; ++s) solver.step(solver.step_limits().smallest());
  const double elapsed = seconds_since(start);
  return {static_cast<long>(solver.particles().size()), threads, elapsed / steps,
          solid_pairs(solver)};
}

int bench(int argc, char** argv) {
  int steps = 200;
  bool quick = false, largest = false, fluid_only = false, solid_only = false, show_sorts = false;
  std::vector<double> spacings{0.008, 0.002, 0.0009};  // about 650, 10 000, 50 000 water particles
  std::vector<int> thread_counts{1, omp_get_num_procs()};
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--steps" && i + 1 < argc)
      steps = std::stoi(argv[++i]);
    else if (option == "--quick")
      quick = true;
    else if (option == "--largest")
      largest = true;
    else if (option == "--fluid")
      fluid_only = true;
    else if (option == "--solid")
      solid_only = true;
    else if (option == "--spacing" && i + 1 < argc)
      spacings = {std::stod(argv[++i])};
    else if (option == "--threads" && i + 1 < argc)
      thread_counts = {std::stoi(argv[++i])};
    else if (option == "--cpu")
      cpu_clock = true;
    else if (option == "--sorts")
      show_sorts = true;
    else if (option == "--set" && i + 1 < argc)
      fluid_settings.push_back(argv[++i]);
    else if (option == "--help" || option == "-h") {
      std::printf(
          "usage: cosph-bench [--steps N] [--quick | --largest] [--fluid | --solid]\n"
          "                   [--spacing DX] [--threads T] [--cpu] [--sorts] [--set F=V]\n\n"
          "Particle-steps per second of the fluid solver on the dam break at about 650, 10 000\n"
          "and 50 000 water particles (--quick: the first two; --largest: the last;\n"
          "--spacing: that one spacing instead), and of the solid (--fluid: not; --solid: the\n"
          "solid only), on one thread and on all cores\n"
          "(--threads: on T only). --cpu: CPU time of the busiest thread instead of wall\n"
          "time, for a shared machine (several threads: the OpenMP build, "
          "OMP_WAIT_POLICY=passive). --sorts: "
          "the fluid's neighbour re-sorts in the timed steps,\n"
          "after its rows. --set F=V: a setting of the dam break for the fluid's runs (as\n"
          "cosph run's; may be repeated). Not a test.\n");
      return 0;
    } else
      throw sph::ConfigError(
          "usage: cosph-bench [--steps N] [--quick | --largest] [--fluid | --solid] [--spacing DX] "
          "[--threads T] [--cpu] [--sorts] [--set F=V]");
  }
#if COSPH_PARALLEL_TBB
  // --cpu reads the CPU time of OpenMP's threads, and oneTBB's workers are
  // other threads: on several threads it would time the main thread alone.
  if (cpu_clock &&
      std::any_of(thread_counts.begin(), thread_counts.end(), [](int t) { return t > 1; }))
    throw sph::ConfigError(
        "--cpu times each OpenMP thread; this build runs its loops on oneTBB, so "
        "give --threads 1 with it, or build with -DCOSPH_PARALLEL=openmp");
#endif
  const std::string case_path = std::string(COSPH_SOURCE_DIR) + "/cases/dam_break.pbtxt";
  if (quick && spacings.size() > 1) spacings.pop_back();
  if (largest) spacings = {spacings.back()};
  std::printf("%-6s %10s %8s %14s %22s %10s %8s\n", "solver", "particles", "threads", "ms/step",
              "particle-steps/s", "pairs", "water");
  for (double spacing : solid_only ? std::vector<double>{} : spacings)
    for (int threads : thread_counts) {
      const Measurement m = time_fluid(case_path, spacing, threads, steps);
      std::printf("%-6s %10ld %8d %14.4f %22.4g %10ld %8ld\n", "fluid", m.particles, m.threads,
                  1e3 * m.seconds_per_step, static_cast<double>(m.particles) / m.seconds_per_step,
                  m.pairs, m.water);
      if (show_sorts) std::printf("#   %ld re-sorts in %d steps\n", m.sorts, steps);
      std::fflush(stdout);
    }
  if (fluid_only) return 0;
  const std::string plate = std::string(COSPH_SOURCE_DIR) + "/cases/oscillating_plate.pbtxt";
  for (double spacing : {0.002, 0.001})
    for (int threads : thread_counts) {
      const Measurement m = time_solid(plate, spacing, threads, steps);
      std::printf("%-6s %10ld %8d %14.4f %22.4g %10ld %8s\n", "solid", m.particles, m.threads,
                  1e3 * m.seconds_per_step, static_cast<double>(m.particles) / m.seconds_per_step,
                  m.pairs, "-");
      std::fflush(stdout);
    }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return sph::run_guarded("cosph-bench", [&] { return bench(argc, argv); });
}
