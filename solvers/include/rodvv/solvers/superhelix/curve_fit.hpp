#pragma once
// Fitting a Super-Helix to a curve a user has (issue 16; in the spirit of the "floating tangents"
// of Derouet-Jourdan, Bertails-Descoubes & Thollot, CAGD 30(5), 2013: the tangents and the points'
// places along the rod are free, not prescribed), so that the inverse statics can start from a
// polyline instead of a q.
//
// Given points p_0 .. p_M, find the rod clamped at p_0 (length L, N equal elements, strains q,
// root tangent free, root frame's n1 fixed by the gauge below) and the arc lengths
// 0 = s_0 < s_1 .. < s_M = L that minimise
//   sum_i |r(s_i) - p_i|^2
// (the orthogonal distance of the points to the rod; the last point is its tip). Unknowns: q (3N),
// L, two angles of the root tangent, s_1 .. s_{M-1}; Levenberg-Marquardt (Marquardt 1963: damped
// Gauss-Newton with the damping divided by 10 on success, multiplied by 4 on failure) with the exact
// Jacobian for q (Kinematics::position_jacobian) and the s_i (the tangent), central differences for L
// and the angles. Started by continuation in N: one helix fitted from the chords' straight line,
// then each element split in two (same strain) and refitted, up to N. A Super-Helix is G1 by
// construction. Measured: points of a Super-Helix are fitted back to round-off; a smooth curve that
// is no piecewise helix to O(h^3) in distance (orders 3.3, 3.0 over N = 4, 8, 16: piecewise helices,
// like biarcs, match position, tangent and curvature across each element).
// Gauge: n1 of the root frame is the unit vector orthogonal to n0 in the plane of n0 and the first
// point's reference direction `reference_normal` (default: the world axis least aligned with the
// first chord).
// Bad input (InputError "points"): fewer than 3 points, a non-finite point, two consecutive points
// closer than 1e-12 of the polyline's length (repeated), a turning angle between consecutive chords
// above 60 degrees (a kink: G1 broken at the sampling's scale, not a curve a smooth rod fits);
// "elements" with 3 N + M + 2 > 3 M (more unknowns than equations). Non-convergence: SolverError
// (iterations, residual).
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

struct CurveFitOptions {
  std::size_t max_iterations = 500;  // per continuation level
  // A level stops when |J^T e|_inf <= tolerance max|J| |e| (first-order optimality, scale-free), the
  // residual is at round-off, or no step decreases it any more.
  double tolerance = 1e-9;
};

struct CurveFit {
  RodModel model;      // root_position = p_0, root_frame, length L, elements N (loads and stiffness defaults)
  VecX q;              // 3N strains
  VecX arc_length;     // s_0 .. s_M
  double max_distance = 0.0;  // max_i |r(s_i) - p_i|
  double rms_distance = 0.0;
  std::size_t iterations = 0;  // over all levels
};

CurveFit fit_super_helix(const std::vector<Vec3>& points, std::size_t elements, const CurveFitOptions& options = {});

}  // namespace rodvv::solvers::superhelix
