// A solver's OpenMP threads are set in two steps (sph::RunThreads): building
// the solver must start no thread that the run will not use, since such a
// thread stays for the whole run and, under OMP_WAIT_POLICY=active, spins on
// a core that the other processes of a coupled run need. The run takes no
// more threads than the cores other processes leave free, and follows them.
#include <gtest/gtest.h>
#include <omp.h>

#include <chrono>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "fluid_parameters.hpp"
#include "fluid_solver.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/free_cores.hpp"
#include "sphcore/run_parameters.hpp"
#include "sphcore/run_threads.hpp"

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

// The cores other processes leave, as a fake meter reports them.
sph::RunThreads::CoresLeft reporting(const double& cores_left) {
  return [&cores_left] { return cores_left; };
}

TEST(RunThreads, OnePerFourThousandParticlesUpToTheCoresUnlessRequested) {
  omp_set_num_threads(2);
  const double quiet = 2.0;
  sph::RunThreads automatic(0, reporting(quiet));
  EXPECT_EQ(omp_get_max_threads(), 1);  // while the solver is built
  EXPECT_EQ(automatic.settle(3000), 1);
  EXPECT_EQ(automatic.settle(9000), 2);
  EXPECT_EQ(automatic.settle(90000), 2);  // no more than OpenMP had
  const double one_core_busy = 1.0;
  sph::RunThreads requested(3, reporting(one_core_busy));
  EXPECT_EQ(omp_get_max_threads(), 3);
  EXPECT_EQ(requested.settle(100), 3);
  EXPECT_EQ(requested.revise_now(), 3);  // the count asked for, busy or not
}

TEST(RunThreads, NoMoreThanTheCoresOtherProcessesLeave) {
  EXPECT_EQ(sph::choose_threads(0, 90000, 2, 2.0), 2);
  EXPECT_EQ(sph::choose_threads(0, 90000, 2, 1.8), 2);  // others use a fifth of a core
  EXPECT_EQ(sph::choose_threads(0, 90000, 2, 1.7), 1);  // ... and a third
  EXPECT_EQ(sph::choose_threads(0, 90000, 2, 1.0), 1);  // one busy loop
  EXPECT_EQ(sph::choose_threads(0, 90000, 2, 0.0), 1);  // at least one
  EXPECT_EQ(sph::choose_threads(0, 90000, 4, 2.9), 3);
}

TEST(RunThreads, FollowTheFreeCoresDuringTheRun) {
  omp_set_num_threads(2);
  double cores_left = 2.0;
  sph::RunThreads automatic(0, reporting(cores_left));
  EXPECT_EQ(automatic.settle(90000), 2);
  cores_left = 1.0;                  // an outside job starts
  EXPECT_EQ(automatic.revise(), 2);  // within the second: not looked at yet
  EXPECT_EQ(automatic.revise_now(), 1);
  EXPECT_EQ(omp_get_max_threads(), 1);
  cores_left = 1.9;  // it stopped
  EXPECT_EQ(automatic.revise_now(), 2);
  EXPECT_EQ(omp_get_max_threads(), 2);
}

// Other processes' CPU time is the machine's less this process's own.
TEST(FreeCores, TheMachinesBusyTimeLessThisProcesss) {
  const sph::CpuTimes before{10.0, 100.0, 20.0};
  // Over 2 s: the machine busy for 3.5 core-seconds, this process for 1.5 of them.
  EXPECT_DOUBLE_EQ(sph::cores_left_by_others(before, {12.0, 103.5, 21.5}, 2), 1.0);
  EXPECT_DOUBLE_EQ(sph::cores_left_by_others(before, {12.0, 101.5, 21.5}, 2), 2.0);
  EXPECT_DOUBLE_EQ(sph::cores_left_by_others(before, {12.0, 106.0, 20.0}, 2), 0.0);  // clamped
}

// A solver's first look, as it starts, is the threads runnable at that
// instant: /proc/stat's procs_running less the reader itself.
TEST(FreeCores, RunnableOthersAreProcsRunningLessTheReader) {
  std::istringstream stat(
      "cpu  100 0 50 1000 0 0 0 0 0 0\ncpu0 50 0 25 500 0 0 0 0 0 0\nintr 12 3 4\n"
      "ctxt 99\nprocs_running 3\nprocs_blocked 0\n");
  EXPECT_DOUBLE_EQ(sph::runnable_others(stat), 2.0);
  std::istringstream without("cpu  100 0 50 1000 0 0 0 0 0 0\n");
  EXPECT_LT(sph::runnable_others(without), 0.0);
  EXPECT_DOUBLE_EQ(sph::cores_left_now(2.0, 2), 0.0);
  EXPECT_DOUBLE_EQ(sph::cores_left_now(0.0, 2), 2.0);
  EXPECT_DOUBLE_EQ(sph::cores_left_now(5.0, 2), 0.0);   // clamped
  EXPECT_DOUBLE_EQ(sph::cores_left_now(-1.0, 2), 2.0);  // unreadable: all of them
}

// A thread caught runnable in one reading of a few does not count: the least
// reading does. An unreadable /proc/stat reads as unknown.
TEST(FreeCores, TheFirstLookTakesTheLeastOfItsReadings) {
  const std::vector<double> readings = {2.0, 0.0, 1.0};
  std::size_t next = 0;
  const auto read = [&] { return readings[next++ % readings.size()]; };
  EXPECT_DOUBLE_EQ(sph::least_runnable_others(read, 3, std::chrono::microseconds(0)), 0.0);
  next = 0;
  EXPECT_DOUBLE_EQ(sph::least_runnable_others(read, 1, std::chrono::microseconds(0)), 2.0);
  EXPECT_LT(sph::least_runnable_others([] { return -1.0; }, 3, std::chrono::microseconds(0)), 0.0);
}

// The first look does not wait for /proc/stat's CPU times to fill a window:
// every run would start 0.1 s late.
TEST(FreeCores, TheFirstLookDoesNotWait) {
  sph::FreeCoreMeter meter;
  const auto start = std::chrono::steady_clock::now();
  const double left = meter.cores_left();
  const double waited =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(waited, 0.5 * sph::FreeCoreMeter::kShortestWindow);
  EXPECT_GE(left, 0.0);
}

}  // namespace
}  // namespace cosph::fluid
