#pragma once
// Exact predicates on points whose exact values are usually known already (shadow
// polygons from receiver_clip.h): interval arithmetic first, and rationals where the
// interval cannot decide — without the exception CGAL's filtered predicates throw
// and catch for every tie.

#include "penumbra/shadow/region.h"

namespace penumbra::detail {

// returns true when a and b are the same point.
inline bool same_point(const Point2& a, const Point2& b) {
  const auto &p = CGAL::approx(a), &q = CGAL::approx(b);
  if (!CGAL::possibly(p.x() == q.x()) || !CGAL::possibly(p.y() == q.y())) return false;
  return CGAL::exact(a) == CGAL::exact(b);
}

// returns true when the rings have the same points in the same order.
inline bool same_ring(const Ring2& a, const Ring2& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!same_point(a[k], b[k])) return false;
  return true;
}

// returns the sign of the orientation of (a, b, c): POSITIVE for a left turn.
inline CGAL::Sign orientation_sign(const Point2& a, const Point2& b, const Point2& c) {
  {
    CGAL::Protect_FPU_rounding<true> upward;
    const auto &p = CGAL::approx(a), &q = CGAL::approx(b), &r = CGAL::approx(c);
    const auto value = (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
    const CGAL::Uncertain<CGAL::Sign> sign = CGAL::sign(value);
    if (CGAL::is_certain(sign)) return sign.make_certain();
  }
  const auto &p = CGAL::exact(a), &q = CGAL::exact(b), &r = CGAL::exact(c);
  return CGAL::sign((q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x()));
}

}  // namespace penumbra::detail
