#include "mesh_face_shadow.h"

#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <map>

#include "penumbra/geometry/exact.h"
#include "region_set.h"

namespace penumbra::detail {

FrameMap::FrameMap(const FaceFrame& from, const FaceFrame& to) {
  // A point o + s u + t v of from has, in to, s' = (X - o').u' / (u'.u') and likewise t'.
  const RationalPoint3& o = exact_value(from.origin());
  const RationalPoint3& o2 = exact_value(to.origin());
  const RationalVector3& u = exact_value(from.u());
  const RationalVector3& v = exact_value(from.v());
  const RationalVector3& u2 = exact_value(to.u());
  const RationalVector3& v2 = exact_value(to.v());
  const Rational& uu2 = exact_value(to.squared_u());
  const Rational& vv2 = exact_value(to.squared_v());
  const RationalVector3 d = o - o2;
  s0_ = d * u2 / uu2;
  su_ = u * u2 / uu2;
  sv_ = v * u2 / uu2;
  t0_ = d * v2 / vv2;
  tu_ = u * v2 / vv2;
  tv_ = v * v2 / vv2;
}

Point2 FrameMap::operator()(const Point2& p) const {
  const RationalPoint2& q = exact_value(p);
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
                        const FaceFrame& frame, const std::optional<Region2>& whole, bool lit) {
  // A face of one piece in the piece's own frame (mesh_parts.cpp gives it that frame): its
  // shadow map is the piece's.
  const auto sort_unique = [](std::vector<std::size_t>& list) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  };
  if (pieces.size() == 1 && pieces[0].second->same_as(frame)) {
    FaceShadow result = *pieces[0].first;
    sort_unique(result.possible_occluders);
    return result;
  }
  FaceShadow result;
  result.faces_away = result.beyond_range = true;
  std::vector<FrameMap> maps;
  for (const auto& [piece, piece_frame] : pieces) {
    const FrameMap& map = maps.emplace_back(*piece_frame, frame);
    result.faces_away = result.faces_away && piece->faces_away;
    result.beyond_range = result.beyond_range && piece->beyond_range;
    result.extended = result.extended || piece->extended;
    result.source_clipped = result.source_clipped || piece->source_clipped;
    result.joint_occlusion = result.joint_occlusion || piece->joint_occlusion;
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
  sort_unique(result.possible_occluders);
  // A set empty on every piece is empty. Shadow and lit split each computed piece, so one of
  // them empty on every piece leaves the other whole on every piece: the face.
  const auto empty_everywhere = [&](Region2 FaceShadow::*member) {
    return std::all_of(pieces.begin(), pieces.end(),
                       [&](const auto& piece) { return ((*piece.first).*member).empty(); });
  };
  const bool computed = !result.beyond_range &&
                        std::none_of(pieces.begin(), pieces.end(),
                                     [](const auto& piece) { return piece.first->beyond_range; });
  // the union of one set over the pieces, each carried into the face's frame.
  const auto united = [&](Region2 FaceShadow::*member) {
    std::vector<Region2> regions;
    for (std::size_t k = 0; k < pieces.size(); ++k)
      regions.push_back(maps[k].region((*pieces[k].first).*member));
    return unite_regions(regions);
  };
  const bool no_shadow = empty_everywhere(&FaceShadow::shadow);
  // Pieces computed without their lit parts (ShadowOptions::lit_parts) say nothing by them.
  const bool no_lit = !lit || empty_everywhere(&FaceShadow::lit);
  result.shadow = no_shadow                            ? Region2{}
                  : lit && no_lit && computed && whole ? *whole
                                                       : united(&FaceShadow::shadow);
  result.lit = no_lit                           ? Region2{}
               : no_shadow && computed && whole ? *whole
                                                : united(&FaceShadow::lit);
  result.umbra = empty_everywhere(&FaceShadow::umbra) ? Region2{} : united(&FaceShadow::umbra);
  result.penumbra =
      empty_everywhere(&FaceShadow::penumbra) ? Region2{} : united(&FaceShadow::penumbra);
  return result;
}

std::shared_ptr<const ExactUmbra> mesh_face_umbra(const Scene& scene, const MeshFace& face,
                                                  const std::vector<const Face*>& pieces,
                                                  const FaceShadow& united, const Point3& q1,
                                                  const Point3& q2) {
  Face whole;
  whole.vertices = face.outer;
  whole.plane = face.plane;
  whole.frame = face.frame;
  whole.ring = face.ring;
  whole.area = face.area;
  std::vector<Ring2> convex, boundary{face.ring};
  for (const Face* piece : pieces)
    convex.push_back(FrameMap(piece->frame, face.frame).ring(piece->ring));
  for (const auto& hole : face.holes) {
    Ring2 ring;
    for (const Point3& p : hole) ring.push_back(face.frame.to_frame(p));
    boundary.push_back(std::move(ring));
  }
  // per occluder, the points of its rings on every piece (already in the face's frame)
  std::map<std::size_t, std::pair<std::vector<Point2>, std::vector<Point2>>> rings;
  for (const OccluderShadow& o : united.occluders) {
    auto& [shadow, umbra] = rings[o.occluder];
    shadow.insert(shadow.end(), o.polygon.begin(), o.polygon.end());
    if (o.umbra) umbra.insert(umbra.end(), o.umbra->begin(), o.umbra->end());
  }
  const auto hull = [](const std::vector<Point2>& points) {
    Ring2 ring;
    CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(ring));
    return ring;
  };
  std::vector<UmbraOccluder> occluders;
  for (const auto& [object, points] : rings) {
    UmbraOccluder occluder{&scene.objects[object].solid, hull(points.first), {}};
    if (!points.second.empty()) occluder.umbra = hull(points.second);
    occluders.push_back(std::move(occluder));
  }
  return std::make_shared<const ExactUmbra>(
      exact_umbra(whole, convex, boundary, q1, q2, occluders));
}

}  // namespace penumbra::detail
