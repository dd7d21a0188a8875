#include "mesh_face_shadow.h"

#include <algorithm>

#include "penumbra/geometry/exact.h"
#include "region_set.h"

namespace penumbra::detail {

FrameMap::FrameMap(const FaceFrame& from, const FaceFrame& to) {
  // A point o + s u + t v of from has, in to, s' = (X - o').u' / (u'.u') and likewise t'.
  const RationalPoint3& o = CGAL::exact(from.origin());
  const RationalPoint3& o2 = CGAL::exact(to.origin());
  const RationalVector3& u = CGAL::exact(from.u());
  const RationalVector3& v = CGAL::exact(from.v());
  const RationalVector3& u2 = CGAL::exact(to.u());
  const RationalVector3& v2 = CGAL::exact(to.v());
  const Rational& uu2 = CGAL::exact(to.squared_u());
  const Rational& vv2 = CGAL::exact(to.squared_v());
  const RationalVector3 d = o - o2;
  s0_ = d * u2 / uu2;
  su_ = u * u2 / uu2;
  sv_ = v * u2 / uu2;
  t0_ = d * v2 / vv2;
  tu_ = u * v2 / vv2;
  tv_ = v * v2 / vv2;
}

Point2 FrameMap::operator()(const Point2& p) const {
  const RationalPoint2& q = CGAL::exact(p);
  return from_exact<Point2>(
      RationalPoint2(s0_ + su_ * q.x() + sv_ * q.y(), t0_ + tu_ * q.x() + tv_ * q.y()));
}

Ring2 FrameMap::ring(const Ring2& ring) const {
  Ring2 result;
  result.reserve(ring.size());
  for (const Point2& p : ring) result.push_back((*this)(p));
  return result;
}

Region2 FrameMap::region(const Region2& region) const {
  std::vector<Polygon2> polygons;
  for (const Polygon2& polygon : region.polygons) {
    Polygon2 mapped{canonical_ring(ring(polygon.outer)), {}};
    for (const Ring2& hole : polygon.holes) mapped.holes.push_back(canonical_ring(ring(hole)));
    polygons.push_back(std::move(mapped));
  }
  return canonical_region(std::move(polygons));
}

FaceShadow unite_pieces(const std::vector<std::pair<const FaceShadow*, const FaceFrame*>>& pieces,
                        const FaceFrame& frame) {
  FaceShadow result;
  result.faces_away = result.beyond_range = true;
  std::vector<Region2> shadow, umbra, penumbra, lit;
  for (const auto& [piece, piece_frame] : pieces) {
    const FrameMap map(*piece_frame, frame);
    result.faces_away = result.faces_away && piece->faces_away;
    result.beyond_range = result.beyond_range && piece->beyond_range;
    result.linear = result.linear || piece->linear;
    result.source_clipped = result.source_clipped || piece->source_clipped;
    result.joint_occlusion = result.joint_occlusion || piece->joint_occlusion;
    shadow.push_back(map.region(piece->shadow));
    umbra.push_back(map.region(piece->umbra));
    penumbra.push_back(map.region(piece->penumbra));
    lit.push_back(map.region(piece->lit));
    for (const OccluderShadow& occluder : piece->occluders) {
      OccluderShadow mapped = occluder;
      mapped.polygon = canonical_ring(map.ring(occluder.polygon));
      if (occluder.umbra) mapped.umbra = canonical_ring(map.ring(*occluder.umbra));
      mapped.penumbra_loop = map.ring(occluder.penumbra_loop);  // raw loops keep their start
      mapped.umbra_loop = map.ring(occluder.umbra_loop);
      result.occluders.push_back(std::move(mapped));
    }
    result.possible_occluders.insert(result.possible_occluders.end(),
                                     piece->possible_occluders.begin(),
                                     piece->possible_occluders.end());
  }
  std::sort(result.possible_occluders.begin(), result.possible_occluders.end());
  result.possible_occluders.erase(
      std::unique(result.possible_occluders.begin(), result.possible_occluders.end()),
      result.possible_occluders.end());
  result.shadow = unite_regions(shadow);
  result.umbra = unite_regions(umbra);
  result.penumbra = unite_regions(penumbra);
  result.lit = unite_regions(lit);
  return result;
}

}  // namespace penumbra::detail
