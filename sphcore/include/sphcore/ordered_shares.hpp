// A pair pass that works each pair out once and gives both particles their
// shares, with every particle's sum taken in one order whatever the thread
// count (results here are the same bits on any number of threads).
//
// The particles are cut into blocks of `block` consecutive indices, a size of
// its own, not the thread count's. One thread visits a block's particles in
// index order. Visiting i, the pass adds i's own sum to sums[i] and sends each
// later particle j > i its share through share(block, sums, j): into sums[j]
// at once if j lies in the same block, else into the block's spill buffer.
// Once every block is done, merge() adds to each particle the spill buffers
// of the blocks before its own, in block order. The order of every sum is
// thus fixed by the indices alone.
//
// The neighbour lists hold a particle's neighbours in index order, so the
// later ones are the end of each list.
#pragma once

#include <omp.h>

#include <algorithm>
#include <span>
#include <vector>

#include "sphcore/parallel.hpp"

namespace sph {

template <class T>
class OrderedShares {
 public:
  // 1024: each of two threads gets many blocks at 10 000 particles and more,
  // while a spill buffer (as long as the reach of a block's pairs past its
  // end, a few hundred particles in the benchmark's scenes) stays small.
  static constexpr long kDefaultBlock = 1024;

  explicit OrderedShares(const T& zero, long block = kDefaultBlock) : zero_(zero), block_(block) {}

  // Sets up the blocks for n particles and zeroes their spill buffers.
  // last_neighbour(i) is the highest index i sends a share to (or below i).
  template <class LastNeighbour>
  long prepare(long n, bool use_team, LastNeighbour&& last_neighbour) {
    const long blocks = (n + block_ - 1) / block_;
    end_.resize(blocks);
    reach_end_.resize(blocks);
    base_.resize(blocks);
    parallel_for(blocks, use_team, [&](long b) {
      end_[b] = std::min(n, (b + 1) * block_);
      long reach_end = end_[b];
      for (long i = begin(b); i < end_[b]; ++i)
        reach_end = std::max(reach_end, last_neighbour(i) + 1);
      reach_end_[b] = reach_end;
    });
    long size = 0;
    for (long b = 0; b < blocks; ++b) {
      base_[b] = size - end_[b];
      size += reach_end_[b] - end_[b];
    }
    spill_.assign(static_cast<std::size_t>(size), zero_);
    return blocks;
  }

  long begin(long block) const { return block * block_; }
  long end(long block) const { return end_[block]; }

  // Where block `block` sends the share of particle j (j > the visited i).
  T& share(long block, T* sums, long j) {
    return j < end_[block] ? sums[j] : spill_[static_cast<std::size_t>(base_[block] + j)];
  }

  // share(block, sums, j) for one block, its bounds held by value: a pair
  // loop whose stores may alias anything (Eigen's packet stores) would
  // otherwise read end_[block] and base_[block] again after every share.
  class BlockShares {
   public:
    T& operator()(long j) const { return j < end_ ? sums_[j] : spill_[base_ + j]; }

   private:
    friend class OrderedShares;
    BlockShares(T* sums, T* spill, long end, long base)
        : sums_(sums), spill_(spill), end_(end), base_(base) {}
    T* sums_;
    T* spill_;
    long end_, base_;
  };
  BlockShares block_shares(long block, T* sums) {
    return {sums, spill_.data(), end_[block], base_[block]};
  }

  // Adds the spill buffers to the sums of the later blocks, in block order.
  void merge(std::span<T> sums, bool use_team) const {
    const long blocks = static_cast<long>(end_.size());
    // Block 0 receives nothing: its loop is empty.
    parallel_for(blocks, use_team, [&](long b) {
      for (long from = 0; from < b; ++from) {
        const long last = std::min(end_[b], reach_end_[from]);
        for (long j = begin(b); j < last; ++j)
          sums[j] += spill_[static_cast<std::size_t>(base_[from] + j)];
      }
    });
  }

 private:
  T zero_;
  long block_;
  std::vector<long> end_;        // of each block
  std::vector<long> reach_end_;  // one past the highest index each block sends to
  std::vector<long> base_;       // spill_[base_[b] + j] is block b's share for j
  std::vector<T> spill_;
};

}  // namespace sph
