// The particle loops of the solvers, on the OpenMP team when that is worth it
// and as plain loops otherwise. Every loop of the solvers gives the same result
// on any number of threads, so this decides speed only.
#pragma once

#include <omp.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

namespace sph {

// Below a few thousand particles a parallel loop costs more in starting
// threads and waiting at its barrier than it saves: on the dam break at 1 182
// particles, two threads took longer per step than one.
inline bool worth_threads(std::size_t particles) {
  return particles >= 4096;
}

// A loop runs on the OpenMP team when the caller allows it (`use_team`: by
// default worth_threads) and the team has more than one thread; otherwise it
// runs as a plain loop rather than as a region of one thread, which libgomp
// still starts as a team and ends with a futex system call (its barrier wakes
// whoever may wait), also when an `if` clause turns the region off. On the
// elastic plate's solid alone (800 particles), without the seven of its plain
// loops each step it ran 6 % faster, and without the six of its two pair
// passes and their ordered shares, 7 % faster again. The solid allows the team at
// any size: its particles cost more, and two threads paid at 1 100 particles
// (the benchmark: 0.49 against 0.67 ms a step).
inline bool on_team(bool use_team) {
  return use_team && omp_get_max_threads() > 1;
}
inline bool threaded(std::size_t particles) {
  return on_team(worth_threads(particles));
}

// For the solid's loops: the team at any size.
inline constexpr bool kTeamAtAnySize = true;

// The calling thread's share of [0, n) as OpenMP's schedule(static) gives it:
// contiguous, the first n % T threads one index more.
inline std::pair<long, long> static_share(long n) {
  const long threads = omp_get_num_threads(), thread = omp_get_thread_num();
  long share = n / threads, extra = n % threads;
  if (thread < extra) {
    ++share;
    extra = 0;
  }
  const long begin = share * thread + extra;
  return {begin, begin + share};
}

// range(begin, end) once for each thread's share of [0, n) under a static
// schedule, or once for all of it when the loop runs alone.
template <class Range>
void for_each_share(std::size_t n, bool use_team, Range&& range) {
  const long count = static_cast<long>(n);
  if (!on_team(use_team)) return range(0L, count);
#pragma omp parallel
  {
    const auto [begin, end] = static_share(count);
    range(begin, end);
  }
}

// The helpers below run `body` in one loop over a range, which both the plain
// and the threaded path call, and flatten it: the body is inlined there, as
// the compiler did into the loop of an omp for. Without flatten, the solid's
// large bodies stayed a call per particle, 7 % slower.

// body(i) for every i in [0, n), under a static schedule.
template <class Body>
void parallel_for(std::size_t n, bool use_team, Body&& body) {
  for_each_share(
      n, use_team, [&body](long begin, long end) __attribute__((flatten)) {
        for (long i = begin; i < end; ++i) body(i);
      });
}

template <class Body>
void parallel_for(std::size_t n, Body&& body) {
  parallel_for(n, worth_threads(n), std::forward<Body>(body));
}

namespace detail {
// What parallel_max keeps: one largest value (double), or one for each of N
// quantities (std::array<double, N>), seen as N doubles for the reduction.
inline void keep_larger(double& largest, double value) {
  largest = std::max(largest, value);
}
template <std::size_t N>
void keep_larger(std::array<double, N>& largest, const std::array<double, N>& value) {
  for (std::size_t k = 0; k < N; ++k) largest[k] = std::max(largest[k], value[k]);
}
inline double* values_of(double& largest) {
  return &largest;
}
template <std::size_t N>
double* values_of(std::array<double, N>& largest) {
  return largest.data();
}
}  // namespace detail

// The largest value(i) over i in [0, n), and `none` if that is larger. With
// `none` a std::array<double, N> and value(i) one too, the largest of each of
// N quantities in one pass. value may also update particle i (one pass
// instead of two).
template <class Maxima, class Value>
Maxima parallel_max(std::size_t n, Maxima none, bool use_team, Value&& value) {
  const auto loop = [&value](long begin, long end, Maxima largest) __attribute__((flatten)) {
    for (long i = begin; i < end; ++i) detail::keep_larger(largest, value(i));
    return largest;
  };
  const long count = static_cast<long>(n);
  if (!on_team(use_team)) return loop(0, count, none);
  constexpr std::size_t kCount = sizeof(Maxima) / sizeof(double);
  Maxima largest = none;
  double* const shared = detail::values_of(largest);
#pragma omp parallel reduction(max : shared[:kCount])
  {
    const auto [begin, end] = static_share(count);
    Maxima mine;
    std::copy(shared, shared + kCount, detail::values_of(mine));  // the reduction's identity
    mine = loop(begin, end, mine);
    std::copy(detail::values_of(mine), detail::values_of(mine) + kCount, shared);
  }
  return largest;
}

template <class Value>
double parallel_max(std::size_t n, double none, Value&& value) {
  return parallel_max(n, none, worth_threads(n), std::forward<Value>(value));
}

// The first i in [0, n) with found(i), as a serial scan finds it; n if none.
template <class Found>
long parallel_find_first(std::size_t n, Found&& found) {
  const auto loop = [&found](long begin, long end) __attribute__((flatten)) {
    for (long i = begin; i < end; ++i)
      if (found(i)) return i;
    return end;
  };
  const long count = static_cast<long>(n);
  if (!threaded(n)) return loop(0, count);
  long first = count;
#pragma omp parallel reduction(min : first)
  {
    const auto [begin, end] = static_share(count);
    if (const long i = loop(begin, end); i < end) first = i;
  }
  return first;
}

// Whether found(i) holds for some i in [0, n). Every i is tested, with no
// early exit, so that a branch-free test on plain arrays vectorises: a screen
// over all particles that is almost always passed costs a fraction of a loop
// that stops at the first hit but tests one particle at a time.
template <class Found>
bool parallel_any(std::size_t n, bool use_team, Found&& found) {
  const auto loop = [&found](long begin, long end) __attribute__((flatten)) {
    long any = 0;  // a bool here, narrower than the tests' doubles, does not vectorise
    for (long i = begin; i < end; ++i) any |= static_cast<long>(found(i));
    return any != 0;
  };
  const long count = static_cast<long>(n);
  if (!on_team(use_team)) return loop(0, count);
  bool any = false;
#pragma omp parallel reduction(|| : any)
  {
    const auto [begin, end] = static_share(count);
    any = loop(begin, end);
  }
  return any;
}

}  // namespace sph
