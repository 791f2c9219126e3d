#pragma once
// Forward-mode automatic differentiation to second order with a compile-time number of variables:
// a Jet<N, 2> carries a value f, its gradient df/dw (N entries) and its Hessian d2f/dw2 (symmetric,
// N (N + 1) / 2 entries: the lower triangle packed column by column); a Jet<N, 1> carries the value
// and the gradient only. Private to solvers/rod3d (discrete_energy.cpp and its tests).
//
// Why not Eigen's AutoDiffScalar: second derivatives with it mean nesting (an AutoDiffScalar whose
// derivatives are AutoDiffScalars), which forms the Hessian as N gradients of N gradients through
// expression templates: N + 2 N^2 numbers per scalar, no symmetry, and several passes per operation.
// The direct second-order rules below (forward propagation of gradients and Hessians; Griewank &
// Walther, "Evaluating Derivatives", 2nd ed., SIAM 2008) do one fused pass per operation over the
// N (N + 1) / 2 distinct Hessian entries:
//   (a + b)''  = a'' + b''
//   (a b)''    = a b'' + b a'' + a' b'^T + b' a'^T
//   (a / b)''  = (a'' - q b'' - q' b'^T - b' q'^T) / b          with q = a / b  (from a = q b)
//   (phi(a))'' = phi'(a) a'' + phi''(a) a' a'^T                 for phi = sqrt, sin, cos, asin, c / x
// The derivatives are exact up to round-off (no finite differences) and the Hessian is symmetric by
// construction (only one triangle exists).
//
// The number of variables is a template parameter so that a computation can be staged: quantities
// that depend on a few variables only are computed with a small jet and then lift()ed (embedded,
// zero-padded) into a larger one, which is exact - their derivatives with respect to the other
// variables are zero. Operations with plain doubles (constants) are scalings, much cheaper than a
// product of two jets; the constructor from a double is explicit so that no jet is made by accident.
#include <array>
#include <cmath>
#include <cstddef>

namespace rodvv::solvers::rod3d::taylor2 {

template <int N, int Order = 2>
struct Jet {
  static_assert(N >= 1, "a jet needs at least one variable");
  static_assert(Order == 1 || Order == 2, "jets of order 1 (gradient) or 2 (gradient and Hessian)");
  static constexpr int kVariables = N;
  static constexpr int kOrder = Order;
  static constexpr int kHessianSize = Order == 2 ? N * (N + 1) / 2 : 0;

  // Position of d2f/dw_i dw_j (i >= j) in h: column j starts after columns 0 .. j-1 of lengths N - c.
  static constexpr int packed(int i, int j) { return j * N - j * (j - 1) / 2 + (i - j); }

  double v = 0.0;                        // value
  std::array<double, N> g{};             // gradient
  std::array<double, kHessianSize> h{};  // Hessian, lower triangle packed by columns (see packed())

