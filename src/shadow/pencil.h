#pragma once
// Pencil coordinates on a face for a linear source (exact_umbra.h). The planes through the
// source's line L meet the face's plane in a pencil of lines through X0 = L ∩ plane (or
// parallel to L when L is parallel to the face). A point is named (s, r): s picks the line
// of the pencil, r the point on it, P(s, r) = A(s) + r B(s) with A and B affine in s:
//   X0 finite:  A = X0, B(s) = (1 - s) a + s b   (the cone of directions a..b, r > 0);
//   X0 at infinity: A(s) = O + s n, B = δ        (δ along L, n across it).
// Every line and every conic through X0 then meets each line of the pencil once more, at
// r = -num(s) / den(s) with rational polynomials of degree <= 2: the curves of the sweep.

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/interval.h"

namespace penumbra::detail {

// A polynomial in s with rational coefficients, lowest degree first.
struct Poly {
  std::vector<Rational> c;

  Poly() = default;
  explicit Poly(std::vector<Rational> coefficients);
  static Poly constant(const Rational& value) { return Poly({value}); }
  static Poly linear(const Rational& c0, const Rational& c1) { return Poly({c0, c1}); }

  bool zero() const { return c.empty(); }
  int degree() const { return static_cast<int>(c.size()) - 1; }
  Rational operator()(const Rational& s) const;
  Poly operator+(const Poly& o) const;
  Poly operator-(const Poly& o) const;
  Poly operator*(const Poly& o) const;
  Poly operator*(const Rational& k) const;
  // returns q(t) = p(c + t), exactly.
  Poly shifted(const Rational& c) const;
};

// returns the monic greatest common divisor of p and q (zero when both are).
Poly gcd(Poly p, Poly q);
// returns p / q for a q that divides p exactly.
Poly exact_quotient(const Poly& p, const Poly& q);

// returns the rational with the smallest denominator strictly between low < high (the
// continued-fraction walk of the Stern-Brocot tree): short numbers for sample points.
Rational simplest_between(const Rational& low, const Rational& high);

// returns a double strictly between the doubles low < high with few significant bits (a
// multiple of the largest power of two that leaves one between them): short numbers for
// sample points found from intervals; nullopt when no double lies between them.
std::optional<double> short_between(double low, double high);

using RationalVector2 = ExactKernel::Vector_2;

// a s^2 + b s t + c t^2 + d s + e t + f in frame coordinates (s, t) (a line when a = b = c
// = 0).
struct Quadratic2 {
  Rational a, b, c, d, e, f;
  Rational operator()(const RationalPoint2& p) const;
  bool straight() const { return CGAL::is_zero(a) && CGAL::is_zero(b) && CGAL::is_zero(c); }
};

// an affine function d s + e t + f of the frame coordinates.
struct Affine2 {
  Rational d, e, f;
  Rational operator()(const RationalPoint2& p) const { return d * p.x() + e * p.y() + f; }
  Quadratic2 line() const { return {0, 0, 0, d, e, f}; }
  Quadratic2 operator*(const Affine2& o) const;
  Affine2 operator-(const Affine2& o) const { return {d - o.d, e - o.e, f - o.f}; }
};

// A curve of the sweep: r = -num(s) / den(s) where den(s) != 0.
struct PencilCurve {
  Poly num, den;
  Rational r(const Rational& s) const { return -num(s) / den(s); }
};

// A curve of the sweep with its coefficients rounded to the nearest doubles once, for the
// many evaluations of densifying and quadrature: r(t) = -num(t) / den(t) by Horner's rule.
struct DoubleCurve {
  DoubleCurve(const Poly& num, const Poly& den);
  explicit DoubleCurve(const PencilCurve& curve) : DoubleCurve(curve.num, curve.den) {}
  // the curve in t = s - c around s = c (Taylor's shift made exactly, then rounded), so
  // that a pencil whose s lies far from 0 keeps its digits.
  static DoubleCurve around(const PencilCurve& curve, const Rational& c) {
    return {curve.num.shifted(c), curve.den.shifted(c)};
  }
  double r(double t) const;
  std::vector<double> num, den;
};

// The enclosures of a polynomial's coefficients (increasing powers), for interval filters.
std::vector<Interval> enclosures(const Poly& p);

// enclosures of the coefficients of a b and a - b from those of a and b (upward rounding).
std::vector<Interval> product(const std::vector<Interval>& a, const std::vector<Interval>& b);
std::vector<Interval> difference(const std::vector<Interval>& a, const std::vector<Interval>& b);

// the enclosure of the polynomial with coefficient enclosures c over s, by Horner's rule
// (upward rounding).
Interval horner(const std::vector<Interval>& c, const Interval& s);

// true when the intervals show that the polynomial with coefficient enclosures c has no root
// in the closed range s (upward rounding): neither its Horner enclosure over s nor its mean
// value form about a point m of s, p(m) + p'(s) (s - m), holds 0. False decides nothing.
bool surely_no_root(const std::vector<Interval>& c, const Interval& s);

// The enclosure of a curve of the sweep, for interval filters (upward rounding).
struct IntervalCurve {
  explicit IntervalCurve(const PencilCurve& curve);
  // the enclosure of r(s); nullopt when den's enclosure holds 0.
  std::optional<Interval> r(const Interval& s) const;
  std::vector<Interval> num, den;
};

// What a line or conic is in pencil coordinates: a curve met once per line of the pencil,
// or lines of the pencil themselves (their s are the roots of rays), or nothing.
struct PencilTrace {
  std::optional<PencilCurve> curve;
  Poly rays;  // zero when none; otherwise the lines s = its roots belong to the curve
};

class Pencil {
 public:
  // the cone of directions a..b around the finite x0 (a x b != 0), s in [0, 1].
  static Pencil cone(const RationalPoint2& x0, const RationalVector2& a, const RationalVector2& b);
  // parallel lines along delta; s in [s_low, s_high] across them, n = delta turned left.
  static Pencil parallel(const RationalVector2& delta, const Rational& s_low,
                         const Rational& s_high);

