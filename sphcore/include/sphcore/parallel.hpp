// The particle loops of the solvers, on several threads when that is worth it
// and as plain loops otherwise. Every loop of the solvers gives the same result
// on any number of threads, so this decides speed only.
//
// The threads are OpenMP's team, or with -DCOSPH_PARALLEL=tbb oneTBB's workers
// (docs/performance.md measures both on a quiet and on a busy machine). The
// thread count is OpenMP's setting in both builds (omp_set_num_threads, as
// sph::RunThreads and the tests set it, a plain variable that starts no
// thread): the TBB build runs its loops in an arena of that many threads.
#pragma once

#include <omp.h>
#if COSPH_PARALLEL_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#endif

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

namespace detail {
// A chunked loop is cut into this many chunks per thread, whatever its
// length: a thread that finishes its chunks takes the next (OpenMP's dynamic
// schedule; TBB's work stealing), so a loop waits neither for the thread with
// the heavier half of uneven work (the neighbour passes: a wall particle has
// no pairs, a water particle dozens, unevenly spread over the indices) nor,
// on TBB, for a thread that lost its core, beyond the chunk it holds.
inline constexpr long kChunksPerThread = 8;

inline long chunk_count(long n) {
  return std::min(n, kChunksPerThread * omp_get_max_threads());
}
}  // namespace detail

#if COSPH_PARALLEL_TBB
namespace detail {

// The arena of OpenMP's thread count, made anew when the count changes.
inline tbb::task_arena& arena() {
  static tbb::task_arena run_arena(1);
  static int threads = 0;
  if (const int wanted = omp_get_max_threads(); wanted != threads) {
    if (run_arena.is_active()) run_arena.terminate();
    run_arena.initialize(wanted);
    threads = wanted;
  }
  return run_arena;
}

// chunk(begin, end, c) for the chunks c of [0, n), on the arena; each chunk is
// a task of its own (simple_partitioner, grain 1).
template <class Chunk>
void for_each_chunk(long n, Chunk&& chunk) {
  const long chunks = chunk_count(n);
  arena().execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<long>(0, chunks, 1),
        [&](const tbb::blocked_range<long>& r) {
          for (long c = r.begin(); c < r.end(); ++c) chunk(n * c / chunks, n * (c + 1) / chunks, c);
        },
        tbb::simple_partitioner());
  });
}

// The reduction of chunk(begin, end, identity) over the chunks of [0, n)
// with join(a, b), on the arena.
template <class Result, class Chunk, class Join>
Result reduce_chunks(long n, Result identity, Chunk&& chunk, Join&& join) {
  const long chunks = chunk_count(n);
  return arena().execute([&] {
    return tbb::parallel_reduce(
        tbb::blocked_range<long>(0, chunks, 1), identity,
        [&](const tbb::blocked_range<long>& r, Result result) {
          for (long c = r.begin(); c < r.end(); ++c)
            result = join(result, chunk(n * c / chunks, n * (c + 1) / chunks, identity));
          return result;
        },
        join, tbb::simple_partitioner());
  });
}
}  // namespace detail
#endif

// How many shares for_each_share cuts [0, n) into: one per thread of the
// team (OpenMP), a fixed number of chunks per thread (TBB), or one.
inline long share_count(std::size_t n, bool use_team) {
  if (!on_team(use_team)) return 1;
#if COSPH_PARALLEL_TBB
  return std::max(1L, detail::chunk_count(static_cast<long>(n)));
#else
  (void)n;
  return omp_get_max_threads();
#endif
}

// range(begin, end, share) once for each share of [0, n), numbered from 0 to
// share_count - 1: each thread's under a static schedule (OpenMP), each chunk
// (TBB), or all of it when the loop runs alone.
template <class Range>
void for_each_share(std::size_t n, bool use_team, Range&& range) {
  const long count = static_cast<long>(n);
  if (!on_team(use_team)) return range(0L, count, 0L);
#if COSPH_PARALLEL_TBB
  detail::for_each_chunk(count, range);
#else
#pragma omp parallel
  {
    const auto [begin, end] = static_share(count);
    range(begin, end, static_cast<long>(omp_get_thread_num()));
  }
#endif
}

// How many chunks for_each_chunk cuts [0, n) into: kChunksPerThread per
// thread of the team, or one.
inline long chunk_count(std::size_t n, bool use_team) {
  if (!on_team(use_team)) return 1;
  return std::max(1L, detail::chunk_count(static_cast<long>(n)));
}

