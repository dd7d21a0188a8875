#include "penumbra/basis/gouraud_image.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "penumbra/basis/patch_mesh.h"
#include "penumbra/scene/camera_frame.h"

namespace penumbra::basis {

using namespace vector_ops;

namespace {

// A vertex in camera space (x right, y up, z forward) with its luminance.
struct CameraVertex {
  Vec3d p;
  std::array<double, 3> value;
};

CameraVertex lerp(const CameraVertex& a, const CameraVertex& b, double t) {
  CameraVertex out;
  out.p = a.p + t * (b.p - a.p);
  for (int c = 0; c < 3; ++c) out.value[c] = a.value[c] + t * (b.value[c] - a.value[c]);
  return out;
}

// clips a polygon to z >= near (Sutherland-Hodgman).
std::vector<CameraVertex> clip_near(const std::vector<CameraVertex>& polygon, double near) {
  std::vector<CameraVertex> out;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const CameraVertex& a = polygon[k];
    const CameraVertex& b = polygon[(k + 1) % polygon.size()];
    if (a.p[2] >= near) out.push_back(a);
    if ((a.p[2] >= near) != (b.p[2] >= near))
      out.push_back(lerp(a, b, (near - a.p[2]) / (b.p[2] - a.p[2])));
  }
  return out;
}

}  // namespace

GouraudImage gouraud_image(const PatchMesh& mesh, const Eigen::MatrixX3f& vertex_luminance,
                           const Camera& camera) {
  GouraudImage image;
  image.width = camera.width;
  image.height = camera.height;
  const std::size_t pixels = static_cast<std::size_t>(camera.width) * camera.height;
  image.radiance.assign(pixels, {0, 0, 0});
  image.patch.assign(pixels, -1);
  std::vector<double> inverse_depth(pixels, 0);  // 1 / z; 0 = nothing drawn

  const CameraFrame frame(camera);
  const double half_height = frame.half_height(), half_width = frame.half_width();
  const double near = 1e-3;

  std::vector<std::uint32_t> triangle_patch;
  const auto triangles = mesh.triangles(&triangle_patch);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    // back faces are not drawn: each side of a two-sided polygon is its own face, and
    // the two would fight in the depth buffer
    const Patch& patch = mesh.patches()[triangle_patch[t]];
    if (dot(patch.normal, camera.eye - patch.centre) <= 0) continue;
    std::vector<CameraVertex> polygon;
    for (std::uint32_t v : triangles[t]) {
      const std::array<double, 3> p = frame.to_camera(mesh.vertices()[v]);
      const auto row = static_cast<Eigen::Index>(v);
      polygon.push_back(
          {{p[0], p[1], p[2]},
           {vertex_luminance(row, 0), vertex_luminance(row, 1), vertex_luminance(row, 2)}});
    }
    polygon = clip_near(polygon, near);
    if (polygon.size() < 3) continue;
    // to image coordinates (x right, y down, pixel units) with 1/z and value/z for
    // perspective-correct interpolation
    struct Screen {
      double x, y, w;
      std::array<double, 3> value_w;
    };
    std::vector<Screen> screen;
    for (const CameraVertex& v : polygon) {
      const double w = 1 / v.p[2];
      screen.push_back({(v.p[0] * w / half_width + 1) * camera.width / 2,
                        (1 - v.p[1] * w / half_height) * camera.height / 2,
                        w,
                        {v.value[0] * w, v.value[1] * w, v.value[2] * w}});
    }
    for (std::size_t k = 1; k + 1 < screen.size(); ++k) {
      const Screen& a = screen[0];
      const Screen& b = screen[k];
      const Screen& c = screen[k + 1];
      const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
      if (area == 0) continue;
      const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
      const int x1 =
          std::min(camera.width - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
      const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
      const int y1 =
          std::min(camera.height - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
      for (int j = y0; j <= y1; ++j)
        for (int i = x0; i <= x1; ++i) {
          const double px = i + 0.5, py = j + 0.5;
          // barycentric coordinates; a pixel centre on a shared edge goes to both
          // triangles, and the depth test keeps one
          const double l1 = ((c.x - px) * (a.y - py) - (a.x - px) * (c.y - py)) / area;
          const double l2 = ((a.x - px) * (b.y - py) - (b.x - px) * (a.y - py)) / area;
          const double l0 = 1 - l1 - l2;
          if (l0 < 0 || l1 < 0 || l2 < 0) continue;
          const double w = l0 * a.w + l1 * b.w + l2 * c.w;
          const std::size_t pixel = static_cast<std::size_t>(j) * camera.width + i;
          if (w <= inverse_depth[pixel]) continue;
          inverse_depth[pixel] = w;
          for (int ch = 0; ch < 3; ++ch)
            image.radiance[pixel][ch] =
                (l0 * a.value_w[ch] + l1 * b.value_w[ch] + l2 * c.value_w[ch]) / w;
          image.patch[pixel] = triangle_patch[t];
        }
    }
  }
  return image;
}

}  // namespace penumbra::basis
