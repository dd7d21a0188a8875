#include "penumbra/visibility/lighting_sphere.h"

#include <cmath>

namespace penumbra {

LightingSphere LightingSphere::absolute(const Point3& centre, double max_candela, double lux) {
  CGAL_precondition(lux > 0);
  LightingSphere sphere;
  sphere.centre_ = centre;
  sphere.squared_radius_ = Exact(max_candela) / Exact(lux);
  return sphere;
}

LightingSphere LightingSphere::around_segment(const Point3& a, const Point3& b,
                                              double candela_per_metre, double lux) {
  CGAL_precondition(lux > 0);
  const double length = std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b)));
  const double radius = std::sqrt(candela_per_metre * length / lux) + length / 2;
  const double up = std::nextafter(radius * (1 + 1e-12), INFINITY);
  LightingSphere sphere;
  sphere.centre_ = CGAL::midpoint(a, b);
  sphere.squared_radius_ = Exact(up) * Exact(up);
  return sphere;
}

double LightingSphere::radius() const {
  return std::sqrt(CGAL::to_double(squared_radius_.exact()));
}

bool LightingSphere::beyond(const Face& face) const {
  const std::vector<Point3>& v = face.vertices;
  for (std::size_t k = 1; k + 1 < v.size(); ++k)
    if (CGAL::squared_distance(centre_, Triangle3(v[0], v[k], v[k + 1])) <= squared_radius_)
      return false;
  return true;
}

}  // namespace penumbra
