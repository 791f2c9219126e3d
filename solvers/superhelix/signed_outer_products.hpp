#pragma once
// sum_k w_k u_k u_k^T for vectors u_k of one size and weights of either sign, gathered as columns
// sqrt(|w_k|) u_k and added by symmetric rank-k updates: matrix products instead of a dense outer product
// per term (the contact Hessians of self_contact.cpp and arc_pair_contact.cpp). Private.
//
// A reduced rod is a chain: a point on element e moves with the dofs of elements 0 .. e only, so its
// u = J^T v is zero past 3 (e + 1). The columns are sorted by that support and updated in blocks of
// kBlock, each into the top-left corner its longest column spans: the cost falls from size^2 per column
// to support^2 (measured on knot/plectoneme-superhelix, whose contacts sit at 45 to 80 % of the rod:
// the update was 44 % of the run).
#include <algorithm>
#include <cmath>
#include <numeric>
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
      // Support of each column: one past its last nonzero entry.
      std::vector<Eigen::Index> support(group->size(), 0);
      for (std::size_t j = 0; j < group->size(); ++j) {
        const VecX& u = (*group)[j];
        Eigen::Index end = u.size();
        while (end > 0 && u[end - 1] == 0.0) --end;
        support[j] = end;
      }
      std::vector<std::size_t> order(group->size());
      std::iota(order.begin(), order.end(), std::size_t{0});
      const auto longer = [&](std::size_t a, std::size_t b) { return support[a] > support[b]; };
      std::stable_sort(order.begin(), order.end(), longer);
      const double sign = group == &positive_ ? 1.0 : -1.0;
      for (std::size_t first = 0; first < order.size(); first += kBlock) {
        const std::size_t last = std::min(order.size(), first + kBlock);
        const Eigen::Index rows = support[order[first]];
        if (rows == 0) break;
        MatX U(rows, static_cast<Eigen::Index>(last - first));
        for (std::size_t j = first; j < last; ++j)
          U.col(static_cast<Eigen::Index>(j - first)) = (*group)[order[j]].head(rows);
        total.topLeftCorner(rows, rows).selfadjointView<Eigen::Lower>().rankUpdate(U, sign);
      }
    }
    total.triangularView<Eigen::StrictlyUpper>() = total.transpose();
    return total;
  }

 private:
  static constexpr std::size_t kBlock = 64;  // columns per update: enough for the product's blocking
  std::vector<VecX> positive_, negative_;
};

}  // namespace rodvv::solvers::superhelix::detail
