#pragma once
// Disjoint sets of the numbers 0 to n - 1 (union-find with path halving), private to the
// shadow layer: touching groups of shadows, clusters of an overlay, the faces and
// components of the pairwise arrangement.

#include <cstddef>
#include <numeric>
#include <vector>

namespace penumbra::detail {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  // returns the representative of k's set.
  std::size_t root(std::size_t k) {
    while (parent_[k] != k) k = parent_[k] = parent_[parent_[k]];
    return k;
  }
  // joins the sets of a and b (b's representative stays).
  void join(std::size_t a, std::size_t b) { parent_[root(a)] = root(b); }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace penumbra::detail
