// inverse/round-trip-sphere: inverse statics with frictional contact (ALGORITHMS.md §3.2;
// Derouet-Jourdan, Bertails-Descoubes, Daviet & Thollot 2013), a Super-Helix hair lying on a sphere
// (a head) under gravity. The target is an arc of a great circle of radius rho = R + a (sphere radius
// R, hair radius a = L/100) in a plane tilted by beta = 20 degrees from the vertical, from 10 degrees
// before its top to arc length L: constant curvature 1/rho, exact at any N. The model has one Gauss
// point per element (its midpoint), and every one touches the sphere (normal radial): N contacts, 3N
// force components for 3N strains. The production path: inverse_statics_with_contacts (the SOCQP by
// block Gauss-Seidel with the SOC law), then contact_model (the found forces as dead point forces)
// and the forward statics from a perturbation of q (forward_round_trip.hpp).
// Gates:
//  - socqp_residual: the Gauss-Seidel's natural-map residual, at most its stopping tolerance 1e-8
//    (W = H K^-2 H^T + 2 gamma I couples every contact to all those upstream: thousands of sweeps,
//    about 2 400, 4 300, 7 600 at N = 8, 16, 32; a tighter tolerance costs sweeps in proportion to
//    its logarithm);
//  - cone_violation: every force in its cone, to round-off (the local solver returns cone points);
//  - round_trip_error: the forward statics returns q, in conditioned eps units as round-trip-3d. The
//    inverse builds H^T r from the dense point Jacobians (kinematics.hpp), the forward statics from
//    the tip-to-root wrench pass (loads.hpp): two paths, so a wrong contact Jacobian is seen;
//  - equilibrium_residual: the forward residual at q, in eps.
// Reported: |q0 - q| / |q| and the fraction of contacts at the friction limit. Measured: the rest
// shape tends to q as gamma -> 0 (0.033, 0.0067, 0.00085 at gamma = 1e-2, 1e-3, 1e-4, N = 8), even
// beyond the friction angle: the SOCQP may hold the hair like a rubber band on a ball (a tension
// along the arc and the normal force T kappa it calls for, with friction building T as on a
// capstan), a moment-free support that the least-deformation objective prefers. So the limit
// q0 -> q is not a check of the friction law; the forward frictional problem is (issue 16).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "../case_builder.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "forward_round_trip.hpp"
#include "hair_on_head.hpp"
#include "inverse_cases.hpp"
#include "rodvv/solvers/superhelix/inverse_contact.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"

