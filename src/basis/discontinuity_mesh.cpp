#include "penumbra/basis/discontinuity_mesh.h"

#include "penumbra/base/input_error.h"
#include "penumbra/shadow/shadow_map.h"

namespace penumbra::basis {

namespace {

// appends region's rings (outer boundaries and holes), carried to the world, as one region.
void add_region(const Region2& region, const FaceFrame& frame, FaceBreaks& out) {
  if (region.polygons.empty()) return;
  auto& rings = out.regions.emplace_back();
  const auto add_ring = [&](const Ring2& ring) {
    auto& points = rings.emplace_back();
    for (const Point2& p : ring) points.push_back(to_double(frame.to_world(p)));
  };
  for (const Polygon2& polygon : region.polygons) {
    add_ring(polygon.outer);
    for (const Ring2& hole : polygon.holes) add_ring(hole);
  }
}

}  // namespace

MeshBreaks shadow_breaks(const Scene& scene, bool parallel) {
  MeshBreaks breaks;
  for (const Light& light : scene.lights) {
    ShadowOptions options;
    options.light = light.name;
    options.parallel = parallel;
    options.unite_mesh_faces = false;  // the mesh's patches are the pieces' faces
    ShadowResult shadows;
    try {
      shadows = compute_shadows(scene, options);
    } catch (const InputError&) {
      continue;
    }
    for (const LightShadows& lit : shadows.lights)
      for (std::size_t r = 0; r < shadows.receivers.size(); ++r) {
        const FaceShadow& map = lit.faces[r];
        if (map.faces_away || map.beyond_range) continue;
        const Receiver& receiver = shadows.receivers[r];
        const Face& face = scene.objects[receiver.object].solid.faces()[receiver.face];
        FaceBreaks& out = breaks[{static_cast<std::uint32_t>(receiver.object),
                                  static_cast<std::uint32_t>(receiver.face)}];
        add_region(map.shadow, face.frame, out);
        if (map.extended) add_region(map.umbra, face.frame, out);
      }
  }
  return breaks;
}

}  // namespace penumbra::basis
