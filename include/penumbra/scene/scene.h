#pragma once
// The scene model (DESIGN.md, "Scene file"): exact convex objects, materials,
// lights and a camera, as loaded from a version-1 scene file.

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "penumbra/base/colour.h"
#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/photometry/distribution.h"
#include "penumbra/scene/camera.h"
#include "penumbra/sun/solar_position.h"

namespace penumbra {

struct Material {
  std::string name;
  double reflectance = 0.5;  // diffuse reflectance rho (luminance of a diffuse face: rho E / pi)
  Colour color{1, 1, 1};     // relative spectral tint, each channel in [0, 1]
  double specular = 0;       // Phong specular coefficient
  double shininess = 0;      // Phong exponent
  double reflect = 0;        // Whitted k_s: mirror reflection weight
  double transmit = 0;       // Whitted k_t: transmission weight
  double ior = 1;            // index of refraction
  double roughness = 0;      // microfacet normal perturbation (Whitted section 2)
};

// An exact sphere, kept beside its tessellation for renderers that can use it.
struct Sphere {
  Vec3d center;
  double radius;
  int segments;  // longitude divisions of the tessellation; latitude gets half
};

struct Object {
  std::string name;      // unique; a mesh with k > 1 convex parts gives name#0 .. name#(k-1)
  std::string kind;      // "box", "convex", "polygon", "mesh" or "sphere"
  std::size_t material;  // index into Scene::materials
  ConvexPolyhedron solid;
  std::optional<Sphere> sphere;
  std::string json_path;  // where it was defined, e.g. "objects[3]"
};

struct PointLight {
  Vec3d position;
  // the luminous intensity distribution; isotropic when the scene gives `candela`.
  std::shared_ptr<const photometry::Distribution> distribution;
  Vec3d axis{0, 0, -1};  // illumination axis (gamma = 0), unit length
  Vec3d c0{1, 0, 0};     // C = 0 reference direction, unit length, orthogonal to axis
  nlohmann::json lid;    // the `lid` specification as written (null when isotropic)
};

struct LinearLight {
  Vec3d start;
  Vec3d end;
  double candela_per_metre;  // Lambertian tube: intensity I sin(theta) per metre (Nishita eq. 5)
};

struct DirectionalLight {
  Vec3d direction;     // the direction light travels (sun into scene), exactly as written: not
                       // normalised
  double illuminance;  // lux on a plane normal to the direction
};

// A sun given by place and time (`"sun": {...}`, docs/sun.md): the scene keeps it so that
// `penumbra sun` and sun studies can move it through time.
struct SunPlacement {
  std::string name;       // the light's name
  std::string json_path;  // "lights[k]"
  sun::Site site;
  std::optional<sun::Atmosphere> atmosphere;  // refraction when pressure and temperature are given
  sun::ZonedInstant time;                     // the scene's instant, with its UTC offset
  double illuminance = 0;                     // lux on a plane normal to the sunlight
};

struct Light {
  std::string name;
  std::variant<PointLight, LinearLight, DirectionalLight> source;
  std::string json_path;
};

struct Scene {
  std::filesystem::path file;       // the scene file; relative paths resolve beside it
  std::vector<Material> materials;  // materials[0] is the default material
  std::vector<Object> objects;
  std::vector<Light> lights;
  std::vector<SunPlacement> suns;  // the lights given by place and time (above the horizon or not)
  double north_deg = 0;  // true north from the model's +Y, counter-clockwise seen from above
  std::optional<Camera> camera;
  std::vector<std::string> warnings;  // e.g. unknown keys: reported, not fatal

  // returns the object with the given name, or nullptr.
  const Object* find_object(const std::string& name) const;
  // returns the light with the given name, or nullptr.
  const Light* find_light(const std::string& name) const;
};

}  // namespace penumbra