namespace rodvv::harness::inverse_cases {

namespace {

namespace sh = solvers::superhelix;
using namespace cases;
constexpr double kPi = std::numbers::pi;
constexpr double kTilt = 20.0 * kPi / 180.0;    // beta
constexpr double kStart = -10.0 * kPi / 180.0;  // root angle from the circle's top
constexpr double kSocqpTolerance = 1e-8;
constexpr std::size_t kSocqpSweeps = 20000;

struct Head {
  sh::RodModel model;  // elements unset
  Vec3 centre;
  double rho = 0;  // centreline radius R + a
};

Head head_of(const Parameters& p) {
  Head head;
  const double L = parameter_value(p, "L"), R = parameter_value(p, "R"), EI = parameter_value(p, "EI");
  head.rho = R + 0.01 * L;
  head.centre = Vec3(0.3, -0.2, 0.1) * L;
  const Vec3 a = Vec3::UnitX(), up = Vec3(0.0, std::sin(kTilt), std::cos(kTilt));  // the circle's plane
  sh::RodModel& m = head.model;
  m.length = L;
  m.stiffness = Vec3(0.6 * EI, 1.4 * EI, EI);  // bends about n2 along the circle
  m.line_density = parameter_value(p, "rhoS");
  m.gauss_points = 1;  // one contact per element, at its midpoint
  m.gravity = Vec3(0.0, 0.0, -parameter_value(p, "g"));
  const Vec3 outward = std::sin(kStart) * a + std::cos(kStart) * up;
  m.root_position = head.centre + head.rho * outward;
  const Vec3 tangent = std::cos(kStart) * a - std::sin(kStart) * up;
  m.root_frame << tangent, -outward, tangent.cross(-outward);  // n1 towards the centre: curls around it
  return head;
}

struct Solved {
  sh::InverseContactResult inverse;
  std::vector<sh::RodContact> contacts;
};

Solved solve(const sh::RodModel& model, const VecX& q, const Vec3& centre, double mu, double gamma) {
  const sh::Kinematics kinematics(model, q);
  Solved s;
  for (std::size_t g = 0; g < kinematics.points().size(); ++g)
    s.contacts.push_back({g, (kinematics.points()[g].position - centre).normalized(), mu});
  sh::InverseContactOptions options;
  options.gamma = gamma;
  options.solver.tolerance = kSocqpTolerance;
  options.solver.max_sweeps = kSocqpSweeps;
  s.inverse = sh::inverse_statics_with_contacts(model, q, s.contacts, options);
  return s;
}

LevelOutput run(const Parameters& p, double level) {
  const Head head = head_of(p);
  sh::RodModel model = head.model;
  model.elements = element_count(level);
  const std::size_t n = model.elements;
  VecX q(Eigen::Index(3 * n));
  for (std::size_t e = 0; e < n; ++e) q.segment<3>(Eigen::Index(3 * e)) = Vec3(0.0, 0.0, 1.0 / head.rho);
  const double mu = parameter_value(p, "mu"), gamma = parameter_value(p, "gamma");

  LevelOutput out;
  const Solved limited = solve(model, q, head.centre, mu, gamma);
  out.metrics["socqp_residual"] = value_sample(limited.inverse.residual, 1.0);
  out.metrics["cone_violation"] = value_sample(limited.inverse.cone_violation, 1.0);
  out.metrics["socqp_sweeps"] = diagnostic(double(limited.inverse.sweeps));
  std::size_t on_boundary = 0;
  for (Eigen::Index c = 0; c < Eigen::Index(limited.contacts.size()); ++c) {
    const Vec3 r = limited.inverse.local_forces.segment<3>(3 * c);
    on_boundary += r[0] > 0.0 && std::hypot(r[1], r[2]) >= (1.0 - 1e-9) * mu * r[0];
  }
  out.metrics["contacts_at_friction_limit"] = diagnostic(double(on_boundary) / double(limited.contacts.size()));

  // Round trip: the forward statics with the found forces held (forward_round_trip.hpp).
  const sh::RodModel rest = sh::contact_model(model, limited.contacts, limited.inverse);
  add_round_trip_metrics(out, rest, q);
  out.metrics["rest_deviation"] =
      diagnostic((limited.inverse.natural_strain - q).lpNorm<Eigen::Infinity>() / q.lpNorm<Eigen::Infinity>());

  return out;
}

}  // namespace

void add_round_trip_sphere(Registry& registry) {
  std::vector<MetricSpec> metrics{
      error_metric("socqp_residual", "", "natural-map residual of the SOCQP (block Gauss-Seidel, SOC law)", std::nullopt),
      error_metric("cone_violation", "", "max (|r_T| - mu r_N)_+, relative", std::nullopt),
      diagnostic_metric("socqp_sweeps", "Gauss-Seidel sweeps"),
      diagnostic_metric("contacts_at_friction_limit", "fraction of contacts with |r_T| = mu r_N"),
      diagnostic_metric("rest_deviation", "|q0 - q| / |q|")};
  std::vector<GateSpec> gates{
      upper_bound_gate("socqp_residual", kSocqpTolerance, GateScope::AllLevels, "the Gauss-Seidel's stopping tolerance"),
      upper_bound_gate("cone_violation", 1e-12, GateScope::AllLevels, "the local solver keeps r in its cone to round-off")};
  add_round_trip_specs(metrics, gates);
  Case c = make_case(
      "inverse",
      {"inverse/round-trip-sphere",
       "Inverse statics with frictional contact: a Super-Helix hair lying on a sphere under gravity",
       "Great-circle arc (radius R + L/100, plane tilted 20 degrees from the vertical, from -10 degrees past its top) "
       "touching the sphere at the midpoint of every element; SOCQP of Derouet-Jourdan et al. 2013 (least deformation, "
       "regularisation gamma) by block Gauss-Seidel with the SOC law; then forward statics with the forces held.",
       "Round trip to round-off (the forces held as dead loads, through the wrench pass); the SOCQP's complementarity "
       "to its tolerance; every force in its cone",
       "ALGORITHMS.md §3.2; Derouet-Jourdan, Bertails-Descoubes, Daviet & Thollot 2013",
       "Super-Helix inverse statics with frictional contact: SOCQP over the Coulomb cones by block Gauss-Seidel "
       "(exact local SOC solver), q0 = q - K^-1 (F + H^T r)"},
      {make_parameter("L", 0.25, 0.0, 1e6, true, false, "length", "hair length"),
       make_parameter("R", 0.2, 0.0, 1e6, true, false, "length", "sphere radius"),
       make_parameter("EI", 1e-3, 0.0, 1e12, true, false, "force length^2", "bending stiffness in the arc's plane (EI1 = 1.4 EI, GJ = 0.6 EI)"),
       make_parameter("rhoS", 0.05, 0.0, 1e12, true, false, "mass / length", "line density"),
       make_parameter("g", 9.81, 0.0, 1e12, true, false, "length / time^2", "gravity"),
       make_parameter("mu", 0.6, 0.0, 1e3, true, false, "", "friction coefficient"),
       // below 1e-3 the Gauss-Seidel needs more than 20 000 sweeps at N = 32 (3.6e-8 after them at 1e-5)
       make_parameter("gamma", 1e-3, 1e-3, 1.0, false, false, "", "SOCQP regularisation, relative to the mean diagonal of H K^-2 H^T")},
      element_levels("number of elements", {8, 16, 32}, {8, 16, 32, 64}), std::move(metrics), std::move(gates), run);
  require_hair_on_head_windows(c);
  hold_round_trip_round_off(c);
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::inverse_cases
