#include "face_json.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "penumbra/base/parallel.h"
#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/exact_sum.h"
#include "penumbra/io/shadow_json.h"

namespace penumbra::io {

double rounded(const Rational& x) {
  return CGAL::to_double(x) + 0.0;
}
double rounded(const Exact& x) {
  // An interval that is a point is the exact value (most areas and frame lengths of CAD
  // models are doubles): no exact evaluation needed.
  const auto& approx = x.approx();
  if (approx.is_point()) return approx.inf() + 0.0;
  // A sum of many areas: its enclosure usually decides the rounding (exact_sum.h).
  if (const std::optional<double> value = truncated_to_double(x)) return *value + 0.0;
  return rounded(exact_value(x));
}

void emit_point(JsonEmitter& out, const RationalPoint3& p) {
  out.begin_array();
  for (int i = 0; i < 3; ++i) out.number(rounded(p[i]));
  out.end_array();
}
namespace {

// returns p's coordinates rounded: a point given as doubles is its own rounding (most
// vertices of a scene are).
std::array<double, 3> rounded_point(const Point3& p) {
  const auto& approx = p.approx();
  if (!approx.x().is_point() || !approx.y().is_point() || !approx.z().is_point()) {
    const RationalPoint3& exact = exact_value(p);
    return {rounded(exact.x()), rounded(exact.y()), rounded(exact.z())};
  }
  return {approx.x().inf() + 0.0, approx.y().inf() + 0.0, approx.z().inf() + 0.0};
}

// returns the vertex of the face's outer ring at frame point p, if p is one.
const Point3* face_vertex(const FaceOutput& output, const Point2& p) {
  const auto vertex = std::find_if(output.ring.begin(), output.ring.end(), [&](const Point2& q) {
    return CGAL::identical(p, q) || same_point(p, q);
  });
  if (vertex == output.ring.end()) return nullptr;
  return &output.face.outer[static_cast<std::size_t>(vertex - output.ring.begin())];
}

}  // namespace

void emit_point(JsonEmitter& out, const Point3& p) {
  out.begin_array();
  for (const double x : rounded_point(p)) out.number(x);
  out.end_array();
}
void emit_exact_point(JsonEmitter& out, const RationalPoint3& p) {
  out.begin_array();
  for (int i = 0; i < 3; ++i) out.string(rational_string(p[i]));
  out.end_array();
}

void emit_unit(JsonEmitter& out, const Vector3& v) {
  const RationalVector3& exact = exact_value(v);
  const double x = rounded(exact.x()), y = rounded(exact.y()), z = rounded(exact.z());
  const double length = std::sqrt(x * x + y * y + z * z);
  out.begin_array();
  for (double c : {x, y, z}) out.number(c / length + 0.0);
  out.end_array();
}

void add_points(FaceOutput& output, std::vector<const Point2*>& points, const Ring2& ring) {
  for (const Point2& p : ring)
    if (output.world.emplace(p.id(), points.size()).second) points.push_back(&p);
}

void add_points(FaceOutput& output, std::vector<const Point2*>& points, const Region2& region) {
  for (const Polygon2& polygon : region.polygons) {
    add_points(output, points, polygon.outer);
    for (const Ring2& hole : polygon.holes) add_points(output, points, hole);
  }
}

void round_points(FaceOutput& output, const std::vector<const Point2*>& points) {
  output.rounded.resize(points.size());
  for_each_index(
      points.size(), points.size() > 256,
      [&](std::size_t k) {
        // A face vertex as it is (the face may not hold it exactly in its plane).
        if (const Point3* vertex = face_vertex(output, *points[k])) {
          output.rounded[k] = rounded_point(*vertex);
          return;
        }
        const RationalPoint3 world = output.face.frame.to_world(exact_value(*points[k]));
        for (int i = 0; i < 3; ++i) output.rounded[k][i] = rounded(world[i]);
      },
      64);
}

// the ring's points in the world: a face vertex as it is, any other point computed in
// rationals from its frame coordinates (no lazy construction made for output).
void emit_ring(JsonEmitter& out, const Ring2& ring, const FaceOutput& output, bool exact) {
  const ReceivingFace& face = output.face;
  out.begin_array();
  for (const Point2& p : ring) {
    // A point computed ahead (face vertices as they are).
    if (!exact) {
      if (const auto known = output.world.find(p.id()); known != output.world.end()) {
        out.begin_array();
        for (double x : output.rounded[known->second]) out.number(x);
        out.end_array();
        continue;
      }
    }
    if (const Point3* vertex = face_vertex(output, p)) {
      if (exact)
        emit_exact_point(out, exact_value(*vertex));
      else
        emit_point(out, *vertex);
      continue;
    }
    const RationalPoint3 world = face.frame.to_world(exact_value(p));
    if (exact)
      emit_exact_point(out, world);
    else
      emit_point(out, world);
  }
  out.end_array();
}

namespace {

// a polygon's rings: {"holes": [...], "outer": [...]}.
void emit_rings(JsonEmitter& out, const Polygon2& polygon, const FaceOutput& face, bool exact) {
  out.key("holes");
  out.begin_array();
  for (const Ring2& hole : polygon.holes) emit_ring(out, hole, face, exact);
  out.end_array();
  out.key("outer");
  emit_ring(out, polygon.outer, face, exact);
}

}  // namespace

void emit_polygons(JsonEmitter& out, const Region2& region, const FaceOutput& face, bool exact) {
  out.key("polygons");
  out.begin_array();
  out.values(region.polygons.size(), [&](std::size_t k, JsonEmitter& value) {
    const Polygon2& polygon = region.polygons[k];
    value.begin_object();
    if (exact) {
      value.key("exact");
      value.begin_object();
      emit_rings(value, polygon, face, true);
      value.end_object();
    }
    emit_rings(value, polygon, face, false);
    value.end_object();
  });
  out.end_array();
}

void emit_region(JsonEmitter& out, const Region2& region, const FaceOutput& face, bool exact) {
  out.begin_object();
  out.key("area");
  out.number(world_area(region, face.face.frame));
  emit_polygons(out, region, face, exact);
  out.end_object();
}

namespace {

// a curved ring's points in world doubles: origin + s u + t v.
void emit_curved_ring(JsonEmitter& out, const CurvedRing& ring, const FaceFrame& frame) {
  const Vec3d o = to_double(frame.origin()), u = to_double(frame.u()), v = to_double(frame.v());
  out.begin_array();
  for (const auto& p : ring.points) {
    out.begin_array();
    for (int k = 0; k < 3; ++k) out.number(o[k] + p[0] * u[k] + p[1] * v[k]);
    out.end_array();
  }
  out.end_array();
}

void emit_arcs(JsonEmitter& out, const CurvedRing& ring) {
  out.begin_array();
  for (const RingArc& arc : ring.arcs) {
    out.begin_object();
    out.key("conic");
    out.begin_array();
    for (const Exact& c : arc.curve) out.string(rational_string(c));
    out.end_array();
    out.key("first");
    out.integer(arc.first);
    out.key("joint");
    out.boolean(arc.joint);
    out.key("last");
    out.integer(arc.last);
    out.end_object();
  }
  out.end_array();
}

void emit_coordinate(JsonEmitter& out, const AlgebraicCoordinate& x) {
  if (x.value) {
    out.string(rational_string(*x.value));
    return;
  }
  out.begin_object();
  out.key("of");
  out.begin_array();
  for (const Exact& c : x.polynomial) out.string(rational_string(c));
  out.end_array();
  out.key("root");
  out.integer(static_cast<std::size_t>(x.root));
  out.end_object();
}

void emit_exact_ring(JsonEmitter& out, const std::vector<ExactEdge>& ring) {
  out.begin_array();
  for (const ExactEdge& edge : ring) {
    out.begin_object();
    out.key("conic");
    out.begin_array();
    for (const Exact& c : edge.curve) out.string(rational_string(c));
    out.end_array();
    out.key("from");
    out.begin_object();
    out.key("s");
    emit_coordinate(out, edge.from.s);
    out.key("t");
    emit_coordinate(out, edge.from.t);
    out.end_object();
    out.key("joint");
    out.boolean(edge.joint);
    out.end_object();
  }
  out.end_array();
}

}  // namespace

void emit_curved_region(JsonEmitter& out, const std::vector<CurvedPolygon>& polygons,
                        double frame_area, const FaceOutput& face,
                        const std::vector<ExactCurvedPolygon>* exact) {
  const FaceFrame& frame = face.face.frame;
  out.begin_object();
  out.key("area");
  out.number(world_area(frame_area, frame));
  // the frame of the conics, exactly: a point is origin + s u + t v (u, v not unit).
  out.key("axes");
  out.begin_object();
  out.key("origin");
  emit_exact_point(out, exact_value(frame.origin()));
  for (const auto& [name, axis] : {std::pair{"u", &frame.u()}, std::pair{"v", &frame.v()}}) {
    out.key(name);
    out.begin_array();
    const RationalVector3 rational = exact_value(*axis);
    for (int k = 0; k < 3; ++k) out.string(rational_string(rational[k]));
    out.end_array();
  }
  out.end_object();
  if (exact) {
    out.key("exact");
    out.begin_array();
    for (const ExactCurvedPolygon& polygon : *exact) {
      out.begin_object();
      out.key("holes");
      out.begin_array();
      for (const auto& hole : polygon.holes) emit_exact_ring(out, hole);
      out.end_array();
      out.key("outer");
      emit_exact_ring(out, polygon.outer);
      out.end_object();
    }
    out.end_array();
  }
  out.key("polygons");
  out.begin_array();
  for (const CurvedPolygon& polygon : polygons) {
    out.begin_object();
    out.key("arcs");
    emit_arcs(out, polygon.outer);
    out.key("hole_arcs");
    out.begin_array();
    for (const CurvedRing& hole : polygon.holes) emit_arcs(out, hole);
    out.end_array();
    out.key("holes");
    out.begin_array();
    for (const CurvedRing& hole : polygon.holes) emit_curved_ring(out, hole, frame);
    out.end_array();
    out.key("outer");
    emit_curved_ring(out, polygon.outer, frame);
    out.end_object();
  }
  out.end_array();
  out.end_object();
}

void emit_plane(JsonEmitter& out, const Plane3& plane, bool exact) {
  out.begin_array();
  if (exact) {
    for (const Rational& k : canonical_plane(plane)) out.string(rational_string(k));
  } else {
    const RationalPlane3& rational = exact_value(plane);
    const double a = rounded(rational.a()), b = rounded(rational.b()), c = rounded(rational.c()),
                 d = rounded(rational.d());
    const double length = std::sqrt(a * a + b * b + c * c);
    for (double k : {a, b, c, d}) out.number(k / length + 0.0);
  }
  out.end_array();
}

namespace {

// a world ring of exact points.
void emit_world_ring(JsonEmitter& out, const std::vector<Point3>& ring, bool exact) {
  out.begin_array();
  for (const Point3& p : ring)
    if (exact)
      emit_exact_point(out, exact_value(p));
    else
      emit_point(out, p);
  out.end_array();
}

}  // namespace

void emit_boundary(JsonEmitter& out, const ReceivingFace& face, bool exact) {
  if (!face.holes) {
    emit_world_ring(out, face.outer, exact);
    return;
  }
  out.begin_object();
  out.key("holes");
  out.begin_array();
  for (const auto& hole : *face.holes) emit_world_ring(out, hole, exact);
  out.end_array();
  out.key("outer");
  emit_world_ring(out, face.outer, exact);
  out.end_object();
}

void emit_face_entry(JsonEmitter& out, const FaceOutput& output, bool exact,
                     const std::function<void()>& members) {
  const ReceivingFace& face = output.face;
  out.begin_object();
  out.key("area");
  out.number(world_area(face.area, face.frame));
  out.key("boundary");
  emit_boundary(out, face, false);
  if (exact) {
    out.key("exact");
    out.begin_object();
    out.key("boundary");
    emit_boundary(out, face, true);
    out.key("plane");
    emit_plane(out, face.plane, true);
    out.end_object();
  }
  out.key("face");
  out.integer(face.face);
  out.key("frame");
  out.begin_object();
  out.key("origin");
  emit_point(out, face.frame.origin());
  out.key("u");
  emit_unit(out, face.frame.u());
  out.key("v");
  emit_unit(out, face.frame.v());
  out.end_object();
  members();
  out.key("object");
  out.string(face.object);
  out.key("plane");
  emit_plane(out, face.plane, false);
  out.end_object();
}

}  // namespace penumbra::io
