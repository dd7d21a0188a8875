// penumbra.Scene's native side: loading, what a scene holds, exact shadows as the shadow
// document (DESIGN.md, "Shadow loops output"), illuminance at points and on a work plane.

#include <array>
#include <map>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include <CGAL/Bbox_3.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "json_to_python.h"
#include "penumbra/base/input_error.h"
#include "penumbra/illuminance/workplane.h"
#include "penumbra/io/shadow_json.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/scene/object_selection.h"

namespace penumbra::python {

namespace py = pybind11;
namespace il = illuminance;

const il::IlluminanceSolver& SceneHandle::solver() const {
  std::call_once(solver_once_, [this] { solver_.emplace(*scene_); });
  return *solver_;
}

std::optional<std::vector<Receiver>> chosen_receivers(const Scene& scene,
                                                      const py::object& receivers) {
  if (receivers.is_none()) return std::nullopt;
  if (py::isinstance<py::str>(receivers))
    return faces_of_objects(scene, select_objects(scene, receivers.cast<std::string>()));
  std::set<std::string> owners;
  for (const py::handle name : receivers) owners.insert(name.cast<std::string>());
  std::vector<std::size_t> objects;
  std::set<std::string> found;
  for (std::size_t k = 0; k < scene.objects.size(); ++k)
    if (owners.count(scene.objects[k].face_owner())) {
      objects.push_back(k);
      found.insert(scene.objects[k].face_owner());
    }
  for (const std::string& owner : owners)
    if (!found.count(owner))
      throw InputError(scene.file.string(), "receivers", "no object or part named '" + owner + "'");
  return faces_of_objects(scene, objects);
}

ShadowOptions shadow_options(const Scene& scene, const py::object& receivers, double range_fraction,
                             double full_scale_lux, std::optional<double> range_lux) {
  ShadowOptions options;
  options.range_fraction = range_fraction;
  options.full_scale_lux = full_scale_lux;
  options.range_lux = range_lux;
  options.receivers = chosen_receivers(scene, receivers);
  return options;
}

namespace {

std::shared_ptr<SceneHandle> load(const std::string& path) {
  py::gil_scoped_release unlocked;
  return std::make_shared<SceneHandle>(load_scene(path));
}

std::shared_ptr<SceneHandle> parse(const std::string& text, const std::string& file) {
  py::gil_scoped_release unlocked;
  return std::make_shared<SceneHandle>(parse_scene(text, file));
}

// the owners of receiving faces (objects, and parts for the pieces of mesh faces), in the
// canonical order of documents (by name), each with its receiving faces' count and the
// bounding box of its objects: what a job splits into spatial tiles.
py::list owners(const SceneHandle& handle) {
  const Scene& scene = handle.scene();
  struct Owner {
    std::size_t faces = 0;
    CGAL::Bbox_3 box;
  };
  std::map<std::string, Owner> by_name;
  for (const Object& object : scene.objects) {
    Owner& owner = by_name[object.face_owner()];
    for (std::size_t f = 0; f < object.solid.faces().size(); ++f) owner.faces += object.receives(f);
    owner.box += object.solid.bbox();
  }
  py::list list;
  for (const auto& [name, owner] : by_name)
    list.append(
        py::make_tuple(name, owner.faces,
                       py::make_tuple(owner.box.xmin(), owner.box.ymin(), owner.box.zmin(),
                                      owner.box.xmax(), owner.box.ymax(), owner.box.zmax())));
  return list;
}

py::tuple shadow_document(const SceneHandle& handle, const std::optional<std::string>& light,
                          const py::object& receivers, bool exact, double range_fraction,
                          double full_scale_lux, std::optional<double> range_lux) {
  const Scene& scene = handle.scene();
  ShadowOptions options =
      shadow_options(scene, receivers, range_fraction, full_scale_lux, range_lux);
  options.light = light;
  const io::ShadowJsonOptions json_options = io::json_options_of(options, exact);
  nlohmann::json document;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release unlocked;
    const ShadowResult result = compute_shadows(scene, options);
    document = io::shadow_json(scene, result, json_options);
    warnings = result.warnings;
  }
  return py::make_tuple(to_python(document), warnings);
}

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

// the receiving points of an (N, 6) array x, y, z, nx, ny, nz, checked as the points file.
std::vector<il::ReceivingPoint> receiving_points(const Doubles& points) {
  if (points.ndim() != 2 || points.shape(1) != 6)
    throw InputError("", "points", "expected an (N, 6) array of x, y, z, nx, ny, nz");
  const auto rows = points.unchecked<2>();
  std::vector<il::ReceivingPoint> receivers;
  receivers.reserve(rows.shape(0));
  for (py::ssize_t k = 0; k < rows.shape(0); ++k)
    receivers.push_back(il::receiving_point(
        {rows(k, 0), rows(k, 1), rows(k, 2), rows(k, 3), rows(k, 4), rows(k, 5)}, "",
        "points[" + std::to_string(k) + "]"));
  return receivers;
}

// returns (E, E per light as (N, lights), index of the object holding each point or -1).
py::tuple values_as_arrays(const std::vector<il::PointIlluminance>& values, std::size_t lights) {
  const auto n = static_cast<py::ssize_t>(values.size());
  py::array_t<double> total(n);
  py::array_t<double> per_light({n, static_cast<py::ssize_t>(lights)});
  py::array_t<std::int64_t> inside(n);
  auto t = total.mutable_unchecked<1>();
  auto p = per_light.mutable_unchecked<2>();
  auto i = inside.mutable_unchecked<1>();
  for (py::ssize_t k = 0; k < n; ++k) {
    t(k) = values[k].total;
    for (std::size_t light = 0; light < lights; ++light)
      p(k, static_cast<py::ssize_t>(light)) = values[k].per_light[light];
    i(k) = values[k].inside ? static_cast<std::int64_t>(*values[k].inside) : -1;
  }
  return py::make_tuple(total, per_light, inside);
}

py::tuple illuminance_at(const SceneHandle& handle, const Doubles& points) {
  const std::vector<il::ReceivingPoint> receivers = receiving_points(points);
  std::vector<il::PointIlluminance> values;
  {
    py::gil_scoped_release unlocked;
    values = il::illuminance_at_points(handle.solver(), receivers);
  }
  return values_as_arrays(values, handle.scene().lights.size());
}

// the work-plane grid (cell centres, normal +z) of `illuminance --workplane`: its points as
// an (N, 6) array and its shape; the region is the scene's plan bounds when not given.
py::tuple workplane_grid(const SceneHandle& handle, double height, double spacing,
                         const std::optional<std::array<double, 4>>& region) {
  il::PlanRegion plan{};
  if (region) {
    plan = {(*region)[0], (*region)[1], (*region)[2], (*region)[3]};
  } else if (const auto bounds = il::plan_bounds(handle.scene())) {
    plan = *bounds;
  } else {
    throw InputError(handle.scene().file.string(), "objects",
                     "the scene has no objects: give a region");
  }
  il::WorkplaneGrid grid;
  try {
    grid = il::make_workplane_grid(height, spacing, plan);
  } catch (const std::invalid_argument& error) {
    throw InputError("", "workplane", error.what());
  }
  py::array_t<double> points({static_cast<py::ssize_t>(grid.size()), py::ssize_t{6}});
  auto rows = points.mutable_unchecked<2>();
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const Vec3d p = grid.point(k);
    const auto r = static_cast<py::ssize_t>(k);
    for (py::ssize_t c = 0; c < 3; ++c) rows(r, c) = p[c];
    rows(r, 3) = 0, rows(r, 4) = 0, rows(r, 5) = 1;
  }
  return py::make_tuple(points, grid.columns, grid.rows,
                        py::make_tuple(plan.x0, plan.y0, plan.x1, plan.y1));
}

}  // namespace

