#include "penumbra/render/scanline_renderer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/parallel.h"
#include "penumbra/input_error.h"
#include "penumbra/io/progress.h"
#include "penumbra/shadow/face_shadow.h"
#include "penumbra/shadow/linear_face_shadow.h"
#include "penumbra/shadow/shadow_map.h"
#include "penumbra/shadow/shadow_polygon.h"
#include "penumbra/visibility/broad_phase.h"
#include "penumbra/visibility/lighting_sphere.h"
#include "vector3.h"

namespace penumbra::render {

using namespace detail;

namespace {

using Segment = std::array<V3, 2>;

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

// === A cull for the objects that can shadow a face beyond a light's sphere of lighting

using Interval = CGAL::Interval_nt<false>;
using IntervalPoint = std::array<Interval, 3>;

IntervalPoint interval_point(const Point3& p) {
  const auto& approx = p.approx();
  return {approx.x(), approx.y(), approx.z()};
}

Interval dot_from(const IntervalPoint& normal, const IntervalPoint& x,
                  const IntervalPoint& origin) {
  return normal[0] * (x[0] - origin[0]) + normal[1] * (x[1] - origin[1]) +
         normal[2] * (x[2] - origin[2]);
}

IntervalPoint cross_from(const IntervalPoint& origin, const IntervalPoint& to_a,
                         const IntervalPoint& to_b) {
  const Interval a[3] = {to_a[0] - origin[0], to_a[1] - origin[1], to_a[2] - origin[2]};
  const Interval b[3] = {to_b[0] - origin[0], to_b[1] - origin[1], to_b[2] - origin[2]};
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The closed region W = conv(face, source) swept by the segments from the face to a tube
// (or a point light: both ends the same), with the planes that certainly support it (W on their
// closed negative side), for a separating-plane test against occluders in interval arithmetic.
class SweptRegion {
 public:
  SweptRegion(const Face& face, const Point3& q1, const Point3& q2) {
    for (const Point3& v : face.vertices) points_.push_back(interval_point(v));
    const std::size_t n = points_.size();
    points_.push_back(interval_point(q1));
    points_.push_back(interval_point(q2));
    const IntervalPoint& a = points_[n];
    const IntervalPoint& b = points_[n + 1];
    // Candidate planes: through the tube and a face vertex; through a face edge and an end
    // of the tube; the face's own plane. Each is kept, oriented, if every point of W is
    // certainly on one closed side of it.
    for (std::size_t k = 0; k < n; ++k) {
      const IntervalPoint& v = points_[k];
      const IntervalPoint& w = points_[(k + 1) % n];
      add(v, cross_from(a, b, v));
      add(v, cross_from(v, w, a));
      add(v, cross_from(v, w, b));
    }
    if (n >= 3) add(points_[0], cross_from(points_[0], points_[1], points_[2]));
  }

  // returns true when a plane certainly separates the occluder's interior from W: the
  // occluder strictly on the positive side of a supporting plane of W, or W strictly on the
  // outer side of one of the occluder's faces. Then no segment from the face to the tube
  // meets the occluder: it casts no shadow on the face.
  bool separated_from(const ConvexPolyhedron& solid) const {
    const CGAL::Protect_FPU_rounding<true> upward;
    for (const Face& face : solid.faces()) {
      const auto& h = face.plane.approx();
      if (std::all_of(points_.begin(), points_.end(), [&](const IntervalPoint& x) {
            return (h.a() * x[0] + h.b() * x[1] + h.c() * x[2] + h.d()).inf() > 0;
          }))
        return true;
    }
    std::vector<IntervalPoint> vertices;
    for (const Point3& v : solid.vertices()) vertices.push_back(interval_point(v));
    for (const auto& [origin, normal] : planes_)
      if (std::all_of(vertices.begin(), vertices.end(), [&](const IntervalPoint& x) {
            return dot_from(normal, x, origin).inf() > 0;
          }))
        return true;
    return false;
  }

 private:
  void add(const IntervalPoint& origin, const IntervalPoint& normal) {
    const CGAL::Protect_FPU_rounding<true> upward;
    if (std::all_of(normal.begin(), normal.end(),
                    [](const Interval& c) { return c.inf() == 0 && c.sup() == 0; }))
      return;
    bool non_positive = true, non_negative = true;
    for (const IntervalPoint& x : points_) {
      const Interval value = dot_from(normal, x, origin);
      non_positive = non_positive && value.sup() <= 0;
      non_negative = non_negative && value.inf() >= 0;
    }
    if (non_positive)
      planes_.push_back({origin, normal});
    else if (non_negative)
      planes_.push_back({origin, {-normal[0], -normal[1], -normal[2]}});
  }

  std::vector<IntervalPoint> points_;
  std::vector<std::pair<IntervalPoint, IntervalPoint>> planes_;
};

}  // namespace

struct ScanlineRenderer::Impl {
  std::vector<Material> materials;
  std::vector<std::size_t> object_material;  // per object: index into materials
  ViewFrame view;
  VisibilityMap visibility;
  illuminance::IlluminanceSolver solver;
  std::vector<std::size_t> first_face;           // per object: its first receiver slot
  std::vector<std::vector<Segment>> boundaries;  // per receiver slot: shadow boundaries
  // per receiver slot, per light: the only objects that can block the light from the face
  std::vector<std::vector<std::vector<std::size_t>>> occluders;
  std::vector<FacePlane> planes;  // per receiver slot
  bool parallel;

