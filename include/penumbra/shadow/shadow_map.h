#pragma once
// Exact shadows of a scene under its point, directional, linear and area sources (Nishita
// 1985 sections 3.1-3.2 and 4.1): for every light and every face, the shadow, umbra,
// penumbra and lit polygon sets and each occluder's shadow polygon (and, for linear
// sources, its umbra and loops), after culling with the sphere of lighting (point
// sources) and a broad phase. Results are in canonical order (objects by name,
// faces by their canonical index), independent of the input order and of threads.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/scene/scene.h"
#include "penumbra/shadow/face_shadow.h"
#include "penumbra/visibility/broad_phase.h"

namespace penumbra {

struct ShadowOptions {
  std::optional<std::string> light;  // only the light of this name; all lights otherwise
  // threshold illuminance of the sphere of lighting as a fraction of the display's
  // full scale (Nishita 1985 section 3.1: 1/256 for an 8-bit display), the same
  // partial sphere `penumbra lid info` reports; 0 disables range culling.
  double range_fraction = 1.0 / 256;
  double full_scale_lux = 500;      // the display's full scale (photometry/figures.h)
  std::optional<double> range_lux;  // an absolute threshold in lux instead of the fraction
  bool broad_phase = true;          // false: test every (occluder, face) pair
  bool parallel = true;             // TBB across faces
  // only these receiving faces (object index, face index), in any order; every face of every
  // object when empty. The results are those of the full run for the faces named.
  std::optional<std::vector<Receiver>> receivers;
  // for a face wholly beyond a light's sphere of lighting (not computed), list in
  // FaceShadow::possible_occluders every object that may shadow it: the broad phase's
  // candidates less those a plane certainly separates from conv(face, source). A superset,
  // so illuminance computed with it stays exact (the renderer's need).
  bool occluders_beyond_range = false;
  // the convex pieces of each mesh face (scene.h, MeshFace) united into the face, as
  // documents report it (docs/shadows.md, "Faces of real models"); false keeps the pieces
  // (the renderer draws them).
  bool unite_mesh_faces = true;
  // linear sources: on faces where occluders' shadows overlap, compute the exact umbra with
  // its joint parts and conic edges (FaceShadow::curved, docs/linear-shadows.md "Joint
  // umbrae"); joint_occlusion then says whether it has joint parts. Faces of mesh parts,
  // whose pieces are united, keep the straight sets.
  bool joint_umbrae = false;
  // false: FaceShadow::lit is left empty for point and directional sources, for callers
  // that use the shadows alone (sun-hours overlays them): the lit part of a face under
  // touching shadows costs a second Boolean operation.
  bool lit_parts = true;
};

struct ShadowStats {
  std::size_t faces = 0;            // receiving faces
  std::size_t faces_away = 0;       // faces wholly unlit because they face away
  std::size_t beyond_range = 0;     // faces outside the sphere of lighting
  std::size_t pairs_possible = 0;   // faces x (objects - 1)
  std::size_t pairs_tested = 0;     // (occluder, face) pairs given to shadow_polygon
  std::size_t pairs_shadowing = 0;  // pairs whose shadow has area
  std::optional<double> radius;     // sphere of lighting, metres
  double seconds = 0;               // wall time for this light
};

struct LightShadows {
  std::size_t light;  // index into Scene::lights
  ShadowStats stats;
  std::vector<FaceShadow> faces;  // parallel to ShadowResult::receivers; occluder = object index
};

struct ShadowResult {
  std::vector<Receiver> receivers;  // object (index into Scene::objects) and face, canonical order
  // with ShadowOptions::unite_mesh_faces, per receiver the MeshFace it stands for (the
  // receiver is then its first piece's face), kNoMeshFace for a face of an object.
  std::vector<std::size_t> mesh_faces;
  std::vector<LightShadows> lights;
  std::vector<std::string> warnings;  // problems worth reporting that did not stop the work
};

// What documents say of a receiving face: who owns it, its number and its exact geometry.
// For a face of a mesh part, the face (possibly non-convex with holes) its pieces make up.
struct ReceivingFace {
  const std::string& object;  // the object's name, or the mesh part's
  std::size_t face;
  const Plane3& plane;
  const FaceFrame& frame;
  const std::vector<Point3>& outer;               // counter-clockwise seen from outside
  const std::vector<Point2>& ring;                // outer in the frame, exact
  const std::vector<std::vector<Point3>>* holes;  // clockwise; nullptr for an object's face
  const Exact& area;                              // in frame units
};

// returns receiver r of result as documents name and draw it.
ReceivingFace receiving_face(const Scene& scene, const ShadowResult& result, std::size_t r);

// computes the shadow maps of every face of scene (or of options.receivers) for its
// lights. Throws InputError when options.light names no light, when options.receivers
// names a face that does not exist, or when a linear source touches an object that
// shadows a face (docs/linear-shadows.md).
ShadowResult compute_shadows(const Scene& scene, const ShadowOptions& options = {});

// every receiving face of the objects (indices into scene.objects), as
// ShadowOptions::receivers (`--receivers`, scene/object_selection.h); the inner sides of closed
// meshes' pieces receive nothing and are left out.
std::vector<Receiver> faces_of_objects(const Scene& scene, const std::vector<std::size_t>& objects);

}  // namespace penumbra
