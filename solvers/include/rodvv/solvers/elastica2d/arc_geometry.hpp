#pragma once
// Singularity-free building blocks of the exact circular-arc element ("arcs" discretisation).
// An arc of length h whose tangent angle goes linearly from a to b has the chord
//   r(h) - r(0) = h S(b - a) (cos m, sin m),   m = (a + b) / 2,   S(u) = sin(u/2) / (u/2),
// which is exact for any curvature (b - a) / h, including 0.
// sinc(v) = sin(v) / v and its first two derivatives use their Taylor series for |v| < 0.5 (summed
// to below round-off) and the closed forms elsewhere, so there is no 0/0 and no cancellation.
namespace rodvv::solvers::elastica2d {

struct SincDerivatives {
  double value;   // sin(v) / v
  double first;   // d/dv
  double second;  // d^2/dv^2
};

SincDerivatives sinc_derivatives(double v) noexcept;

}  // namespace rodvv::solvers::elastica2d
