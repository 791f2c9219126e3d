#include "planar_derivation.hpp"

#include <cmath>
#include <numbers>

namespace rodvv::solution_files {

namespace {

// Derivative at s[i] of the quadratic through the three nodes a, b, c (any of which may be i).
double quadratic_slope(const std::vector<double>& s, const std::vector<double>& f, std::size_t a, std::size_t b,
                       std::size_t c, std::size_t i) {
  // Lagrange basis derivatives: l_a'(x) = ((x - s_b) + (x - s_c)) / ((s_a - s_b)(s_a - s_c)), etc.
  const double x = s[i];
  const auto basis = [&](std::size_t p, std::size_t q, std::size_t r) {
    return ((x - s[q]) + (x - s[r])) / ((s[p] - s[q]) * (s[p] - s[r]));
  };
  return f[a] * basis(a, b, c) + f[b] * basis(b, a, c) + f[c] * basis(c, a, b);
}

}  // namespace

std::vector<double> derivative(const std::vector<double>& s, const std::vector<double>& f) {
  const std::size_t n = s.size();
  std::vector<double> d(n);
  if (n == 2) {
    d[0] = d[1] = (f[1] - f[0]) / (s[1] - s[0]);
    return d;
  }
  d[0] = quadratic_slope(s, f, 0, 1, 2, 0);
  for (std::size_t i = 1; i + 1 < n; ++i) d[i] = quadratic_slope(s, f, i - 1, i, i + 1, i);
  d[n - 1] = quadratic_slope(s, f, n - 3, n - 2, n - 1, n - 1);
  return d;
}

std::vector<double> tangent_angle(const std::vector<double>& s, const std::vector<double>& x,
                                  const std::vector<double>& y) {
  const auto dx = derivative(s, x), dy = derivative(s, y);
  std::vector<double> theta(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    theta[i] = std::atan2(dy[i], dx[i]);
    if (i > 0) theta[i] -= 2.0 * std::numbers::pi * std::round((theta[i] - theta[i - 1]) / (2.0 * std::numbers::pi));
  }
  return theta;
}

}  // namespace rodvv::solution_files
