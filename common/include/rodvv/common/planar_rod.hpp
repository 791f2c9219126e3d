#pragma once
// Solution of a planar rod problem, as every planar solver returns it (discrete or continuous) and
// as the invariants read it (PHYSICS.md §0, §1.3-1.4). Plain data.
//
// Conventions (PHYSICS.md §0): arclength s in [0, L]; tangent t = (cos theta, sin theta);
// curvature kappa = theta'; internal force n(s) is the force exerted by the material on (s, L]
// on the material on [0, s]; "axial force" (tension) is n.t, positive in tension; moment
// m = EI (kappa - kappa_hat). External conservative loads come from a potential V(x, y) per unit
// length.
//
// Nodes i = 0 .. N (N + 1 values): s, x, y, theta, kappa, bending_stiffness, natural_curvature,
// potential, and the internal force n = (force_x, force_y) and axial force n.t evaluated at the
// node. A discrete solver with forces on edges averages the two adjacent edges onto a node
// (consistent to O(h^2), PHYSICS.md §1.4) and also fills the edge arrays (N values, edge i joins
// nodes i and i+1); a continuous (shooting) solver leaves the edge arrays empty.
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace rodvv {

struct PlanarRodSolution {
  std::string method;  // which solver / discretisation produced it
  double length = 0.0;

  std::vector<double> s;
  std::vector<double> x;
  std::vector<double> y;
  std::vector<double> theta;
  std::vector<double> kappa;
  std::vector<double> bending_stiffness;  // EI(s)
  std::vector<double> natural_curvature;  // kappa_hat(s)
  std::vector<double> potential;          // V(x(s), y(s)) per unit length
  std::vector<double> force_x;            // n(s), node values
  std::vector<double> force_y;
  std::vector<double> axial_force;        // n.t at nodes

  std::vector<double> edge_axial_force;   // discrete solvers: n.t on edges (Lagrange multiplier or EA strain)

  // Extensible / shearable (planar Reissner) rods: t = (cos theta, sin theta) is the cross-section
  // director, r' = (1 + n.t / EA) t + (n.N / GA) N with N = e_z x t. +infinity = rigid (elastica).
  // shear_force n.N at nodes (and edges): filled by the discrete solver; may be left empty when
  // shear_stiffness is infinite (it then does not enter H).
  double axial_stiffness = std::numeric_limits<double>::infinity();  // EA
  double shear_stiffness = std::numeric_limits<double>::infinity();  // GA
  std::vector<double> shear_force;       // n.N at nodes
  std::vector<double> edge_shear_force;  // discrete solvers: n.N on edges

  std::size_t iterations = 0;  // Newton / shooting iterations of the final solve
  double residual = 0.0;       // final residual norm

  std::size_t nodes() const noexcept { return s.size(); }
};

}  // namespace rodvv
