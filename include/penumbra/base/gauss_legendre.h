#pragma once
// Gauss-Legendre quadrature: the accurate integration behind the Legendre weights of
// Dobashi 1995 eq. (3), the sphere rules of the spherical-harmonic tests and the areas of
// curved umbrae (shadow/exact_umbra.h).

#include <vector>

namespace penumbra {

// A one-dimensional quadrature rule: sum_i weights[i] f(nodes[i]) approximates the
// integral of f over the rule's interval.
struct QuadratureRule {
  std::vector<double> nodes;
  std::vector<double> weights;
};

// computes the points-point Gauss-Legendre rule on [-1, 1], exact for polynomials of
// degree 2 points - 1. The nodes are the zeros of P_points, found by Newton's method
// from Tricomi's estimate cos(pi (i - 1/4) / (points + 1/2)); the weights are
// 2 / ((1 - x^2) P'_points(x)^2) (Abramowitz and Stegun 25.4.29). Nodes increase.
// Precondition: points >= 1.
QuadratureRule gauss_legendre(int points);

// returns rule (on [-1, 1]) mapped affinely onto [a, b].
QuadratureRule mapped(const QuadratureRule& rule, double a, double b);

}  // namespace penumbra