  Jet() = default;
  explicit Jet(double value) : v(value) {}  // a constant
  // The independent variable w_index at the given value.
  static Jet variable(double value, int index) {
    Jet x(value);
    x.g[static_cast<std::size_t>(index)] = 1.0;
    return x;
  }
  // d2f/dw_i dw_j, either order of i and j.
  double hessian(int i, int j) const
    requires(Order == 2)
  {
    return i >= j ? h[static_cast<std::size_t>(packed(i, j))] : h[static_cast<std::size_t>(packed(j, i))];
  }
};

namespace detail {
// phi(a) from f0 = phi(a.v), f1 = phi'(a.v), f2 = phi''(a.v): the chain rule to second order.
template <int N, int O>
Jet<N, O> chain(const Jet<N, O>& a, double f0, double f1, double f2) {
  Jet<N, O> r(f0);
  for (int i = 0; i < N; ++i) r.g[i] = f1 * a.g[i];
  if constexpr (O == 2) {
    int k = 0;
    for (int j = 0; j < N; ++j)
      for (int i = j; i < N; ++i, ++k) r.h[k] = f1 * a.h[k] + f2 * (a.g[i] * a.g[j]);
  }
  return r;
}
// alpha a + beta b (linear: no cross terms).
template <int N, int O>
Jet<N, O> combine(double alpha, const Jet<N, O>& a, double beta, const Jet<N, O>& b) {
  Jet<N, O> r(alpha * a.v + beta * b.v);
  for (int i = 0; i < N; ++i) r.g[i] = alpha * a.g[i] + beta * b.g[i];
  for (int k = 0; k < Jet<N, O>::kHessianSize; ++k) r.h[k] = alpha * a.h[k] + beta * b.h[k];
  return r;
}
template <int N, int O>
Jet<N, O> scale(double alpha, const Jet<N, O>& a) {
  Jet<N, O> r(alpha * a.v);
  for (int i = 0; i < N; ++i) r.g[i] = alpha * a.g[i];
  for (int k = 0; k < Jet<N, O>::kHessianSize; ++k) r.h[k] = alpha * a.h[k];
  return r;
}
}  // namespace detail

// ---- arithmetic between jets ---------------------------------------------------------------------

template <int N, int O>
Jet<N, O> operator+(const Jet<N, O>& a, const Jet<N, O>& b) {
  return detail::combine(1.0, a, 1.0, b);
}
template <int N, int O>
Jet<N, O> operator-(const Jet<N, O>& a, const Jet<N, O>& b) {
  return detail::combine(1.0, a, -1.0, b);
}
template <int N, int O>
Jet<N, O> operator-(const Jet<N, O>& a) {
  return detail::scale(-1.0, a);
}

template <int N, int O>
Jet<N, O> operator*(const Jet<N, O>& a, const Jet<N, O>& b) {
  Jet<N, O> r(a.v * b.v);
  for (int i = 0; i < N; ++i) r.g[i] = a.v * b.g[i] + b.v * a.g[i];
  if constexpr (O == 2) {
    int k = 0;
    for (int j = 0; j < N; ++j)
      for (int i = j; i < N; ++i, ++k) r.h[k] = a.v * b.h[k] + b.v * a.h[k] + (a.g[i] * b.g[j] + b.g[i] * a.g[j]);
  }
  return r;
}

// q = a / b: a = q b differentiated once and twice, solved for q' and q'' (one division).
template <int N, int O>
Jet<N, O> operator/(const Jet<N, O>& a, const Jet<N, O>& b) {
  const double inv = 1.0 / b.v;
  Jet<N, O> q(a.v * inv);
  for (int i = 0; i < N; ++i) q.g[i] = (a.g[i] - q.v * b.g[i]) * inv;
  if constexpr (O == 2) {
    int k = 0;
    for (int j = 0; j < N; ++j)
      for (int i = j; i < N; ++i, ++k) q.h[k] = (a.h[k] - q.v * b.h[k] - (q.g[i] * b.g[j] + b.g[i] * q.g[j])) * inv;
  }
  return q;
}

// ---- arithmetic with constants -------------------------------------------------------------------

template <int N, int O>
Jet<N, O> operator+(const Jet<N, O>& a, double c) {
  Jet<N, O> r = a;
  r.v += c;
  return r;
}
template <int N, int O>
Jet<N, O> operator+(double c, const Jet<N, O>& a) {
  return a + c;
}
template <int N, int O>
Jet<N, O> operator-(const Jet<N, O>& a, double c) {
  return a + (-c);
}
template <int N, int O>
Jet<N, O> operator-(double c, const Jet<N, O>& a) {
  return -a + c;
}
template <int N, int O>
Jet<N, O> operator*(const Jet<N, O>& a, double c) {
  return detail::scale(c, a);
}
template <int N, int O>
Jet<N, O> operator*(double c, const Jet<N, O>& a) {
  return detail::scale(c, a);
}
template <int N, int O>
Jet<N, O> operator/(const Jet<N, O>& a, double c) {
  return detail::scale(1.0 / c, a);
}
// c / a = phi(a) with phi(x) = c / x: phi' = -c / x^2, phi'' = 2 c / x^3.
template <int N, int O>
Jet<N, O> operator/(double c, const Jet<N, O>& a) {
  const double inv = 1.0 / a.v, q = c * inv;
  return detail::chain(a, q, -q * inv, 2.0 * q * inv * inv);
}

// ---- elementary functions (found by argument-dependent lookup, next to std::sin etc.) ------------

template <int N, int O>
Jet<N, O> sqrt(const Jet<N, O>& a) {
  const double s = std::sqrt(a.v);
  return detail::chain(a, s, 0.5 / s, -0.25 / (s * a.v));
}
template <int N, int O>
Jet<N, O> sin(const Jet<N, O>& a) {
  const double s = std::sin(a.v), c = std::cos(a.v);
  return detail::chain(a, s, c, -s);
}
template <int N, int O>
Jet<N, O> cos(const Jet<N, O>& a) {
  const double s = std::sin(a.v), c = std::cos(a.v);
  return detail::chain(a, c, -s, -c);
}
// asin' = (1 - x^2)^(-1/2), asin'' = x (1 - x^2)^(-3/2): finite for |x| < 1 (the caller's chart).
template <int N, int O>
Jet<N, O> asin(const Jet<N, O>& a) {
  const double d = 1.0 / std::sqrt(1.0 - a.v * a.v);
  return detail::chain(a, std::asin(a.v), d, a.v * d * d * d);
}

// ---- staging -------------------------------------------------------------------------------------

// The jet a of variables (w_0 .. w_{N-1}) as a jet of M >= N variables in which they are
// w_offset .. w_{offset+N-1}: exact, the derivatives with respect to the other variables being zero.
template <int M, int N, int O>
Jet<M, O> lift(const Jet<N, O>& a, int offset) {
  static_assert(M >= N, "lift embeds into at least as many variables");
  Jet<M, O> r(a.v);
  for (int i = 0; i < N; ++i) r.g[offset + i] = a.g[i];
  if constexpr (O == 2) {
    int k = 0;
    for (int j = 0; j < N; ++j)
      for (int i = j; i < N; ++i, ++k) r.h[Jet<M, O>::packed(offset + i, offset + j)] = a.h[k];
  }
  return r;
}

}  // namespace rodvv::solvers::rod3d::taylor2
