// The visible parts of a linear source seen from a receiving point (Nishita 1985 section
// 4.2.3), the solver's tube query: decided in intervals when they are certain, exactly
// otherwise (docs/illuminance.md, "Illuminance in a scene").

#include <algorithm>
#include <array>

#include "penumbra/illuminance/linear_source.h"
#include "solver_impl.h"

namespace penumbra::illuminance {

using namespace detail;

std::vector<ExactInterval> IlluminanceSolver::Impl::linear_visible(const CachedLinear& tube,
                                                                   const QueryPoint& point,
                                                                   const Vec3d& normal,
                                                                   OccluderSubset subset) const {
  const LinearLight& light = *tube.light;
  // Fig. 7, S3: only the part strictly on the outer side of the receiving plane can light P.
  std::optional<ExactInterval> outer;
  const Certainly start_out = outer_side(normal, light.start, point.doubles());
  const Certainly end_out = outer_side(normal, light.end, point.doubles());
  const bool whole_source = start_out == Certainly::yes && end_out == Certainly::yes;
  if (whole_source)
    outer = ExactInterval{0, 1};
  else if (start_out == Certainly::no && end_out == Certainly::no)
    return {};
  else
    outer = outer_side_interval_exact(point.exact(), to_exact_vector(normal), tube.start, tube.end);
  if (!outer) return {};
  // Section 4.2.3: each occluder near the triangle (P, Q1, Q2) hides an open sub-segment,
  // the source clipped by the pyramid from P through its contour. Occluders whose boxes
  // miss the triangle's box, or that the triangle certainly misses, are skipped first.
  const Box triangle = box_of({&point.doubles(), &light.start, &light.end});
  std::vector<ExactInterval> hidden;
  const bool umbra = any_occluder(occluders.size(), subset, [&](std::size_t k) {
    const Occluder& occluder = occluders[k];
    const TubeCull cull = cull_for_tube(occluder, triangle, point.doubles(), light, whole_source);
    if (cull != TubeCull::examine) return cull == TubeCull::hides_all;
    const HiddenRegion region = hidden_region(*occluder.solid, point.exact());
    if (region.empty()) return false;
    const auto blocked = hidden_interval(region, tube.start, tube.end);
    if (!blocked) return false;
    // One occluder hides the whole outer part: umbra.
    if (!(outer->low < blocked->low) && !(blocked->high < outer->high)) return true;
    hidden.push_back(*blocked);
    return false;
  });
  if (umbra) return {};
  return visible_intervals(*outer, std::move(hidden));
}

std::optional<std::vector<SourceInterval>> IlluminanceSolver::Impl::linear_visible_filtered(
    const CachedLinear& tube, const QueryPoint& point, const Vec3d& normal,
    OccluderSubset subset) const {
  const LinearLight& light = *tube.light;
  const CGAL::Protect_FPU_rounding<true> upward;
  // The outer part (Fig. 7, S3) as in linear_visible, its cut u* = F(a) / (F(a) - F(b))
  // with F = n.(Q - P) in intervals.
  const Certainly start_out = outer_side(normal, light.start, point.doubles());
  const Certainly end_out = outer_side(normal, light.end, point.doubles());
  if (start_out == Certainly::unknown || end_out == Certainly::unknown) return std::nullopt;
  if (start_out == Certainly::no && end_out == Certainly::no) return std::vector<SourceInterval>{};
  const bool whole_source = start_out == Certainly::yes && end_out == Certainly::yes;
  Interval outer_low(0), outer_high(1);
  if (!whole_source) {
    const Interval at_start = dot_difference(normal, light.start, point.doubles());
    const Interval at_end = dot_difference(normal, light.end, point.doubles());
    const Interval cut = at_start / (at_start - at_end);
    (start_out == Certainly::yes ? outer_high : outer_low) = cut;
  }
  const Box triangle = box_of({&point.doubles(), &light.start, &light.end});
  std::vector<std::array<Interval, 2>> hidden;
  bool certain = true;
  const bool umbra = any_occluder(occluders.size(), subset, [&](std::size_t k) {
    const Occluder& occluder = occluders[k];
    const TubeCull cull = cull_for_tube(occluder, triangle, point.doubles(), light, whole_source);
    if (cull != TubeCull::examine) return cull == TubeCull::hides_all;
    const HiddenIntervalBounds blocked =
        hidden_interval_filter(*occluder.solid, point.doubles(), light.start, light.end);
    if (blocked.verdict == HiddenIntervalBounds::Verdict::nothing) return false;
    if (blocked.verdict == HiddenIntervalBounds::Verdict::unknown) {
      certain = false;
      return true;
    }
    // One occluder hides the whole outer part: umbra (certainly, or certainly not).
    if (blocked.low.sup() <= outer_low.inf() && outer_high.sup() <= blocked.high.inf()) return true;
    if (!(blocked.low.inf() > outer_low.sup() || blocked.high.sup() < outer_high.inf())) {
      certain = false;
      return true;
    }
    hidden.push_back({blocked.low, blocked.high});
    return false;
  });
  if (!certain) return std::nullopt;
  if (umbra) return std::vector<SourceInterval>{};
  // visible_intervals in intervals: every comparison certain, or the exact path decides.
  std::sort(hidden.begin(), hidden.end(),
            [](const auto& x, const auto& y) { return x[0].inf() < y[0].inf(); });
  for (std::size_t k = 0; k + 1 < hidden.size(); ++k)
    if (!(hidden[k][0].sup() <= hidden[k + 1][0].inf())) return std::nullopt;
  const auto less = [&](const Interval& x, const Interval& y) -> std::optional<bool> {
    if (x.sup() < y.inf()) return true;
    if (x.inf() >= y.sup()) return false;
    return std::nullopt;
  };
  std::vector<std::array<Interval, 2>> visible;
  Interval cursor = outer_low;
  for (const auto& blocked : hidden) {
    const auto open = less(cursor, outer_high);
    if (!open) return std::nullopt;
    if (!*open) break;
    const auto before = less(cursor, blocked[0]);
    if (!before) return std::nullopt;
    if (*before) {
      const auto inside = less(blocked[0], outer_high);
      if (!inside) return std::nullopt;
      visible.push_back({cursor, *inside ? blocked[0] : outer_high});
    }
    const auto extends = less(cursor, blocked[1]);
    if (!extends) return std::nullopt;
    if (*extends) cursor = blocked[1];
  }
  const auto rest = less(cursor, outer_high);
  if (!rest) return std::nullopt;
  if (*rest) visible.push_back({cursor, outer_high});
  // The ends become doubles to integrate, as the exact path's do: known here to within
  // 1e-12 of the piece's length, or the exact path gives them.
  std::vector<SourceInterval> parts;
  for (const auto& piece : visible) {
    const double length = piece[1].inf() - piece[0].sup();
    if (!(piece[0].sup() - piece[0].inf() + piece[1].sup() - piece[1].inf() <= 1e-12 * length))
      return std::nullopt;
    parts.emplace_back(CGAL::to_double(piece[0]), CGAL::to_double(piece[1]));
  }
  return parts;
}

double IlluminanceSolver::Impl::linear_light(const CachedLinear& tube, const QueryPoint& point,
                                             const Vec3d& normal, OccluderSubset subset) const {
  const LinearLight& light = *tube.light;
  // Decided in intervals whenever they are certain (the same parts, up to the rounding of
  // their ends); the exact construction otherwise.
  if (const auto parts = linear_visible_filtered(tube, point, normal, subset)) {
    if (parts->empty()) return 0;
    return linear_illuminance(point.doubles(), normal, light.start, light.end,
                              light.candela_per_metre, *parts);
  }
  const std::vector<ExactInterval> visible = linear_visible(tube, point, normal, subset);
  if (visible.empty()) return 0;
  // The exact interval ends become doubles only here, to integrate the closed form.
  std::vector<SourceInterval> parts;
  parts.reserve(visible.size());
  for (const ExactInterval& part : visible)
    parts.emplace_back(CGAL::to_double(part.low), CGAL::to_double(part.high));
  return linear_illuminance(point.doubles(), normal, light.start, light.end,
                            light.candela_per_metre, parts);
}

}  // namespace penumbra::illuminance
