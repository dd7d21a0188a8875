#include "penumbra/visibility/broad_phase.h"

#include "occluder_tree.h"
#include "penumbra/base/parallel.h"
#include "penumbra/visibility/swept_region.h"

namespace penumbra {
namespace {

// queries the tree of the objects with each receiver's swept region, across threads.
template <typename Region>
std::vector<std::vector<std::size_t>> query(const std::vector<const ConvexPolyhedron*>& objects,
                                            const std::vector<Receiver>& receivers,
                                            Region region_of) {
  const detail::OccluderTree tree(objects);
  std::vector<std::vector<std::size_t>> candidates(receivers.size());
  for_each_index(receivers.size(), receivers.size() > 16, [&](std::size_t r) {
    const Receiver& receiver = receivers[r];
    candidates[r] = tree.candidates(region_of(objects[receiver.object]->faces()[receiver.face]),
                                    receiver.object);
  });
  return candidates;
}

}  // namespace

std::vector<std::vector<std::size_t>> candidate_occluders(
    const std::vector<const ConvexPolyhedron*>& objects, const std::vector<Receiver>& receivers,
    const LightPosition& light) {
  return query(objects, receivers, [&](const Face& face) { return SweptRegion(face, light); });
}

std::vector<std::vector<std::size_t>> candidate_occluders(
    const std::vector<const ConvexPolyhedron*>& objects, const std::vector<Receiver>& receivers,
    const Point3& q1, const Point3& q2) {
  return query(objects, receivers, [&](const Face& face) { return SweptRegion(face, q1, q2); });
}

std::vector<std::vector<std::size_t>> candidate_occluders(
    const std::vector<const ConvexPolyhedron*>& objects, const std::vector<Receiver>& receivers,
    const std::vector<Point3>& source) {
  return query(objects, receivers, [&](const Face& face) { return SweptRegion(face, source); });
}

}  // namespace penumbra
