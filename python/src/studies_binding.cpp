// The studies over time (sun position, sun-hours: docs/sun.md, docs/sun-hours.md) and the
// writers of documents, as the module offers them: the same functions `penumbra sun-hours`
// calls, so that a document made here, formatted by format_json, is the command's file.

#include <sstream>
#include <string>
#include <tuple>

#include <pybind11/stl.h>

#include "bindings.h"
#include "json_to_python.h"
#include "penumbra/base/atomic_file.h"
#include "penumbra/base/input_error.h"
#include "penumbra/io/shadow_diagram.h"
#include "penumbra/io/shadow_json.h"
#include "penumbra/io/sun_hours_document.h"
#include "penumbra/studies/sun_hours.h"
#include "penumbra/studies/sun_hours_request.h"
#include "penumbra/sun/solar_position.h"

namespace penumbra::python {

namespace py = pybind11;

namespace {

studies::SunHoursRequest request_of(const SceneHandle& handle, const py::dict& arguments) {
  studies::SunHoursRequest request;
  request.scene_path = handle.scene().file.string();
  const auto text = [&](const char* key, std::string& field) {
    if (arguments.contains(key) && !arguments[key].is_none())
      field = arguments[key].cast<std::string>();
  };
  text("light", request.light);
  text("site", request.site);
  text("date", request.date);
  text("to", request.to);
  text("step", request.step);
  text("utc_offset", request.utc_offset);
  return request;
}

// the sun-hours document (`penumbra sun-hours -o`) of the faces receivers names.
py::tuple sun_hours_document(const SceneHandle& handle, const py::dict& arguments,
                             const py::object& receivers, bool exact) {
  const Scene& scene = handle.scene();
  const studies::SunHoursPlan plan = studies::plan_sun_hours(scene, request_of(handle, arguments));
  studies::SunHoursOptions options;
  options.receivers = chosen_receivers(scene, receivers);
  nlohmann::json document;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release unlocked;
    const studies::SunHoursResult result =
        studies::sun_hours(scene, plan.sun, plan.instants, plan.step, options);
    document = io::sun_hours_json(scene, result, io::sun_hours_header(scene, plan), exact);
    warnings = result.faces.warnings;
  }
  return py::make_tuple(to_python(document), warnings);
}

// the steps of a study: (time, azimuth, elevation, dx, dy, dz, sun up) each.
py::list sun_steps(const SceneHandle& handle, const py::dict& arguments) {
  const Scene& scene = handle.scene();
  const studies::SunHoursPlan plan = studies::plan_sun_hours(scene, request_of(handle, arguments));
  py::list rows;
  for (const studies::SunStep& step : studies::sun_steps(plan.sun, scene.north_deg, plan.instants))
    rows.append(py::make_tuple(sun::format_date_time(step.time, plan.offset_minutes),
                               step.position.azimuth_deg, step.position.elevation_deg,
                               step.direction[0], step.direction[1], step.direction[2], step.up()));
  return rows;
}

py::tuple solar_position(double latitude, double longitude, const std::string& time,
                         double elevation, std::optional<double> pressure_hpa,
                         std::optional<double> temperature_c) {
  const sun::ZonedInstant when = sun::parse_date_time(time, std::nullopt, {"", "time"});
  std::optional<sun::Atmosphere> air;
  if (pressure_hpa || temperature_c) {
    air.emplace();
    if (pressure_hpa) air->pressure_hpa = *pressure_hpa;
    if (temperature_c) air->temperature_c = *temperature_c;
  }
  try {
    const sun::SolarPosition seen =
        sun::solar_position({latitude, longitude, elevation}, when.utc, air);
    return py::make_tuple(seen.azimuth_deg, seen.elevation_deg);
  } catch (const std::invalid_argument& error) {
    throw InputError("", "site", error.what());
  }
}

using StepValues = std::tuple<std::string, double, double, double, double, double>;

// the step of the sun named light (the only one when empty) at time (ISO 8601; without an
// offset, on the clock of the sun's time): (time, azimuth, elevation, dx, dy, dz, sun up).
py::tuple sun_step_at(const SceneHandle& handle, const std::string& light,
                      const std::string& time) {
  const Scene& scene = handle.scene();
  const SunPlacement& sun = studies::choose_sun(scene, scene.file.string(), light);
  const sun::ZonedInstant when = sun::parse_date_time(time, sun.time.offset_minutes, {"", "time"});
  const studies::SunStep step = studies::sun_steps(sun, scene.north_deg, {when.utc}).front();
  return py::make_tuple(sun::format_date_time(when.utc, when.offset_minutes),
                        step.position.azimuth_deg, step.position.elevation_deg, step.direction[0],
                        step.direction[1], step.direction[2], step.up());
}

// the shadow documents of the scene lit by its sun light alone from each step (when, azimuth,
// elevation, dx, dy, dz): the times of `shadows --times`, and its tasks on Dask.
py::tuple sun_shadow_documents(const SceneHandle& handle, const std::string& light,
                               const std::vector<StepValues>& steps, const py::object& receivers,
                               bool exact, double range_fraction, double full_scale_lux,
                               std::optional<double> range_lux) {
  const Scene& scene = handle.scene();
  const SunPlacement& sun = studies::choose_sun(scene, scene.file.string(), light);
  const ShadowOptions options =
      shadow_options(scene, receivers, range_fraction, full_scale_lux, range_lux);
  const io::ShadowJsonOptions json_options = io::json_options_of(options, exact);
  std::vector<nlohmann::json> documents;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release unlocked;
    io::SunShadows shadows(scene, sun, options, json_options);
    for (const auto& [when, azimuth, elevation, dx, dy, dz] : steps) {
      studies::SunStep step;
      step.position = {azimuth, elevation};
      step.direction = {dx, dy, dz};
      documents.push_back(std::move(shadows.at(step, when).shadows));
    }
    warnings = shadows.warnings();
  }
  py::list list;
  for (const nlohmann::json& document : documents) list.append(to_python(document));
  return py::make_tuple(list, warnings);
}

