#pragma once
// Solution of a three-dimensional (Kirchhoff or special Cosserat) rod problem, as every 3-D solver
// returns it and as the 3-D invariants read it (PHYSICS.md §1.1, ARCHITECTURE.md "Which way the
// arrows point"). Plain data.
//
// Conventions (ALGORITHMS.md §1 notation, PHYSICS.md §0):
//  - arclength s in [0, L]; the material frame R = [n0 n1 n2] (columns, world components) with
//    n0 the director that is the tangent for an unshearable rod;
//  - strains in MATERIAL components, index 0 = the tangent direction:
//      u = (twist, kappa1, kappa2) with R' = R [u]x,   v = R^T r' (= e0 = (1, 0, 0) for a
//      Kirchhoff rod);
//  - stiffness K = diag(stiffness) acting on u - natural_strain: (GJ, EI1, EI2);
//    m = R K (u - u_hat) in WORLD components, n the internal force in WORLD components, both the
//    action of the material on (s, L] on the material on [0, s] (PHYSICS.md §0);
//  - potential V(r(s)) per unit length of the external conservative field (gravity:
//    V = -rho S g . r); shear_energy W_shear per unit length (0 for a Kirchhoff rod).
//
// Two sets of points:
//  - stations (the arrays below without "vertex_"): where the strain and stress fields are sampled
//    and where invariants are evaluated. A piecewise-constant-strain solver (Super-Helix) puts them
//    at element midpoints, where its strain is a second-order approximation of the continuous one.
//  - vertices: the N + 1 element ends, for the shape (positions and frames only).
#include <cstddef>
#include <string>
#include <vector>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv {

struct SpatialRodSolution {
  std::string method;
  double length = 0.0;

  // stations
  std::vector<double> s;
  std::vector<Vec3> position;        // r(s), world
  std::vector<Mat3> frame;           // R(s) = [n0 n1 n2], world columns
  std::vector<Vec3> strain_u;        // material components (twist, kappa1, kappa2)
  std::vector<Vec3> strain_v;        // material components of r' (e0 for a Kirchhoff rod)
  std::vector<Vec3> stiffness;       // diagonal of K = (GJ, EI1, EI2)
  std::vector<Vec3> natural_strain;  // u_hat, material components
  std::vector<Vec3> force_n;         // internal force, world
  std::vector<Vec3> moment_m;        // internal moment, world
  std::vector<double> potential;     // V(r(s)) per unit length
  std::vector<double> shear_energy;  // W_shear per unit length (empty or zeros for Kirchhoff)

  // vertices (element ends)
  std::vector<double> vertex_s;
  std::vector<Vec3> vertex_position;
  std::vector<Mat3> vertex_frame;

  std::size_t iterations = 0;  // Newton iterations of the final solve (all load steps)
  double residual = 0.0;       // final residual norm

  std::size_t stations() const noexcept { return s.size(); }
};

}  // namespace rodvv
