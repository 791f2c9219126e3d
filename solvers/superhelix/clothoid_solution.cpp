#include "rodvv/solvers/superhelix/clothoid_solution.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include "rodvv/solvers/superhelix/clothoid_element.hpp"
#include "rodvv/solvers/superhelix/clothoid_kinematics.hpp"
#include "rodvv/solvers/superhelix/clothoid_statics.hpp"

namespace rodvv::solvers::superhelix {

namespace {

// (element, offset) of every station, in increasing s.
std::vector<std::pair<std::size_t, double>> station_points(std::size_t elements, double ell, ClothoidStations kind) {
  std::vector<std::pair<std::size_t, double>> points;
  const double g = 0.5 / std::sqrt(3.0);  // Gauss-Legendre 2-point nodes at (1/2 -+ g) ell
  for (std::size_t e = 0; e < elements; ++e) {
    switch (kind) {
      case ClothoidStations::Gauss:
        points.emplace_back(e, (0.5 - g) * ell);
        points.emplace_back(e, (0.5 + g) * ell);
        break;
      case ClothoidStations::Midpoints:
        points.emplace_back(e, 0.5 * ell);
        break;
      case ClothoidStations::Nodes:
        points.emplace_back(e, 0.0);
        break;
    }
  }
  if (kind == ClothoidStations::Nodes) points.emplace_back(elements - 1, ell);  // the tip node
  return points;
}

}  // namespace

SpatialRodSolution make_clothoid_solution(const RodModel& model, const VecX& q, ClothoidStations stations,
                                          std::string method) {
  validate_clothoid(model);
  const ClothoidKinematics kinematics(model, q, false);  // element ends only: stations are posed below
  const std::size_t n = model.elements;
  const double ell = kinematics.element_length();
  SpatialRodSolution solution;
  solution.method = std::move(method);
  solution.length = model.length;
  for (const auto& [e, sigma] : station_points(n, ell, stations)) {
    const double s = static_cast<double>(e) * ell + sigma;
    const Vec3 a = q.segment<3>(static_cast<Eigen::Index>(3 * e));
    const Vec3 b = (q.segment<3>(static_cast<Eigen::Index>(3 * (e + 1))) - a) / ell;
    Mat3 R = kinematics.base_frame(e);
    Vec3 r = kinematics.base_position(e);
    if (sigma > 0.0) {
      const ClothoidPose local = clothoid_element(a, b, sigma);  // series pose in the element's base frame
      r += R * local.r;
      R = R * local.R;
    }
    const Vec3 u = a + sigma * b;
    solution.s.push_back(s);
    solution.position.push_back(r);
    solution.frame.push_back(R);
    solution.strain_u.push_back(u);
    solution.strain_v.push_back(Vec3::UnitX());
    solution.stiffness.push_back(model.stiffness);
    solution.natural_strain.push_back(model.natural_strain);
    solution.moment_m.push_back(R * model.stiffness.cwiseProduct(u - model.natural_strain));
    solution.force_n.push_back(model.end_force + model.line_density * (model.length - s) * model.gravity);
    solution.potential.push_back(-model.line_density * model.gravity.dot(r));
    solution.shear_energy.push_back(0.0);
  }
  for (std::size_t i = 0; i <= n; ++i) {
    solution.vertex_s.push_back(static_cast<double>(i) * ell);
    solution.vertex_position.push_back(kinematics.base_position(i));
    solution.vertex_frame.push_back(kinematics.base_frame(i));
  }
  return solution;
}

}  // namespace rodvv::solvers::superhelix
