#include "penumbra/geometry/exact_sum.h"

#include <cmath>
#include <limits>
#include <utility>

#include "penumbra/geometry/exact.h"

namespace penumbra {

Enclosure Enclosure::of(const Rational& x) {
  mpz_class shifted = x.get_num(), remainder;
  mpz_mul_2exp(shifted.get_mpz_t(), shifted.get_mpz_t(), kEnclosureBits);
  Enclosure e;
  mpz_fdiv_qr(e.lower.get_mpz_t(), remainder.get_mpz_t(), shifted.get_mpz_t(), x.get_den_mpz_t());
  e.upper = remainder == 0 ? e.lower : e.lower + 1;
  return e;
}

namespace {

// returns bound / 2^kEnclosureBits rounded toward zero: mpz_get_d truncates, and scaling by a
// power of two is exact (a nonzero bound is at least 2^-kEnclosureBits, far from underflow).
double truncated(const mpz_class& bound) {
  return std::ldexp(bound.get_d(), -static_cast<int>(kEnclosureBits));
}

CGAL::Interval_nt<false> interval_of(const Enclosure& e) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double low = truncated(e.lower), high = truncated(e.upper);
  // Toward zero is downward for a non-negative bound and upward for a negative one.
  return {sgn(e.lower) >= 0 ? low : std::nextafter(low, -inf),
          sgn(e.upper) <= 0 ? high : std::nextafter(high, inf)};
}

class SumRep final : public CGAL::Lazy_exact_nt_rep<Rational> {
 public:
  SumRep(Enclosure enclosure, std::vector<Rational> leaves, std::vector<Exact> others,
         std::function<Rational()> deferred = {})
      : CGAL::Lazy_exact_nt_rep<Rational>(interval_of(enclosure)),
        enclosure_(std::move(enclosure)),
        leaves_(std::move(leaves)),
        others_(std::move(others)),
        deferred_(std::move(deferred)) {}

  const Enclosure& enclosure() const { return enclosure_; }

  void update_exact() const override {
    std::vector<Rational> values = std::move(leaves_);
    for (const Exact& other : others_) values.push_back(exact_value(other));
    if (deferred_) values.push_back(deferred_());
    auto* exact = new Indirect(pairwise_sum(std::move(values)));
    this->set_at(exact);
    this->set_ptr(exact);
    leaves_.clear();
    others_.clear();
    deferred_ = nullptr;
  }

 private:
  const Enclosure enclosure_;
  mutable std::vector<Rational> leaves_;
  mutable std::vector<Exact> others_;
  mutable std::function<Rational()> deferred_;
};

// returns x's representation when x is a sum made here. (CGAL keeps a lazy number's
// representation private; Handle hands out its address for Compact_container.)
const SumRep* sum_rep(const Exact& x) {
  return dynamic_cast<const SumRep*>(static_cast<const CGAL::Rep*>(x.for_compact_container()));
}

}  // namespace

Rational pairwise_sum(std::vector<Rational> values) {
  if (values.empty()) return 0;
  for (std::size_t width = 1; width < values.size(); width *= 2)
    for (std::size_t k = 0; k + width < values.size(); k += 2 * width)
      values[k] += values[k + width];
  return std::move(values.front());
}

Exact exact_sum(const std::vector<Exact>& terms) {
  Enclosure enclosure;
  std::vector<Rational> leaves;
  std::vector<Exact> sums;
  for (const Exact& term : terms) {
    if (const SumRep* rep = sum_rep(term)) {
      enclosure.add(rep->enclosure());
      sums.push_back(term);
    } else {
      leaves.push_back(exact_value(term));
      enclosure.add(Enclosure::of(leaves.back()));
    }
  }
  return Exact(new SumRep(std::move(enclosure), std::move(leaves), std::move(sums)));
}

Exact exact_sum(const std::vector<Enclosure>& terms, std::function<Rational()> exact) {
  Enclosure enclosure;
  for (const Enclosure& term : terms) enclosure.add(term);
  return Exact(new SumRep(std::move(enclosure), {}, {}, std::move(exact)));
}

std::optional<Enclosure> enclosure_of(const Exact& x) {
  if (const SumRep* rep = sum_rep(x)) return rep->enclosure();
  return std::nullopt;
}

std::optional<double> truncated_to_double(const Exact& x) {
  const SumRep* rep = sum_rep(x);
  if (!rep) return std::nullopt;
  // Rounding toward zero is monotone: the ends agreeing decide every value between them.
  const double low = truncated(rep->enclosure().lower);
  if (low != truncated(rep->enclosure().upper)) return std::nullopt;
  return low;
}

}  // namespace penumbra