std::string format_json(const py::object& document) {
  const nlohmann::json value = from_python(document);
  py::gil_scoped_release unlocked;
  return io::format_json(value);
}

void write_sun_hours_svg(const py::object& document, const std::string& path,
                         const std::string& view) {
  const auto chosen = io::parse_svg_view(view);
  if (!chosen || *chosen == io::SvgView::camera)
    throw InputError("", "view", "expected top or faces");
  const nlohmann::json value = from_python(document);
  py::gil_scoped_release unlocked;
  write_atomically(path, [&](std::ostream& out) { io::write_sun_hours_svg(out, value, *chosen); });
}

void write_sun_hours_png(const py::object& document, const std::string& path, int width) {
  if (width < 16 || width > 16384) throw InputError("", "width", "expected 16 to 16384 pixels");
  const nlohmann::json value = from_python(document);
  py::gil_scoped_release unlocked;
  io::write_sun_hours_png(path, value, width);
}

}  // namespace

void bind_studies(py::module_& module) {
  module.def("sun_hours_document", &sun_hours_document, py::arg("scene"), py::arg("arguments"),
             py::arg("receivers"), py::arg("exact"));
  module.def("sun_steps", &sun_steps, py::arg("scene"), py::arg("arguments"));
  module.def("solar_position", &solar_position, py::arg("latitude"), py::arg("longitude"),
             py::arg("time"), py::arg("elevation") = 0.0, py::arg("pressure_hpa") = py::none(),
             py::arg("temperature_c") = py::none());
  module.def("sun_step_at", &sun_step_at, py::arg("scene"), py::arg("light"), py::arg("time"));
  module.def("sun_shadow_documents", &sun_shadow_documents, py::arg("scene"), py::arg("light"),
             py::arg("steps"), py::arg("receivers"), py::arg("exact"), py::arg("range_fraction"),
             py::arg("full_scale_lux"), py::arg("range_lux"));
  module.def("format_json", &format_json, py::arg("document"),
             "the document as the command line writes it to files");
  module.def("write_sun_hours_svg", &write_sun_hours_svg, py::arg("document"), py::arg("path"),
             py::arg("view") = "top");
  module.def("write_sun_hours_png", &write_sun_hours_png, py::arg("document"), py::arg("path"),
             py::arg("width") = 1200);
}

}  // namespace penumbra::python
