#pragma once
// The discrete Lagrangian of a planar elastica (problem.hpp) in either discretisation
// (discretisation.hpp), in a mixed form whose KKT matrix is banded:
//
//   L(z) = Pi(r, angles) + sum_i n_i . (r_{i+1} - r_i - g_i(angles)) + sum_k mu_k (z_{d_k} - target_k)
//
//   Pi    = bending energy + lambda * sum_i w_i V(r_i) - lambda * (F_0.r_0 + M_0 theta(0)
//           + F_L.r_N + M_L theta(L))      (lambda = load factor, 1 for the final solve)
//   g_i   = chord of element i: polygon h (cos phi_i, sin phi_i); arcs h S(theta_{i+1} - theta_i)
//           (cos, sin)((theta_i + theta_{i+1}) / 2) (arc_geometry.hpp)
//   n_i   = multiplier of the inextensibility of element i: it IS the internal force n on edge i
//           (force of the material after the edge on the material before it, PHYSICS.md §0)
//   mu_k  = multipliers of the boundary rows (prescribed x, y at ends; prescribed angle at a clamped
//           end of the "arcs" scheme; a polygon clamp enters the bending energy instead).
//
// Extensible / shearable rod (finite EA or GA, problem.hpp): the mixed (Hellinger-Reissner) term
//   L += - sum_i h/2 n_i^T C_i(angles) n_i      (compliance.hpp)
// turns the element constraint into r_{i+1} - r_i - g_i - h C_i n_i = 0, so n_i is the element
// force and C_i n_i its strain; the KKT matrix keeps its band (the n-n block becomes -h C_i). With
// EA = GA = +infinity the term is absent (not merely zero), so the elastica results are unchanged.
//
// Unknowns. "polygon": edge angles phi_i (i < N); "arcs": node angles theta_i (i <= N), which are
// the start angle plus the running sum of the element curvatures kappa_e = (theta_{e+1} -
// theta_e) / h, a linear, invertible change of the reduced coordinates (theta_0, kappa_0..N-1) that
// keeps the Hessian banded. Node positions r_i are carried as unknowns tied by the element
// constraints, so that the potential and the dead loads give a banded Hessian; eliminating r and n
// gives back the pure angle (reduced-coordinate) formulation with identical solutions.
//
// Layout of z (interleaved per element, so the KKT matrix has bandwidth ~5):
//   [start rows mu] [x_0 y_0 a_0 nx_0 ny_0] [x_1 y_1 a_1 nx_1 ny_1] ... [x_N y_N (theta_N)] [end rows mu]
// where a_i = phi_i (polygon) or theta_i (arcs).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstddef>
#include <vector>

#include "rodvv/solvers/elastica2d/compliance.hpp"
#include "rodvv/solvers/elastica2d/discretisation.hpp"
#include "rodvv/solvers/elastica2d/problem.hpp"

namespace rodvv::solvers::elastica2d {

// One boundary row: z[dof] - target = 0.
struct BoundaryRow {
  std::size_t dof = 0;
  double target = 0.0;
};

class DiscreteLagrangian {
 public:
  // Validates problem and discretisation (InputError), samples EI and kappa_hat (InputError if
  // EI <= 0 or either is non-finite at a sample point).
  DiscreteLagrangian(const Problem& problem, const Discretisation& discretisation);

  Scheme scheme() const noexcept { return scheme_; }
  std::size_t elements() const noexcept { return n_; }
  double element_length() const noexcept { return h_; }
  std::size_t size() const noexcept { return size_; }
  std::size_t angle_count() const noexcept { return scheme_ == Scheme::Polygon ? n_ : n_ + 1; }

  // Indices into z.
  std::size_t x(std::size_t node) const noexcept { return offset_ + 5 * node; }
  std::size_t y(std::size_t node) const noexcept { return offset_ + 5 * node + 1; }
  std::size_t angle(std::size_t j) const noexcept { return offset_ + 5 * j + 2; }
  std::size_t nx(std::size_t edge) const noexcept { return offset_ + 5 * edge + 3; }
  std::size_t ny(std::size_t edge) const noexcept { return offset_ + 5 * edge + 4; }
  const std::vector<BoundaryRow>& rows() const noexcept { return rows_; }
  std::size_t row_multiplier(std::size_t k) const noexcept { return row_index_[k]; }
  bool is_multiplier(std::size_t index) const noexcept;

  // Homotopy controls: the load factor scales dead loads and the potential; targets of the
  // boundary rows may be moved (displacement stepping).
  void set_load_factor(double lambda) noexcept { lambda_ = lambda; }
  double load_factor() const noexcept { return lambda_; }
  void set_row_target(std::size_t k, double target) noexcept { rows_[k].target = target; }

  // 1/EA and 1/GA (0 when rigid); compliant() is false for the inextensible, unshearable rod.
  double axial_compliance() const noexcept { return axial_compliance_; }
  double shear_compliance() const noexcept { return shear_compliance_; }
  bool compliant() const noexcept { return axial_compliance_ != 0.0 || shear_compliance_ != 0.0; }

  double energy(const Eigen::VectorXd& z) const;    // Pi (no constraint terms)
  double value(const Eigen::VectorXd& z) const;     // L
  Eigen::VectorXd gradient(const Eigen::VectorXd& z) const;            // grad L (the KKT residual)
  Eigen::SparseMatrix<double> hessian(const Eigen::VectorXd& z) const;  // Hessian of L (KKT matrix)

  // r_{i+1} - r_i of element `edge` implied by the angles in z (the chord g_i).
  Eigen::Vector2d element_chord(const Eigen::VectorXd& z, std::size_t edge) const {
    return chord(z, edge).g;
  }

  // Sampled data (index = node for EI/kappa_hat at nodes; bending terms are internal).
  double node_stiffness(std::size_t i) const noexcept { return node_ei_[i]; }
  double node_natural_curvature(std::size_t i) const noexcept { return node_khat_[i]; }
  const Problem& problem() const noexcept { return problem_; }

 private:
  struct BendingTerm {  // (w / 2) (c0 a_{j0} + c1 a_{j1} - b)^2
    std::size_t j0 = 0, j1 = 0;
    double c0 = 0.0, c1 = 0.0;
    double w = 0.0, b = 0.0;
  };
  struct Chord {  // g_i and its derivatives w.r.t. its one (polygon) or two (arcs) angles
    Eigen::Vector2d g;
    Eigen::Vector2d d[2];
    Eigen::Vector2d dd[2][2];
  };
  Chord chord(const Eigen::VectorXd& z, std::size_t edge) const;
  ElementCompliance compliance(const Eigen::VectorXd& z, std::size_t edge) const;
  std::size_t chord_angle(std::size_t edge, int k) const noexcept;
  int chord_arity() const noexcept { return scheme_ == Scheme::Polygon ? 1 : 2; }
  double node_weight(std::size_t i) const noexcept;
  Eigen::Matrix2d potential_hessian(double px, double py) const;
  std::size_t start_angle() const noexcept { return angle(0); }
  std::size_t end_angle() const noexcept { return angle(scheme_ == Scheme::Polygon ? n_ - 1 : n_); }

  Problem problem_;
  Scheme scheme_;
  std::size_t n_;
  double h_;
  std::size_t offset_ = 0;
  std::size_t size_ = 0;
  double lambda_ = 1.0;
  double axial_compliance_ = 0.0, shear_compliance_ = 0.0;
  std::vector<BendingTerm> bending_;
  std::vector<BoundaryRow> rows_;
  std::vector<std::size_t> row_index_;
  std::vector<double> node_ei_, node_khat_;
};

}  // namespace rodvv::solvers::elastica2d
