#include "receiver_clip.h"

#include <deque>
#include <utility>

#include "half_plane.h"
#include "penumbra/geometry/exact.h"

namespace penumbra::detail {
namespace {

using Rational = ReceiverClip::Rational;
using ExactPoint2 = std::decay_t<decltype(exact_value(std::declval<const Point2&>()))>;

// A vertex of the interval clip: face vertex `corner`, or (corner < 0) the crossing
// of lines first and second; lines 0..n-1 are the face's edges, n + j plane j's
// trace. exact holds the vertex's rational coordinates once they were needed.
struct Vertex {
  Interval s, t;
  int corner;
  int first, second;
  std::optional<ExactPoint2> exact;
};

// returns a point whose exact coordinates are known, so that later exact
// predicates on it evaluate no construction.
Point2 exact_point(ExactPoint2&& point) {
  return Point2(Point2::Rep(std::move(point)));
}

}  // namespace

ReceiverClip::ReceiverClip(const Face& face) : face_(&face) {
  const auto& origin = exact_value(face.frame.origin());
  const auto& u = exact_value(face.frame.u());
  const auto& v = exact_value(face.frame.v());
  for (int i = 0; i < 3; ++i) {
    origin_[i] = origin[i];
    u_[i] = u[i];
    v_[i] = v[i];
    // The approximations are refined to the exact values just computed.
    origin_box_[i] = CGAL::approx(face.frame.origin())[i];
    u_box_[i] = CGAL::approx(face.frame.u())[i];
    v_box_[i] = CGAL::approx(face.frame.v())[i];
  }
  const Rational uu = sparse_dot(u_, u_);
  const Rational vv = sparse_dot(v_, v_);
  // face_ring(face), the frame coordinates (d.u / u.u, d.v / v.v) of each vertex.
  std::vector<ExactPoint2> points;
  for (const Point3& vertex : face.vertices) {
    const auto& p = exact_value(vertex);
    const Rational d[3] = {p[0] - origin_[0], p[1] - origin_[1], p[2] - origin_[2]};
    points.emplace_back(sparse_dot(d, u_) / uu, sparse_dot(d, v_) / vv);
  }
  const std::size_t n = points.size();
  for (std::size_t k = 0; k < n; ++k) {
    const ExactPoint2& p = points[k];
    const ExactPoint2& q = points[(k + 1) % n];
    Line edge{q.y() - p.y(), p.x() - q.x(), 0};
    edge.c = -(edge.a * p.x() + edge.b * p.y());
    edges_.push_back(std::move(edge));
  }
  for (ExactPoint2& p : points) {
    ring_.push_back(exact_point(std::move(p)));
    s_.push_back(CGAL::approx(ring_.back()).x());
    t_.push_back(CGAL::approx(ring_.back()).y());
  }
}

ReceiverClip::Line ReceiverClip::trace(const Plane3& plane) const {
  // restrict_to: n.u s + n.v t + plane(o) for the point o + s u + t v.
  const auto& p = exact_value(plane);
  const auto normal = p.orthogonal_vector();
  return {sparse_dot(normal, u_), sparse_dot(normal, v_), sparse_dot(normal, origin_) + p.d()};
}

std::optional<Ring2> ReceiverClip::clip(const std::vector<Plane3>& volume,
                                        const std::vector<PlaneLimit>& limits) const {
  const int n = static_cast<int>(ring_.size());
  // The planes clipped in turn: volume's, then the limits of those that hold the face.
  std::vector<const Plane3*> planes;
  for (const Plane3& plane : volume) planes.push_back(&plane);
  // Exact lines, computed when first needed.
  std::deque<std::optional<Line>> traces(planes.size());
  auto line_of = [&](int id) -> const Line& {
    if (id < n) return edges_[static_cast<std::size_t>(id)];
    auto& cached = traces[static_cast<std::size_t>(id - n)];
    if (!cached) cached = trace(*planes[static_cast<std::size_t>(id - n)]);
    return *cached;
  };
  // The exact vertex: a face corner as it is; the crossing of two lines solved in
  // rationals (never parallel: the clipped edge changed sign strictly).
  auto exact_of = [&](Vertex& vertex) -> const ExactPoint2& {
    if (vertex.corner >= 0) return exact_value(ring_[static_cast<std::size_t>(vertex.corner)]);
    if (!vertex.exact) {
      const Line& first = line_of(vertex.first);
      const Line& second = line_of(vertex.second);
      const Rational det = first.a * second.b - second.a * first.b;
      vertex.exact.emplace((first.b * second.c - second.b * first.c) / det,
                           (second.a * first.c - first.a * second.c) / det);
    }
    return *vertex.exact;
  };

  std::vector<Vertex> ring;
  std::vector<int> line;  // line[k]: the line of the edge from ring[k] to ring[k + 1]
  for (int k = 0; k < n; ++k) {
    ring.push_back({s_[k], t_[k], k, -1, -1, std::nullopt});
    line.push_back(k);
  }
  std::vector<Vertex> out;
  std::vector<int> out_line;
  std::vector<Interval> value;
  std::vector<CGAL::Sign> sign;
  for (std::size_t j = 0; j < planes.size(); ++j) {
    const int trace_id = n + static_cast<int>(j);
    Interval a, b, c;
    {
      CGAL::Protect_FPU_rounding<true> upward;
      const auto& plane = CGAL::approx(*planes[j]);
      a = normal_dot(plane, u_box_);
      b = normal_dot(plane, v_box_);
      c = plane_value(plane, origin_box_);
    }
    const CGAL::Uncertain<bool> a_zero = CGAL::is_zero(a), b_zero = CGAL::is_zero(b);
    const bool constant =
        CGAL::is_certain(a_zero) && CGAL::is_certain(b_zero)
            ? a_zero.make_certain() && b_zero.make_certain()
            : CGAL::is_zero(line_of(trace_id).a) && CGAL::is_zero(line_of(trace_id).b);
    if (constant) {
      // A trace parallel to the face: all or nothing, as in clip(); where the plane holds the
      // face, its limits instead when it has them (clipped after the others: the order of
      // the half-planes does not change their intersection).
      const CGAL::Uncertain<CGAL::Sign> certain = CGAL::sign(c);
      const CGAL::Sign side =
          CGAL::is_certain(certain) ? certain.make_certain() : CGAL::sign(line_of(trace_id).c);
      if (side == CGAL::NEGATIVE) continue;
      const std::size_t before = planes.size();
      if (side == CGAL::ZERO && j < volume.size())
        for (const PlaneLimit& limit : limits)
          if (limit.plane == j) planes.push_back(&limit.limit);
      if (planes.size() == before) return std::nullopt;
      traces.resize(planes.size());
      continue;
    }
    const std::size_t m = ring.size();
    value.resize(m);
    sign.resize(m);
    for (std::size_t k = 0; k < m; ++k) {
      CGAL::Uncertain<CGAL::Sign> certain;
      {
        CGAL::Protect_FPU_rounding<true> upward;
        value[k] = a * ring[k].s + b * ring[k].t + c;
        certain = CGAL::sign(value[k]);
      }
      if (CGAL::is_certain(certain)) {
        sign[k] = certain.make_certain();
      } else {
        // The interval cannot tell (often a vertex exactly on the trace): decide in rationals.
        const Line& trace = line_of(trace_id);
        const ExactPoint2& p = exact_of(ring[k]);
        sign[k] = CGAL::sign(trace.a * p.x() + trace.b * p.y() + trace.c);
      }
    }
    // Sutherland-Hodgman as in clip(), keeping the line under each new edge: an
    // edge leaving a kept vertex runs along its old line unless the next vertex is
    // cut away, in which case the boundary continues along the trace.
    out.clear();
    out_line.clear();
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t next = (k + 1) % m;
      if (sign[k] != CGAL::POSITIVE) {
        out.push_back(ring[k]);
        out_line.push_back(sign[k] == CGAL::ZERO && sign[next] == CGAL::POSITIVE ? trace_id
                                                                                 : line[k]);
      }
      if (sign[k] * sign[next] == CGAL::NEGATIVE) {
        CGAL::Protect_FPU_rounding<true> upward;
        const Interval t = value[k] / (value[k] - value[next]);
        out.push_back({ring[k].s + t * (ring[next].s - ring[k].s),
                       ring[k].t + t * (ring[next].t - ring[k].t), -1, line[k], trace_id,
                       std::nullopt});
        out_line.push_back(sign[next] == CGAL::POSITIVE ? trace_id : line[k]);
      }
    }
    if (out.size() < 3) return std::nullopt;
    std::swap(ring, out);
    std::swap(line, out_line);
  }

  Ring2 exact;
  exact.reserve(ring.size());
  for (Vertex& vertex : ring) {
    if (vertex.corner >= 0) {
      exact.push_back(ring_[static_cast<std::size_t>(vertex.corner)]);
    } else {
      exact_of(vertex);
      exact.push_back(exact_point(std::move(*vertex.exact)));
    }
  }
  return ring_with_area(exact);
}

}  // namespace penumbra::detail
