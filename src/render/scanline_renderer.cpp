#include "penumbra/render/scanline_renderer.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/base/parallel.h"
#include "penumbra/base/progress.h"
#include "penumbra/base/vec3d.h"
#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/shadow/exact_umbra.h"
#include "penumbra/shadow/face_shadow.h"
#include "penumbra/shadow/shadow_map.h"

namespace penumbra::render {

using namespace vector_ops;

namespace {

using Segment = std::array<Vec3d, 2>;

// appends the edges of every ring of region, carried from the face frame to the world.
void append_boundary(const Region2& region, const FaceFrame& frame, std::vector<Segment>& out) {
  const auto append_ring = [&](const Ring2& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k)
      out.push_back({to_double(frame.to_world(ring[k])),
                     to_double(frame.to_world(ring[(k + 1) % ring.size()]))});
  };
  for (const Polygon2& polygon : region.polygons) {
    append_ring(polygon.outer);
    for (const Ring2& hole : polygon.holes) append_ring(hole);
  }
}

// returns the objects casting a shadow on the face in map, largest shadow first (the
// likeliest blocker of a point of the face is tested first).
std::vector<std::size_t> shadowing_objects(const FaceShadow& map) {
  std::vector<std::pair<double, std::size_t>> by_area;
  for (const OccluderShadow& shadow : map.occluders)
    by_area.emplace_back(CGAL::to_double(signed_area(shadow.polygon)), shadow.occluder);
  std::sort(by_area.begin(), by_area.end(), [](const auto& a, const auto& b) {
    return a.first > b.first || (a.first == b.first && a.second < b.second);
  });
  std::vector<std::size_t> objects;
  for (const auto& entry : by_area) objects.push_back(entry.second);
  return objects;
}

// appends the edges of every ring of a curved region (exact_umbra.h: conic arcs densified
// within 1e-6 m), carried from the face frame to the world.
void append_boundary(const std::vector<CurvedPolygon>& polygons, const FaceFrame& frame,
                     std::vector<Segment>& out) {
  const Vec3d o = to_double(frame.origin()), u = to_double(frame.u()), v = to_double(frame.v());
  const auto append_ring = [&](const CurvedRing& ring) {
    const auto& p = ring.points;
    for (std::size_t k = 0; k < p.size(); ++k) {
      const auto& a = p[k];
      const auto& b = p[(k + 1) % p.size()];
      out.push_back({o + a[0] * u + a[1] * v, o + b[0] * u + b[1] * v});
    }
  };
  for (const CurvedPolygon& polygon : polygons) {
    append_ring(polygon.outer);
    for (const CurvedRing& hole : polygon.holes) append_ring(hole);
  }
}

}  // namespace

struct ScanlineRenderer::Impl {
  std::vector<Material> materials;
  std::vector<std::size_t> object_material;  // per object: index into materials
  CameraFrame view;
  VisibilityMap visibility;
  illuminance::IlluminanceSolver solver;
  std::vector<std::size_t> first_face;           // per object: its first receiver slot
  std::vector<std::vector<Segment>> boundaries;  // per receiver slot: shadow boundaries
  // per receiver slot, per light: the only objects that can block the light from the face
  std::vector<std::vector<std::vector<std::size_t>>> occluders;
  std::vector<FacePlane> planes;  // per receiver slot
  bool parallel;
  bool joint_umbrae;

  Impl(const Scene& scene_in, const Camera& camera, bool parallel_in, bool joint_umbrae_in)
      : materials(scene_in.materials),
        view(camera),
        visibility(scanline_visibility(scene_in, camera, parallel_in)),
        solver(scene_in),
        parallel(parallel_in),
        joint_umbrae(joint_umbrae_in) {
    std::size_t slots = 0;
    for (const Object& object : scene_in.objects) {
      object_material.push_back(object.material);
      first_face.push_back(slots);
      slots += object.solid.faces().size();
    }
    boundaries.resize(slots);
    occluders.assign(slots, std::vector<std::vector<std::size_t>>(scene_in.lights.size()));
    for (std::size_t object = 0; object < scene_in.objects.size(); ++object)
      for (const Face& face : scene_in.objects[object].solid.faces())
        planes.push_back(face_plane(face));
    if (scene_in.lights.empty()) return;
    prepare_shadows(scene_in);
  }

  // stores, for one face slot and light, the face's shadow map: its occluders and the
  // edges of its shadow (and umbra) regions.
  void keep(std::size_t face_slot, std::size_t light, const Face& face, const FaceShadow& map) {
    // The objects whose shadow (penumbra or umbra) meets the face are the only ones
    // that can hide any part of the light from a point of it: the solver tests just
    // those (none on a wholly lit face). A face turned away keeps none: the solver's
    // outer-side test gives 0 before any occluder is looked at.
    occluders[face_slot][light] = shadowing_objects(map);
    if (map.faces_away) return;
    std::vector<Segment>& out = boundaries[face_slot];
    append_boundary(map.shadow, face.frame, out);
    if (map.curved)  // the exact umbra with joint parts: conic edges
      append_boundary(map.curved->umbra_polygons(), face.frame, out);
    else if (map.extended)
      append_boundary(map.umbra, face.frame, out);
  }

