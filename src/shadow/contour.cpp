#include "penumbra/shadow/contour.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace penumbra {

std::vector<int> contour(const ConvexPolyhedron& solid, const Point3& source) {
  const std::vector<Face>& faces = solid.faces();
  std::vector<bool> toward(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) toward[f] = turned_toward(faces[f], source);

  // The faces turned toward an exterior source form a disk (they project one to
  // one onto the silhouette); its boundary, taken along the faces' own
  // counter-clockwise edges, runs counter-clockwise seen from the source.
  std::map<int, int> next;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!toward[f]) continue;
    const Face& face = faces[f];
    const std::size_t n = face.vertex_ids.size();
    for (std::size_t k = 0; k < n; ++k) {
      if (toward[face.neighbours[k]]) continue;
      if (!next.emplace(face.vertex_ids[k], face.vertex_ids[(k + 1) % n]).second)
        throw std::logic_error("contour: a vertex with two outgoing contour edges");
    }
  }
  std::vector<int> loop;
  if (next.empty()) return loop;
  const int start = next.begin()->first;
  int vertex = start;
  do {
    loop.push_back(vertex);
    const auto it = next.find(vertex);
    if (it == next.end() || loop.size() > next.size())
      throw std::logic_error("contour: the contour edges do not close into one loop");
    vertex = it->second;
  } while (vertex != start);
  if (loop.size() != next.size()) throw std::logic_error("contour: more than one contour loop");
  // Clockwise seen from the source, as the paper defines C_r.
  std::reverse(loop.begin() + 1, loop.end());
  return loop;
}

}  // namespace penumbra
