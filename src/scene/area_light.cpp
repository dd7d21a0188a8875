#include "area_light.h"

#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/geometry/geometry_error.h"

namespace penumbra {

double AreaLight::area() const {
  // Newell's vector: twice the area vector of a planar polygon.
  Vec3d twice{0, 0, 0};
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const Vec3d& a = vertices[k];
    const Vec3d& b = vertices[(k + 1) % vertices.size()];
    twice[0] += (a[1] - b[1]) * (a[2] + b[2]);
    twice[1] += (a[2] - b[2]) * (a[0] + b[0]);
    twice[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return 0.5 * std::sqrt(twice[0] * twice[0] + twice[1] * twice[1] + twice[2] * twice[2]);
}

namespace detail {

AreaLight read_area_light(const JsonCursor& cursor) {
  AreaLight light;
  const JsonCursor corners = cursor.at("area");
  light.vertices = corners.points(3);
  std::vector<Point3> cycle;
  for (const Vec3d& p : light.vertices) cycle.push_back(to_exact(p));
  for (std::size_t k = 0; k < cycle.size(); ++k)
    if (cycle[k] == cycle[(k + 1) % cycle.size()])
      corners.at(k).fail("an area source repeats this point next to itself");
  try {
    light.polygon = std::make_shared<const ConvexPolyhedron>(ConvexPolyhedron::flat_polygon(cycle));
  } catch (const GeometryError& e) {
    if (e.index() >= 0) corners.at(static_cast<std::size_t>(e.index())).fail(e.what());
    corners.fail(std::string(e.what()) + " (an area source is a planar convex polygon)");
  }
  // The emitting side: the one the given cycle turns counter-clockwise around. The cycle is
  // convex, so any three of its points not on one line give its orientation.
  std::size_t third = 2;
  while (CGAL::collinear(cycle[0], cycle[1], cycle[third])) ++third;
  const Vector3 normal = CGAL::cross_product(cycle[1] - cycle[0], cycle[third] - cycle[0]);
  const auto& faces = light.polygon->faces();
  light.front = CGAL::is_positive(faces[0].plane.orthogonal_vector() * normal) ? 0 : 1;

  if (cursor.has("two_sided")) light.two_sided = cursor.at("two_sided").boolean();
  const int given = cursor.has("luminance") + cursor.has("exitance") + cursor.has("lumens");
  if (given != 1)
    cursor.fail(
        "an area source needs exactly one of \"luminance\" (cd/m^2), \"exitance\" "
        "(lm/m^2) or \"lumens\"");
  // A Lambertian surface of luminance L has exitance M = pi L on each emitting side, and
  // emits Phi = M A per side.
  const double sides = light.two_sided ? 2 : 1;
  if (auto luminance = cursor.find("luminance"))
    light.luminance = luminance->non_negative_number();
  else if (auto exitance = cursor.find("exitance"))
    light.luminance = exitance->non_negative_number() / pi;
  else
    light.luminance = cursor.at("lumens").non_negative_number() / (pi * light.area() * sides);
  return light;
}

}  // namespace detail
}  // namespace penumbra
