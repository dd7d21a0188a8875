#pragma once
// A bounding volume hierarchy over the occluders' boxes (private to the broad phase): boxes
// split at the median of their centres along the longest axis, down to a few per leaf. A
// query walks it with a swept region, leaving every node whose box a supporting plane of the
// region certainly separates, and tests the occluders of the leaves it reaches one by one.
// (CGAL's AABB_tree offers such a query only through its internal traversal interface.)

#include <cstddef>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/visibility/swept_region.h"

namespace penumbra::detail {

class OccluderTree {
 public:
  explicit OccluderTree(const std::vector<const ConvexPolyhedron*>& solids);

  // returns the indices (increasing) of the solids other than skip that region may meet:
  // every one that no plane certainly separates from it.
  std::vector<std::size_t> candidates(const SweptRegion& region, std::size_t skip) const;

 private:
  struct Node {
    CGAL::Bbox_3 box;
    std::size_t begin, end;  // the solids order_[begin, end) below the node
    std::size_t left = 0;    // the children (right = left + 1); 0 for a leaf
  };
  void build(std::size_t node, const std::vector<CGAL::Bbox_3>& boxes);

  const std::vector<const ConvexPolyhedron*>& solids_;
  std::vector<std::size_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace penumbra::detail
