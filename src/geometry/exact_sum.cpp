#include "penumbra/geometry/exact_sum.h"

#include <cmath>
#include <limits>
#include <utility>

#include "penumbra/geometry/exact.h"

namespace penumbra {

GridFloor GridFloor::of(const Rational& x) {
  GridFloor result;
  const mpz_srcptr den = x.get_den_mpz_t();
  const mp_bitcnt_t twos = mpz_scan1(den, 0);
  if (mpz_sizeinbase(den, 2) == twos + 1 && twos <= kEnclosureBits) {
    // A denominator 2^twos (a double's): a shift, nothing rounded away.
    mpz_mul_2exp(result.floor.get_mpz_t(), x.get_num_mpz_t(), kEnclosureBits - twos);
    return result;
  }
  mpz_class shifted, remainder;
  mpz_mul_2exp(shifted.get_mpz_t(), x.get_num_mpz_t(), kEnclosureBits);
  mpz_fdiv_qr(result.floor.get_mpz_t(), remainder.get_mpz_t(), shifted.get_mpz_t(), den);
  result.exact = remainder == 0;
  return result;
}

Enclosure Enclosure::of(const Rational& x) {
  GridFloor grid = GridFloor::of(x);
  Enclosure e;
  e.upper = grid.exact ? grid.floor : grid.floor + 1;
  e.lower = std::move(grid.floor);
  return e;
}

namespace {

// adds |x| to sum.
void add_abs(mpz_class& sum, const mpz_class& x) {
  if (sgn(x) >= 0)
    mpz_add(sum.get_mpz_t(), sum.get_mpz_t(), x.get_mpz_t());
  else
    mpz_sub(sum.get_mpz_t(), sum.get_mpz_t(), x.get_mpz_t());
}

// adds to bound what bounds |X_i b_j + a_i Y_j + a_i b_j|.
void add_error(mpz_class& bound, const GridFloor& xi, const GridFloor& yj) {
  if (!yj.exact) add_abs(bound, xi.floor);
  if (!xi.exact) add_abs(bound, yj.floor);
  if (!xi.exact && !yj.exact) ++bound;
}

}  // namespace

void ShoelaceEnclosure::add_edge(const GridFloor& xi, const GridFloor& yi, const GridFloor& xj,
                                 const GridFloor& yj) {
  mpz_addmul(sum_.get_mpz_t(), xi.floor.get_mpz_t(), yj.floor.get_mpz_t());
  mpz_submul(sum_.get_mpz_t(), xj.floor.get_mpz_t(), yi.floor.get_mpz_t());
  add_error(bound_, xi, yj);
  add_error(bound_, xj, yi);
}

void ShoelaceEnclosure::add(const ShoelaceEnclosure& other) {
  sum_ += other.sum_;
  bound_ += other.bound_;
}

void ShoelaceEnclosure::remove(const ShoelaceEnclosure& other) {
  sum_ -= other.sum_;
  bound_ += other.bound_;
}

std::optional<int> ShoelaceEnclosure::sign() const {
  if (cmp(sum_, bound_) > 0) return 1;
  if (cmp(sum_, -bound_) < 0) return -1;
  if (sgn(bound_) == 0) return 0;  // sum is exact, and 0
  return std::nullopt;
}

Enclosure ShoelaceEnclosure::area() const {
  // area 2^k = (twice 2^2k) / 2^(k + 1).
  Enclosure area;
  mpz_class end = sum_ - bound_;
  mpz_fdiv_q_2exp(area.lower.get_mpz_t(), end.get_mpz_t(), kEnclosureBits + 1);
  end = sum_ + bound_;
  mpz_cdiv_q_2exp(area.upper.get_mpz_t(), end.get_mpz_t(), kEnclosureBits + 1);
  return area;
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
