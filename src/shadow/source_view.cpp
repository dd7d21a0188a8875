#include "penumbra/shadow/source_view.h"

#include <algorithm>
#include <functional>

#include "penumbra/shadow/shadow_polygon.h"
#include "penumbra/visibility/swept_region.h"
#include "receiver_clip.h"
#include "region_set.h"

namespace penumbra {
namespace {

// The most rings inclusion and exclusion may make before the Boolean difference is cheaper.
constexpr std::size_t kMostTerms = 64;

// appends to rings the part of the source clip.clip(cut) less the union of the parts
// clip.clip(cut + volumes[i]) by inclusion and exclusion: each intersection of hidden parts is
// the clip by all their volumes' planes at once (receiver_clip.h: exact, no chains of lazy
// constructions). Returns false, leaving rings as they were, past kMostTerms rings.
bool include_exclude(const detail::ReceiverClip& clip, const std::vector<Plane3>& cut,
                     const std::vector<std::vector<Plane3>>& volumes,
                     const std::vector<Ring2>& hidden, std::vector<Ring2>& rings) {
  std::vector<Ring2> terms;
  // Depth-first over the subsets in increasing order: an empty intersection ends a branch.
  // The single parts are hidden[i] already.
  std::function<bool(const std::vector<Plane3>&, std::size_t, std::size_t)> add =
      [&](const std::vector<Plane3>& planes, std::size_t from, std::size_t size) {
        for (std::size_t i = from; i < volumes.size(); ++i) {
          std::vector<Plane3> more = planes;
          more.insert(more.end(), volumes[i].begin(), volumes[i].end());
          // the intersection of size + 1 hidden parts, taken away when that number is odd.
          const auto meet = size == 0 ? std::optional<Ring2>(hidden[i]) : clip.clip(more);
          if (!meet) continue;
          terms.push_back(*meet);
          if (size % 2 == 0) std::reverse(terms.back().begin(), terms.back().end());
          if (terms.size() > kMostTerms || !add(more, i + 1, size + 1)) return false;
        }
        return true;
      };
  if (!add(cut, 0, 0)) return false;
  rings.insert(rings.end(), terms.begin(), terms.end());
  return true;
}

}  // namespace

std::vector<Ring2> visible_source(const Face& source, const Point3& point, const Plane3& receiving,
                                  const std::vector<const ConvexPolyhedron*>& occluders) {
  if (source.plane.oriented_side(point) != CGAL::ON_POSITIVE_SIDE) return {};
  // The receiving surface hides the part of the source on or behind its plane (Fig. 7, S3):
  // the part kept is the closed side receiving.opposite() <= 0.
  const detail::ReceiverClip clip(source);
  const std::vector<Plane3> cut{receiving.opposite()};
  const auto part = clip.clip(cut);
  if (!part) return {};
  const LightPosition light = LightPosition::at(point);
  // Only an occluder meeting the pyramid conv(point, source) can hide part of the source:
  // those a plane certainly separates from it (interval arithmetic) are skipped.
  const SweptRegion pyramid({point}, source.vertices);
  std::vector<std::vector<Plane3>> volumes;
  std::vector<Ring2> hidden;
  for (const ConvexPolyhedron* occluder : occluders) {
    if (pyramid.separated_from(*occluder)) continue;
    std::vector<Plane3> volume = shadow_volume(*occluder, light);
    volume.push_back(cut.front());
    if (auto shadow = detail::shadow_polygon(*occluder, volume, clip)) {
      // One occluder hides all of it (the usual umbra): nothing is visible, exactly 0.
      if (*shadow == *part) return {};
      hidden.push_back(std::move(*shadow));
      volume.pop_back();
      volumes.push_back(std::move(volume));
    }
  }
  std::vector<Ring2> rings{*part};
  if (hidden.empty() || include_exclude(clip, cut, volumes, hidden, rings)) return rings;
  rings.clear();
  for (const Polygon2& polygon : detail::unite_minus({*part}, hidden).polygons) {
    rings.push_back(polygon.outer);
    rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
  }
  return rings;
}

}  // namespace penumbra
