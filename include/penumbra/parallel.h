#pragma once
// One loop over [0, count) that runs on TBB's threads when asked and in order otherwise
// (serial runs are how tests check that results do not depend on the threads).

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

namespace penumbra {

// calls work(k) for every k in [0, count), across threads when parallel.
template <typename Work>
void for_each_index(std::size_t count, bool parallel, const Work& work) {
  if (parallel)
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t k = range.begin(); k != range.end(); ++k) work(k);
                      });
  else
    for (std::size_t k = 0; k < count; ++k) work(k);
}

}  // namespace penumbra