void bind_scene(py::module_& module) {
  py::class_<SceneHandle, std::shared_ptr<SceneHandle>>(module, "NativeScene",
                                                        "A loaded scene (use penumbra.Scene).")
      .def_static("load", &load, py::arg("path"), "loads the scene file at path")
      .def_static("parse", &parse, py::arg("text"), py::arg("file"),
                  "parses scene JSON text as if read from file (relative paths resolve beside "
                  "it)")
      .def_property_readonly("file", [](const SceneHandle& h) { return h.scene().file.string(); })
      .def_property_readonly("objects",
                             [](const SceneHandle& h) {
                               std::vector<std::string> names;
                               for (const Object& o : h.scene().objects) names.push_back(o.name);
                               return names;
                             })
      .def_property_readonly("lights",
                             [](const SceneHandle& h) {
                               std::vector<std::pair<std::string, std::string>> lights;
                               for (const Light& l : h.scene().lights)
                                 lights.emplace_back(l.name, kind_name(l));
                               return lights;
                             })
      .def_property_readonly("suns",
                             [](const SceneHandle& h) {
                               std::vector<std::string> names;
                               for (const SunPlacement& s : h.scene().suns) names.push_back(s.name);
                               return names;
                             })
      .def_property_readonly("north_deg", [](const SceneHandle& h) { return h.scene().north_deg; })
      .def_property_readonly("warnings", [](const SceneHandle& h) { return h.scene().warnings; })
      .def("owners", &owners)
      .def("shadow_document", &shadow_document, py::arg("light"), py::arg("receivers"),
           py::arg("exact"), py::arg("range_fraction"), py::arg("full_scale_lux"),
           py::arg("range_lux"))
      .def("illuminance", &illuminance_at, py::arg("points"))
      .def("workplane_grid", &workplane_grid, py::arg("height"), py::arg("spacing"),
           py::arg("region"));
}

}  // namespace penumbra::python
