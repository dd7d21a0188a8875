#include "penumbra/raytrace/embree_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "penumbra/base/vec3d.h"
#include "penumbra/raytrace/bezier_intersection.h"
#include "penumbra/scene/scene.h"

namespace penumbra::raytrace {

using namespace vector_ops;
namespace {

// A face plane in doubles: unit outward normal and offset, n . x + offset = 0.
struct FacePlane {
  Vec3d normal;
  double offset;
};

FacePlane double_plane(const Plane3& plane) {
  const Vec3d n{CGAL::to_double(plane.a()), CGAL::to_double(plane.b()), CGAL::to_double(plane.c())};
  const double norm = length(n);
  return {(1 / norm) * n, CGAL::to_double(plane.d()) / norm};
}

float to_float(double value) {
  return static_cast<float>(value);
}

RTCRayHit embree_ray(const Ray& ray) {
  RTCRayHit query{};
  query.ray.org_x = to_float(ray.origin[0]);
  query.ray.org_y = to_float(ray.origin[1]);
  query.ray.org_z = to_float(ray.origin[2]);
  query.ray.dir_x = to_float(ray.direction[0]);
  query.ray.dir_y = to_float(ray.direction[1]);
  query.ray.dir_z = to_float(ray.direction[2]);
  query.ray.tnear = to_float(ray.t_near);
  query.ray.tfar =
      std::isinf(ray.t_far) ? std::numeric_limits<float>::infinity() : to_float(ray.t_far);
  query.ray.mask = 0xFFFFFFFFu;
  query.ray.flags = 0;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return query;
}

// Embree's intersection context with the ray in double precision, so that the patch
// callbacks intersect the ray as the caller gave it; and the double-precision patch hit the
// callbacks accepted last (the nearest so far).
struct PatchContext {
  RTCIntersectContext context;
  const Ray* ray;
  PatchHit patch_hit{};
  explicit PatchContext(const Ray* r) : ray(r) { rtcInitIntersectContext(&context); }
};

// the ray of a callback in double precision: the caller's, cut to Embree's current segment.
Ray callback_ray(const PatchContext& context, RTCRayN* rays, unsigned n) {
  Ray ray = *context.ray;
  ray.t_far = std::min(ray.t_far, static_cast<double>(RTCRayN_tfar(rays, n, 0)));
  return ray;
}

}  // namespace

struct EmbreeScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  unsigned triangle_geometry = RTC_INVALID_GEOMETRY_ID;
  unsigned sphere_geometry = RTC_INVALID_GEOMETRY_ID;
  // triangle primitive -> (object, face); sphere primitive -> object.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> triangle_faces;
  std::vector<std::uint32_t> sphere_objects;
  unsigned patch_geometry = RTC_INVALID_GEOMETRY_ID;
  std::vector<BezierPatch> patches;            // every patch of every patch object
  std::vector<std::uint32_t> patch_objects;    // per patch: the object hits report
  std::vector<PatchPiece> pieces;              // user primitive -> piece of patches[piece.patch]
  std::vector<std::vector<FacePlane>> planes;  // per object, per face
  std::vector<bool> flat;                      // per object: a two-sided polygon
  std::vector<BoundingSphere> bounds;
  double scale = 1;

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  void check(const char* step) const {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
      throw std::runtime_error(std::string("Embree failed while ") + step + " (error " +
                               std::to_string(static_cast<int>(error)) + ")");
  }

  // the bounds of a piece of a patch: its control points' box, rounded outward to floats.
  static void piece_bounds(const RTCBoundsFunctionArguments* args) {
    const auto& impl = *static_cast<const Impl*>(args->geometryUserPtr);
    const PatchPiece& piece = impl.pieces[args->primID];
    const Vec3d& low = piece.low;
    const Vec3d& high = piece.high;
    const float down = -std::numeric_limits<float>::infinity();
    const float up = std::numeric_limits<float>::infinity();
    RTCBounds& box = *args->bounds_o;
    box.lower_x = std::nextafter(to_float(low[0]), down);
    box.lower_y = std::nextafter(to_float(low[1]), down);
    box.lower_z = std::nextafter(to_float(low[2]), down);
    box.upper_x = std::nextafter(to_float(high[0]), up);
    box.upper_y = std::nextafter(to_float(high[1]), up);
    box.upper_z = std::nextafter(to_float(high[2]), up);
  }

