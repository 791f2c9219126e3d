#include "rodvv/solvers/elastica2d/banded_lu.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rodvv::solvers::elastica2d {

bool BandedLU::factorize(const Eigen::SparseMatrix<double>& matrix) {
  n_ = matrix.rows();
  kl_ = 0;
  ku_ = 0;
  for (Eigen::Index c = 0; c < matrix.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, c); it; ++it) {
      kl_ = std::max(kl_, it.row() - it.col());
      ku_ = std::max(ku_, it.col() - it.row());
    }
  ld_ = 2 * kl_ + ku_ + 1;  // ku + kl rows of U (fill from pivoting) and kl rows of L
  ab_.assign(static_cast<std::size_t>(ld_ * n_), 0.0);
  pivot_.assign(static_cast<std::size_t>(n_), 0);
  for (Eigen::Index c = 0; c < matrix.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, c); it; ++it)
      at(it.row(), it.col()) += it.value();

  for (Eigen::Index j = 0; j < n_; ++j) {
    const Eigen::Index km = std::min(kl_, n_ - 1 - j);
    Eigen::Index p = j;
    for (Eigen::Index i = j + 1; i <= j + km; ++i)
      if (std::abs(at(i, j)) > std::abs(at(p, j))) p = i;
    pivot_[static_cast<std::size_t>(j)] = p;
    if (at(p, j) == 0.0) return false;
    const Eigen::Index last = std::min(n_ - 1, j + kl_ + ku_);
    if (p != j)
      for (Eigen::Index c = j; c <= last; ++c) std::swap(at(p, c), at(j, c));
    const double inverse = 1.0 / at(j, j);
    for (Eigen::Index i = j + 1; i <= j + km; ++i) at(i, j) *= inverse;
    for (Eigen::Index c = j + 1; c <= last; ++c) {
      const double t = at(j, c);
      if (t == 0.0) continue;
      for (Eigen::Index i = j + 1; i <= j + km; ++i) at(i, c) -= at(i, j) * t;
    }
  }
  return true;
}

Eigen::VectorXd BandedLU::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = b;
  for (Eigen::Index j = 0; j < n_; ++j) {
    const Eigen::Index p = pivot_[static_cast<std::size_t>(j)];
    if (p != j) std::swap(x[j], x[p]);
    const Eigen::Index km = std::min(kl_, n_ - 1 - j);
    for (Eigen::Index i = j + 1; i <= j + km; ++i) x[i] -= at(i, j) * x[j];
  }
  for (Eigen::Index j = n_ - 1; j >= 0; --j) {
    x[j] /= at(j, j);
    const Eigen::Index first = std::max<Eigen::Index>(0, j - kl_ - ku_);
    for (Eigen::Index i = first; i < j; ++i) x[i] -= at(i, j) * x[j];
  }
  return x;
}

}  // namespace rodvv::solvers::elastica2d