  // Nishita 1985 section 4.2.2: the shadow, umbra (and so penumbra) boundaries of each
  // light on each face the camera sees (a face no pixel shows is never shaded), from the
  // shadow maps of compute_shadows (shadow_map.h) with the sphere of lighting of `penumbra
  // shadows` (section 3.1: 1/256 of a 500 lx full scale). A face wholly beyond a light's
  // sphere gets no shadow map for it: its occluder list is the superset compute_shadows
  // gives (ShadowOptions::occluders_beyond_range), so the values stay exact, but it has no
  // boundaries for that light, so interpolation there may bridge the edge of a shadow worth
  // less than the threshold (docs/render.md).
  void prepare_shadows(const Scene& scene) {
    std::vector<char> seen(boundaries.size(), 0);
    for (std::size_t pixel = 0; pixel < visibility.objects.size(); ++pixel)
      if (visibility.objects[pixel] >= 0)
        seen[slot(visibility.objects[pixel], visibility.faces[pixel])] = 1;
    ShadowOptions options;
    options.parallel = parallel;
    options.joint_umbrae = joint_umbrae;
    options.occluders_beyond_range = true;
    options.unite_mesh_faces = false;  // the pieces are drawn
    options.receivers.emplace();
    for (std::size_t object = 0; object < scene.objects.size(); ++object)
      for (std::size_t face = 0; face < scene.objects[object].solid.faces().size(); ++face)
        if (seen[first_face[object] + face]) options.receivers->push_back({object, face});
    const ShadowResult shadows = compute_shadows(scene, options);
    for (const LightShadows& light : shadows.lights)
      for (std::size_t r = 0; r < shadows.receivers.size(); ++r) {
        const Receiver& receiver = shadows.receivers[r];
        const std::size_t face_slot = first_face[receiver.object] + receiver.face;
        const FaceShadow& map = light.faces[r];
        if (map.beyond_range)
          occluders[face_slot][light.light] = map.possible_occluders;
        else
          keep(face_slot, light.light, scene.objects[receiver.object].solid.faces()[receiver.face],
               map);
      }
  }

  std::size_t slot(long object, int face) const {
    return first_face[static_cast<std::size_t>(object)] + static_cast<std::size_t>(face);
  }

  std::optional<std::array<Vec3d, 2>> point(int i, int j) const {
    const std::size_t pixel = visibility.index(i, j);
    const long object = visibility.objects[pixel];
    if (object < 0) return std::nullopt;
    const FacePlane& plane = planes[slot(object, visibility.faces[pixel])];
    const Vec3d direction = view.direction(i + 0.5, j + 0.5);
    const double eye_distance = dot(plane.normal, view.eye()) + plane.offset;
    const double t = -eye_distance / dot(plane.normal, direction);
    Vec3d p = view.eye() + t * direction;
    // onto the plane, then lifted off it along the outward normal
    const double magnitude = std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
    p = p + (surface_lift * (1 + magnitude) - (dot(plane.normal, p) + plane.offset)) * plane.normal;
    return std::array<Vec3d, 2>{p, plane.normal};
  }

  double evaluate(int i, int j) const {
    const auto at = point(i, j);
    const std::size_t pixel = visibility.index(i, j);
    return solver
        .at((*at)[0], (*at)[1], occluders[slot(visibility.objects[pixel], visibility.faces[pixel])])
        .total;
  }