  std::optional<PatchHit> piece_hit(unsigned piece, const Ray& ray) const {
    const PatchPiece& p = pieces[piece];
    return intersect_piece(patches[p.patch], p, ray);
  }

  static void intersect_piece_callback(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    const auto& impl = *static_cast<const Impl*>(args->geometryUserPtr);
    auto& context = *reinterpret_cast<PatchContext*>(args->context);
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    const auto hit = impl.piece_hit(args->primID, callback_ray(context, rays, args->N));
    if (!hit) return;
    context.patch_hit = *hit;
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
    const Vec3d normal = impl.patches[impl.pieces[args->primID].patch].normal(hit->u, hit->v);
    RTCRayN_tfar(rays, args->N, 0) = to_float(hit->t);
    RTCHitN_Ng_x(hits, args->N, 0) = to_float(normal[0]);
    RTCHitN_Ng_y(hits, args->N, 0) = to_float(normal[1]);
    RTCHitN_Ng_z(hits, args->N, 0) = to_float(normal[2]);
    RTCHitN_u(hits, args->N, 0) = to_float(hit->u);
    RTCHitN_v(hits, args->N, 0) = to_float(hit->v);
    RTCHitN_primID(hits, args->N, 0) = args->primID;
    RTCHitN_geomID(hits, args->N, 0) = args->geomID;
    RTCHitN_instID(hits, args->N, 0, 0) = args->context->instID[0];
  }

  static void occluded_piece_callback(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    const auto& impl = *static_cast<const Impl*>(args->geometryUserPtr);
    const auto& context = *reinterpret_cast<const PatchContext*>(args->context);
    if (impl.piece_hit(args->primID, callback_ray(context, args->ray, args->N)))
      RTCRayN_tfar(args->ray, args->N, 0) = -std::numeric_limits<float>::infinity();
  }

  // refines Embree's single-precision hit against the exact surface in double precision.
  Hit refine(const Ray& ray, const RTCRayHit& query, const PatchHit& patch_hit) const {
    Hit hit{};
    double t = query.ray.tfar;
    if (query.hit.geomID == patch_geometry) {
      // The callback intersected the patch in double precision already.
      const std::size_t patch = pieces[query.hit.primID].patch;
      hit.object = patch_objects[patch];
      hit.face = -1;
      hit.distance = patch_hit.t;
      hit.point = ray.origin + patch_hit.t * ray.direction;
      hit.normal = patches[patch].normal(patch_hit.u, patch_hit.v);
      return hit;
    }
    if (query.hit.geomID == sphere_geometry) {
      hit.object = sphere_objects[query.hit.primID];
      hit.face = -1;
      const BoundingSphere& sphere = bounds[hit.object];
      // Solve |o + t d - c|^2 = r^2 (|d| = 1) in the stable form and keep the root Embree
      // found (it reports the far root for rays starting inside).
      const Vec3d oc = ray.origin - sphere.center;
      const double b = dot(ray.direction, oc);
      const double c = dot(oc, oc) - sphere.radius * sphere.radius;
      const double discriminant = b * b - c;
      if (discriminant >= 0) {
        const double q = -b - std::copysign(std::sqrt(discriminant), b);
        const double t1 = q;
        const double t2 = q != 0 ? c / q : q;
        t = std::abs(t1 - t) < std::abs(t2 - t) ? t1 : t2;
      }
      hit.distance = t;
      hit.point = ray.origin + t * ray.direction;
      hit.normal = normalized(hit.point - sphere.center);
      return hit;
    }
    const auto [object, face] = triangle_faces[query.hit.primID];
    hit.object = object;
    const FacePlane* plane = &planes[object][face];
    int face_index = static_cast<int>(face);
    // A two-sided polygon entered once: report the face whose outward side meets the ray.
    if (flat[object] && dot(ray.direction, plane->normal) > 0) {
      face_index = 1 - face_index;
      plane = &planes[object][static_cast<std::size_t>(face_index)];
    }
    hit.face = face_index;
    const double along = dot(plane->normal, ray.direction);
    if (along != 0) t = -(dot(plane->normal, ray.origin) + plane->offset) / along;
    hit.distance = t;
    hit.point = ray.origin + t * ray.direction;
    hit.normal = plane->normal;
    return hit;
  }
};

