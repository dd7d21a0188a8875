#include "back_pieces.h"

#include <unordered_map>

namespace penumbra::detail {
namespace {

// true when p lies strictly outside box (exactly: the box's bounds are doubles).
bool outside(const Point3& p, const CGAL::Bbox_3& box) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < Exact(box.min(k)) || p[k] > Exact(box.max(k))) return true;
  return false;
}

}  // namespace

std::vector<char> back_pieces(const Scene& scene, const LightPosition& light) {
  std::vector<char> back(scene.objects.size(), 0);
  // The outer side of each piece of a closed part: the one face that receives.
  std::vector<int> outer(scene.objects.size(), -1);
  std::unordered_map<std::string, CGAL::Bbox_3> part_box;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const Object& object = scene.objects[o];
    if (object.mesh_faces.size() != 2) continue;
    const bool first = object.receives(0), second = object.receives(1);
    if (first == second) continue;  // an open face: both sides receive
    outer[o] = first ? 0 : 1;
    part_box[object.part] += object.solid.bbox();
  }
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    if (outer[o] < 0) continue;
    const Object& object = scene.objects[o];
    if (light.side_of(object.solid.faces()[outer[o]].plane) != CGAL::NEGATIVE) continue;
    if (light.at_infinity() || outside(light.point(), part_box[object.part])) back[o] = 1;
  }
  return back;
}

}  // namespace penumbra::detail
