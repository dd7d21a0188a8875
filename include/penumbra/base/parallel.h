#pragma once
// One loop over [0, count) that runs on TBB's threads when asked and in order otherwise
// (serial runs are how tests check that results do not depend on the threads). Every
// parallel loop of penumbra goes through here.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

namespace penumbra {

// limits every parallel loop to PENUMBRA_THREADS threads when that environment variable is
// a positive whole number (1: every loop on one thread; a Dask worker given one core), to
// TBB's default otherwise; read once, on the first call. for_each_range calls it.
void apply_thread_limit();

// calls work(begin, end) on disjoint sub-ranges that together cover [0, count): across
// threads when parallel, each at least grain long where count allows; once with (0, count)
// otherwise.
template <typename Work>
void for_each_range(std::size_t count, bool parallel, const Work& work, std::size_t grain = 1) {
  if (parallel) apply_thread_limit();
  if (parallel)
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, count, grain),
        [&](const tbb::blocked_range<std::size_t>& range) { work(range.begin(), range.end()); });
  else
    work(std::size_t{0}, count);
}

// calls work(k) for every k in [0, count), across threads when parallel.
template <typename Work>
void for_each_index(std::size_t count, bool parallel, const Work& work, std::size_t grain = 1) {
  for_each_range(
      count, parallel,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k != end; ++k) work(k);
      },
      grain);
}

}  // namespace penumbra
