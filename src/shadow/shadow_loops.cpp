#include "penumbra/shadow/shadow_loops.h"

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>

#include <algorithm>
#include <map>
#include <queue>

#include "half_plane.h"
#include "penumbra/shadow/face_shadow.h"

namespace penumbra {
namespace {

using Traits = CGAL::Arr_segment_traits_2<Kernel>;
using Arrangement = CGAL::Arrangement_2<Traits>;

// appends contour[from .. to] (walking forward, both ends included) of the ring.
void append_string(Ring2& loop, const Ring2& projected, const std::vector<int>& contour, int from,
                   int to) {
  const std::size_t n = contour.size();
  std::size_t i = std::find(contour.begin(), contour.end(), from) - contour.begin();
  for (;;) {
    loop.push_back(projected[i]);
    if (contour[i] == to) break;
    i = (i + 1) % n;
  }
}

// returns the net number of loop segments running along the halfedge's direction.
int net_crossings(Arrangement::Halfedge_const_handle edge, const std::vector<Segment2>& segments) {
  const Point2& source = edge->source()->point();
  const Point2& target = edge->target()->point();
  int net = 0;
  for (const Segment2& segment : segments) {
    if (!segment.has_on(source) || !segment.has_on(target)) continue;
    // Same direction when the segment's source comes first along the halfedge.
    net += (CGAL::compare_distance_to_point(segment.source(), source, target) == CGAL::SMALLER)
               ? 1
               : -1;
  }
  return net;
}

// returns a face's boundary cycle as a ring.
Ring2 ring_of(Arrangement::Ccb_halfedge_const_circulator circulator) {
  Ring2 ring;
  const auto start = circulator;
  do {
    ring.push_back(circulator->source()->point());
  } while (++circulator != start);
  return ring;
}

std::optional<Ring2> single_convex(const std::vector<Ring2>& regions, const Ring2& window) {
  if (regions.size() != 1) return std::nullopt;
  return detail::ring_with_area(detail::clip_to_convex(regions.front(), window));
}

}  // namespace

ShadowLoops shadow_loops(const ConvexPolyhedron& solid, const Face& face, const Point3& q1,
                         const Point3& q2, const LinearVolumes& volumes) {
  const Ring2 c1 = projected_contour(solid, volumes.contour1, face, q1);
  const Ring2 c2 = projected_contour(solid, volumes.contour2, face, q2);
  ShadowLoops loops;
  if (volumes.kind == LinearCase::B) {
    loops.penumbra_loop = volumes.nearer_is_q1 ? c1 : c2;
    loops.umbra_loop = volumes.nearer_is_q1 ? c2 : c1;
    return loops;
  }
  append_string(loops.penumbra_loop, c1, volumes.contour1, volumes.left, volumes.right);
  append_string(loops.penumbra_loop, c2, volumes.contour2, volumes.right, volumes.left);
  append_string(loops.umbra_loop, c1, volumes.contour1, volumes.right, volumes.left);
  append_string(loops.umbra_loop, c2, volumes.contour2, volumes.left, volumes.right);
  return loops;
}

std::vector<Ring2> clockwise_regions(const Ring2& loop) {
  std::vector<Segment2> segments;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Point2& p = loop[k];
    const Point2& q = loop[(k + 1) % loop.size()];
    if (p != q) segments.emplace_back(p, q);
  }
  Arrangement arrangement;
  CGAL::insert(arrangement, segments.begin(), segments.end());

  // Winding numbers by a walk over the faces from the unbounded one (winding 0):
  // crossing a halfedge from its right to its left adds the net number of loop
  // segments running along it (a counter-clockwise loop has +1 on its left).
  std::map<Arrangement::Face_const_handle, int> winding;
  std::queue<Arrangement::Face_const_handle> pending;
  winding[arrangement.unbounded_face()] = 0;
  pending.push(arrangement.unbounded_face());
  while (!pending.empty()) {
    const auto face = pending.front();
    pending.pop();
    std::vector<Arrangement::Ccb_halfedge_const_circulator> boundaries;
    if (!face->is_unbounded()) boundaries.push_back(face->outer_ccb());
    for (auto hole = face->inner_ccbs_begin(); hole != face->inner_ccbs_end(); ++hole)
      boundaries.push_back(*hole);
    for (auto start : boundaries) {
      auto edge = start;
      do {
        const auto across = edge->twin();
        const auto neighbour = across->face();
        if (!winding.count(neighbour)) {
          winding[neighbour] = winding[face] + net_crossings(across, segments);
          pending.push(neighbour);
        }
      } while (++edge != start);
    }
  }

  std::vector<Ring2> regions;
  for (auto face = arrangement.faces_begin(); face != arrangement.faces_end(); ++face) {
    if (face->is_unbounded() || winding[face] != -1) continue;
    // Bounded faces of a single closed loop have no holes with winding -1 inside
    // them that matter here; the outer boundary is counter-clockwise.
    Ring2 ring = canonical_ring(ring_of(face->outer_ccb()));
    if (!ring.empty()) regions.push_back(std::move(ring));
  }
  std::sort(regions.begin(), regions.end(), [](const Ring2& a, const Ring2& b) {
    return CGAL::compare_xy(a.front(), b.front()) == CGAL::SMALLER;
  });
  return regions;
}

LinearShadowRings loop_regions(const Face& face, const ShadowLoops& loops) {
  const Ring2 window = face_ring(face);
  return {single_convex(clockwise_regions(loops.penumbra_loop), window),
          single_convex(clockwise_regions(loops.umbra_loop), window)};
}

}  // namespace penumbra