  Impl(const Scene& scene_in, const Camera& camera, bool parallel_in)
      : materials(scene_in.materials),
        view(camera),
        visibility(scanline_visibility(scene_in, camera, parallel_in)),
        solver(scene_in),
        parallel(parallel_in) {
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
    if (map.linear) append_boundary(map.umbra, face.frame, out);
  }

  // Nishita 1985 section 4.2.2: the shadow, umbra (and so penumbra) boundaries of each
  // light on each face the camera sees (a face no pixel shows is never shaded). The maps
  // are those of compute_shadows (shadow_map.h), built from the same steps (broad phase,
  // shadow volumes, shadow polygons, exact union) face by face; only the occluders and
  // region edges are kept.
  //
  // Section 3.1, the sphere of lighting of a point or linear source (the default of
  // `penumbra shadows`: 1/256 of a 500 lx full scale): a face wholly beyond it gets less
  // than that threshold from the light everywhere. Such a face gets no shadow map for the
  // light: its occluder list is the broad phase's candidates (every object whose box meets
  // the box of conv(face, source)) less those a plane certainly separates from
  // conv(face, source) (SweptRegion): a superset of the objects shadowing the face, so the
  // values stay exact. It has no boundaries for that light, so interpolation there may
  // bridge the edge of a shadow worth less than the threshold (docs/render.md).
  void prepare_shadows(const Scene& scene) {
    std::vector<char> seen(boundaries.size(), 0);
    for (std::size_t pixel = 0; pixel < visibility.objects.size(); ++pixel)
      if (visibility.objects[pixel] >= 0)
        seen[slot(visibility.objects[pixel], visibility.faces[pixel])] = 1;
    std::vector<Receiver> receivers;
    for (std::size_t object = 0; object < scene.objects.size(); ++object)
      for (std::size_t face = 0; face < scene.objects[object].solid.faces().size(); ++face)
        if (seen[first_face[object] + face]) receivers.push_back({object, face});
    std::vector<const ConvexPolyhedron*> solids;
    for (const Object& object : scene.objects) solids.push_back(&object.solid);
    const auto face_of = [&](const Receiver& receiver) -> const Face& {
      return scene.objects[receiver.object].solid.faces()[receiver.face];
    };
    const auto slot_of = [&](const Receiver& receiver) {
      return first_face[receiver.object] + receiver.face;
    };
    const auto for_each = [&](std::size_t count, const auto& work) {
      for_each_index(count, parallel, work);
    };
    const ShadowOptions defaults;  // the sphere of lighting of `penumbra shadows`
    const double threshold = defaults.range_fraction * defaults.full_scale_lux;
    const auto keep_far = [&](std::size_t light, const std::vector<Receiver>& far,
                              const std::vector<std::vector<std::size_t>>& candidates,
                              const Point3& q1, const Point3& q2) {
      for_each(far.size(), [&](std::size_t r) {
        const SweptRegion swept(face_of(far[r]), q1, q2);
        std::vector<std::size_t>& list = occluders[slot_of(far[r])][light];
        for (std::size_t o : candidates[r])
          if (!swept.separated_from(*solids[o])) list.push_back(o);
      });
    };
    for (std::size_t light = 0; light < scene.lights.size(); ++light) {
      const Light& source = scene.lights[light];
      if (const auto* tube = std::get_if<LinearLight>(&source.source)) {
        // End points in lexicographic order, as compute_shadows takes them.
        Point3 q1 = to_exact(tube->start), q2 = to_exact(tube->end);
        if (CGAL::compare_xyz(q2, q1) == CGAL::SMALLER) std::swap(q1, q2);
        const LightingSphere sphere =
            LightingSphere::around_segment(q1, q2, tube->candela_per_metre, threshold);
        std::vector<Receiver> near, far;
        for (const Receiver& receiver : receivers)
          (sphere.beyond(face_of(receiver)) ? far : near).push_back(receiver);
        keep_far(light, far, candidate_occluders(solids, far, q1, q2), q1, q2);
        const auto candidates = candidate_occluders(solids, near, q1, q2);
        for_each(near.size(), [&](std::size_t r) {
          std::vector<Occluder> list;
          for (std::size_t o : candidates[r]) list.push_back({o, solids[o]});
          const Face& face = face_of(near[r]);
          try {
            keep(slot_of(near[r]), light, face, linear_face_shadow(face, q1, q2, std::move(list)));
          } catch (const std::domain_error&) {
            throw InputError(scene.file.string(), source.json_path,
                             "the linear source '" + source.name +
                                 "' touches or passes through an object that shadows face " +
                                 std::to_string(near[r].face) + " of '" +
                                 scene.objects[near[r].object].name +
                                 "': not supported (docs/linear-shadows.md)");
          }
        });
        continue;
      }
      const LightPosition position =
          std::holds_alternative<PointLight>(source.source)
              ? LightPosition::at(to_exact(std::get<PointLight>(source.source).position))
              : LightPosition::toward(
                    to_exact_vector(std::get<DirectionalLight>(source.source).direction));
      // Faces turned away are wholly unlit (no occluders, no boundaries); the sun has no
      // sphere of lighting.
      std::optional<LightingSphere> sphere;
      if (const auto* lamp = std::get_if<PointLight>(&source.source))
        sphere = LightingSphere::absolute(position.point(), lamp->distribution->max_intensity(),
                                          threshold);
      std::vector<Receiver> active, far;
      for (const Receiver& receiver : receivers)
        if (!faces_away(face_of(receiver), position))
          (sphere && sphere->beyond(face_of(receiver)) ? far : active).push_back(receiver);
      if (!far.empty())
        keep_far(light, far, candidate_occluders(solids, far, position), position.point(),
                 position.point());
      const auto candidates = candidate_occluders(solids, active, position);
      // The shadow volume of each occluder depends only on the light: build it once.
      std::vector<char> needed(scene.objects.size(), 0);
      for (const auto& list : candidates)
        for (std::size_t o : list) needed[o] = 1;
      std::vector<std::vector<Plane3>> volumes(scene.objects.size());
      for_each(scene.objects.size(), [&](std::size_t o) {
        if (needed[o]) volumes[o] = shadow_volume(*solids[o], position);
      });
      for_each(active.size(), [&](std::size_t r) {
        const Face& face = face_of(active[r]);
        std::vector<OccluderShadow> shadows;
        for (std::size_t o : candidates[r])
          if (auto polygon = shadow_polygon(*solids[o], volumes[o], face))
            shadows.push_back({o, std::move(*polygon)});
        keep(slot_of(active[r]), light, face, unite_shadows(face, std::move(shadows)));
      });
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
    const V3 direction = view.direction(i + 0.5, j + 0.5);
    const double eye_distance = dot(plane.normal, view.eye()) + plane.offset;
    const double t = -eye_distance / dot(plane.normal, direction);
    V3 p = view.eye() + t * direction;
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
  std::array<std::size_t, 2> shade_row(int j, int interval, RenderedImage& image) const {
    const int width = visibility.width;
    const long* objects = &visibility.objects[visibility.index(0, j)];
    const int* faces = &visibility.faces[visibility.index(0, j)];
    const V3 row_direction = view.direction(width / 2.0, j + 0.5);
    const V3 plane_normal = cross(view.right(), row_direction);
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
          const V3 crossing = edge[0] + (side_a / (side_a - side_b)) * (edge[1] - edge[0]);
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
          const double luminance = material.reflectance * image.illuminance[pixel] / M_PI;
          image.luminance[pixel] = luminance;
          for (int c = 0; c < 3; ++c) image.radiance[pixel][c] = luminance * material.color[c];
        }
      }
      first = last + 1;
    }
    return counts;
  }
};

ScanlineRenderer::ScanlineRenderer(const Scene& scene, const Camera& camera, bool parallel)
    : impl_(std::make_unique<Impl>(scene, camera, parallel)) {}

ScanlineRenderer::~ScanlineRenderer() = default;

const VisibilityMap& ScanlineRenderer::visibility() const {
  return impl_->visibility;
}

const ViewFrame& ScanlineRenderer::view() const {
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
  image.luminance.assign(pixels, 0);
  image.radiance.assign(pixels, Colour{0, 0, 0});
  std::atomic<std::size_t> evaluations{0}, crossings{0};
  // Long renders show progress per scan line on a terminal (quiet otherwise).
  io::Progress progress("shading scan lines", static_cast<std::size_t>(image.height));
  const auto rows = [&](int first, int last) {
    for (int j = first; j < last; ++j) {
      const auto counts = impl_->shade_row(j, options.interval, image);
      evaluations += counts[0];
      crossings += counts[1];
      progress.advance();
    }
  };
  if (options.parallel && impl_->parallel)
    tbb::parallel_for(
        tbb::blocked_range<int>(0, image.height),
        [&](const tbb::blocked_range<int>& range) { rows(range.begin(), range.end()); });
  else
    rows(0, image.height);
  image.evaluations = evaluations;
  image.boundary_crossings = crossings;
  return image;
}

RenderedImage render_scanline(const Scene& scene, const Camera& camera,
                              const RenderOptions& options) {
  return ScanlineRenderer(scene, camera, options.parallel).render(options);
}

}  // namespace penumbra::render
