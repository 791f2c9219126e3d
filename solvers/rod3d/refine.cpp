#include "rodvv/solvers/rod3d/refine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::rod3d {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The cubic Hermite interpolant of values v_k at uniformly spaced abscissae x_k = x0 + k dx, with
// Catmull-Rom tangents (v_{k+1} - v_{k-1}) / 2 inside and the one-sided (-3 v_0 + 4 v_1 - v_2) / 2 at
// the ends (the tangents of the parabola through the end three), evaluated at x (extrapolated by the
// end cubic outside [x_0, x_n]).
template <typename Value>
class UniformHermite {
 public:
  UniformHermite(std::vector<Value> values, double x0, double dx) : v_(std::move(values)), x0_(x0), dx_(dx) {}

  Value operator()(double x) const {
    const std::size_t last = v_.size() - 1;
    double u_all = (x - x0_) / dx_;
    // A point on a node (to round-off in x0 + k dx) takes the node's value exactly.
    if (std::abs(u_all - std::round(u_all)) <= 1e-12) u_all = std::round(u_all);
    const auto k = static_cast<std::size_t>(std::clamp(std::floor(u_all), 0.0, double(last - 1)));
    const double u = u_all - double(k);
    const double u2 = u * u, u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * v_[k] + (u3 - 2 * u2 + u) * tangent(k) + (-2 * u3 + 3 * u2) * v_[k + 1] +
           (u3 - u2) * tangent(k + 1);
  }

 private:
  Value tangent(std::size_t k) const {
    const std::size_t last = v_.size() - 1;
    if (k == 0) return 0.5 * (-3.0 * v_[0] + 4.0 * v_[1] - v_[2]);
    if (k == last) return 0.5 * (3.0 * v_[last] - 4.0 * v_[last - 1] + v_[last - 2]);
    return 0.5 * (v_[k + 1] - v_[k - 1]);
  }

  std::vector<Value> v_;
  double x0_, dx_;
};

void require_same_problem(const RodModel& coarse, const RodModel& fine) {
  if (std::abs(fine.length - coarse.length) > 64.0 * kEps * coarse.length)
    throw InputError("fine_model", "invalid parameter 'fine_model': its length " + format_value(fine.length) +
                                       " differs from the coarse rod's " + format_value(coarse.length));
  if (fine.root.support != coarse.root.support || fine.tip.support != coarse.tip.support)
    throw InputError("fine_model", "invalid parameter 'fine_model': its end supports differ from the coarse rod's");
  if (fine.elements < coarse.elements)
    throw InputError("fine_model", "invalid parameter 'fine_model': " + std::to_string(fine.elements) +
                                       " edges, fewer than the coarse rod's " + std::to_string(coarse.elements) +
                                       " (refine_state refines)");
}

}  // namespace

RodState refine_state(const RodModel& coarse_model, const RodState& coarse, const RodModel& fine_model) {
  validate(coarse_model);
  validate(fine_model);
  const std::size_t nc = coarse_model.elements;
  if (nc < 3 || coarse.elements() != nc || coarse.position.size() != nc + 1 || coarse.reference_director.size() != nc)
    throw InputError("coarse", "invalid parameter 'coarse': a state of the coarse model (" + std::to_string(nc) +
                                   " edges, at least 3) was expected, got " + std::to_string(coarse.elements()) +
                                   " edges");
  require_same_problem(coarse_model, fine_model);

  // The coarse material angles from the space-parallel transport of edge 0's director, accumulated.
  const std::vector<Vec3> tangents = edge_tangents(coarse);
  std::vector<double> angle(nc, 0.0);
  Vec3 director = material_frame(coarse, 0).col(1);
  const Vec3 first_director = director;
  for (std::size_t j = 1; j < nc; ++j) {
    if (!(tangents[j - 1].dot(tangents[j]) > -1.0 + 1e-12))
      throw InputError("coarse", "invalid parameter 'coarse': edge " + std::to_string(j) +
                                     " is reversed against edge " + std::to_string(j - 1));
    director = parallel_transport(tangents[j - 1], tangents[j], director);
    const Vec3 material = material_frame(coarse, j).col(1);
    angle[j] = angle[j - 1] + signed_angle(director, material, tangents[j]);
    director = material;  // transport the material director on: each increment is one vertex's twist
  }

  const double ebar_c = rest_edge_length(coarse_model), ebar_f = rest_edge_length(fine_model);
  const double s0_c = vertex_arclength(coarse_model, 0);
  const UniformHermite<Vec3> position(coarse.position, s0_c, ebar_c);
  const UniformHermite<double> material_angle(angle, s0_c + 0.5 * ebar_c, ebar_c);

  const std::size_t nf = fine_model.elements;
  std::vector<Vec3> positions(nf + 1);
  for (std::size_t i = 0; i <= nf; ++i) positions[i] = position(vertex_arclength(fine_model, i));
  std::vector<double> angles(nf);
  const double s0_f = vertex_arclength(fine_model, 0);
  for (std::size_t j = 0; j < nf; ++j) angles[j] = material_angle(s0_f + (double(j) + 0.5) * ebar_f);
  const Vec3 fine_t0 = (positions[1] - positions[0]).normalized();
  Vec3 m1_first = parallel_transport(tangents[0], fine_t0, first_director);
  m1_first = (m1_first - m1_first.dot(fine_t0) * fine_t0).normalized();
  RodState fine = make_state(positions, m1_first, angles);

  if (is_inextensible(coarse_model) && is_inextensible(fine_model) && coarse.multiplier.size() == nc) {
    const UniformHermite<double> axial_force(coarse.multiplier, s0_c + 0.5 * ebar_c, ebar_c);
    fine.multiplier.resize(nf);
    for (std::size_t j = 0; j < nf; ++j) fine.multiplier[j] = axial_force(s0_f + (double(j) + 0.5) * ebar_f);
  }
  return fine;
}

}  // namespace rodvv::solvers::rod3d
