#include "penumbra/raytrace/embree_scene.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "penumbra/base/vec3d.h"
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

}  // namespace

struct EmbreeScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  unsigned triangle_geometry = RTC_INVALID_GEOMETRY_ID;
  unsigned sphere_geometry = RTC_INVALID_GEOMETRY_ID;
  // triangle primitive -> (object, face); sphere primitive -> object.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> triangle_faces;
  std::vector<std::uint32_t> sphere_objects;
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

  // refines Embree's single-precision hit against the exact surface in double precision.
  Hit refine(const Ray& ray, const RTCRayHit& query) const {
    Hit hit{};
    double t = query.ray.tfar;
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

EmbreeScene::EmbreeScene(const Scene& scene) : impl_(std::make_unique<Impl>()) {
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
  rtcCommitScene(impl.scene);
  impl.check("building the scene");
}

EmbreeScene::~EmbreeScene() = default;
EmbreeScene::EmbreeScene(EmbreeScene&&) noexcept = default;
EmbreeScene& EmbreeScene::operator=(EmbreeScene&&) noexcept = default;

std::optional<Hit> EmbreeScene::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query = embree_ray(ray);
  rtcIntersect1(impl_->scene, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return impl_->refine(ray, query);
}

bool EmbreeScene::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay query = embree_ray(ray).ray;
  rtcOccluded1(impl_->scene, &context, &query);
  // Embree marks an occluded ray by setting tfar to -infinity.
  return query.tfar < 0;
}

std::size_t EmbreeScene::traverse(const std::vector<Ray>& rays) const {
  std::size_t hits = 0;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (const Ray& ray : rays) {
    RTCRayHit query = embree_ray(ray);
    rtcIntersect1(impl_->scene, &context, &query);
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
