#pragma once
// The pieces every document about receiving faces writes alike (private to io/): exact
// values rounded to doubles, points and planes, a region's polygons in world coordinates
// (with their exact rationals on request), and a face's entry: its area, boundary, frame,
// object and plane around the members a document adds (shadows per light, sun-hours).

#include <functional>
#include <unordered_map>
#include <vector>

#include "json_emitter.h"
#include "penumbra/io/rational.h"
#include "penumbra/shadow/exact_umbra.h"
#include "penumbra/shadow/shadow_map.h"

namespace penumbra::io {

// rounds from the exact value, never from the lazy kernel's interval, whose width
// depends on what was evaluated before (and so on threads); adding +0.0 turns -0.0
// into 0.0, so that equal points print alike.
double rounded(const Rational& x);
double rounded(const Exact& x);

void emit_point(JsonEmitter& out, const RationalPoint3& p);
void emit_point(JsonEmitter& out, const Point3& p);
void emit_exact_point(JsonEmitter& out, const RationalPoint3& p);
// the unit vector along v, rounded from v's exact coordinates.
void emit_unit(JsonEmitter& out, const Vector3& v);

// A receiving face while it is written. Its shadow, umbra, lit holes and occluder polygons
// repeat the same points (the same lazy handles), each converted from frame to world
// coordinates in rationals: rounded holds each point's world doubles, computed once and
// across threads (a ground under a city has 10^5 of them), world maps a point's identity
// to its slot.
struct FaceOutput {
  const ReceivingFace& face;
  const Ring2& ring;  // the outer ring's points in the frame
  std::unordered_map<std::size_t, std::size_t> world;
  std::vector<std::array<double, 3>> rounded;
  std::unordered_map<const OccluderShadow*, double> occluder_area;  // m^2, computed alike
};

// returns the output of a face with no points computed ahead.
inline FaceOutput plain_output(const ReceivingFace& face) {
  return FaceOutput{face, face.ring, {}, {}, {}};
}

// adds the points of a ring or region not seen yet (by identity) to points, giving each its
// slot of output.world.
void add_points(FaceOutput& output, std::vector<const Point2*>& points, const Ring2& ring);
void add_points(FaceOutput& output, std::vector<const Point2*>& points, const Region2& region);
// computes output.rounded: the world doubles of points, in the slots add_points gave them,
// across threads.
void round_points(FaceOutput& output, const std::vector<const Point2*>& points);

// the ring's points in the world: a face vertex as it is, any other point computed in
// rationals from its frame coordinates.
void emit_ring(JsonEmitter& out, const Ring2& ring, const FaceOutput& output, bool exact);
// a region as {"area": m^2, "polygons": [...]}.
void emit_region(JsonEmitter& out, const Region2& region, const FaceOutput& face, bool exact);
// a region's "polygons" member: each polygon's rings, with "exact" rationals on request.
void emit_polygons(JsonEmitter& out, const Region2& region, const FaceOutput& face, bool exact);
// a curved region (the exact umbra or penumbra of joint occlusion, shadow/exact_umbra.h) as
// {"area": m^2, "axes": {"origin", "u", "v"}, "polygons": [{"arcs": [...], "hole_arcs":
// [[...], ...], "holes": [...], "outer": [...]}]}: the rings' points (the arcs densified)
// in world doubles, and per ring its curved edges {"conic": six rationals a..f of
// a s^2 + b s t + c t^2 + d s + e t + f = 0, "first", "joint", "last"} in the exact frame
// that axes gives (origin + s u + t v, rationals); points first..last lie on the arc, and
// last may be the ring's length: the arc ends at its first point.
// With exact, "exact" lists the region's polygons in canonical form (ExactCurvedPolygon):
// {"holes": [ring, ...], "outer": ring}, a ring a list of edges {"conic": six rationals,
// normalised, "from": corner, "joint"}, a corner {"s": x, "t": x} where x is "p/q" or
// {"of": [integer coefficients, lowest degree first], "root": k} (the k-th real root from 0,
// increasing): what `check` compares.
void emit_curved_region(JsonEmitter& out, const std::vector<CurvedPolygon>& polygons,
                        double frame_area, const FaceOutput& face,
                        const std::vector<ExactCurvedPolygon>* exact = nullptr);
// the plane scaled to a unit normal, in doubles; exactly, scaled so that its largest
// normal component has magnitude 1 (a canonical exact form).
void emit_plane(JsonEmitter& out, const Plane3& plane, bool exact);
// the face's boundary: its ring, or for a face of a mesh part {"holes": [...], "outer": [...]}.
void emit_boundary(JsonEmitter& out, const ReceivingFace& face, bool exact);

// the entry of a receiving face, members in key order: area, boundary, exact (with
// exact), face, frame, then what members() writes (keys sorting after "frame" and before
// "object"), object and plane.
void emit_face_entry(JsonEmitter& out, const FaceOutput& output, bool exact,
                     const std::function<void()>& members);

}  // namespace penumbra::io
