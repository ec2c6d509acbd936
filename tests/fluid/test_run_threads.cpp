// A solver's OpenMP threads are set in two steps (sph::RunThreads): building
// the solver must start no thread that the run will not use, since such a
// thread stays for the whole run and, under OMP_WAIT_POLICY=active, spins on
// a core that the other processes of a coupled run need.
#include <gtest/gtest.h>
#include <omp.h>

#include <filesystem>
#include <string>

#include "fluid_parameters.hpp"
#include "fluid_solver.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/run_parameters.hpp"

namespace cosph::fluid {
namespace {

const std::string kCase = std::string(COSPH_SOURCE_DIR) + "/cases/dam_break.pbtxt";

long threads_of_this_process() {
  long count = 0;
  for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task"))
    ++count;
  return count;
}

// At 3 mm the dam break has about 6 000 particles: enough for its loops to
// take threads, too few for a second thread to be chosen.
TEST(RunThreads, BuildingTheSolverStartsNoThreadTheRunDoesNotUse) {
  const sph::CaseFile case_file = sph::load_case(kCase, {"fluid.spacing=0.003"});
  const FluidParameters parameters = read_fluid_parameters(case_file);
  omp_set_num_threads(2);  // as OpenMP starts on a two-core machine
  const long before = threads_of_this_process();
  sph::RunThreads threads(parameters.run.threads);
  FluidSolver solver(case_file, parameters);
  ASSERT_EQ(threads.settle(solver.particles().size()), 1);
  solver.step(solver.step_limits().smallest());
  EXPECT_EQ(threads_of_this_process(), before);
}

TEST(RunThreads, OnePerFourThousandParticlesUpToTheCoresUnlessRequested) {
  omp_set_num_threads(2);
  sph::RunThreads automatic(0);
  EXPECT_EQ(omp_get_max_threads(), 1);  // while the solver is built
  EXPECT_EQ(automatic.settle(3000), 1);
  EXPECT_EQ(automatic.settle(9000), 2);
  EXPECT_EQ(automatic.settle(90000), 2);  // no more than OpenMP had
  sph::RunThreads requested(3);
  EXPECT_EQ(omp_get_max_threads(), 3);
  EXPECT_EQ(requested.settle(100), 3);
}

}  // namespace
}  // namespace cosph::fluid
