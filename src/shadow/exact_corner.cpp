#include "exact_corner.h"

#include <algorithm>
#include <stdexcept>

#include "algebraic.h"
#include "penumbra/geometry/exact.h"

namespace penumbra::detail {
namespace {

std::array<Rational, 6> coefficients(const Quadratic2& q) {
  return {q.a, q.b, q.c, q.d, q.e, q.f};
}

bool same_curve(const Quadratic2& p, const Quadratic2& q) {
  return coefficients(p) == coefficients(q);
}

// q as a polynomial of degree <= 2 in the variable eliminated: alpha x^2 + beta x + gamma,
// with polynomial coefficients in the other variable.
struct InOneVariable {
  Poly alpha, beta, gamma;
  int degree() const { return !alpha.zero() ? 2 : !beta.zero() ? 1 : 0; }
};

InOneVariable split(const Quadratic2& q, bool eliminate_s) {
  // eliminating t: c t^2 + (b s + e) t + (a s^2 + d s + f); eliminating s likewise.
  if (eliminate_s) return {Poly::constant(q.a), Poly::linear(q.d, q.b), Poly({q.f, q.e, q.c})};
  return {Poly::constant(q.c), Poly::linear(q.e, q.b), Poly({q.f, q.d, q.a})};
}

// The Sylvester determinants of two polynomials of degree <= 2 (up to sign; a constant
// factor raised to a power is left at power one: only the roots matter).
Poly sylvester(const InOneVariable& p, const InOneVariable& q) {
  const int m = p.degree(), n = q.degree();
  if (m == 0 && n == 0) return gcd(p.gamma, q.gamma);
  if (m == 0) return p.gamma;
  if (n == 0) return q.gamma;
  if (m == 1 && n == 1) return p.beta * q.gamma - q.beta * p.gamma;
  if (m == 1) return sylvester(q, p);
  if (n == 1)  // det [[a1 b1 g1] [b2 g2 0] [0 b2 g2]]
    return p.alpha * q.gamma * q.gamma - p.beta * q.beta * q.gamma + p.gamma * q.beta * q.beta;
  const Poly ag = p.alpha * q.gamma - q.alpha * p.gamma;
  return ag * ag - (p.alpha * q.beta - q.alpha * p.beta) * (p.beta * q.gamma - q.beta * p.gamma);
}

// The rationals l <= x <= h overlap [low, high].
bool overlap(const std::pair<Rational, Rational>& a, const std::pair<Rational, Rational>& b) {
  return !(a.second < b.first || b.second < a.first);
}

// the coordinate (0: s, 1: t) of the corner between curves p and q that box encloses, as a
// root of their resultant: the one root whose enclosure meets the corner's.
struct RootChoice {
  Poly polynomial;
  std::vector<Algebraic> roots;
  std::optional<int> chosen;
};

AlgebraicCoordinate coordinate_of(const RootChoice& choice) {
  AlgebraicCoordinate result;
  const std::vector<Rational>& p = choice.polynomial.c;
  if (p.size() == 2) {  // a rational root: written as one
    result.value = exact_number(-p[0] / p[1]);
    return result;
  }
  for (const Rational& c : choice.polynomial.c) result.polynomial.push_back(exact_number(c));
  result.root = *choice.chosen;
  return result;
}

// A corner named, with its coordinates' values (to compare corners without solving again).
struct NamedCorner {
  ExactCorner corner;
  std::array<Algebraic, 2> values;
};

NamedCorner name_corner(const Quadratic2& before, const Quadratic2& after,
                        const CornerEnclosure& enclose) {
  ExactCorner corner;
  if (before.straight() && after.straight()) {
    const Rational det = before.d * after.e - before.e * after.d;
    if (CGAL::is_zero(det)) throw std::logic_error("exact_ring: consecutive parallel lines");
    const Rational s = (before.e * after.f - before.f * after.e) / det;
    const Rational t = (before.f * after.d - before.d * after.f) / det;
    corner.s.value = exact_number(s);
    corner.t.value = exact_number(t);
    return {corner, {algebraic(s), algebraic(t)}};
  }
  std::array<RootChoice, 2> choices;
  for (int k = 0; k < 2; ++k) {
    const Poly r = resultant(before, after, k == 1);
    if (r.degree() < 1)
      throw std::logic_error("exact_ring: two curves of a corner share a component");
    choices[k].polynomial = squarefree_primitive(r);
    choices[k].roots = all_roots(choices[k].polynomial);
  }
  for (int bits = 64; bits <= (1 << 16); bits *= 2) {
    const std::optional<RationalBox> box = enclose(bits);
    if (!box) continue;
    for (int k = 0; k < 2; ++k) {
      RootChoice& choice = choices[k];
      if (choice.chosen) continue;
      std::vector<int> meeting;
      for (std::size_t i = 0; i < choice.roots.size(); ++i)
        if (overlap(enclosure(choice.roots[i], bits), (*box)[k])) meeting.push_back(int(i));
      if (meeting.empty()) throw std::logic_error("exact_ring: a corner off its curves");
      if (meeting.size() == 1) choice.chosen = meeting.front();
    }
    if (choices[0].chosen && choices[1].chosen) {
      corner.s = coordinate_of(choices[0]);
      corner.t = coordinate_of(choices[1]);
      return {corner, {choices[0].roots[*choices[0].chosen], choices[1].roots[*choices[1].chosen]}};
    }
  }
  throw std::logic_error("exact_ring: a corner's roots could not be told apart");
}

Algebraic value_of(const AlgebraicCoordinate& x) {
  if (x.value) return algebraic(exact_value(*x.value));
  std::vector<Rational> c;
  for (const Exact& k : x.polynomial) c.push_back(exact_value(k));
  return all_roots(Poly(std::move(c)))[x.root];
}

// compares corners: s, then t.
int compare(const ExactCorner& a, const ExactCorner& b) {
  for (const auto member : {&ExactCorner::s, &ExactCorner::t}) {
    const AlgebraicCoordinate &x = a.*member, &y = b.*member;
    if (x.value && y.value) {
      const Rational &p = exact_value(*x.value), &q = exact_value(*y.value);
      if (p != q) return p < q ? -1 : 1;
      continue;
    }
    const Algebraic u = value_of(x), v = value_of(y);
    if (u != v) return u < v ? -1 : 1;
  }
  return 0;
}

// compares edges by their curves (after their corners).
int compare_curves(const ExactEdge& a, const ExactEdge& b) {
  for (int k = 0; k < 6; ++k) {
    const Rational &p = exact_value(a.curve[k]), &q = exact_value(b.curve[k]);
    if (p != q) return p < q ? -1 : 1;
  }
  return 0;
}

// compares edges by their corner, then curve.
int compare(const ExactEdge& a, const ExactEdge& b) {
  if (const int c = compare(a.from, b.from)) return c;
  return compare_curves(a, b);
}

bool ring_less(const std::vector<ExactEdge>& a, const std::vector<ExactEdge>& b) {
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    if (const int c = compare(a[k], b[k])) return c < 0;
  return a.size() < b.size();
}

using Range = std::pair<Rational, Rational>;

Range times(const Range& a, const Range& b) {
  const Rational p[4] = {a.first * b.first, a.first * b.second, a.second * b.first,
                         a.second * b.second};
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}

// Horner's scheme on intervals: encloses p over [low, high].
Range poly_range(const Poly& p, const Range& s) {
  Range value{0, 0};
  for (auto k = p.c.rbegin(); k != p.c.rend(); ++k) {
    value = times(value, s);
    value = {value.first + *k, value.second + *k};
  }
  return value;
}

}  // namespace

std::optional<std::pair<Rational, Rational>> ratio_range(const Poly& num, const Poly& den,
                                                         const Rational& low,
                                                         const Rational& high) {
  const Range n = poly_range(num, {low, high}), d = poly_range(den, {low, high});
  if (!(CGAL::is_positive(d.first) || CGAL::is_negative(d.second))) return std::nullopt;
  const Range inverse{1 / d.second, 1 / d.first};
  return times(n, inverse);
}

Quadratic2 normalised(const Quadratic2& q) {
  for (const Rational& k : coefficients(q))
    if (!CGAL::is_zero(k)) return {q.a / k, q.b / k, q.c / k, q.d / k, q.e / k, q.f / k};
  return q;
}

bool degenerate(const Quadratic2& q) {
  if (q.straight()) return false;
  // det [[a, b/2, d/2], [b/2, c, e/2], [d/2, e/2, f]] = 0, times 4
  const Rational det =
      4 * q.a * q.c * q.f + q.b * q.e * q.d - q.a * q.e * q.e - q.c * q.d * q.d - q.f * q.b * q.b;
  return CGAL::is_zero(det);
}

Poly resultant(const Quadratic2& p, const Quadratic2& q, bool eliminate_s) {
  return sylvester(split(p, eliminate_s), split(q, eliminate_s));
}

std::vector<ExactEdge> exact_ring(const std::vector<TracedEdge>& traced) {
  // Merge: an edge that continues the previous one's line or conic adds no corner.
  std::vector<const TracedEdge*> edges;
  std::vector<Quadratic2> curves;
  for (const TracedEdge& edge : traced) {
    const Quadratic2 curve = normalised(edge.curve);
    if (!curves.empty() && same_curve(curves.back(), curve) && !degenerate(curve)) continue;
    edges.push_back(&edge);
    curves.push_back(curve);
  }
  // the last edge may continue into the first
  if (edges.size() > 1 && same_curve(curves.back(), curves.front()) &&
      !degenerate(curves.front())) {
    edges.front() = edges.back();
    edges.pop_back();
    curves.pop_back();
  }
  if (edges.size() < 2) throw std::logic_error("exact_ring: a ring of one curve");
  std::vector<ExactEdge> ring;
  std::vector<std::array<Algebraic, 2>> values;  // each corner's (s, t)
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const Quadratic2& before = curves[(k + curves.size() - 1) % curves.size()];
    ExactEdge edge;
    NamedCorner named = name_corner(before, curves[k], edges[k]->start);
    edge.from = std::move(named.corner);
    values.push_back(std::move(named.values));
    edge.curve = {exact_number(curves[k].a), exact_number(curves[k].b), exact_number(curves[k].c),
                  exact_number(curves[k].d), exact_number(curves[k].e), exact_number(curves[k].f)};
    edge.joint = edges[k]->joint;
    ring.push_back(std::move(edge));
  }
  std::size_t first = 0;
  for (std::size_t k = 1; k < ring.size(); ++k)
    if (values[k] < values[first] ||
        (values[k] == values[first] && compare_curves(ring[k], ring[first]) < 0))
      first = k;
  std::rotate(ring.begin(), ring.begin() + first, ring.end());
  return ring;
}

void canonical_order(std::vector<ExactCurvedPolygon>& polygons) {
  for (ExactCurvedPolygon& polygon : polygons)
    std::sort(polygon.holes.begin(), polygon.holes.end(), ring_less);
  std::sort(polygons.begin(), polygons.end(),
            [](const ExactCurvedPolygon& a, const ExactCurvedPolygon& b) {
              return ring_less(a.outer, b.outer);
            });
}

}  // namespace penumbra::detail