EmbreeScene::EmbreeScene(const Scene& scene, PatchSurfaces surfaces)
    : impl_(std::make_unique<Impl>()) {
  Impl& impl = *impl_;
  impl.device = rtcNewDevice(nullptr);
  if (!impl.device) throw std::runtime_error("cannot create an Embree device");
  impl.scene = rtcNewScene(impl.device);
  // Robust traversal: rays through shared triangle edges (box corners, checker tiles) must
  // not slip between triangles.
  rtcSetSceneFlags(impl.scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl.scene, RTC_BUILD_QUALITY_HIGH);

  std::vector<float> vertices;
  std::vector<std::uint32_t> indices;
  std::vector<float> spheres;
  Vec3d low{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity()};
  Vec3d high = -low;
  std::vector<const void*> patch_sets;  // the patch lists entered (pieces of one part share one)
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const Object& object = scene.objects[o];
    std::vector<FacePlane> planes;
    for (const Face& face : object.solid.faces()) planes.push_back(double_plane(face.plane));
    impl.planes.push_back(planes);
    impl.flat.push_back(object.solid.is_flat());
    const CGAL::Bbox_3 box = object.solid.bbox();
    if (object.sphere) {
      const Sphere& sphere = *object.sphere;
      impl.bounds.push_back({sphere.center, sphere.radius});
      impl.sphere_objects.push_back(static_cast<std::uint32_t>(o));
      for (double value : sphere.center) spheres.push_back(to_float(value));
      spheres.push_back(to_float(sphere.radius));
      for (int k = 0; k < 3; ++k) {
        low[k] = std::min(low[k], sphere.center[k] - sphere.radius);
        high[k] = std::max(high[k], sphere.center[k] + sphere.radius);
      }
      continue;
    }
    const Vec3d box_low{box.xmin(), box.ymin(), box.zmin()};
    const Vec3d box_high{box.xmax(), box.ymax(), box.zmax()};
    impl.bounds.push_back({0.5 * (box_low + box_high), 0.5 * length(box_high - box_low)});
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], box_low[k]);
      high[k] = std::max(high[k], box_high[k]);
    }
    if (object.patches && surfaces == PatchSurfaces::exact) {
      // The pieces of a patch object's tessellation all carry its patches: enter them once,
      // reported as the first piece.
      if (std::find(patch_sets.begin(), patch_sets.end(), object.patches.get()) != patch_sets.end())
        continue;
      patch_sets.push_back(object.patches.get());
      for (const BezierPatch& patch : *object.patches) {
        const std::vector<PatchPiece> pieces = flat_pieces(patch, impl.patches.size());
        impl.pieces.insert(impl.pieces.end(), pieces.begin(), pieces.end());
        impl.patches.push_back(patch);
        impl.patch_objects.push_back(static_cast<std::uint32_t>(o));
        const auto [patch_low, patch_high] = patch.bounds();
        for (int k = 0; k < 3; ++k) {
          low[k] = std::min(low[k], patch_low[k]);
          high[k] = std::max(high[k], patch_high[k]);
        }
      }
      continue;
    }
    const std::size_t face_count = object.solid.is_flat() ? 1 : object.solid.faces().size();
    for (std::size_t f = 0; f < face_count; ++f) {
      const Face& face = object.solid.faces()[f];
      // Faces are convex and counter-clockwise from outside: a fan from the first vertex.
      const auto first = static_cast<std::uint32_t>(vertices.size() / 3);
      for (const Point3& p : face.vertices)
        for (double value : to_double(p)) vertices.push_back(to_float(value));
      for (std::uint32_t k = 1; k + 1 < face.vertices.size(); ++k) {
        indices.insert(indices.end(), {first, first + k, first + k + 1});
        impl.triangle_faces.emplace_back(static_cast<std::uint32_t>(o),
                                         static_cast<std::uint32_t>(f));
      }
    }
  }
  if (!scene.objects.empty()) impl.scale = std::max(length(high - low), 1e-3);

  if (!indices.empty()) {
    RTCGeometry geometry = rtcNewGeometry(impl.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertex_buffer = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), vertices.size() / 3));
    std::copy(vertices.begin(), vertices.end(), vertex_buffer);
    auto* index_buffer = static_cast<std::uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(std::uint32_t), indices.size() / 3));
    std::copy(indices.begin(), indices.end(), index_buffer);
    rtcCommitGeometry(geometry);
    impl.triangle_geometry = rtcAttachGeometry(impl.scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  if (!spheres.empty()) {
    RTCGeometry geometry = rtcNewGeometry(impl.device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* buffer = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT4, 4 * sizeof(float),
                                                               spheres.size() / 4));
    std::copy(spheres.begin(), spheres.end(), buffer);
    rtcCommitGeometry(geometry);
    impl.sphere_geometry = rtcAttachGeometry(impl.scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  if (!impl.pieces.empty()) {
    RTCGeometry geometry = rtcNewGeometry(impl.device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(impl.pieces.size()));
    rtcSetGeometryUserData(geometry, &impl);
    rtcSetGeometryBoundsFunction(geometry, &Impl::piece_bounds, &impl);
    rtcSetGeometryIntersectFunction(geometry, &Impl::intersect_piece_callback);
    rtcSetGeometryOccludedFunction(geometry, &Impl::occluded_piece_callback);
    rtcCommitGeometry(geometry);
    impl.patch_geometry = rtcAttachGeometry(impl.scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(impl.scene);
  impl.check("building the scene");
}

EmbreeScene::~EmbreeScene() = default;
EmbreeScene::EmbreeScene(EmbreeScene&&) noexcept = default;
EmbreeScene& EmbreeScene::operator=(EmbreeScene&&) noexcept = default;

std::optional<Hit> EmbreeScene::intersect(const Ray& ray) const {
  PatchContext context(&ray);
  RTCRayHit query = embree_ray(ray);
  rtcIntersect1(impl_->scene, &context.context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return impl_->refine(ray, query, context.patch_hit);
}

bool EmbreeScene::occluded(const Ray& ray) const {
  PatchContext context(&ray);
  RTCRay query = embree_ray(ray).ray;
  rtcOccluded1(impl_->scene, &context.context, &query);
  // Embree marks an occluded ray by setting tfar to -infinity.
  return query.tfar < 0;
}

std::size_t EmbreeScene::traverse(const std::vector<Ray>& rays) const {
  std::size_t hits = 0;
  for (const Ray& ray : rays) {
    PatchContext context(&ray);
    RTCRayHit query = embree_ray(ray);
    rtcIntersect1(impl_->scene, &context.context, &query);
    if (query.hit.geomID != RTC_INVALID_GEOMETRY_ID) ++hits;
  }
  return hits;
}

double EmbreeScene::scale() const {
  return impl_->scale;
}

const std::vector<BoundingSphere>& EmbreeScene::bounding_spheres() const {
  return impl_->bounds;
}

}  // namespace penumbra::raytrace
