#include "rod_on_curve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rodvv/common/validation.hpp"

namespace rodvv::harness::knot_cases {

TiedRod rod_on_curve(const std::vector<Vec3>& curve, std::size_t elements, bool clamped_tip) {
  require_at_least("elements", elements, 3);
  require_at_least("curve points", curve.size(), 2);
  std::vector<double> arclength(curve.size(), 0.0);
  for (std::size_t i = 1; i < curve.size(); ++i) arclength[i] = arclength[i - 1] + (curve[i] - curve[i - 1]).norm();
  TiedRod rod;
  rod.length = arclength.back();
  const double ebar = rod.length / (double(elements) - (clamped_tip ? 1.0 : 0.5));
  const Vec3 root_direction = (curve[1] - curve[0]).normalized();
  const Vec3 tip_direction = (curve.back() - curve[curve.size() - 2]).normalized();
  std::size_t j = 0;
  for (std::size_t i = 0; i <= elements; ++i) {
    const double s = (double(i) - 0.5) * ebar;
    if (s <= 0.0) {  // the root's ghost vertex, on the root segment's line
      rod.vertices.push_back(curve.front() + s * root_direction);
      continue;
    }
    if (s >= rod.length) {  // a clamped tip's ghost vertex (or round-off at a free tip)
      rod.vertices.push_back(curve.back() + (s - rod.length) * tip_direction);
      continue;
    }
    while (j + 2 < curve.size() && arclength[j + 1] < s) ++j;
    const double u = std::min(1.0, (s - arclength[j]) / (arclength[j + 1] - arclength[j]));
    rod.vertices.push_back(curve[j] + u * (curve[j + 1] - curve[j]));
  }
  return rod;
}

solvers::rod3d::RodModel isotropic_rod_on(const TiedRod& laid, double B, double C,
                                          const solvers::rod3d::SelfContact& contact) {
  solvers::rod3d::RodModel model;
  model.elements = laid.vertices.size() - 1;
  model.length = laid.length;
  model.stiffness = Vec3(C, B, B);
  model.twist_inertia = 0.0;
  model.self_contact = contact;
  return model;
}

double ease(double u) { return 0.5 - 0.5 * std::cos(std::numbers::pi * std::clamp(u, 0.0, 1.0)); }

}  // namespace rodvv::harness::knot_cases
