#pragma once
// Lanczos sigma factors against the Gibbs ripples of a truncated Legendre series:
// Dobashi 1995 section 3.3.2, eqs. (12)-(13), after Hamming 1977.

#include <vector>

namespace penumbra::basis {

// returns sigma(N, l) of eq. (13): 1 for l = 0, else sin(t) / t with t = pi l / (N + 1).
// It is the factor by which averaging over one period of the first neglected degree
// (N + 1) damps degree l: for a Fourier mode cos(l x), the mean over
// [x - pi / (N + 1), x + pi / (N + 1)] is sin(t) / t cos(l x). Preconditions:
// 0 <= l, 0 <= degree.
double sigma_factor(int degree, int l);

// returns sigma(N, 0) .. sigma(N, N).
std::vector<double> sigma_factors(int degree);

}  // namespace penumbra::basis
