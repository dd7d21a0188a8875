#pragma once
// The exact corners of curved rings and the rings' canonical form (exact_umbra.h,
// ExactCorner, ExactCurvedPolygon): what `shadows --exact` writes of a curved region and
// `check` compares (issue #17). A corner is named by what depends only on the two curves
// that meet there: a rational point where both are lines, otherwise its coordinates as
// indexed roots of the two resultants, picked out by refining an enclosure of the corner
// that the sweep knows exactly (pencil coordinates) until one root alone can hold it.

#include <array>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "pencil.h"
#include "penumbra/shadow/exact_umbra.h"

namespace penumbra::detail {

// a box of rationals: {s_low, s_high}, {t_low, t_high}.
using RationalBox = std::array<std::pair<Rational, Rational>, 2>;
// returns a box that holds the corner, about 2^-bits wide or less; nullopt when it cannot
// at this precision (ask again with more bits).
using CornerEnclosure = std::function<std::optional<RationalBox>(int bits)>;

// an enclosure of num(s) / den(s) for s in [low, high] (rational interval arithmetic);
// nullopt when den's enclosure holds 0.
std::optional<std::pair<Rational, Rational>> ratio_range(const Poly& num, const Poly& den,
                                                         const Rational& low, const Rational& high);

// q scaled so that its first nonzero coefficient (a, b, c, d, e, f) is 1.
Quadratic2 normalised(const Quadratic2& q);

// true for a conic whose matrix is singular (a pair of lines, a point, nothing) and that is
// not a line.
bool degenerate(const Quadratic2& q);

// the resultant of p and q eliminating t (a polynomial in s) or, with eliminate_s, s (a
// polynomial in t): it vanishes at the coordinate of every common point, and is zero when
// p and q share a component.
Poly resultant(const Quadratic2& p, const Quadratic2& q, bool eliminate_s);

// An edge of a ring as the sweep traced it: its curve, and its first point, enclosed.
struct TracedEdge {
  Quadratic2 curve;
  bool joint = false;
  CornerEnclosure start;
};

// the ring in canonical form: consecutive edges on one line or one non-degenerate conic
// merged, corners named exactly, started at its smallest corner (s, then t).
std::vector<ExactEdge> exact_ring(const std::vector<TracedEdge>& edges);

// sorts each polygon's holes and then the polygons by their rings, corner by corner.
void canonical_order(std::vector<ExactCurvedPolygon>& polygons);

}  // namespace penumbra::detail
