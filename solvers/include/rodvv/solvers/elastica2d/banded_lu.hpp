#pragma once
// LU factorisation with partial (row) pivoting of a square band matrix, LAPACK dgbtf2/dgbtrs style:
// O(n kl (kl + ku)) work and O(n (2 kl + ku)) storage. The KKT matrices of the discrete Lagrangian
// (lagrangian.hpp) are banded (half-bandwidth <= 5 in its interleaved ordering), so one Newton step
// costs O(N). The bandwidths are read from the sparsity pattern.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace rodvv::solvers::elastica2d {

class BandedLU {
 public:
  // Returns false if a pivot is exactly zero (singular matrix); the matrix must be square.
  bool factorize(const Eigen::SparseMatrix<double>& matrix);
  // Solves A x = b with the last successful factorisation.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  Eigen::Index lower_bandwidth() const noexcept { return kl_; }
  Eigen::Index upper_bandwidth() const noexcept { return ku_; }

 private:
  double& at(Eigen::Index i, Eigen::Index j) noexcept { return ab_[static_cast<std::size_t>(j * ld_ + kl_ + ku_ + i - j)]; }
  double at(Eigen::Index i, Eigen::Index j) const noexcept { return ab_[static_cast<std::size_t>(j * ld_ + kl_ + ku_ + i - j)]; }

  Eigen::Index n_ = 0, kl_ = 0, ku_ = 0, ld_ = 1;
  std::vector<double> ab_;
  std::vector<Eigen::Index> pivot_;
};

}  // namespace rodvv::solvers::elastica2d
