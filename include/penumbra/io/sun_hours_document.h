#pragma once
// The documents of `penumbra sun-hours` (docs/sun-hours.md): the JSON of every face cut
// into parts by sunlit duration (exact polygons, with rationals on request), the CSV of
// the area that gets at least H hours per face (DESIGN.md's columns), and the heat maps
// (SVG in plan view or one panel per face, PNG in plan view) drawn from the JSON.

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "penumbra/io/shadow_drawing.h"
#include "penumbra/studies/sun_hours.h"
#include "penumbra/studies/sun_hours_request.h"

namespace penumbra::io {

// What the document says of the study besides its faces.
struct SunHoursHeader {
  std::string sun;         // the sun light's name
  int offset_minutes = 0;  // the clock the times are written on
  std::string from, to;    // the range asked for, ISO 8601
  double north_deg = 0;    // the scene's
  sun::Site site;
};

// returns the header of the study plan asks for on scene.
SunHoursHeader sun_hours_header(const Scene& scene, const studies::SunHoursPlan& plan);

// builds the document: {"faces": [...], "penumbra_sun_hours": 1, "steps": {...}, "sun": {...}};
// each face entry as the shadow document's with "hours": [{"area", "hours", "minutes",
// "polygons"}] (parts increasing in duration) instead of "lights".
nlohmann::json sun_hours_json(const Scene& scene, const studies::SunHoursResult& result,
                              const SunHoursHeader& header, bool exact);

// writes the document of sun_hours_json as format_json would lay it out, without building
// it: the faces' entries made as text across threads, a block at a time (a city's document
// runs to a gigabyte).
void write_sun_hours_json(std::ostream& out, const Scene& scene,
                          const studies::SunHoursResult& result, const SunHoursHeader& header,
                          bool exact);

// rebuilds the result that an exact document (sun_hours_json with exact) describes: the
// inverse of sun_hours_json on its exact keys, for the merged document of a distributed run
// (penumbra.dask), so that every output is then written as from one process. The steps come
// from plan, the receiving faces from receivers (as SunHoursOptions::receivers); the
// document's faces must be those, in order, each part's minutes a whole number of steps and
// its polygons exact. Throws InputError(file, "faces[k]...") for a document that does not fit.
studies::SunHoursResult sun_hours_from_json(const Scene& scene, const studies::SunHoursPlan& plan,
                                            const std::optional<std::vector<Receiver>>& receivers,
                                            const nlohmann::json& document,
                                            const std::string& file);

// returns the areas (m^2) of face r with at least h whole hours of sun, h = 0, 1, ..., hours
// (the world areas the JSON gives, summed exactly before rounding).
std::vector<double> areas_at_least(const Scene& scene, const studies::SunHoursResult& result,
                                   std::size_t r, std::size_t hours);

// returns the longest duration any part of any face gets, in whole hours (rounded down).
std::size_t longest_whole_hours(const studies::SunHoursResult& result);

// writes the report: object,face,face_area,area_ge_0h,area_ge_1h,... (one column per whole
// hour up to the longest duration found), one row per face.
void write_sun_hours_csv(std::ostream& out, const Scene& scene,
                         const studies::SunHoursResult& result);

// writes the heat map of a sun-hours document: faces filled by duration on one colour
// scale from 0 to the longest duration, with a legend; view top (plan, faces turned up)
// or faces (one panel per face the sun reaches). Precondition: view is not camera.
void write_sun_hours_svg(std::ostream& out, const nlohmann::json& document, SvgView view);

// writes the plan-view heat map as a PNG width pixels wide (the height follows the plan),
// faces turned up drawn lowest first, as the SVG's top view.
void write_sun_hours_png(const std::string& path, const nlohmann::json& document, int width);

}  // namespace penumbra::io