  bool finite() const { return finite_; }
  const Rational& s_low() const { return s_low_; }
  const Rational& s_high() const { return s_high_; }

  RationalPoint2 point(const Rational& s, const Rational& r) const;
  std::array<double, 2> point(double s, double r) const;
  // the point of curve on the line s of the pencil as (x(s), y(s), w(s)): P = (x, y) / w,
  // where w(s) = curve.den(s) != 0.
  std::array<Poly, 3> curve_point(const PencilCurve& curve) const;
  // returns (s, r) of p when p lies in the closed sector (for a cone: p != x0 and p in
  // the closed cone; s may lie outside [s_low, s_high] for parallel lines).
  std::optional<std::pair<Rational, Rational>> coordinates(const RationalPoint2& p) const;
  // returns what the line or conic q = 0 is in this pencil's coordinates. Throws
  // std::logic_error for a conic that misses x0 (no conic of exact_umbra does).
  PencilTrace trace(const Quadratic2& q) const;
  // the enclosures of A's and B's coefficients a0, a1, b0, b1 (for interval filters).
  const std::array<std::array<Interval, 2>, 4>& enclosures() const { return enclosures_; }
  // the area element: dA = jacobian * r dr ds (cone) or jacobian * dr ds (parallel).
  double jacobian() const { return jacobian_; }
  // +1 when larger r lies to the left of the direction of increasing s, -1 otherwise.
  int r_side() const { return r_side_; }

 private:
  bool finite_ = true;
  void enclose();

  RationalVector2 a0_, a1_, b0_, b1_;  // A(s) = a0 + s a1, B(s) = b0 + s b1
  std::array<std::array<Interval, 2>, 4> enclosures_;
  std::array<std::array<double, 2>, 4> doubles_;  // the nearest doubles, for point(double)
  RationalPoint2 origin_;
  Rational s_low_ = 0, s_high_ = 1;
  double jacobian_ = 1;
  int r_side_ = 1;
};

}  // namespace penumbra::detail
