#include "rodvv/solvers/contact/factored_delassus.hpp"

#include <cmath>
#include <string>

#include <Eigen/Cholesky>

#include "block_gauss_seidel.hpp"
#include "rodvv/common/errors.hpp"

namespace rodvv::solvers::contact {

namespace {

std::string contact_name(std::size_t k) { return "contact " + std::to_string(k); }

void validate_weights(const FactoredDelassus& W) {
  for (std::size_t body = 0; body < W.body_weights.size(); ++body) {
    const VecX& m = W.body_weights[body];
    if (!(m.allFinite() && (m.array() > 0.0).all()))
      throw InputError("body_weights", "invalid parameter 'body_weights': the weights of body " + std::to_string(body) +
                                           " must be finite and > 0");
  }
}

void validate_contact(const FactoredDelassus& W, std::size_t k) {
  if (k >= W.sides.size())
    throw InputError("contact", "invalid parameter 'contact': " + std::to_string(k) + ", must be below " +
                                    std::to_string(W.sides.size()));
  const auto& sides = W.sides[k];
  if (sides.empty() || sides.size() > 2 || (sides.size() == 2 && sides[0].body == sides[1].body))
    throw InputError("sides", "invalid parameter 'sides': " + contact_name(k) +
                                  " must act on one body or on two distinct bodies");
  for (const ContactSide& side : sides) {
    if (side.body >= W.body_weights.size())
      throw InputError("sides", "invalid parameter 'sides': " + contact_name(k) + " names body " +
                                    std::to_string(side.body) + ", must be below " +
                                    std::to_string(W.body_weights.size()));
    if (side.rows.cols() < 1 || side.rows.cols() > W.body_weights[side.body].size() || !side.rows.allFinite())
      throw InputError("sides", "invalid parameter 'sides': " + contact_name(k) +
                                    " must have 3 x m finite rows, 1 <= m <= " +
                                    std::to_string(W.body_weights[side.body].size()) + " on body " +
                                    std::to_string(side.body));
  }
}

void validate_factors(const FactoredDelassus& W) {
  validate_weights(W);
  const std::size_t n = W.sides.size();
  for (std::size_t k = 0; k < n; ++k) validate_contact(W, k);
  if (W.compliance.size() != 0 &&
      (W.compliance.size() != Eigen::Index(n) || !W.compliance.allFinite() || (W.compliance.array() < 0.0).any()))
    throw InputError("compliance", "invalid parameter 'compliance': must be empty or hold one finite value >= 0 per "
                                   "contact (" + std::to_string(n) + ")");
}

void validate(const FactoredDelassus& W, const VecX& b, const VecX& mu) {
  validate_factors(W);
  const std::size_t n = W.sides.size();
  if (b.size() != Eigen::Index(3 * n) || !b.allFinite())
    throw InputError("b", "invalid parameter 'b': must hold " + std::to_string(3 * n) + " finite values (3 per contact)");
  if (mu.size() != Eigen::Index(n))
    throw InputError("mu", "invalid parameter 'mu': must hold one friction coefficient per contact (" +
                               std::to_string(n) + ")");
  for (Eigen::Index k = 0; k < mu.size(); ++k)
    if (!(std::isfinite(mu[k]) && mu[k] >= 0.0))
      throw InputError("mu", "invalid parameter 'mu': friction coefficient of contact " + std::to_string(k) +
                                 " must be finite and >= 0, got " + format_value(mu[k]));
}

// block_gauss_seidel.hpp's operator: the diagonal blocks computed once, y_b = M_b H_b^T r kept.
class FactoredOperator {
 public:
  explicit FactoredOperator(const FactoredDelassus& W) : W_(W) {
    for (std::size_t k = 0; k < W.sides.size(); ++k) {
      blocks_.push_back(diagonal_block(W, k));
      if (Eigen::LLT<Mat3>(blocks_.back()).info() != Eigen::Success)
        throw InputError("W", "invalid parameter 'W': the diagonal block of " + contact_name(k) +
                                  " is not positive definite");
    }
    for (const VecX& m : W.body_weights) y_.push_back(VecX::Zero(m.size()));
  }
  Eigen::Index contacts() const { return Eigen::Index(blocks_.size()); }
  Mat3 block(Eigen::Index k) const { return blocks_[std::size_t(k)]; }
  Vec3 product(Eigen::Index k, const VecX& r) const {
    Vec3 result = compliance(k) * r.segment<3>(3 * k);
    for (const ContactSide& side : W_.sides[std::size_t(k)]) result.noalias() += side.rows * y_[side.body].head(side.rows.cols());
    return result;
  }
  void changed(Eigen::Index k, const Vec3& delta) {
    // Column by column: the expression (M H^T delta) would allocate a temporary per contact and sweep
    // (a tenth of a bundle's solve in malloc and free).
    for (const ContactSide& side : W_.sides[std::size_t(k)]) {
      VecX& y = y_[side.body];
      const VecX& weights = W_.body_weights[side.body];
      for (Eigen::Index j = 0; j < side.rows.cols(); ++j) y[j] += weights[j] * side.rows.col(j).dot(delta);
    }
  }
  VecX velocities(const VecX& r) const {  // W r from y (kept equal to M H^T r by changed())
    VecX u(r.size());
    for (Eigen::Index k = 0; k < contacts(); ++k) u.segment<3>(3 * k) = product(k, r);
    return u;
  }

