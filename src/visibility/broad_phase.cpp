#include "penumbra/visibility/broad_phase.h"

#include <algorithm>
#include <cmath>

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>

namespace penumbra {
namespace {

using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t,
                                                      CGAL::Box_intersection_d::ID_EXPLICIT>;

// returns the bounding box of the region from face toward the source.
CGAL::Bbox_3 region_box(const Face& face, const LightPosition& light, const CGAL::Bbox_3& scene) {
  CGAL::Bbox_3 box;
  for (const Point3& p : face.vertices) box += p.bbox();
  if (!light.at_infinity()) return box + light.point().bbox();
  // Prism toward the sun, F + t (-d), cut at t_max: beyond it the coordinate along
  // the dominant axis i of d has moved by more than the scene's extent, so the
  // prism has left the scene box.
  const Vec3d d = to_double(light.travel());
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(d[i]) > std::abs(d[axis])) axis = i;
  const Exact extent = Exact(scene.max(axis)) - Exact(scene.min(axis));
  const Exact component = axis == 0   ? light.travel().x()
                          : axis == 1 ? light.travel().y()
                                      : light.travel().z();
  const Exact t_max = extent / CGAL::abs(component);
  for (const Point3& p : face.vertices) box += (p - t_max * light.travel()).bbox();
  return box;
}

// intersects the receivers' region boxes with the objects' boxes.
template <typename RegionBox>
std::vector<std::vector<std::size_t>> intersect_boxes(
    const std::vector<const ConvexPolyhedron*>& objects, const std::vector<Receiver>& receivers,
    RegionBox region_box) {
  std::vector<Box> object_boxes;
  CGAL::Bbox_3 scene;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const CGAL::Bbox_3 box = objects[k]->bbox();
    scene += box;
    object_boxes.emplace_back(box, k);
  }
  std::vector<Box> receiver_boxes;
  for (std::size_t r = 0; r < receivers.size(); ++r) {
    const Face& face = objects[receivers[r].object]->faces()[receivers[r].face];
    receiver_boxes.emplace_back(region_box(face, scene), r);
  }

  std::vector<std::vector<std::size_t>> candidates(receivers.size());
  CGAL::box_intersection_d(receiver_boxes.begin(), receiver_boxes.end(), object_boxes.begin(),
                           object_boxes.end(), [&](const Box& receiver, const Box& object) {
                             if (receivers[receiver.info()].object != object.info())
                               candidates[receiver.info()].push_back(object.info());
                           });
  for (auto& list : candidates) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return candidates;
}

}  // namespace

std::vector<std::vector<std::size_t>> candidate_occluders(
    const std::vector<const ConvexPolyhedron*>& objects, const std::vector<Receiver>& receivers,
    const LightPosition& light) {
  return intersect_boxes(objects, receivers, [&](const Face& face, const CGAL::Bbox_3& scene) {
    return region_box(face, light, scene);
  });
}

std::vector<std::vector<std::size_t>> candidate_occluders(
    const std::vector<const ConvexPolyhedron*>& objects, const std::vector<Receiver>& receivers,
    const Point3& q1, const Point3& q2) {
  return intersect_boxes(objects, receivers, [&](const Face& face, const CGAL::Bbox_3&) {
    CGAL::Bbox_3 box = q1.bbox() + q2.bbox();
    for (const Point3& p : face.vertices) box += p.bbox();
    return box;
  });
}

}  // namespace penumbra
