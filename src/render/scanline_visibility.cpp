#include "penumbra/render/scanline_visibility.h"

#include "penumbra/base/parallel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include "penumbra/base/vec3d.h"

namespace penumbra::render {

using namespace vector_ops;

FacePlane face_plane(const Face& face) {
  const Vec3d normal = to_double(face.normal());
  const double length = std::sqrt(dot(normal, normal));
  return {(1 / length) * normal, CGAL::to_double(face.plane.d()) / length};
}

namespace {

// A front face in doubles (Appendix A1 step (i)).
struct FrontFace {
  long object;
  int face;
  std::vector<Vec3d> vertices;
  FacePlane plane;
  double eye_distance;  // F(S, eye) > 0
};

// One face's span on a scan line with its inverse depth 1/t = alpha + beta x, which is
// linear in the image x for a plane (the ray's forward component is 1).
struct Span {
  std::size_t face;  // index into the front faces
  double left, right;
  double alpha, beta;
  double inverse_depth(double x) const { return alpha + beta * x; }
};

// The depth below which a point counts as behind the eye: the scan segment is clipped
// there, so faces passing beside the eye keep a finite projection.
constexpr double near_depth = 1e-6;

std::vector<FrontFace> front_faces(const Scene& scene, const Vec3d& eye) {
  std::vector<FrontFace> result;
  for (std::size_t object = 0; object < scene.objects.size(); ++object) {
    const auto& faces = scene.objects[object].solid.faces();
    for (std::size_t face = 0; face < faces.size(); ++face) {
      FrontFace front{
          static_cast<long>(object), static_cast<int>(face), {}, face_plane(faces[face]), 0};
      front.eye_distance = dot(front.plane.normal, eye) + front.plane.offset;
      if (!(front.eye_distance > 0)) continue;
      for (const Point3& vertex : faces[face].vertices) front.vertices.push_back(to_double(vertex));
      result.push_back(std::move(front));
    }
  }
  return result;
}

// cuts a front face with the scan plane through eye with normal `plane_normal` and
// returns its span in image x, or {} when the face misses the scan line or lies behind.
std::optional<Span> face_span(const FrontFace& face, std::size_t index, const CameraFrame& view,
                              const Vec3d& plane_normal, const Vec3d& row_direction) {
  // the face polygon is convex, so the scan plane cuts it in one segment [A, B].
  std::vector<Vec3d> cut;
  const std::size_t n = face.vertices.size();
  std::vector<double> side(n);
  for (std::size_t k = 0; k < n; ++k) side[k] = dot(plane_normal, face.vertices[k] - view.eye());
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t next = (k + 1) % n;
    if (side[k] == 0) cut.push_back(face.vertices[k]);
    if ((side[k] < 0 && side[next] > 0) || (side[k] > 0 && side[next] < 0)) {
      const double s = side[k] / (side[k] - side[next]);
      cut.push_back(face.vertices[k] + s * (face.vertices[next] - face.vertices[k]));
    }
  }
  if (cut.size() < 2) return std::nullopt;
  // the extreme cut points along right; with side == 0 vertices there may be more than two.
  Vec3d a = cut[0], b = cut[0];
  const auto lateral = [&](const Vec3d& p) { return dot(p - view.eye(), view.right()); };
  const auto depth = [&](const Vec3d& p) { return dot(p - view.eye(), view.forward()); };
  // order by the angle seen from the eye within the scan plane: lateral / depth is not
  // defined behind the eye, so order along the segment's own direction instead.
  for (const Vec3d& p : cut) {
    if (dot(p - a, p - a) > 0 && dot(b - a, b - a) == 0) b = p;
  }
  if (dot(b - a, b - a) == 0) return std::nullopt;
  for (const Vec3d& p : cut) {
    // extend [a, b] to cover every cut point on the line a-b.
    const double s = dot(p - a, b - a) / dot(b - a, b - a);
    if (s < 0) a = p;
    if (s > 1) b = p;
  }
  double depth_a = depth(a), depth_b = depth(b);
  if (depth_a < near_depth && depth_b < near_depth) return std::nullopt;
  if (depth_a < near_depth) {
    a = a + ((near_depth - depth_a) / (depth_b - depth_a)) * (b - a);
    depth_a = near_depth;
  } else if (depth_b < near_depth) {
    b = b + ((near_depth - depth_b) / (depth_a - depth_b)) * (a - b);
    depth_b = near_depth;
  }
  const double width = view.width();
  const double half_width = view.half_width();
  const auto image_x = [&](const Vec3d& p, double d) {
    return (lateral(p) / d / half_width + 1) * width / 2;
  };
  const double xa = image_x(a, depth_a), xb = image_x(b, depth_b);
  Span span{index, std::min(xa, xb), std::max(xa, xb), 0, 0};
  // 1/t = -(n . d(x)) / F(S, eye), with d(x) = row_direction + a(x) right and
  // a(x) = (2x / width - 1) half_width.
  const double n_row = dot(face.plane.normal, row_direction);
  const double n_right = dot(face.plane.normal, view.right());
  span.alpha = -(n_row - half_width * n_right) / face.eye_distance;
  span.beta = -(2 * half_width / width * n_right) / face.eye_distance;
  return span;
}

// resolves one scan line (Appendix A1 step (iii)): writes the visible face of every pixel
// of row j; returns the number of pieces decided.
std::size_t resolve_row(const std::vector<Span>& spans, const std::vector<FrontFace>& faces,
                        int width, long* objects, int* face_ids) {
  std::vector<double> ends;
  ends.reserve(2 * spans.size() + 2);
  ends.push_back(0);
  ends.push_back(width);
  for (const Span& span : spans) {
    if (span.left > 0 && span.left < width) ends.push_back(span.left);
    if (span.right > 0 && span.right < width) ends.push_back(span.right);
  }
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  std::size_t pieces = 0;
  std::vector<const Span*> active;
  const auto fill = [&](double from, double to, const Span* span) {
    // pixel centres i + 0.5 in [from, to)
    const int first = std::max(0, static_cast<int>(std::ceil(from - 0.5)));
    const int last = std::min(width, static_cast<int>(std::ceil(to - 0.5)));
    for (int i = first; i < last; ++i) {
      objects[i] = faces[span->face].object;
      face_ids[i] = faces[span->face].face;
    }
  };
  for (std::size_t k = 0; k + 1 < ends.size(); ++k) {
    const double from = ends[k], to = ends[k + 1];
    if (std::ceil(from - 0.5) >= std::ceil(to - 0.5)) continue;  // no pixel centre inside
    const double middle = (from + to) / 2;
    active.clear();
    for (const Span& span : spans)
      if (span.left < middle && middle < span.right) active.push_back(&span);
    if (active.empty()) continue;
    ++pieces;
    // the nearest face at the piece's first pixel centre (largest 1/t; ties go to the one
    // nearer to the right), then wherever another face overtakes it, split the piece there.
    // Faces that touch (a screen standing on the floor) meet exactly at a piece's end, so
    // the comparison is made at a pixel centre, never at the end itself.
    double at = std::ceil(from - 0.5) + 0.5;
    const Span* nearest = nullptr;
    for (const Span* span : active) {
      if (!nearest) {
        nearest = span;
        continue;
      }
      const double here = span->inverse_depth(at), best = nearest->inverse_depth(at);
      if (here > best || (here == best && span->beta > nearest->beta)) nearest = span;
    }
    while (true) {
      double next = to;
      const Span* successor = nullptr;
      for (const Span* span : active) {
        if (span == nearest || !(span->beta > nearest->beta)) continue;
        // where span's inverse depth reaches nearest's
        const double cross_x = (nearest->alpha - span->alpha) / (span->beta - nearest->beta);
        if (cross_x > at && cross_x < next) {
          next = cross_x;
          successor = span;
        }
      }
      fill(at == std::ceil(from - 0.5) + 0.5 ? from : at, next, nearest);
      if (!successor) break;
      at = next;
      nearest = successor;
    }
  }
  return pieces;
}

}  // namespace

