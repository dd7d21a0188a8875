#include "occluder_tree.h"

#include <algorithm>
#include <numeric>

namespace penumbra::detail {
namespace {

constexpr std::size_t kLeafSize = 4;

}  // namespace

OccluderTree::OccluderTree(const std::vector<const ConvexPolyhedron*>& solids) : solids_(solids) {
  if (solids.empty()) return;
  std::vector<CGAL::Bbox_3> boxes;
  boxes.reserve(solids.size());
  for (const ConvexPolyhedron* solid : solids) boxes.push_back(solid->bbox());
  order_.resize(solids.size());
  std::iota(order_.begin(), order_.end(), 0);
  nodes_.reserve(2 * solids.size() / kLeafSize + 1);
  nodes_.push_back({{}, 0, solids.size()});
  build(0, boxes);
}

void OccluderTree::build(std::size_t node, const std::vector<CGAL::Bbox_3>& boxes) {
  const std::size_t begin = nodes_[node].begin, end = nodes_[node].end;
  CGAL::Bbox_3 box;
  for (std::size_t k = begin; k < end; ++k) box += boxes[order_[k]];
  nodes_[node].box = box;
  if (end - begin <= kLeafSize) return;
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (box.max(i) - box.min(i) > box.max(axis) - box.min(axis)) axis = i;
  const std::size_t middle = begin + (end - begin) / 2;
  // Ties broken by index, so the tree does not depend on the library's nth_element.
  std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(begin),
                   order_.begin() + static_cast<std::ptrdiff_t>(middle),
                   order_.begin() + static_cast<std::ptrdiff_t>(end),
                   [&](std::size_t a, std::size_t b) {
                     const double ca = boxes[a].min(axis) + boxes[a].max(axis);
                     const double cb = boxes[b].min(axis) + boxes[b].max(axis);
                     return ca != cb ? ca < cb : a < b;
                   });
  const std::size_t left = nodes_.size();
  nodes_[node].left = left;
  nodes_.push_back({{}, begin, middle});
  nodes_.push_back({{}, middle, end});
  build(left, boxes);
  build(left + 1, boxes);
}

std::vector<std::size_t> OccluderTree::candidates(const SweptRegion& region,
                                                  std::size_t skip) const {
  std::vector<std::size_t> found;
  if (nodes_.empty()) return found;
  std::vector<std::size_t> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (region.separated_from(node.box)) continue;
    if (node.left != 0) {
      stack.push_back(node.left);
      stack.push_back(node.left + 1);
      continue;
    }
    for (std::size_t k = node.begin; k < node.end; ++k) {
      const std::size_t solid = order_[k];
      if (solid != skip && !region.separated_from(*solids_[solid])) found.push_back(solid);
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace penumbra::detail
