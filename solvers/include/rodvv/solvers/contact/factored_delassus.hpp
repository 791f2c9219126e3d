#pragma once
// A Delassus operator in factored form, for many bodies with few contacts each (a hair bundle):
//
//   W = sum_b H_b M_b H_b^T + diag(c_k I_3),
//
// bodies b with n_b degrees of freedom and a positive diagonal weight M_b (an inverse mass matrix; the
// inverse statics' K^-2), contacts k touching one body (an obstacle) or two (two rods), each side the
// leading columns of a 3 x n_b row block H_kb in the contact's frame (normal first), signed for the
// force on that body,
// c_k >= 0 a compliance or regularisation. W is never formed (10^4 contacts would make it 7 GB dense):
// the block Gauss-Seidel of cone_complementarity.hpp keeps y_b = M_b H_b^T r per body, so
// (W r)_k = sum_sides H_kb y_b + c_k r_k and the update after a local solve cost O(n_b) each, a sweep
// O(sum_k n_b) (So-bogus keeps W = H M^-1 H^T in the same factors; Daviet, Bertails-Descoubes &
// Boissieux 2011). The same problem, laws, residual, settings and results as the dense form.
// Bad input (InputError naming it): a weight that is not finite and > 0 ("body_weights"); a contact
// without sides, with more than two, with two on one body, a side naming no body or with rows that
// are not 3 x m (1 <= m <= n_b) and finite ("sides"); c_k < 0 or not finite, or not one per contact ("compliance");
// b, mu as the dense form; a diagonal block W_kk that is not positive definite ("W").
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/contact/cone_complementarity.hpp"

namespace rodvv::solvers::contact {

struct ContactSide {
  std::size_t body = 0;
  // 3 x m, 1 <= m <= n_body: the contact's (normal, t1, t2) velocities per unit velocity of the body's
  // first m degrees of freedom; the rest of H_kb is zero (a rod's point moves with the elements up to
  // its own only: half the memory and work of a full block on average)
  Eigen::Matrix<double, 3, Eigen::Dynamic> rows;
};

struct FactoredDelassus {
  std::vector<VecX> body_weights;               // M_b's diagonal, one vector per body
  std::vector<std::vector<ContactSide>> sides;  // per contact: one side, or two on distinct bodies
  VecX compliance;                              // c_k per contact; empty: none
};

// W_kk of one contact (its sides checked as above; "contact" out of range) and W r (the factors checked
// as above; "r" of another size than 3 per contact).
Mat3 diagonal_block(const FactoredDelassus& W, std::size_t contact);
VecX apply(const FactoredDelassus& W, const VecX& r);

ConeSolution solve_cone_complementarity(const FactoredDelassus& W, const VecX& b, const VecX& mu, ConeLaw law,
                                        const ConeSettings& settings = {});

}  // namespace rodvv::solvers::contact