 private:
  double compliance(Eigen::Index k) const { return W_.compliance.size() == 0 ? 0.0 : W_.compliance[k]; }
  const FactoredDelassus& W_;
  std::vector<Mat3> blocks_;
  std::vector<VecX> y_;
};

}  // namespace

Mat3 diagonal_block(const FactoredDelassus& W, std::size_t contact) {
  validate_contact(W, contact);
  if (W.compliance.size() != 0 && Eigen::Index(contact) >= W.compliance.size())
    throw InputError("compliance", "invalid parameter 'compliance': no value for " + contact_name(contact));
  Mat3 block = Mat3::Zero();
  for (const ContactSide& side : W.sides[contact])
    block.noalias() += side.rows * W.body_weights[side.body].head(side.rows.cols()).asDiagonal() * side.rows.transpose();
  if (W.compliance.size() != 0) block.diagonal().array() += W.compliance[Eigen::Index(contact)];
  return 0.5 * (block + block.transpose());
}

VecX apply(const FactoredDelassus& W, const VecX& r) {
  validate_factors(W);
  if (r.size() != Eigen::Index(3 * W.sides.size()))
    throw InputError("r", "invalid parameter 'r': must hold " + std::to_string(3 * W.sides.size()) +
                              " values (3 per contact)");
  std::vector<VecX> y;
  for (const VecX& m : W.body_weights) y.push_back(VecX::Zero(m.size()));
  for (std::size_t k = 0; k < W.sides.size(); ++k)
    for (const ContactSide& side : W.sides[k])
      y[side.body].head(side.rows.cols()).noalias() += side.rows.transpose() * r.segment<3>(Eigen::Index(3 * k));
  for (std::size_t body = 0; body < y.size(); ++body) y[body] = W.body_weights[body].cwiseProduct(y[body]);
  VecX product = VecX::Zero(r.size());
  for (std::size_t k = 0; k < W.sides.size(); ++k) {
    auto segment = product.segment<3>(Eigen::Index(3 * k));
    for (const ContactSide& side : W.sides[k]) segment.noalias() += side.rows * y[side.body].head(side.rows.cols());
    if (W.compliance.size() != 0) segment += W.compliance[Eigen::Index(k)] * r.segment<3>(Eigen::Index(3 * k));
  }
  return product;
}

ConeSolution solve_cone_complementarity(const FactoredDelassus& W, const VecX& b, const VecX& mu, ConeLaw law,
                                        const ConeSettings& settings) {
  validate(W, b, mu);
  FactoredOperator op(W);
  return detail::block_gauss_seidel(op, b, mu, law, settings);
}

}  // namespace rodvv::solvers::contact
