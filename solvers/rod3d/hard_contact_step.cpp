#include "hard_contact_step.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "rodvv/solvers/contact/lcp.hpp"

namespace rodvv::solvers::rod3d::detail {

namespace {

// G_c as a vector on the DofLayout (zero at held dofs).
VecX gap_gradient(const RodModel& model, const ContactPair& pair, const std::vector<char>& held) {
  const DofLayout layout(model);
  VecX g = VecX::Zero(Eigen::Index(layout.size()));
  const auto gradient = distance_gradient(pair);
  const auto vertex = pair_vertices(pair);
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 3; ++c) {
      const std::size_t k = layout.vertex(vertex[std::size_t(a)]) + std::size_t(c);
      if (!held[k]) g[Eigen::Index(k)] += gradient[std::size_t(a)][c];
    }
  return g;
}

}  // namespace

double hard_contact_reach(const RodModel& model) { return 3.0 * model.self_contact.radius; }

std::vector<ContactPair> candidates_with_forces(const RodModel& model, const RodState& state,
                                                const std::vector<ContactPair>& forces) {
  auto pairs =
      contact_candidates(model.self_contact, state.position, rest_edge_length(model), hard_contact_reach(model));
  // Both lists are sorted by (first, second): one merge.
  const auto key = [](const ContactPair& p) { return std::make_pair(p.first, p.second); };
  auto known = forces.begin();
  for (auto& pair : pairs) {
    while (known != forces.end() && key(*known) < key(pair)) ++known;
    pair.force = (known != forces.end() && key(*known) == key(pair)) ? known->force : 0.0;
  }
  return pairs;
}

void subtract_contact_forces(const RodModel& model, const std::vector<ContactPair>& pairs, VecX& r) {
  const DofLayout layout(model);
  for (const auto& pair : pairs) {
    if (pair.force == 0.0) continue;
    const auto gradient = distance_gradient(pair);
    const auto vertex = pair_vertices(pair);
    for (int a = 0; a < 4; ++a)
      r.segment<3>(Eigen::Index(layout.vertex(vertex[std::size_t(a)]))) -= pair.force * gradient[std::size_t(a)];
  }
}

double complementarity_measure(const RodModel& model, const std::vector<ContactPair>& pairs, double force_scale,
                               double length_scale) {
  const double contact_distance = 2.0 * model.self_contact.radius;
  double worst = 0.0;
  for (const auto& pair : pairs) {
    const double gap = (pair.distance - contact_distance) / length_scale;
    worst = std::max(worst, std::abs(std::min(pair.force / force_scale, gap)));
  }
  return worst;
}

void add_contact_stiffness(const RodModel& model, const RodState& state, const std::vector<ContactPair>& pairs,
                           double rho, Eigen::SparseMatrix<double>& jacobian) {
  std::vector<Eigen::Triplet<double>> coordinates;
  contact_force_hessian(state.position, pairs, coordinates);
  for (const auto& pair : pairs) {
    if (!(pair.force > 0.0)) continue;
    const auto gradient = distance_gradient(pair);
    const auto vertex = pair_vertices(pair);
    for (int a = 0; a < 12; ++a)
      for (int b = 0; b < 12; ++b) {
        const double value = rho * gradient[std::size_t(a / 3)][a % 3] * gradient[std::size_t(b / 3)][b % 3];
        if (value != 0.0)
          coordinates.emplace_back(int(3 * vertex[a / 3] + a % 3), int(3 * vertex[b / 3] + b % 3), value);
      }
  }
  const DofLayout layout(model);
  const auto dof = [&](int coordinate) { return int(layout.vertex(std::size_t(coordinate) / 3)) + coordinate % 3; };
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(coordinates.size());
  for (const auto& entry : coordinates) entries.emplace_back(dof(entry.row()), dof(entry.col()), entry.value());
  Eigen::SparseMatrix<double> extra(jacobian.rows(), jacobian.cols());
  extra.setFromTriplets(entries.begin(), entries.end());
  jacobian += extra;
}

HardContactStep hard_contact_step(const RodModel& model, const std::vector<ContactPair>& candidates,
                                  const std::vector<char>& held, const VecX& residual,
                                  const std::function<VecX(const VecX&)>& solve) {
  HardContactStep step;
  step.dz = solve(-residual);
  step.pairs = candidates;
  const auto m = Eigen::Index(candidates.size());
  if (m == 0) return step;
  MatX G(m, step.dz.size()), X(step.dz.size(), m);
  for (Eigen::Index c = 0; c < m; ++c) {
    G.row(c) = gap_gradient(model, candidates[std::size_t(c)], held).transpose();
    X.col(c) = solve(G.row(c).transpose());
  }
  MatX W = G * X;
  W = 0.5 * (W + W.transpose()).eval();  // symmetric in exact arithmetic (J is, on the free dofs)
  VecX b(m);
  const double contact_distance = 2.0 * model.self_contact.radius;
  for (Eigen::Index c = 0; c < m; ++c)
    b[c] = candidates[std::size_t(c)].distance - contact_distance + G.row(c).dot(step.dz);
  const auto lcp = contact::solve_lcp(W, b, contact::LcpMethod::Lemke);
  step.dz += X * lcp.lambda;
  for (Eigen::Index c = 0; c < m; ++c) step.pairs[std::size_t(c)].force = lcp.lambda[c];
  step.lcp_pivots = lcp.iterations;
  return step;
}

}  // namespace rodvv::solvers::rod3d::detail
