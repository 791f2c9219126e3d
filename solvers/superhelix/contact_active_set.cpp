#include "contact_active_set.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "rodvv/common/errors.hpp"

namespace rodvv::solvers::superhelix::detail {

std::optional<VecX> active_set_contact_solve(const MatX& W, const VecX& b, const VecX& mu, const VecX& guess) {
  enum class Status { Open, Stick, Slide };
  const Eigen::Index m = mu.size();
  const double force_scale = std::max(guess.lpNorm<Eigen::Infinity>(), b.lpNorm<Eigen::Infinity>() /
                                                                            W.diagonal().maxCoeff());
  const double slip_scale = std::max(b.lpNorm<Eigen::Infinity>(), W.diagonal().maxCoeff() * force_scale);
  const double tol = 1e-10;
  std::vector<Status> status(static_cast<std::size_t>(m));
  std::vector<Vec2> direction(static_cast<std::size_t>(m), Vec2::Zero());
  VecX u = W * guess + b;
  for (Eigen::Index c = 0; c < m; ++c) {
    const Vec2 slip = u.segment<2>(3 * c + 1);
    const bool closed = guess[3 * c] > 0.0 || u[3 * c] < 0.0;
    const bool sliding = mu[c] > 0.0 && slip.norm() > tol * slip_scale;
    status[std::size_t(c)] = !closed ? Status::Open : sliding ? Status::Slide : Status::Stick;
    if (sliding) direction[std::size_t(c)] = slip.normalized();
    if (closed && mu[c] == 0.0) status[std::size_t(c)] = Status::Slide;  // frictionless: r_T = 0
  }
  // Rounds: all violated statuses flipped at once first (30 rounds); if that cycles, one at a time, the
  // least index first (Murty's least-index rule, finite for the frictionless LCP with W positive definite).
  const int rounds = 30 + 8 * int(m);
  // The rows of W (slips, a compliance times forces) are divided by W's largest diagonal entry, so that they
  // are forces like the rows r = 0 and r_T + mu r_N s = 0 beside them: the LU's pivoting then does not depend
  // on the problem's force unit (unscaled, the hanging fold converged at one unit of force and not at 0.3 of it).
  const double compliance = W.diagonal().maxCoeff();
  for (int round = 0; round < rounds; ++round) {
    const bool one_at_a_time = round >= 30;
    bool flipped = false;
    MatX system = MatX::Zero(3 * m, 3 * m);
    VecX rhs = VecX::Zero(3 * m);
    for (Eigen::Index c = 0; c < m; ++c) {
      const auto i = 3 * c;
      switch (status[std::size_t(c)]) {
        case Status::Open:
          system.block<3, 3>(i, i).setIdentity();
          break;
        case Status::Stick:
          system.middleRows(i, 3) = W.middleRows(i, 3) / compliance;
          rhs.segment<3>(i) = -b.segment<3>(i) / compliance;
          break;
        case Status::Slide: {
          system.row(i) = W.row(i) / compliance;
          rhs[i] = -b[i] / compliance;
          const Vec2& s = direction[std::size_t(c)];  // r_T + mu r_N s = 0
          system(i + 1, i + 1) = 1.0, system(i + 1, i) = mu[c] * s[0];
          system(i + 2, i + 2) = 1.0, system(i + 2, i) = mu[c] * s[1];
          break;
        }
      }
    }
    const Eigen::PartialPivLU<MatX> lu(system);
    const VecX r = lu.solve(rhs);
    if (!r.allFinite()) return std::nullopt;
    u = W * r + b;
    bool changed = false;
    for (Eigen::Index c = 0; c < m; ++c) {
      Status& st = status[std::size_t(c)];
      if (one_at_a_time && flipped) continue;
      const double r_N = r[3 * c], u_N = u[3 * c];
      const Vec2 r_T = r.segment<2>(3 * c + 1), slip = u.segment<2>(3 * c + 1);
      Status next = st;
      if (st == Status::Open) {
        if (u_N < -tol * slip_scale) next = mu[c] > 0.0 ? Status::Stick : Status::Slide;
      } else if (r_N < -tol * force_scale) {
        next = Status::Open;
      } else if (st == Status::Stick && r_T.norm() > mu[c] * r_N + tol * force_scale) {
        next = Status::Slide;
        direction[std::size_t(c)] = -r_T.normalized();
      } else if (st == Status::Slide && mu[c] > 0.0) {
        Vec2& s = direction[std::size_t(c)];
        if (slip.dot(s) < -tol * slip_scale) {
          next = Status::Stick;
        } else if (slip.norm() > tol * slip_scale && (slip.normalized() - s).norm() > tol) {
          s = slip.normalized();  // the slip turned: slide along it
          changed = true;
        }
      }
      flipped = flipped || next != st;
      changed = changed || next != st;
      st = next;
    }
    if (!changed) return r;
  }
  return std::nullopt;
}

Augmentation augmentation_of(const MatX& G, const VecX& g) {
  return {G.transpose() * G, G.transpose() * g, G.rows() == 0};
}

StepMatrix::StepMatrix(const MatX& A, const std::vector<Augmentation>& augmentations, double rho_0, const VecX& k,
                       const char* method, std::size_t iteration, double residual)
    : augmented_rhs_(VecX::Zero(A.rows())) {
  const auto positive_definite = [this](const MatX& M) {
    cholesky_.compute(0.5 * (M + M.transpose()));
    return cholesky_.info() == Eigen::Success;
  };
  MatX A_step = A;
  bool definite = positive_definite(A_step);
  for (const Augmentation& augmentation : augmentations) {
    if (augmentation.empty) continue;
    for (double trial = rho_0; !definite && trial <= 1e6 * rho_0; trial *= 10.0)
      if ((definite = positive_definite(A_step = A + trial * augmentation.normal_matrix)))
        augmented_rhs_ = trial * augmentation.rhs;
  }
  const bool first = !augmentations.empty() && !augmentations.front().empty;
  for (double sigma = 1e-6; !definite; sigma *= 10.0) {
    if (sigma > 1e12) throw SolverError(method, "no positive definite shift of the tangent stiffness", iteration, residual);
    A_step = A;
    if (first) {
      A_step += rho_0 * augmentations.front().normal_matrix;
      augmented_rhs_ = rho_0 * augmentations.front().rhs;
    }
    A_step.diagonal() += sigma * k;
    definite = positive_definite(A_step);
  }
  // The Cholesky factor when the matrix is symmetric to round-off (gravity, dead end forces, the normal
  // forces' turning: half the work of an LU, the factor already made); else (a dead end moment) LU.
  // Either way the fixed point is the same (dq = 0).
  symmetric_ = (A_step - A_step.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * A_step.cwiseAbs().maxCoeff();
  if (!symmetric_) lu_.compute(A_step);
}

MatX StepMatrix::solve(const MatX& rhs) const { return symmetric_ ? MatX(cholesky_.solve(rhs)) : MatX(lu_.solve(rhs)); }

}  // namespace rodvv::solvers::superhelix::detail
