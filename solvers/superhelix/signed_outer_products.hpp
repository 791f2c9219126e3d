#pragma once
// sum_k w_k u_k u_k^T for vectors u_k of one size and weights of either sign, gathered as columns
// sqrt(|w_k|) u_k and added by two symmetric rank-k updates: one matrix product instead of a dense outer
// product per term (the contact Hessians of self_contact.cpp and arc_pair_contact.cpp). Private.
#include <cmath>
#include <vector>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::superhelix::detail {

class SignedOuterProducts {
 public:
  void add(const VecX& u, double w) {
    if (w > 0.0) positive_.push_back(std::sqrt(w) * u);
    if (w < 0.0) negative_.push_back(std::sqrt(-w) * u);
  }
  // The sum, a symmetric size x size matrix (zero when nothing was added).
  MatX sum(Eigen::Index size) const {
    MatX total = MatX::Zero(size, size);
    for (const auto* group : {&positive_, &negative_}) {
      if (group->empty()) continue;
      MatX U(size, static_cast<Eigen::Index>(group->size()));
      for (std::size_t j = 0; j < group->size(); ++j) U.col(static_cast<Eigen::Index>(j)) = (*group)[j];
      total.selfadjointView<Eigen::Lower>().rankUpdate(U, group == &positive_ ? 1.0 : -1.0);
    }
    total.triangularView<Eigen::StrictlyUpper>() = total.transpose();
    return total;
  }

 private:
  std::vector<VecX> positive_, negative_;
};

}  // namespace rodvv::solvers::superhelix::detail