  // Nishita 1985 section 3.3: shades row j; returns (evaluations, crossings).
  std::array<std::size_t, 2> shade_row(int j, const RenderOptions& options,
                                       RenderedImage& image) const {
    const int interval = options.interval;
    const int width = visibility.width;
    const long* objects = &visibility.objects[visibility.index(0, j)];
    const int* faces = &visibility.faces[visibility.index(0, j)];
    const Vec3d row_direction = view.direction(width / 2.0, j + 0.5);
    const Vec3d plane_normal = cross(view.right(), row_direction);
    std::array<std::size_t, 2> counts{0, 0};
    std::vector<int> samples;
    std::vector<double> values;
    for (int first = 0; first < width;) {
      int last = first;
      while (last + 1 < width && objects[last + 1] == objects[first] &&
             faces[last + 1] == faces[first])
        ++last;
      if (objects[first] >= 0) {
        // the run [first, last] of one face: its ends and every K pixels ...
        samples.clear();
        for (int i = first; i <= last; i += interval) samples.push_back(i);
        samples.push_back(last);
        // ... and both sides of every shadow boundary crossing the scan line (4.2.2)
        for (const Segment& edge : boundaries[slot(objects[first], faces[first])]) {
          const double side_a = dot(plane_normal, edge[0] - view.eye());
          const double side_b = dot(plane_normal, edge[1] - view.eye());
          if ((side_a > 0 && side_b > 0) || (side_a < 0 && side_b < 0) || side_a == side_b)
            continue;
          const Vec3d crossing = edge[0] + (side_a / (side_a - side_b)) * (edge[1] - edge[0]);
          const auto projected = view.project(crossing);
          if (!projected) continue;
          const double x = (*projected)[0];
          if (x < first + 0.5 || x > last + 0.5) continue;
          ++counts[1];
          const int left = static_cast<int>(std::floor(x - 0.5));
          if (left >= first) samples.push_back(left);
          if (left + 1 <= last) samples.push_back(left + 1);
        }
        std::sort(samples.begin(), samples.end());
        samples.erase(std::unique(samples.begin(), samples.end()), samples.end());
        values.resize(samples.size());
        for (std::size_t k = 0; k < samples.size(); ++k) values[k] = evaluate(samples[k], j);
        counts[0] += samples.size();
        // linear interpolation between consecutive evaluations
        for (std::size_t k = 0; k + 1 < samples.size(); ++k) {
          const int a = samples[k], b = samples[k + 1];
          for (int i = a; i < b; ++i) {
            const double s = static_cast<double>(i - a) / (b - a);
            image.illuminance[image.index(i, j)] = (1 - s) * values[k] + s * values[k + 1];
          }
        }
        image.illuminance[image.index(samples.back(), j)] = values.back();
        const Material& material =
            materials[object_material[static_cast<std::size_t>(objects[first])]];
        for (int i = first; i <= last; ++i) {
          const std::size_t pixel = image.index(i, j);
          const double direct = image.illuminance[pixel];
          Colour indirect{0, 0, 0};
          if (options.indirect) {
            indirect = options.indirect(static_cast<std::size_t>(objects[first]),
                                        static_cast<std::size_t>(faces[first]), (*point(i, j))[0]);
            image.indirect[pixel] = photometric_value(indirect);
            image.illuminance[pixel] += image.indirect[pixel];
          }
          image.luminance[pixel] = material.reflectance * image.illuminance[pixel] / pi;
          for (int c = 0; c < 3; ++c)
            image.radiance[pixel][c] =
                material.reflectance * material.color[c] * (direct + indirect[c]) / pi;
        }
      }
      first = last + 1;
    }
    return counts;
  }
};

ScanlineRenderer::ScanlineRenderer(const Scene& scene, const Camera& camera, bool parallel,
                                   bool joint_umbrae)
    : impl_(std::make_unique<Impl>(scene, camera, parallel, joint_umbrae)) {}

ScanlineRenderer::~ScanlineRenderer() = default;

const VisibilityMap& ScanlineRenderer::visibility() const {
  return impl_->visibility;
}

const CameraFrame& ScanlineRenderer::view() const {
  return impl_->view;
}

std::optional<std::array<Vec3d, 2>> ScanlineRenderer::visible_point(int i, int j) const {
  return impl_->point(i, j);
}

RenderedImage ScanlineRenderer::render(const RenderOptions& options) const {
  if (options.interval < 1) throw std::invalid_argument("render: interval must be at least 1");
  RenderedImage image;
  image.width = impl_->visibility.width;
  image.height = impl_->visibility.height;
  image.visibility = impl_->visibility;
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  image.illuminance.assign(pixels, 0);
  image.indirect.assign(pixels, 0);
  image.luminance.assign(pixels, 0);
  image.radiance.assign(pixels, Colour{0, 0, 0});
  std::atomic<std::size_t> evaluations{0}, crossings{0};
  // Long renders show progress per scan line on a terminal (quiet otherwise).
  Progress progress("shading scan lines", static_cast<std::size_t>(image.height));
  const auto rows = [&](int first, int last) {
    for (int j = first; j < last; ++j) {
      const auto counts = impl_->shade_row(j, options, image);
      evaluations += counts[0];
      crossings += counts[1];
      progress.advance();
    }
  };
  for_each_range(static_cast<std::size_t>(image.height), options.parallel && impl_->parallel,
                 [&](std::size_t first, std::size_t last) {
                   rows(static_cast<int>(first), static_cast<int>(last));
                 });
  image.evaluations = evaluations;
  image.boundary_crossings = crossings;
  return image;
}

RenderedImage render_scanline(const Scene& scene, const Camera& camera,
                              const RenderOptions& options) {
  return ScanlineRenderer(scene, camera, options.parallel).render(options);
}

}  // namespace penumbra::render
