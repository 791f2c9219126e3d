#include "rodvv/solvers/superhelix/clothoid_solution.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include "rodvv/solvers/superhelix/clothoid_element.hpp"
#include "rodvv/solvers/superhelix/clothoid_kinematics.hpp"
#include "rodvv/solvers/superhelix/clothoid_statics.hpp"
#include "rodvv/solvers/superhelix/solution.hpp"

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
  // Element ends (and the Gauss points when dead point forces load them: they enter n(s) as in make_solution).
  const ClothoidKinematics kinematics(model, q, !model.point_forces.empty());
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
    append_station(solution, model, s, r, R, a + sigma * b, model.natural_strain);
    for (std::size_t g = 0; g < model.point_forces.size(); ++g) {  // n(s): the forces beyond s (half at s)
      const auto& point = kinematics.points()[g];
      const double at = static_cast<double>(point.element) * ell + point.sigma;
      solution.force_n.back() += (at > s ? 1.0 : at == s ? 0.5 : 0.0) * model.point_forces[g];
    }
  }
  append_vertices(solution, kinematics, n, ell);
  return solution;
}

}  // namespace rodvv::solvers::superhelix
