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
#include "penumbra/geometry/bezier_patch.h"
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

// Faces of mesh parts that are not convex solids (docs/scene-format.md, "Mesh import") are
// cut into convex pieces, each an object of its own (a two-sided flat polygon), so that every
// verb sees convex occluders and receivers; documents unite the pieces again per face.
constexpr std::size_t kNoMeshFace = static_cast<std::size_t>(-1);

struct Object {
  std::string name;      // unique; a piece of a mesh face is "<part>#<k>"
  std::string kind;      // "box", "convex", "polygon", "mesh", "sphere" or "bezier"
  std::size_t material;  // index into Scene::materials
  ConvexPolyhedron solid;
  std::optional<Sphere> sphere;
  std::string json_path;  // where it was defined, e.g. "objects[3]"
  // a convex piece of a mesh face: the part's name ("house/wing"), and for each of the
  // solid's two faces the MeshFace it lies on (kNoMeshFace: the inner side of a closed
  // solid's face, which receives nothing). Empty for other objects.
  std::string part;
  std::vector<std::size_t> mesh_faces;
  // the Bézier patches of a patch object (docs/bezier-patches.md), shared by the pieces of its
  // tessellation: the ray tracer intersects these, every other verb sees the pieces.
  std::shared_ptr<const std::vector<BezierPatch>> patches;

  // true when face f receives light: every face, but the inner sides of closed meshes.
  bool receives(std::size_t f) const { return mesh_faces.empty() || mesh_faces[f] != kNoMeshFace; }
  // the name documents use for the object's faces: the part of a piece, the name otherwise.
  const std::string& face_owner() const { return part.empty() ? name : part; }
};

// One side of a planar face of a mesh part that is not a convex solid: a polygon, possibly
// non-convex and with holes, made of convex pieces (objects). A face of a closed solid has
// one side (its outside); a face of an open surface has two, numbered one after the other.
struct MeshFace {
  std::string part;   // the part's name, as documents name the face's owner
  std::size_t index;  // the face's number within its part
  Plane3 plane;       // positive side = the side that receives
  FaceFrame frame;    // the face's own frame: the single piece's, or at outer[0] along outer
  std::vector<Point3> outer;  // counter-clockwise seen from the positive side, from its smallest
  std::vector<Point2> ring;   // outer in the frame (to_frame), exact
  std::vector<std::vector<Point3>> holes;  // clockwise, each from its smallest point, sorted
  Exact area;                              // in frame units
  // the pieces: (object, face of the object lying on this side), in the object order.
  std::vector<std::pair<std::size_t, std::size_t>> pieces;
};

// A patch object as the exact verbs see it: its tessellation, which documents mention.
struct TessellatedPatches {
  std::string name;       // the object's name (the part of its pieces)
  std::string json_path;  // "objects[k]"
  std::size_t patches = 0;
  std::size_t triangles = 0;  // triangles of the tessellation, degenerate ones left out
  double tolerance = 0;       // every triangle lies within this distance of its patch (m)
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

// A Lambertian planar convex polygon (docs/area-sources.md): a recessed troffer, a light panel, a
// skylight. Its luminance is the same at every point and in every direction of its emitting side.
struct AreaLight {
  std::vector<Vec3d> vertices;  // as written: counter-clockwise seen from the emitting side
  double luminance;             // cd/m^2
  bool two_sided = false;       // emits on both sides (each with `luminance`)
  // the polygon, exact: a flat solid whose faces are its two sides (ConvexPolyhedron::
  // flat_polygon), and the index of the face on the emitting side (counter-clockwise
  // from outside, so its ring is the source seen from the lit half-space).
  std::shared_ptr<const ConvexPolyhedron> polygon;
  std::size_t front = 0;

  // the emitting area, m^2 (one side).
  double area() const;
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
  std::variant<PointLight, LinearLight, DirectionalLight, AreaLight> source;
  std::string json_path;
};

// returns the light's kind as files name it: "point", "linear", "area" or "directional".
const char* kind_name(const Light& light);

struct Scene {
  std::filesystem::path file;       // the scene file; relative paths resolve beside it
  std::vector<Material> materials;  // materials[0] is the default material
  std::vector<Object> objects;
  std::vector<MeshFace> mesh_faces;  // the faces that the pieces among objects make up
  std::vector<Light> lights;
  std::vector<TessellatedPatches> tessellated;  // the patch objects, in the object order
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
