#pragma once
// Euler critical loads of a straight planar rod from the linearised stiffness eigenproblem of the
// discrete Lagrangian (lagrangian.hpp), for both discretisations (discretisation.hpp).
//
// The straight rod along +x, loaded by an axial compressive force P (internal force n = -P e_x on
// every edge), is an equilibrium for every P: the angle rows of the KKT residual are -n.dg_i/da =
// P h sin(0) = 0 and the support reactions carry the load. Its second variation, restricted to the
// perturbations dz allowed by the supports and the linearised inextensibility J dz = 0, is
//
//   dz^T (K_b - P K_g) dz,    K_b = Hessian of L at n = 0,  K_g = Hessian(n = 0) - Hessian(n = -e_x)
//
// (primal block; K_g = e_x . d^2 g_i / d angles^2, the "geometric stiffness"). Both come from the
// production DiscreteLagrangian::hessian(), as does J (its multiplier rows). The critical loads are
// the eigenvalues of the symmetric-definite pencil Z^T K_b Z v = P Z^T K_g Z v, Z a basis of null(J).
// For the polygon K_g = h I on the edge angles (a lumped "mass"); for the arcs it is the consistent
// linear-element matrix h [1/3 1/6; 1/6 1/3] per element. Both converge as O(h^2).
//
// Clamped-clamped: both ends prescribed in x and y (Support::Clamped). Linearised about the straight
// state the chain constraints give dx_{i+1} = dx_i (dg_i/da is along e_y), so the two prescribed x
// rows are the same row (rank deficient J, handled by a rank-revealing QR) and the axial force is
// the reaction: the production supports suffice, no sliding clamp is needed. The same holds for the
// prescribed x at a pinned end s = L.
//
// Null space. The chain rows r_{i+1} - r_i - g_i = 0 read from the Hessian express every node
// position through (dr_0, angles); the few remaining boundary rows (<= 6) are removed by a column-
// pivoted Householder QR of their transpose. Cost O(N^3) in the dense reduced eigenproblem
// (bench_buckling, CPU time: N = 64 ~1 ms, N = 256 ~40 ms, N = 512 ~0.3 s).
#include <cstddef>
#include <string_view>
#include <vector>

#include "rodvv/solvers/elastica2d/discretisation.hpp"

namespace rodvv::solvers::elastica2d {

// Supports of the column; the first word is the end s = 0 (always the clamped one where mixed).
enum class EndSupports { PinnedPinned, ClampedFree, ClampedClamped, ClampedPinned };

std::string_view end_supports_id(EndSupports supports);  // "pinned-pinned", "clamped-free", ...
EndSupports end_supports_from_id(std::string_view id);   // InputError ("supports") if unknown

struct BucklingProblem {
  EndSupports supports = EndSupports::PinnedPinned;
  double length = 1.0;             // L > 0
  double bending_stiffness = 1.0;  // EI > 0 (constant)
};

// One critical load and its mode shape theta(s) (the perturbation of the tangent angle).
// Stations: polygon edge midpoints s = (j + 1/2) h (edge angles), arcs nodes s = j h.
// Normalisation: max |theta| = 1, and theta > 0 at the first station where |theta| >= 1/2.
struct BucklingMode {
  double load = 0.0;  // P_cr [force]
  std::vector<double> s;
  std::vector<double> theta;
};

struct BucklingResult {
  std::vector<BucklingMode> modes;  // ascending load
  std::size_t reduced_size = 0;     // dimension of the constrained eigenproblem
};

// The lowest `modes` critical loads. Throws InputError naming "length", "bending_stiffness",
// "elements", "scheme", "supports" or "modes" (1 <= modes <= reduced_size: N - 1 (polygon; N for
// clamped-free), N (arcs; N - 1 clamped-pinned, N - 2 clamped-clamped)) and SolverError if the
// eigen decomposition fails or the pencil is not definite.
BucklingResult critical_loads(const BucklingProblem& problem, const Discretisation& discretisation,
                              std::size_t modes);

}  // namespace rodvv::solvers::elastica2d
