#include "pencil.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rational_enclosure.h"

namespace penumbra::detail {
namespace {

void trim(std::vector<Rational>& c) {
  while (!c.empty() && CGAL::is_zero(c.back())) c.pop_back();
}

Rational cross(const RationalVector2& a, const RationalVector2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace

Poly::Poly(std::vector<Rational> coefficients) : c(std::move(coefficients)) {
  trim(c);
}

Rational Poly::operator()(const Rational& s) const {
  Rational value = 0;
  for (auto k = c.rbegin(); k != c.rend(); ++k) value = value * s + *k;
  return value;
}

Poly Poly::operator+(const Poly& o) const {
  std::vector<Rational> sum(std::max(c.size(), o.c.size()), Rational(0));
  for (std::size_t k = 0; k < c.size(); ++k) sum[k] += c[k];
  for (std::size_t k = 0; k < o.c.size(); ++k) sum[k] += o.c[k];
  return Poly(std::move(sum));
}

Poly Poly::operator-(const Poly& o) const {
  return *this + o * Rational(-1);
}

Poly Poly::operator*(const Poly& o) const {
  if (zero() || o.zero()) return {};
  std::vector<Rational> product(c.size() + o.c.size() - 1, Rational(0));
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = 0; j < o.c.size(); ++j) product[i + j] += c[i] * o.c[j];
  return Poly(std::move(product));
}

Poly Poly::operator*(const Rational& k) const {
  std::vector<Rational> scaled = c;
  for (Rational& x : scaled) x *= k;
  return Poly(std::move(scaled));
}

namespace {

// returns {quotient, remainder} of p / q (q not zero).
std::pair<Poly, Poly> divide(Poly p, const Poly& q) {
  std::vector<Rational> quotient(p.c.size() >= q.c.size() ? p.c.size() - q.c.size() + 1 : 0,
                                 Rational(0));
  while (!p.zero() && p.degree() >= q.degree()) {
    const int shift = p.degree() - q.degree();
    const Rational k = p.c.back() / q.c.back();
    quotient[shift] = k;
    std::vector<Rational> term(shift + 1, Rational(0));
    term[shift] = k;
    p = p - q * Poly(std::move(term));
  }
  return {Poly(std::move(quotient)), p};
}

}  // namespace

Poly gcd(Poly p, Poly q) {
  while (!q.zero()) {
    Poly remainder = divide(p, q).second;
    p = std::move(q);
    q = std::move(remainder);
  }
  if (p.zero()) return p;
  return p * (Rational(1) / p.c.back());
}

Poly exact_quotient(const Poly& p, const Poly& q) {
  return divide(p, q).first;
}

namespace {

Rational floor_of(const Rational& x) {
  Rational result = x;
  mpz_fdiv_q(mpq_numref(result.get_mpq_t()), mpq_numref(x.get_mpq_t()), mpq_denref(x.get_mpq_t()));
  mpz_set_ui(mpq_denref(result.get_mpq_t()), 1);
  return result;
}

}  // namespace

Rational simplest_between(const Rational& low, const Rational& high) {
  const Rational whole = floor_of(low) + 1;
  if (whole < high) {
    // an integer lies strictly between: the one nearest zero
    if (!CGAL::is_positive(whole) && CGAL::is_positive(high)) return 0;
    if (CGAL::is_negative(high)) {
      const Rational top = -floor_of(-high) - 1;  // the largest integer below high
      return top > low ? top : whole;
    }
    return whole;
  }
  // low and high share the unit interval [f, f + 1]: f + 1 / x with x between the inverses.
  const Rational f = whole - 1;
  if (low == f) return f + Rational(1) / (floor_of(Rational(1) / (high - f)) + 1);
  return f + Rational(1) / simplest_between(Rational(1) / (high - f), Rational(1) / (low - f));
}

Rational Quadratic2::operator()(const RationalPoint2& p) const {
  const Rational& x = p.x();
  const Rational& y = p.y();
  return a * x * x + b * x * y + c * y * y + d * x + e * y + f;
}

Quadratic2 Affine2::operator*(const Affine2& o) const {
  return {d * o.d, d * o.e + e * o.d, e * o.e, d * o.f + f * o.d, e * o.f + f * o.e, f * o.f};
}

Pencil Pencil::cone(const RationalPoint2& x0, const RationalVector2& a, const RationalVector2& b) {
  Pencil pencil;
  pencil.finite_ = true;
  pencil.origin_ = x0;
  pencil.a0_ = x0 - CGAL::ORIGIN;
  pencil.a1_ = RationalVector2(0, 0);
  pencil.b0_ = a;
  pencil.b1_ = b - a;
  const Rational det = cross(a, b);
  if (CGAL::is_zero(det)) throw std::logic_error("a pencil cone needs two independent directions");
  pencil.jacobian_ = std::abs(CGAL::to_double(det));
  // dP/dr x dP/ds = r (a x b): when positive, increasing s turns left of the ray, so the
  // ray's far side (larger r) is on the right of the direction of increasing s.
  pencil.r_side_ = CGAL::is_positive(det) ? -1 : 1;
  pencil.enclose();
  return pencil;
}

Pencil Pencil::parallel(const RationalVector2& delta, const Rational& s_low,
                        const Rational& s_high) {
  Pencil pencil;
  pencil.finite_ = false;
  pencil.origin_ = RationalPoint2(0, 0);
  const RationalVector2 n(-delta.y(), delta.x());
  pencil.a0_ = RationalVector2(0, 0);
  pencil.a1_ = n;
  pencil.b0_ = delta;
  pencil.b1_ = RationalVector2(0, 0);
  pencil.s_low_ = s_low;
  pencil.s_high_ = s_high;
  const Rational det = cross(delta, n);  // = |delta|^2 > 0
  pencil.jacobian_ = CGAL::to_double(det);
  pencil.r_side_ = -1;
  pencil.enclose();
  return pencil;
}

Poly Poly::shifted(const Rational& shift) const {
  // Taylor's shift by repeated synthetic division by (s - shift).
  std::vector<Rational> q = c;
  const std::size_t n = q.size();
  for (std::size_t k = 0; k + 1 < n; ++k)
    for (std::size_t i = n - 1; i > k; --i) q[i - 1] += shift * q[i];
  return Poly(std::move(q));
}

std::optional<double> short_between(double low, double high) {
  const double width = high - low;
  if (!(low < high) || !std::isfinite(width)) return std::nullopt;
  // (every step is exact while g is at least the spacing of the doubles near low)
  for (double g = std::ldexp(1.0, std::ilogb(width)); g > 0; g /= 2) {
    const double c = (std::floor(low / g) + 1) * g;
    if (c > low && c < high) return c;
    if (std::nextafter(low, high) >= high) break;  // adjacent: nothing between
  }
  return std::nullopt;
}

std::vector<Interval> enclosures(const Poly& p) {
  std::vector<Interval> result;
  for (const Rational& c : p.c) result.push_back(enclosure(c));
  return result;
}

std::vector<Interval> product(const std::vector<Interval>& a, const std::vector<Interval>& b) {
  if (a.empty() || b.empty()) return {};
  std::vector<Interval> result(a.size() + b.size() - 1, Interval(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) result[i + j] += a[i] * b[j];
  return result;
}

std::vector<Interval> difference(const std::vector<Interval>& a, const std::vector<Interval>& b) {
  std::vector<Interval> result(std::max(a.size(), b.size()), Interval(0));
  for (std::size_t k = 0; k < a.size(); ++k) result[k] += a[k];
  for (std::size_t k = 0; k < b.size(); ++k) result[k] -= b[k];
  return result;
}

Interval horner(const std::vector<Interval>& c, const Interval& s) {
  Interval value = 0;
  for (auto k = c.rbegin(); k != c.rend(); ++k) value = value * s + *k;
  return value;
}

bool surely_no_root(const std::vector<Interval>& c, const Interval& s) {
  const auto holds_zero = [](const Interval& x) { return x.inf() <= 0 && x.sup() >= 0; };
  if (!holds_zero(horner(c, s))) return true;
  if (c.size() < 2) return false;  // a zero constant
  // mean value theorem: p(x) = p(m) + p'(xi) (x - m) for some xi between m and x, in s.
  const double m = std::clamp(s.inf() / 2 + s.sup() / 2, s.inf(), s.sup());
  std::vector<Interval> derivative;
  for (std::size_t k = 1; k < c.size(); ++k) derivative.push_back(c[k] * static_cast<double>(k));
  return !holds_zero(horner(c, Interval(m)) + horner(derivative, s) * (s - m));
}

namespace {

std::vector<double> nearest_doubles(const Poly& p) {
  std::vector<double> c;
  for (const Rational& x : p.c) c.push_back(CGAL::to_double(x));
  return c;
}

double horner(const std::vector<double>& c, double t) {
  double value = 0;
  for (auto k = c.rbegin(); k != c.rend(); ++k) value = value * t + *k;
  return value;
}

}  // namespace

DoubleCurve::DoubleCurve(const Poly& num_, const Poly& den_)
    : num(nearest_doubles(num_)), den(nearest_doubles(den_)) {}

double DoubleCurve::r(double t) const {
  return -horner(num, t) / horner(den, t);
}

IntervalCurve::IntervalCurve(const PencilCurve& curve)
    : num(enclosures(curve.num)), den(enclosures(curve.den)) {}

std::optional<Interval> IntervalCurve::r(const Interval& s) const {
  const Interval d = horner(den, s);
  if (d.inf() <= 0 && d.sup() >= 0) return std::nullopt;
  return -horner(num, s) / d;
}

void Pencil::enclose() {
  const RationalVector2* vectors[4] = {&a0_, &a1_, &b0_, &b1_};
  for (int k = 0; k < 4; ++k) {
    enclosures_[k] = {enclosure(vectors[k]->x()), enclosure(vectors[k]->y())};
    doubles_[k] = {CGAL::to_double(vectors[k]->x()), CGAL::to_double(vectors[k]->y())};
  }
}

RationalPoint2 Pencil::point(const Rational& s, const Rational& r) const {
  return CGAL::ORIGIN + (a0_ + s * a1_) + r * (b0_ + s * b1_);
}

std::array<Poly, 3> Pencil::curve_point(const PencilCurve& curve) const {
  // P = A(s) + r B(s) with r = -num / den: P den = A den - num B.
  std::array<Poly, 3> result;
  for (int k = 0; k < 2; ++k) {
    const Poly a = Poly::linear(a0_[k], a1_[k]), b = Poly::linear(b0_[k], b1_[k]);
    result[k] = a * curve.den - curve.num * b;
  }
  result[2] = curve.den;
  return result;
}

std::array<double, 2> Pencil::point(double s, double r) const {
  const auto& [a0, a1, b0, b1] = doubles_;
  return {a0[0] + s * a1[0] + r * (b0[0] + s * b1[0]), a0[1] + s * a1[1] + r * (b0[1] + s * b1[1])};
}

std::optional<std::pair<Rational, Rational>> Pencil::coordinates(const RationalPoint2& p) const {
  const RationalVector2 w = p - CGAL::ORIGIN - a0_;
  if (finite_) {
    // w = alpha a + beta b with a = b0, b = b0 + b1: r = alpha + beta, s = beta / r.
    const RationalVector2 b = b0_ + b1_;
    const Rational det = cross(b0_, b);
    const Rational alpha = cross(w, b) / det, beta = cross(b0_, w) / det;
    if (CGAL::is_negative(alpha) || CGAL::is_negative(beta)) return std::nullopt;
    const Rational r = alpha + beta;
    if (CGAL::is_zero(r)) return std::nullopt;
    return std::make_pair(beta / r, r);
  }
  // w = s n + r delta.
  const Rational det = cross(a1_, b0_);
  return std::make_pair(cross(w, b0_) / det, cross(a1_, w) / det);
}

PencilTrace Pencil::trace(const Quadratic2& q) const {
  // q(X + r Y) = c0 + c1 r + c2 r^2; for a line c2 = 0 and c0, c1 are affine in s.
  Poly c0, c1, c2;
  if (q.straight()) {
    c1 = Poly::linear(q.d * b0_.x() + q.e * b0_.y(), q.d * b1_.x() + q.e * b1_.y());
    c0 = Poly::linear(q.d * a0_.x() + q.e * a0_.y() + q.f, q.d * a1_.x() + q.e * a1_.y());
  } else {
    const Poly xu = Poly::linear(a0_.x(), a1_.x()), xv = Poly::linear(a0_.y(), a1_.y());
    const Poly yu = Poly::linear(b0_.x(), b1_.x()), yv = Poly::linear(b0_.y(), b1_.y());
    c2 = yu * yu * q.a + yu * yv * q.b + yv * yv * q.c;
    c1 =
        xu * yu * (2 * q.a) + (xu * yv + xv * yu) * q.b + xv * yv * (2 * q.c) + yu * q.d + yv * q.e;
    c0 = xu * xu * q.a + xu * xv * q.b + xv * xv * q.c + xu * q.d + xv * q.e + Poly::constant(q.f);
  }
  Poly num, den;
  PencilTrace trace;
  if (c2.zero()) {
    if (c1.zero()) {
      trace.rays = c0;  // lines of the pencil (or nothing when c0 is a nonzero constant)
      return trace;
    }
    if (c0.zero() && finite_) {
      trace.rays = c1;  // r = 0: lines through x0
      return trace;
    }
    num = c0;
    den = c1;
  } else {
    if (!c0.zero()) throw std::logic_error("a conic of the sweep misses the pencil's centre");
    if (c1.zero()) {
      trace.rays = c2;  // a pair of lines through x0
      return trace;
    }
    num = c1;
    den = c2;
  }
  // A common factor of num and den is a line of the pencil on the curve (a degenerate
  // conic); the rest is met once per line. (A constant has none: no gcd needed.)
  const Poly common = num.degree() >= 1 && den.degree() >= 1 ? gcd(num, den) : Poly();
  if (common.degree() >= 1) {
    trace.rays = common;
    num = exact_quotient(num, common);
    den = exact_quotient(den, common);
  }
  // (r = 0 is the centre of a cone, but a line like any other across parallel lines)
  if (!finite_ || !num.zero()) trace.curve = PencilCurve{num, den};
  return trace;
}

}  // namespace penumbra::detail
