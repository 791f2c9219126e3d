#include "rodvv/solvers/superhelix/solution.hpp"

#include "rodvv/solvers/superhelix/kinematics.hpp"

namespace rodvv::solvers::superhelix {

SpatialRodSolution make_solution(const RodModel& model, const VecX& q, std::string method) {
  validate(model);
  require_statics_only_loads_absent(model, "the Super-Helix solution struct (n(s) from gravity and the end force)");
  const Kinematics kinematics(model, q);
  const std::size_t n = model.elements;
  const double ell = element_length(model);
  SpatialRodSolution solution;
  solution.method = std::move(method);
  solution.length = model.length;
  for (std::size_t e = 0; e < n; ++e) {
    const double s = (static_cast<double>(e) + 0.5) * ell;
    const Vec3 u = q.segment<3>(3 * e), u_hat = natural_strain(model, e);
    const Mat3 R = kinematics.frame(e, 0.5 * ell);
    const Vec3 r = kinematics.position(e, 0.5 * ell);
    append_station(solution, model, s, r, R, u, u_hat);
  }
  append_vertices(solution, kinematics, n, ell);
  return solution;
}

void append_station(SpatialRodSolution& solution, const RodModel& model, double s, const Vec3& r, const Mat3& R,
                    const Vec3& u, const Vec3& u_hat) {
  solution.s.push_back(s);
  solution.position.push_back(r);
  solution.frame.push_back(R);
  solution.strain_u.push_back(u);
  solution.strain_v.push_back(Vec3::UnitX());
  solution.stiffness.push_back(model.stiffness);
  solution.natural_strain.push_back(u_hat);
  solution.moment_m.push_back(R * model.stiffness.cwiseProduct(u - u_hat));
  solution.force_n.push_back(model.end_force + model.line_density * (model.length - s) * model.gravity);
  solution.potential.push_back(-model.line_density * model.gravity.dot(r));
  solution.shear_energy.push_back(0.0);
}

}  // namespace rodvv::solvers::superhelix
