#include "penumbra/scene/load_scene.h"

#include <cmath>
#include <exception>
#include <functional>
#include <set>
#include <sstream>

#include "area_light.h"
#include "bezier_objects.h"
#include "json_cursor.h"
#include "mesh_parts.h"
#include "penumbra/base/input_error.h"
#include "penumbra/base/input_file.h"
#include "penumbra/base/parallel.h"
#include "penumbra/geometry/geometry_error.h"
#include "penumbra/scene/model_import.h"
#include "sphere_points.h"

namespace penumbra {
namespace {

using detail::JsonCursor;

constexpr int kDefaultSphereSegments = 16;
// the finest sphere: 512 meridians by 256 bands, 130,000 points (docs/reliability.md, "Limits")
constexpr int kMaxSphereSegments = 512;
// The default distance (m) within which the tessellation of a Bézier patch object lies.
constexpr double kBezierTolerance = 1e-3;
// The most triangles the tessellation of one Bézier patch object may have.
constexpr double kMaxBezierTriangles = 2e6;

std::vector<Point3> exact_points(const std::vector<Vec3d>& points) {
  std::vector<Point3> result;
  for (const Vec3d& p : points) result.push_back(to_exact(p));
  return result;
}

// runs a geometry construction, reporting its failure at the cursor's path (and at
// the offending point's index when the construction names one).
template <typename Build>
ConvexPolyhedron build_solid(const JsonCursor& where, Build build) {
  try {
    return build();
  } catch (const GeometryError& e) {
    if (e.index() >= 0) where.at(static_cast<std::size_t>(e.index())).fail(e.what());
    where.fail(e.what());
  }
}

Vec3d unit(const Vec3d& v) {
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / length, v[1] / length, v[2] / length};
}

double dot(const Vec3d& a, const Vec3d& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

bool parallel(const Vec3d& a, const Vec3d& b) {
  const Vector3 c = CGAL::cross_product(to_exact_vector(a), to_exact_vector(b));
  return c == CGAL::NULL_VECTOR;
}

class SceneReader {
 public:
  SceneReader(Scene& scene, std::string file) : scene_(scene), file_(std::move(file)) {}

  void read(const nlohmann::json& document) {
    const JsonCursor root(document, "", file_, &scene_.warnings);
    root.require_object();
    root.warn_unknown_keys({"penumbra", "materials", "objects", "lights", "camera", "north_deg"});
    const JsonCursor version = root.at("penumbra");
    if (!version.value().is_number_integer() || version.value().get<long>() != 1)
      version.fail("unsupported scene format version " + version.value().dump() + " (expected 1)");

    Material default_material;
    default_material.name = "default";
    scene_.materials.push_back(default_material);
    if (const auto materials = root.find("materials"))
      for (const auto& [name, cursor] : materials->members()) read_material(name, cursor);

    if (const auto north = root.find("north_deg")) scene_.north_deg = north->number_in(-360, 360);
    if (const auto objects = root.find("objects")) read_objects(*objects);
    if (const auto lights = root.find("lights"))
      for (const JsonCursor& light : lights->elements()) read_light(light);
    if (const auto camera = root.find("camera")) read_camera(*camera);
  }

 private:
  // A solid to build once every object has been read: the object it belongs to and the
  // construction (which throws InputError naming the object's JSON path).
  struct PendingSolid {
    std::size_t object;
    std::function<ConvexPolyhedron()> build;
  };

  // reads the objects, building their solids in parallel (a hull per object is the bulk
  // of loading a large scene). The error reported is the first in document order, as a
  // serial reading would find it: a reading error ends the reading, and is reported only
  // if no solid before it fails.
  void read_objects(const JsonCursor& objects) {
    std::exception_ptr reading_error;
    try {
      for (const JsonCursor& object : objects.elements()) read_object(object);
    } catch (const InputError&) {
      reading_error = std::current_exception();
    }
    std::vector<std::exception_ptr> errors(pending_.size());
    for_each_index(pending_.size(), true, [&](std::size_t k) {
      try {
        scene_.objects[pending_[k].object].solid = pending_[k].build();
      } catch (const InputError&) {
        errors[k] = std::current_exception();
      }
    });
    for (const std::exception_ptr& error : errors)
      if (error) std::rethrow_exception(error);
    if (reading_error) std::rethrow_exception(reading_error);
    pending_.clear();
  }

  // defers the construction of the solid of the object being read (the next in
  // scene_.objects).
  void defer(std::function<ConvexPolyhedron()> build) {
    pending_.push_back({scene_.objects.size(), std::move(build)});
  }

  void read_material(const std::string& name, const JsonCursor& cursor) {
    cursor.require_object();
    cursor.warn_unknown_keys({"reflectance", "color", "specular", "shininess", "reflect",
                              "transmit", "ior", "roughness"});
    Material m;
    m.name = name;
    if (auto c = cursor.find("reflectance")) m.reflectance = c->number_in(0, 1);
    if (auto c = cursor.find("color")) {
      const Vec3d rgb = c->vec3();
      for (std::size_t i = 0; i < 3; ++i) {
        if (rgb[i] < 0 || rgb[i] > 1) c->at(i).fail("a colour channel must lie in [0, 1]");
        m.color[i] = rgb[i];
      }
    }
    if (auto c = cursor.find("specular")) m.specular = c->number_in(0, 1);
    if (auto c = cursor.find("shininess")) m.shininess = c->non_negative_number();
    if (auto c = cursor.find("reflect")) m.reflect = c->number_in(0, 1);
    if (auto c = cursor.find("transmit")) m.transmit = c->number_in(0, 1);
    if (auto c = cursor.find("ior")) m.ior = c->positive_number();
    if (auto c = cursor.find("roughness")) m.roughness = c->number_in(0, 1);
    scene_.materials.push_back(m);
  }

  std::size_t material_index(const JsonCursor& cursor) const {
    const std::string name = cursor.string();
    for (std::size_t i = 1; i < scene_.materials.size(); ++i)
      if (scene_.materials[i].name == name) return i;
    if (name == "default") return 0;
    cursor.fail("unknown material \"" + name + "\"");
  }

  void claim_name(const JsonCursor& where, const std::string& name, std::set<std::string>& taken) {
    if (name.empty()) where.fail("a name must not be empty");
    if (name.find('#') != std::string::npos)
      where.fail("names must not contain '#' (reserved for the parts of a mesh)");
    if (!taken.insert(name).second) where.fail("duplicate name \"" + name + "\"");
  }

  void read_object(const JsonCursor& cursor) {
    cursor.require_object();
    static const char* kinds[] = {"box",    "convex", "polygon",       "mesh",
                                  "sphere", "bezier", "bezier_patches"};
    std::string kind;
    for (const char* k : kinds) {
      if (!cursor.has(k)) continue;
      if (!kind.empty())
        cursor.fail("an object has one shape, found both \"" + kind + "\" and \"" + k + "\"");
      kind = k;
    }
    if (kind.empty())
      cursor.fail(
          "an object needs one of \"box\", \"convex\", \"polygon\", \"mesh\", \"sphere\", "
          "\"bezier\", \"bezier_patches\"");
    if (kind == "mesh")
      cursor.warn_unknown_keys({"name", "material", "mesh", "up", "scale", "transform", "snap"});
    else if (kind == "bezier" || kind == "bezier_patches")
      cursor.warn_unknown_keys(
          {"name", "material", kind.c_str(), "tolerance", "up", "scale", "transform", "snap"});
    else
      cursor.warn_unknown_keys(
          {"name", "material", "box", "convex", "polygon", "mesh", "sphere", "segments"});

    Object object;
    object.kind = kind;
    object.json_path = cursor.path();
    object.name = cursor.has("name") ? cursor.at("name").string()
                                     : kind + std::to_string(scene_.objects.size());
    claim_name(cursor.has("name") ? cursor.at("name") : cursor, object.name, object_names_);
    object.material = cursor.has("material") ? material_index(cursor.at("material")) : 0;

    const JsonCursor shape = cursor.at(kind.c_str());
    if (kind == "box") {
      shape.require_object();
      shape.warn_unknown_keys({"min", "max"});
      const Vec3d low = shape.at("min").vec3();
      const Vec3d high = shape.at("max").vec3();
      for (int i = 0; i < 3; ++i)
        if (!(low[i] < high[i])) shape.at("max").fail("each coordinate of max must exceed min");
      defer([low, high] {
        std::vector<Point3> corners;
        for (int k = 0; k < 8; ++k)
          corners.push_back(Point3((k & 1) ? high[0] : low[0], (k & 2) ? high[1] : low[1],
                                   (k & 4) ? high[2] : low[2]));
        return ConvexPolyhedron::hull(corners);
      });
    } else if (kind == "convex") {
      defer([shape, points = shape.points(4)] {
        return build_solid(shape, [&] { return ConvexPolyhedron::hull(exact_points(points)); });
      });
    } else if (kind == "polygon") {
      defer([shape, points = shape.points(3)] {
        return build_solid(shape,
                           [&] { return ConvexPolyhedron::flat_polygon(exact_points(points)); });
      });
    } else if (kind == "sphere") {
      shape.require_object();
      shape.warn_unknown_keys({"center", "radius", "segments"});
      Sphere sphere{shape.at("center").vec3(), shape.at("radius").positive_number(),
                    kDefaultSphereSegments};
      if (auto s = shape.find("segments")) {
        sphere.segments = s->positive_integer();
        if (sphere.segments < 4) s->fail("a sphere needs at least 4 segments");
        if (sphere.segments > kMaxSphereSegments)
          s->fail("a sphere has at most " + std::to_string(kMaxSphereSegments) + " segments");
      }
      defer([sphere] {
        return ConvexPolyhedron::hull(
            exact_points(detail::sphere_points(sphere.center, sphere.radius, sphere.segments)));
      });
      object.sphere = sphere;
    } else if (kind == "mesh") {
      read_mesh_object(cursor, shape, std::move(object));
      return;
    } else {
      read_bezier_object(cursor, shape, std::move(object));
      return;
    }
    scene_.objects.push_back(std::move(object));
  }

  // reads the placement keys of a mesh object (docs/scene-format.md, "Placement").
  static Placement read_placement(const JsonCursor& cursor) {
    Placement placement;
    if (const auto up = cursor.find("up")) {
      const std::string axis = up->string();
      if (axis != "y" && axis != "z") up->fail("the up axis is \"z\" (the default) or \"y\"");
      placement.y_up = axis == "y";
    }
    if (const auto scale = cursor.find("scale")) placement.scale = scale->positive_number();
    if (const auto snap = cursor.find("snap")) placement.snap = snap->non_negative_number();
    if (const auto transform = cursor.find("transform")) {
      const auto rows = transform->elements();
      if (rows.size() != 16) transform->fail("a transform is 16 numbers (4 x 4, row-major)");
      std::array<double, 16> matrix{};
      for (std::size_t k = 0; k < 16; ++k) matrix[k] = rows[k].number();
      if (matrix[12] != 0 || matrix[13] != 0 || matrix[14] != 0 || matrix[15] != 1)
        transform->fail("the last row of a transform must be 0, 0, 0, 1");
      placement.transform = matrix;
    }
    return placement;
  }

  // reads a real model (docs/scene-format.md, "Mesh import"): each part becomes a convex
  // object when it is a closed convex solid, and otherwise the convex pieces of its faces.
  void read_mesh_object(const JsonCursor& cursor, const JsonCursor& shape, Object object) {
    const Placement placement = read_placement(cursor);
    const std::filesystem::path path = scene_.file.parent_path() / shape.string();
    ImportedModel model;
    try {
      model = import_model(path, placement);
    } catch (const InputError& e) {
      // Name both the model's problem and where the scene referenced it.
      shape.fail(e.what());
    }
    if (const std::string repaired = detail::repair_summary(model.repairs); !repaired.empty())
      scene_.warnings.push_back(file_ + ": " + shape.path() + ": " + path.filename().string() +
                                ": " + repaired);
    const bool own_material = cursor.has("material");
    std::vector<detail::MeshPartObjects> parts(model.parts.size());
    for_each_index(model.parts.size(), true, [&](std::size_t k) {
      parts[k] = detail::mesh_part_objects(model.parts[k], path.string());
    });
    for (std::size_t k = 0; k < parts.size(); ++k) {
      const ModelPart& part = model.parts[k];
      const std::string name =
          model.parts.size() == 1 ? object.name : object.name + "/" + part.name;
      if (model.parts.size() > 1 && !object_names_.insert(name).second)
        (cursor.has("name") ? cursor.at("name") : cursor)
            .fail("the part name \"" + name + "\" is taken by another object");
      Object base = object;
      base.name = name;
      if (!own_material && part.colour) {
        Material material;
        material.name = name;
        for (int i = 0; i < 3; ++i) material.color[i] = (*part.colour)[i];
        base.material = scene_.materials.size();
        scene_.materials.push_back(material);
      }
      detail::add_mesh_part(scene_, base, part, std::move(parts[k]));
    }
  }

  // reads an object of Bézier patches (docs/bezier-patches.md): the patches, placed, kept
  // for the ray tracer; their tessellation made into convex pieces for every other verb.
  void read_bezier_object(const JsonCursor& cursor, const JsonCursor& shape, Object object) {
    const Placement placement = read_placement(cursor);
    const double tolerance =
        cursor.has("tolerance") ? cursor.at("tolerance").positive_number() : kBezierTolerance;
    std::vector<BezierPatch> patches;
    object.kind = "bezier";
    if (shape.value().is_string()) {
      const std::filesystem::path path = scene_.file.parent_path() / shape.string();
      try {
        patches = detail::read_bezier_file(path);
      } catch (const InputError& e) {
        shape.fail(e.what());
      }
    } else {
      // One patch as 16 points, or a list of patches.
      const auto elements = shape.elements();
      const bool one = !elements.empty() && elements[0].value().is_array() &&
                       !elements[0].value().empty() && elements[0].value()[0].is_number();
      const auto read_patch = [&](const JsonCursor& points) {
        const std::vector<Vec3d> read = points.points(16);
        if (read.size() != 16) points.fail("a bicubic patch has 16 control points");
        BezierPatch patch;
        std::copy(read.begin(), read.end(), patch.points.begin());
        patches.push_back(patch);
      };
      if (one) {
        read_patch(shape);
      } else {
        if (elements.empty()) shape.fail("a list of patches must not be empty");
        for (const JsonCursor& element : elements) read_patch(element);
      }
    }
    patches = detail::placed_patches(std::move(patches), placement);
    for (const BezierPatch& patch : patches)
      for (const Vec3d& p : patch.points)
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
          shape.fail("a control point is not finite once placed (scale or transform too large)");
    // Refuse a tessellation too large to build before building it.
    const double segments = detail::grid_segments(patches, tolerance);
    const double triangles = 2 * segments * segments * static_cast<double>(patches.size());
    if (triangles > kMaxBezierTriangles) {
      std::ostringstream message;
      message << "the tessellation within " << tolerance << " m would have "
              << static_cast<long long>(triangles)
              << " triangles, more than the limit of 2000000: give a larger tolerance";
      (cursor.has("tolerance") ? cursor.at("tolerance") : shape).fail(message.str());
    }
    detail::PatchTessellation tessellation =
        detail::tessellate(patches, tolerance, placement.snap, object.name);
    if (tessellation.part.faces.empty()) shape.fail("every patch is degenerate (no area)");
    object.patches = std::make_shared<const std::vector<BezierPatch>>(std::move(patches));
    TessellatedPatches record{object.name, object.json_path, object.patches->size(),
                              tessellation.triangles, tolerance};
    std::ostringstream note;
    note << file_ << ": " << object.json_path << ": '" << object.name << "': " << record.patches
         << " Bézier patches tessellated into " << record.triangles << " triangles within "
         << tolerance
         << " m; every verb but raytrace uses the tessellation (raytrace intersects the "
            "patches)";
    scene_.warnings.push_back(note.str());
    scene_.tessellated.push_back(std::move(record));
    detail::MeshPartObjects parts = detail::mesh_part_objects(
        tessellation.part, shape.value().is_string() ? shape.string() : file_);
    detail::add_mesh_part(scene_, object, tessellation.part, std::move(parts));
  }

  void read_light(const JsonCursor& cursor) {
    cursor.require_object();
    static const char* kinds[] = {"point", "linear", "area", "directional", "sun"};
    std::string kind;
    for (const char* k : kinds) {
      if (!cursor.has(k)) continue;
      if (!kind.empty())
        cursor.fail("a light has one kind, found both \"" + kind + "\" and \"" + k + "\"");
      kind = k;
    }
    if (kind.empty())
      cursor.fail("a light needs one of \"point\", \"linear\", \"area\", \"directional\", \"sun\"");

    Light light;
    light.json_path = cursor.path();
    light.name = cursor.has("name") ? cursor.at("name").string()
                                    : kind + std::to_string(scene_.lights.size());
    claim_name(cursor.has("name") ? cursor.at("name") : cursor, light.name, light_names_);

    if (kind == "point") {
      cursor.warn_unknown_keys({"name", "point", "candela", "lid", "axis", "c0"});
      light.source = read_point_light(cursor);
    } else if (kind == "linear") {
      cursor.warn_unknown_keys({"name", "linear", "candela_per_metre"});
      const JsonCursor ends = cursor.at("linear");
      const auto points = ends.points(2);
      if (points.size() != 2) ends.fail("a linear source has exactly 2 end points");
      if (points[0] == points[1]) ends.fail("a linear source must not have zero length");
      light.source =
          LinearLight{points[0], points[1], cursor.at("candela_per_metre").non_negative_number()};
    } else if (kind == "area") {
      cursor.warn_unknown_keys({"name", "area", "luminance", "exitance", "lumens", "two_sided"});
      light.source = detail::read_area_light(cursor);
    } else if (kind == "directional") {
      cursor.warn_unknown_keys({"name", "directional", "illuminance"});
      light.source = DirectionalLight{cursor.at("directional").direction(),
                                      cursor.at("illuminance").non_negative_number()};
    } else {
      cursor.warn_unknown_keys({"name", "sun", "illuminance"});
      SunPlacement sun = read_sun(cursor.at("sun"));
      sun.name = light.name;
      sun.json_path = cursor.path();
      sun.illuminance = cursor.at("illuminance").non_negative_number();
      scene_.suns.push_back(sun);
      // The direction at the scene's time; a sun below the horizon lights nothing.
      const sun::SolarPosition seen = sun::solar_position(sun.site, sun.time.utc, sun.atmosphere);
      if (seen.elevation_deg <= 0) {
        scene_.warnings.push_back(file_ + ": " + cursor.path() + ": the sun '" + light.name +
                                  "' is below the horizon at " +
                                  sun::format_date_time(sun.time.utc, sun.time.offset_minutes) +
                                  " (elevation " + std::to_string(seen.elevation_deg) +
                                  " degrees): it lights nothing");
        return;
      }
      light.source =
          DirectionalLight{sun::light_direction(seen, scene_.north_deg), sun.illuminance};
    }
    scene_.lights.push_back(std::move(light));
  }

  // reads "sun": {"latitude", "longitude", "time", "elevation", "pressure", "temperature"}.
  SunPlacement read_sun(const JsonCursor& cursor) const {
    cursor.require_object();
    cursor.warn_unknown_keys(
        {"latitude", "longitude", "time", "elevation", "pressure", "temperature"});
    SunPlacement sun;
    sun.site.latitude_deg = cursor.at("latitude").number_in(-90, 90);
    sun.site.longitude_deg = cursor.at("longitude").number_in(-180, 180);
    if (const auto elevation = cursor.find("elevation")) sun.site.elevation_m = elevation->number();
    const JsonCursor time = cursor.at("time");
    sun.time = sun::parse_date_time(time.string(), std::nullopt, {file_, time.path()});
    if (cursor.has("pressure") != cursor.has("temperature"))
      cursor.fail("give both \"pressure\" and \"temperature\" for refraction, or neither");
    if (cursor.has("pressure"))
      sun.atmosphere = sun::Atmosphere{cursor.at("pressure").positive_number(),
                                       cursor.at("temperature").number_in(-273.15, 100)};
    return sun;
  }

  PointLight read_point_light(const JsonCursor& cursor) const {
    PointLight light;
    light.position = cursor.at("point").vec3();
    if (cursor.has("candela") == cursor.has("lid"))
      cursor.fail("a point light needs exactly one of \"candela\" (isotropic) or \"lid\"");
    if (auto candela = cursor.find("candela")) {
      light.distribution = photometry::make_isotropic(candela->non_negative_number());
    } else {
      const JsonCursor lid = cursor.at("lid");
      light.lid = lid.value();
      try {
        light.distribution = photometry::make_distribution(
            lid.value(), photometry::SpecContext{file_, lid.path(), scene_.file.parent_path()});
      } catch (const InputError& e) {
        if (e.file() == file_) throw;
        lid.fail(e.what());  // a photometric file's problem, named where the scene refers to it
      }
    }
    if (auto axis = cursor.find("axis")) light.axis = unit(axis->direction());
    if (auto c0 = cursor.find("c0")) {
      const Vec3d raw = c0->direction();
      if (parallel(raw, light.axis)) c0->fail("c0 must not be parallel to the axis");
      // Keep the part of c0 orthogonal to the axis: the C = 0 half-plane it names.
      const double along = dot(raw, light.axis);
      light.c0 = unit({raw[0] - along * light.axis[0], raw[1] - along * light.axis[1],
                       raw[2] - along * light.axis[2]});
    } else {
      // Default C = 0 direction: world x made orthogonal to the axis (world y when
      // the axis is along x).
      const Vec3d x{1, 0, 0};
      light.c0 =
          unit(cross(cross(light.axis, parallel(x, light.axis) ? Vec3d{0, 1, 0} : x), light.axis));
    }
    return light;
  }

  void read_camera(const JsonCursor& cursor) {
    cursor.require_object();
    cursor.warn_unknown_keys({"eye", "target", "up", "fov_deg", "width", "height"});
    Camera camera;
    camera.eye = cursor.at("eye").vec3();
    camera.target = cursor.at("target").vec3();
    if (camera.eye == camera.target)
      cursor.at("target").fail("the target must differ from the eye");
    if (auto up = cursor.find("up")) camera.up = up->direction();
    const Vec3d view{camera.target[0] - camera.eye[0], camera.target[1] - camera.eye[1],
                     camera.target[2] - camera.eye[2]};
    if (parallel(view, camera.up))
      (cursor.has("up") ? cursor.at("up") : cursor)
          .fail("up must not be parallel to the view direction");
    if (auto fov = cursor.find("fov_deg")) {
      camera.fov_deg = fov->number();
      if (!(camera.fov_deg > 0 && camera.fov_deg < 180)) fov->fail("fov_deg must lie in (0, 180)");
    }
    if (auto width = cursor.find("width")) camera.width = width->positive_integer();
    if (auto height = cursor.find("height")) camera.height = height->positive_integer();
    if (const std::string problem = image_size_problem(camera.width, camera.height);
        !problem.empty())
      cursor.fail(problem);
    scene_.camera = camera;
  }

  Scene& scene_;
  std::string file_;
  std::vector<PendingSolid> pending_;
  std::set<std::string> object_names_;
  std::set<std::string> light_names_;
};

}  // namespace

Scene parse_scene(const std::string& text, const std::filesystem::path& file) {
  const nlohmann::json document = parse_input_json(text, file.string());
  Scene scene;
  scene.file = file;
  SceneReader(scene, file.string()).read(document);
  return scene;
}

Scene load_scene(const std::filesystem::path& path) {
  return parse_scene(read_input_file(path, "scene file", file_limits::scene), path);
}

const Object* Scene::find_object(const std::string& name) const {
  for (const Object& object : objects)
    if (object.name == name) return &object;
  return nullptr;
}

const char* kind_name(const Light& light) {
  if (std::holds_alternative<PointLight>(light.source)) return "point";
  if (std::holds_alternative<LinearLight>(light.source)) return "linear";
  if (std::holds_alternative<AreaLight>(light.source)) return "area";
  return "directional";
}

const Light* Scene::find_light(const std::string& name) const {
  for (const Light& light : lights)
    if (light.name == name) return &light;
  return nullptr;
}

}  // namespace penumbra
