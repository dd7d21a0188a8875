#include "penumbra/raytrace/tube_visibility.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <variant>

#include "penumbra/illuminance/linear_source.h"
#include "penumbra/illuminance/occlusion.h"
#include "penumbra/scene/scene.h"

namespace penumbra::raytrace {
namespace {

using illuminance::ExactInterval;

struct Occluder {
  const ConvexPolyhedron* solid;
  CGAL::Bbox_3 box;               // contains the exact solid (closed, rounded outward)
  std::array<Point3, 8> corners;  // of the box, exact
  // light passed by the open segment P -> Q crossing the occluder from outside (two
  // surfaces of a solid, one of a flat polygon) and from a point inside it (one surface)
  double through;
  double from_inside;
};

struct Tube {
  Point3 start, end;
  const LinearLight* light;
};

// the box of one point given as doubles (exact: no arithmetic).
CGAL::Bbox_3 point_box(const Vec3d& p) {
  return {p[0], p[1], p[2], p[0], p[1], p[2]};
}

std::array<Point3, 8> corners_of(const CGAL::Bbox_3& box) {
  std::array<Point3, 8> corners;
  for (int k = 0; k < 8; ++k)
    corners[k] = Point3((k & 1) ? box.xmax() : box.xmin(), (k & 2) ? box.ymax() : box.ymin(),
                        (k & 4) ? box.zmax() : box.zmin());
  return corners;
}

// returns true when the box lies strictly on one side of the plane through p, a, b: then it
// cannot meet a segment from p to the tube a b, which all lie in that plane. False when p, a,
// b are collinear. Exact.
bool beside_plane(const std::array<Point3, 8>& corners, const Point3& p, const Point3& a,
                  const Point3& b) {
  const CGAL::Orientation first = CGAL::orientation(p, a, b, corners[0]);
  if (first == CGAL::COPLANAR) return false;
  for (int k = 1; k < 8; ++k)
    if (CGAL::orientation(p, a, b, corners[k]) != first) return false;
  return true;
}

// A sub-segment of the tube hidden by one occluder, with the light it lets through.
struct Hidden {
  ExactInterval interval;
  double passed;
};

// cuts `outer` at the end of every hidden sub-segment and weights each piece by the product
// of the factors of the sub-segments containing it (open intervals, so a piece between two
// consecutive cut points lies either inside or outside each). Exact comparisons only.
std::vector<TubePiece> weighted_pieces(const ExactInterval& outer,
                                       const std::vector<Hidden>& hidden, double min_passed) {
  std::vector<Exact> cuts{outer.low, outer.high};
  for (const Hidden& part : hidden)
    for (const Exact& end : {part.interval.low, part.interval.high})
      if (outer.low < end && end < outer.high) cuts.push_back(end);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<TubePiece> pieces;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    double passed = 1;
    for (const Hidden& part : hidden)
      if (!(cuts[k] < part.interval.low) && !(part.interval.high < cuts[k + 1]))
        passed *= part.passed;
    if (passed < min_passed || passed == 0) continue;
    const double low = CGAL::to_double(cuts[k]), high = CGAL::to_double(cuts[k + 1]);
    // Neighbours passing the same fraction make one piece (one closed-form evaluation).
    if (!pieces.empty() && pieces.back().passed == passed && pieces.back().high == low)
      pieces.back().high = high;
    else
      pieces.push_back({low, high, passed});
  }
  return pieces;
}

}  // namespace

struct TubeVisibility::Impl {
  std::vector<Occluder> occluders;         // in the order of Scene::objects
  std::vector<std::optional<Tube>> tubes;  // in the order of Scene::lights
  double min_passed;
};

TubeVisibility::TubeVisibility(const Scene& scene, double min_passed)
    : impl_(std::make_unique<Impl>()) {
  impl_->min_passed = min_passed;
  for (const Object& object : scene.objects) {
    const double k_t = scene.materials[object.material].transmit;
    const bool flat = object.solid.is_flat();
    const CGAL::Bbox_3 box = object.solid.bbox();
    impl_->occluders.push_back({&object.solid, box, corners_of(box), flat ? k_t : k_t * k_t, k_t});
  }
  for (const Light& light : scene.lights) {
    if (const auto* tube = std::get_if<LinearLight>(&light.source))
      impl_->tubes.emplace_back(Tube{to_exact(tube->start), to_exact(tube->end), tube});
    else
      impl_->tubes.emplace_back();
  }
}

TubeVisibility::~TubeVisibility() = default;

std::vector<TubePiece> TubeVisibility::pieces(std::size_t light, const Vec3d& point,
                                              const Vec3d& normal,
                                              const std::optional<ShadedSurface>& surface) const {
  const std::optional<Tube>& tube = impl_->tubes.at(light);
  if (!tube) throw std::invalid_argument("TubeVisibility::pieces: light is not linear");
  const Point3 receiver = to_exact(point);
  // Nishita Fig. 7, S3: only the part strictly on the outer side of the receiving plane.
  const auto outer = illuminance::outer_side_interval_exact(receiver, to_exact_vector(normal),
                                                            tube->start, tube->end);
  if (!outer) return {};
  // Nishita section 4.2.3: every occluder meeting the triangle (P, start, end) may hide an
  // open sub-segment, the tube clipped by the shadow pyramid from P. Boxes cull first.
  const CGAL::Bbox_3 triangle =
      point_box(point) + point_box(tube->light->start) + point_box(tube->light->end);
  std::vector<Hidden> hidden;
  // records a hidden sub-segment; returns false when it leaves no light at all (umbra).
  const auto hide = [&](const ExactInterval& interval, double passed) {
    if (passed < impl_->min_passed && !(outer->low < interval.low) &&
        !(interval.high < outer->high))
      return false;
    hidden.push_back({interval, passed});
    return true;
  };
  for (std::size_t k = 0; k < impl_->occluders.size(); ++k) {
    const Occluder& occluder = impl_->occluders[k];
    if (surface && surface->object == k) {
      // The shaded object itself, decided by convexity rather than from the rounded P.
      if (surface->inside && !occluder.solid->is_flat() && !hide(*outer, occluder.from_inside))
        return {};
      continue;
    }
    if (!CGAL::do_overlap(occluder.box, triangle) ||
        beside_plane(occluder.corners, receiver, tube->start, tube->end))
      continue;
    const illuminance::HiddenRegion region = illuminance::hidden_region(*occluder.solid, receiver);
    if (region.empty()) continue;
    const auto blocked = illuminance::hidden_interval(region, tube->start, tube->end);
    if (!blocked) continue;
    if (!hide(*blocked, region.everywhere ? occluder.from_inside : occluder.through)) return {};
  }
  return weighted_pieces(*outer, hidden, impl_->min_passed);
}

double tube_illuminance(const LinearLight& tube, const Vec3d& point, const Vec3d& normal,
                        const std::vector<TubePiece>& pieces) {
  double sum = 0;
  for (const TubePiece& piece : pieces)
    sum += piece.passed * illuminance::linear_illuminance(point, normal, tube.start, tube.end,
                                                          tube.candela_per_metre,
                                                          {{piece.low, piece.high}});
  return sum;
}

}  // namespace penumbra::raytrace
