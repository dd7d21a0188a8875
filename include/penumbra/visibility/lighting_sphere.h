#pragma once
// The sphere of lighting of a point source (Nishita 1985 section 3.1, Fig. 2): the
// ball around the source outside which its illuminance cannot reach the display
// threshold, so faces wholly outside it need no shadow detection. The threshold
// illuminance E_t is either a fraction of the illuminance I_max / (1 m)^2 that the
// brightest direction gives at 1 m (1/256 by default: one step of an 8-bit display),
// or an absolute value in lux. The radius solves I_max / r^2 = E_t.

#include <optional>

#include "penumbra/geometry/convex_polyhedron.h"

namespace penumbra {

class LightingSphere {
 public:
  // builds the sphere with an absolute threshold E_t = lux > 0: radius sqrt(I_max / lux).
  static LightingSphere absolute(const Point3& centre, double max_candela, double lux);

  // builds the sphere that holds the capsule of radius sqrt(I L / lux) around a
  // linear source from a to b of intensity I per metre and length L: no element of
  // the tube gives more than I L / d^2 at distance d from the segment, so beyond the
  // capsule its illuminance is below lux. The radius is rounded up (conservative).
  static LightingSphere around_segment(const Point3& a, const Point3& b, double candela_per_metre,
                                       double lux);

  // the radius in metres (rounded; decisions use the exact squared radius).
  double radius() const;
  // returns true when every point of face is strictly farther than the radius.
  bool beyond(const Face& face) const;

 private:
  Point3 centre_;
  Exact squared_radius_;
};

}  // namespace penumbra
