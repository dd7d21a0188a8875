#include "back_pieces.h"

#include <unordered_map>

#include <CGAL/intersections.h>

namespace penumbra::detail {
namespace {

// true when p lies strictly outside box (exactly: the box's bounds are doubles).
bool outside(const Point3& p, const CGAL::Bbox_3& box) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < Exact(box.min(k)) || p[k] > Exact(box.max(k))) return true;
  return false;
}

// The box's bounds are doubles: exactly the same box in the exact kernel.
CGAL::Iso_cuboid_3<Kernel> exact_box(const CGAL::Bbox_3& box) {
  return {Point3(box.xmin(), box.ymin(), box.zmin()), Point3(box.xmax(), box.ymax(), box.zmax())};
}

// The closed pieces of closed parts: for each object the index of its one receiving face (the
// outer side) or -1, and each part's bounding box.
struct ClosedPieces {
  std::vector<int> outer;
  std::unordered_map<std::string, CGAL::Bbox_3> part_box;
};

ClosedPieces closed_pieces(const Scene& scene) {
  ClosedPieces pieces{std::vector<int>(scene.objects.size(), -1), {}};
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const Object& object = scene.objects[o];
    if (object.mesh_faces.size() != 2) continue;
    const bool first = object.receives(0), second = object.receives(1);
    if (first == second) continue;  // an open face: both sides receive
    pieces.outer[o] = first ? 0 : 1;
    pieces.part_box[object.part] += object.solid.bbox();
  }
  return pieces;
}

// marks the pieces whose outer plane turned_away says is turned strictly away from the light,
// of the parts whose box outside says the light lies strictly outside.
template <typename TurnedAway, typename Outside>
std::vector<char> mark(const Scene& scene, TurnedAway turned_away, Outside outside) {
  ClosedPieces pieces = closed_pieces(scene);
  std::vector<char> back(scene.objects.size(), 0);
  std::unordered_map<std::string, bool> part_outside;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    if (pieces.outer[o] < 0) continue;
    const Object& object = scene.objects[o];
    if (!turned_away(object.solid.faces()[pieces.outer[o]].plane)) continue;
    auto known = part_outside.find(object.part);
    if (known == part_outside.end())
      known = part_outside.emplace(object.part, outside(pieces.part_box[object.part])).first;
    back[o] = known->second ? 1 : 0;
  }
  return back;
}

}  // namespace

std::vector<char> back_pieces(const Scene& scene, const LightPosition& light) {
  return mark(
      scene, [&](const Plane3& plane) { return light.side_of(plane) == CGAL::NEGATIVE; },
      [&](const CGAL::Bbox_3& box) { return light.at_infinity() || outside(light.point(), box); });
}

std::vector<char> back_pieces(const Scene& scene, const Point3& q1, const Point3& q2) {
  return mark(
      scene,
      [&](const Plane3& plane) {
        return plane.oriented_side(q1) == CGAL::ON_NEGATIVE_SIDE &&
               plane.oriented_side(q2) == CGAL::ON_NEGATIVE_SIDE;
      },
      [&](const CGAL::Bbox_3& box) {
        return !CGAL::do_intersect(exact_box(box), Segment3(q1, q2));
      });
}

}  // namespace penumbra::detail
