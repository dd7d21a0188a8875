// The inverse of sun_hours_json on exact documents (sun_hours_document.h): a distributed
// sun-hours run (penumbra.dask, `sun-hours --dask`) returns the document of each tile of
// faces; the merged document is read back into the result one process would have made.

#include <cmath>
#include <sstream>
#include <string>

#include "penumbra/base/input_error.h"
#include "penumbra/geometry/exact.h"
#include "penumbra/io/sun_hours_document.h"

namespace penumbra::io {
namespace {

using nlohmann::json;

// Reads the exact parts of one face entry, naming what does not fit.
class FaceReader {
 public:
  FaceReader(const ReceivingFace& face, const std::string& file, std::string where)
      : face_(face), file_(file), where_(std::move(where)) {}

  Ring2 ring(const json& points, const std::string& where) const {
    if (!points.is_array()) fail(where, "expected a list of points");
    Ring2 ring;
    for (const json& point : points) {
      if (!point.is_array() || point.size() != 3) fail(where, "expected points of three rationals");
      const RationalPoint3 world(number(point[0], where), number(point[1], where),
                                 number(point[2], where));
      ring.push_back(point_from<Point2>(face_.frame.to_frame(world)));
    }
    return ring;
  }

  Region2 region(const json& polygons, const std::string& where) const {
    if (!polygons.is_array()) fail(where, "expected a list of polygons");
    std::vector<Polygon2> read;
    for (std::size_t k = 0; k < polygons.size(); ++k) {
      const std::string at = where + "[" + std::to_string(k) + "].exact";
      const json* exact = polygons[k].is_object() && polygons[k].contains("exact")
                              ? &polygons[k]["exact"]
                              : nullptr;
      if (!exact || !exact->contains("outer") || !exact->contains("holes"))
        fail(at, "missing: the document must be exact (--exact)");
      Polygon2 polygon{ring((*exact)["outer"], at + ".outer"), {}};
      for (const json& hole : (*exact)["holes"]) polygon.holes.push_back(ring(hole, at + ".holes"));
      read.push_back(std::move(polygon));
    }
    return canonical_region(std::move(read));
  }

  [[noreturn]] void fail(const std::string& where, const std::string& message) const {
    throw InputError(file_, where_ + where, message);
  }

 private:
  Rational number(const json& value, const std::string& where) const {
    if (!value.is_string()) fail(where, "expected a rational \"p/q\"");
    std::istringstream in(value.get<std::string>());
    Rational x;
    in >> x;
    if (in.fail() || in.peek() != std::char_traits<char>::eof())
      fail(where, "not a rational: \"" + value.get<std::string>() + "\"");
    return x;
  }

  const ReceivingFace& face_;
  const std::string& file_;
  std::string where_;
};

}  // namespace

studies::SunHoursResult sun_hours_from_json(const Scene& scene, const studies::SunHoursPlan& plan,
                                            const std::optional<std::vector<Receiver>>& receivers,
                                            const json& document, const std::string& file) {
  studies::SunHoursResult result;
  result.steps = studies::sun_steps(plan.sun, scene.north_deg, plan.instants);
  result.step = plan.step;
  Scene unlit = scene;
  unlit.lights.clear();
  ShadowOptions options;
  options.receivers = receivers;
  result.faces = compute_shadows(unlit, options);  // the receivers in order, as sun_hours
  const json* faces =
      document.is_object() && document.contains("faces") ? &document["faces"] : nullptr;
  if (!faces || !faces->is_array() || faces->size() != result.faces.receivers.size())
    throw InputError(
        file, "faces",
        "expected the " + std::to_string(result.faces.receivers.size()) + " faces of the study");
  const double step_minutes = result.minutes(1);
  for (std::size_t r = 0; r < faces->size(); ++r) {
    const json& entry = (*faces)[r];
    const ReceivingFace face = receiving_face(scene, result.faces, r);
    const FaceReader read(face, file, "faces[" + std::to_string(r) + "]");
    if (!entry.is_object() || entry.value("object", std::string()) != face.object ||
        !entry.contains("face") || entry["face"] != face.face || !entry.contains("hours"))
      read.fail("", "expected face " + std::to_string(face.face) + " of " + face.object);
    studies::FaceSunHours hours;
    for (std::size_t k = 0; k < entry["hours"].size(); ++k) {
      const json& part = entry["hours"][k];
      const std::string at = ".hours[" + std::to_string(k) + "]";
      const double minutes = part.is_object() ? part.value("minutes", -1.0) : -1.0;
      const double steps = std::round(minutes / step_minutes);
      if (!(steps >= 0) || result.minutes(static_cast<std::size_t>(steps)) != minutes)
        read.fail(at + ".minutes",
                  "not a whole number of " + std::to_string(step_minutes) + "-minute steps");
      hours.parts.push_back({static_cast<std::size_t>(steps),
                             read.region(part.value("polygons", json()), at + ".polygons")});
    }
    result.hours.push_back(std::move(hours));
  }
  return result;
}

}  // namespace penumbra::io
