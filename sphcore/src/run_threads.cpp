#include "sphcore/run_threads.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "sphcore/free_cores.hpp"

namespace sph {

int choose_threads(int requested, std::size_t particles, int available, double cores_left) {
  if (requested > 0) return requested;
  constexpr std::size_t kParticlesPerThread = 4000;
  const int useful = static_cast<int>(std::max<std::size_t>(1, particles / kParticlesPerThread));
  const int free_cores = static_cast<int>(std::floor(cores_left + kBusyCoreShare));
  return std::max(1, std::min({useful, available, free_cores}));
}

namespace {
RunThreads::CoresLeft machine_meter() {
  auto meter = std::make_shared<FreeCoreMeter>();
  return [meter] { return meter->cores_left(); };
}
}  // namespace

RunThreads::RunThreads(int requested) : RunThreads(requested, machine_meter()) {}

RunThreads::RunThreads(int requested, CoresLeft cores_left)
    : requested_(requested), available_(omp_get_max_threads()), cores_left_(std::move(cores_left)) {
  omp_set_num_threads(requested > 0 ? requested : 1);
}

int RunThreads::settle(std::size_t particles) {
  particles_ = particles;
  return revise_now();
}

int RunThreads::revise() {
  if (requested_ > 0 || std::chrono::steady_clock::now() < next_revision_) return threads_;
  return revise_now();
}

int RunThreads::revise_now() {
  const double left = requested_ > 0 ? 0.0 : cores_left_();
  threads_ = choose_threads(requested_, particles_, available_, left);
  omp_set_num_threads(threads_);
  next_revision_ = std::chrono::steady_clock::now() + kRevisionPeriod;
  return threads_;
}

}  // namespace sph
