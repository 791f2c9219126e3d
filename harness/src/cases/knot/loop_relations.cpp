#include "loop_relations.hpp"

#include <cmath>
#include <vector>

#include "rodvv/common/errors.hpp"

namespace rodvv::harness::knot_cases {

LoopRelations loop_relations(const SpatialRodSolution& solution, double B, double T, const std::string& method,
                             std::size_t iterations, double residual) {
  std::vector<double> tx, kappa;
  for (std::size_t i = 0; i < solution.s.size(); ++i) {
    tx.push_back(solution.frame[i].col(0).x());
    kappa.push_back(std::hypot(solution.strain_u[i][1], solution.strain_u[i][2]));
  }
  std::vector<std::size_t> turns;  // i: t.e_x changes sign between stations i and i + 1
  double perpendicular_sum = 0.0;
  for (std::size_t i = 0; i + 1 < tx.size(); ++i)
    if ((tx[i] > 0) != (tx[i + 1] > 0)) {
      const double u = tx[i] / (tx[i] - tx[i + 1]);
      const double kappa_b = kappa[i] + u * (kappa[i + 1] - kappa[i]);
      perpendicular_sum += 0.5 * B * kappa_b * kappa_b / T;
      turns.push_back(i);
    }
  if (turns.size() < 2)
    throw SolverError(method, "no loop: the tangent turns through perpendicular to the pull at " +
                                  std::to_string(turns.size()) + " stations (a tied knot's loop: 2)",
                      iterations, residual);
  std::size_t apex = turns.front() + 1;
  for (std::size_t i = turns.front() + 1; i <= turns.back(); ++i)
    if (tx[i] < tx[apex]) apex = i;
  LoopRelations relations;
  relations.perpendicular_ratio = perpendicular_sum / double(turns.size());
  relations.perpendicular_points = turns.size();
  relations.apex_ratio = B * kappa[apex] * kappa[apex] / (4.0 * T);
  return relations;
}

}  // namespace rodvv::harness::knot_cases
