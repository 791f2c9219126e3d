#include "contact_profile.hpp"

#include <map>

#include "rodvv/harness/trajectory_metrics.hpp"
#include "rodvv/solvers/contact/cubic_barrier.hpp"

namespace rodvv::harness::knot_cases {

Series contact_force_series(const solvers::rod3d::RodModel& model,
                            const std::vector<solvers::rod3d::ContactPair>& contacts) {
  namespace rod = solvers::rod3d;
  const std::size_t vertices = model.elements + 1;
  std::vector<Vec3> force(vertices, Vec3::Zero());
  for (const auto& c : contacts) {
    const Vec3 f = c.force * c.normal;  // on the first segment; minus that on the second
    force[c.first] += (1.0 - c.s) * f;
    force[c.first + 1] += c.s * f;
    force[c.second] -= (1.0 - c.t) * f;
    force[c.second + 1] -= c.t * f;
  }
  const double ebar = rod::rest_edge_length(model);
  std::vector<double> s(vertices), p(vertices);
  for (std::size_t i = 0; i < vertices; ++i) {
    s[i] = rod::vertex_arclength(model, i);
    p[i] = force[i].norm() / ebar;
  }
  return thin_series("contact force p(s)", "s", "p (force per length)", s, p);
}

Series contact_force_series(double element_length, const solvers::superhelix::SelfContact& contact,
                            const std::vector<solvers::superhelix::ArcContact>& contacts) {
  const solvers::contact::CubicBarrier law{contact.radius, contact.stiffness};
  std::map<double, double> density;  // by arclength
  for (const auto& c : contacts) density[static_cast<double>(c.first) * element_length + c.s] += law.force(c.distance);
  std::vector<double> s, p;
  for (const auto& [at, value] : density) {
    s.push_back(at);
    p.push_back(value);
  }
  return thin_series("contact force p(s)", "s", "p (force per length)", s, p);
}

Series point_contact_force_series(double element_length, const std::vector<solvers::superhelix::ArcContact>& contacts) {
  std::map<double, double> magnitude;  // by arclength; a point shared by two pairs sums them
  for (const auto& c : contacts) {
    if (c.force <= 0.0) continue;
    magnitude[static_cast<double>(c.first) * element_length + c.s] += c.force;
    magnitude[static_cast<double>(c.second) * element_length + c.t] += c.force;
  }
  std::vector<double> s, f;
  for (const auto& [at, value] : magnitude) {
    s.push_back(at);
    f.push_back(value);
  }
  return thin_series("contact point forces f", "s", "f (force)", s, f);
}

}  // namespace rodvv::harness::knot_cases