// range(begin, end, chunk) once for each chunk of [0, n), numbered from 0 to
// chunk_count - 1, contiguous and in index order, each on whichever thread is
// free first: for loops whose work per index is uneven. Which thread runs a
// chunk changes nothing but the speed: a chunk's result must not depend on it.
template <class Range>
void for_each_chunk(std::size_t n, bool use_team, Range&& range) {
  const long count = static_cast<long>(n);
  if (!on_team(use_team) || count == 0) return range(0L, count, 0L);  // one chunk, as counted
#if COSPH_PARALLEL_TBB
  detail::for_each_chunk(count, range);
#else
  const long chunks = chunk_count(n, use_team);
#pragma omp parallel for schedule(dynamic, 1)
  for (long c = 0; c < chunks; ++c) range(count * c / chunks, count * (c + 1) / chunks, c);
#endif
}

// The helpers below run `body` in one loop over a range, which both the plain
// and the threaded path call, and flatten it: the body is inlined there, as
// the compiler did into the loop of an omp for. Without flatten, the solid's
// large bodies stayed a call per particle, 7 % slower.

// body(i) for every i in [0, n), under a static schedule.
template <class Body>
void parallel_for(std::size_t n, bool use_team, Body&& body) {
  for_each_share(
      n, use_team, [&body](long begin, long end, long) __attribute__((flatten)) {
        for (long i = begin; i < end; ++i) body(i);
      });
}

template <class Body>
void parallel_for(std::size_t n, Body&& body) {
  parallel_for(n, worth_threads(n), std::forward<Body>(body));
}

// body(i) for every i in [0, n), for the neighbour passes, whose bodies are
// large and whose work per index is uneven: in chunks (for_each_chunk), and
// not flattened (written through parallel_for, the two pair passes ran slower
// on large scenes). Without the team, a plain loop.
template <class Body>
void parallel_pass(std::size_t n, bool use_team, const Body& body) {
  for_each_chunk(n, use_team, [&body](long begin, long end, long) {
    for (long i = begin; i < end; ++i) body(i);
  });
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

// The largest of what range(begin, end, largest) returns over the shares of
// [0, n), and `none` if that is larger: range raises `largest` by the values
// of its share and returns it. For a loop that holds its arrays in locals over
// a share; `none` may be a std::array<double, N> of N quantities.
template <class Maxima, class Range>
Maxima parallel_max_of_shares(std::size_t n, Maxima none, bool use_team, Range&& range) {
  const long count = static_cast<long>(n);
  if (!on_team(use_team)) return range(0L, count, none);
#if COSPH_PARALLEL_TBB
  return detail::reduce_chunks(count, none, range, [](Maxima a, const Maxima& b) {
    detail::keep_larger(a, b);
    return a;
  });
#else
  constexpr std::size_t kCount = sizeof(Maxima) / sizeof(double);
  Maxima largest = none;
  double* const shared = detail::values_of(largest);
#pragma omp parallel reduction(max : shared[:kCount])
  {
    const auto [begin, end] = static_share(count);
    Maxima mine;
    std::copy(shared, shared + kCount, detail::values_of(mine));  // the reduction's identity
    mine = range(begin, end, mine);
    std::copy(detail::values_of(mine), detail::values_of(mine) + kCount, shared);
  }
  return largest;
#endif
}

// The largest value(i) over i in [0, n), and `none` if that is larger. With
// `none` a std::array<double, N> and value(i) one too, the largest of each of
// N quantities in one pass. value may also update particle i (one pass
// instead of two).
template <class Maxima, class Value>
Maxima parallel_max(std::size_t n, Maxima none, bool use_team, Value&& value) {
  return parallel_max_of_shares(
      n, none, use_team, [&value](long begin, long end, Maxima largest) __attribute__((flatten)) {
        for (long i = begin; i < end; ++i) detail::keep_larger(largest, value(i));
        return largest;
      });
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
#if COSPH_PARALLEL_TBB
  // A chunk without a hit gives count, which no hit exceeds.
  return detail::reduce_chunks(
      count, count,
      [&loop, count](long begin, long end, long) {
        const long i = loop(begin, end);
        return i < end ? i : count;
      },
      [](long a, long b) { return std::min(a, b); });
#else
  long first = count;
#pragma omp parallel reduction(min : first)
  {
    const auto [begin, end] = static_share(count);
    if (const long i = loop(begin, end); i < end) first = i;
  }
  return first;
#endif
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
#if COSPH_PARALLEL_TBB
  return detail::reduce_chunks(
      count, false, [&loop](long begin, long end, bool) { return loop(begin, end); },
      [](bool a, bool b) { return a || b; });
#else
  bool any = false;
#pragma omp parallel reduction(|| : any)
  {
    const auto [begin, end] = static_share(count);
    any = loop(begin, end);
  }
  return any;
#endif
}

}  // namespace sph