VisibilityMap scanline_visibility(const Scene& scene, const Camera& camera, bool parallel) {
  const CameraFrame view(camera);
  VisibilityMap map;
  map.width = camera.width;
  map.height = camera.height;
  const std::size_t pixels = static_cast<std::size_t>(map.width) * map.height;
  map.objects.assign(pixels, -1);
  map.faces.assign(pixels, -1);
  const std::vector<FrontFace> faces = front_faces(scene, view.eye());
  std::atomic<std::size_t> span_count{0}, piece_count{0};

  const auto run_rows = [&](int first, int last) {
    std::vector<Span> spans;
    for (int j = first; j < last; ++j) {
      // the scan plane of row j: through the eye and the pixel centres of the row.
      const Vec3d row_direction = view.direction(map.width / 2.0, j + 0.5);
      const Vec3d plane_normal = cross(view.right(), row_direction);
      spans.clear();
      for (std::size_t k = 0; k < faces.size(); ++k)
        if (auto span = face_span(faces[k], k, view, plane_normal, row_direction))
          spans.push_back(*span);
      span_count += spans.size();
      piece_count += resolve_row(spans, faces, map.width, &map.objects[map.index(0, j)],
                                 &map.faces[map.index(0, j)]);
    }
  };
  for_each_range(static_cast<std::size_t>(map.height), parallel,
                 [&](std::size_t first, std::size_t last) {
                   run_rows(static_cast<int>(first), static_cast<int>(last));
                 });
  map.spans = span_count;
  map.pieces = piece_count;
  return map;
}

}  // namespace penumbra::render
