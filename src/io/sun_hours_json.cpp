#include <algorithm>
#include <chrono>

#include "face_json.h"
#include "penumbra/base/csv.h"
#include "penumbra/io/sun_hours_document.h"

namespace penumbra::io {
namespace {

using nlohmann::json;
using studies::SunHoursResult;

// The entry of "faces" for receiver r; members in key order.
void emit_face(JsonEmitter& out, const Scene& scene, const SunHoursResult& result, std::size_t r,
               bool exact) {
  const ReceivingFace face = receiving_face(scene, result.faces, r);
  FaceOutput output = plain_output(face);
  // A ground under a city holds millions of points, each in the rings of the parts on
  // either side: their world doubles are computed once, ahead, across threads.
  std::vector<const Point2*> points;
  std::size_t corners = 0;  // with repeats: an upper bound on the points, for one allocation
  for (const Coverage& part : result.hours[r].parts)
    for (const Polygon2& polygon : part.region.polygons) {
      corners += polygon.outer.size();
      for (const Ring2& hole : polygon.holes) corners += hole.size();
    }
  output.world.reserve(corners);
  points.reserve(corners);
  for (const Coverage& part : result.hours[r].parts) add_points(output, points, part.region);
  round_points(output, points);
  emit_face_entry(out, output, exact, [&] {
    out.key("hours");
    out.begin_array();
    for (const Coverage& part : result.hours[r].parts) {
      const double minutes = result.minutes(part.count);
      out.begin_object();
      out.key("area");
      out.number(world_area(part.region, face.frame));
      out.key("hours");
      out.number(minutes / 60);
      out.key("minutes");
      out.number(minutes);
      emit_polygons(out, part.region, output, exact);
      out.end_object();
    }
    out.end_array();
  });
}

}  // namespace

SunHoursHeader sun_hours_header(const Scene& scene, const studies::SunHoursPlan& plan) {
  SunHoursHeader header;
  header.sun = plan.sun.name;
  header.offset_minutes = plan.offset_minutes;
  header.from = sun::format_date_time(plan.from, plan.offset_minutes);
  header.to = sun::format_date_time(plan.end, plan.offset_minutes);
  header.north_deg = scene.north_deg;
  header.site = plan.sun.site;
  return header;
}

namespace {

// the document without its faces.
json header_json(const SunHoursResult& result, const SunHoursHeader& header) {
  json times = json::array();
  for (const studies::SunStep& step : result.steps)
    if (step.up())
      times.push_back({{"time", sun::format_date_time(step.time, header.offset_minutes)},
                       {"azimuth_deg", step.position.azimuth_deg},
                       {"elevation_deg", step.position.elevation_deg}});
  return {{"penumbra_sun_hours", 1},
          {"sun",
           {{"name", header.sun},
            {"latitude", header.site.latitude_deg},
            {"longitude", header.site.longitude_deg},
            {"north_deg", header.north_deg}}},
          {"steps",
           {{"from", header.from},
            {"to", header.to},
            {"step_minutes", result.minutes(1)},
            {"count", result.steps.size()},
            {"sun_up", result.steps_up()},
            {"times", std::move(times)}}},
          {"longest_minutes", result.minutes(result.longest_count())}};
}

}  // namespace

json sun_hours_json(const Scene& scene, const SunHoursResult& result, const SunHoursHeader& header,
                    bool exact) {
  json document = header_json(result, header);
  json faces = json::array();
  for (std::size_t r = 0; r < result.faces.receivers.size(); ++r) {
    TreeEmitter tree;
    emit_face(tree, scene, result, r, exact);
    faces.push_back(std::move(tree.result()));
  }
  document["faces"] = std::move(faces);
  return document;
}

void write_sun_hours_json(std::ostream& out, const Scene& scene, const SunHoursResult& result,
                          const SunHoursHeader& header, bool exact) {
  FacesDocumentWriter writer(out);
  const std::size_t count = result.faces.receivers.size();
  writer.begin(header_json(result, header), count);
  write_faces(writer, count, [&](std::size_t r, std::string& text) {
    TextEmitter emitter(text, 2);
    emit_face(emitter, scene, result, r, exact);
  });
  writer.end();
}

std::vector<double> areas_at_least(const Scene& scene, const SunHoursResult& result, std::size_t r,
                                   std::size_t hours) {
  const ReceivingFace face = receiving_face(scene, result.faces, r);
  std::vector<double> areas;
  for (std::size_t h = 0; h <= hours; ++h)
    areas.push_back(world_area(
        result.area_at_least(r, std::chrono::hours(static_cast<long long>(h))), face.frame));
  return areas;
}

std::size_t longest_whole_hours(const SunHoursResult& result) {
  return static_cast<std::size_t>((result.step * static_cast<long long>(result.longest_count())) /
                                  std::chrono::hours(1));
}

void write_sun_hours_csv(std::ostream& out, const Scene& scene, const SunHoursResult& result) {
  const std::size_t hours = longest_whole_hours(result);
  std::vector<std::string> columns{"object", "face", "face_area"};
  for (std::size_t h = 0; h <= hours; ++h) columns.push_back("area_ge_" + std::to_string(h) + "h");
  CsvWriter csv(out, columns);
  for (std::size_t r = 0; r < result.faces.receivers.size(); ++r) {
    const ReceivingFace face = receiving_face(scene, result.faces, r);
    csv.text(face.object).integer(static_cast<long long>(face.face));
    csv.number(world_area(face.area, face.frame));
    for (double area : areas_at_least(scene, result, r, hours)) csv.number(area);
    csv.end_row();
  }
}

}  // namespace penumbra::io
