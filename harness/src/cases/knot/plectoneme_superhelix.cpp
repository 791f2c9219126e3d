// knot/plectoneme-superhelix: the plectoneme of knot/plectoneme-nodal on the Super-Helix (PHYSICS.md §5.2):
// an inextensible isotropic rod (B, C != B) with frictionless line self-contact on its helical arcs
// (superhelix/self_contact.hpp), two strands wound into a left-handed ply with a free end loop, held by
// the twist; the root clamped on its tail, the tip in a sliding clamp (superhelix/tip_guide.hpp: free to
// slide along its tail, its frame held) under the dead pull T_ext = the tension law at the laid helix
// angle theta_0 and R = h, so that the ply's R, theta and length find the equilibrium of that tension and
// of the laid link, as the nodal case's EndCondition::slides does.
//
// Laid as the nodal case's ply (plectoneme_tying.hpp: R = h, ply along y, eased helix angle, bulb-shaped
// end loop) but shorter - a ply 60 h long (2.6 turns of its strands at 15 deg) and tails of 10 h instead of
// 120 h and 40 h: the Super-Helix's elements are equal, and the shorter rod (about 190 h) puts them where the
// ply is. The rod is laid element by element on the curve (superhelix_on_curve.hpp) with the uniform twist
// M_t(theta_0) / C that holds the ply, and relaxed by Newton on the potential (superhelix/statics.hpp).
//
// Relaxation: 256 to 362 Newton iterations at N = 70, 100, 200, but at N = 120 and 141 none converged in 2000:
// the potential falls there steadily (by 3e-3 of itself over 1900 iterations) with a Hessian slightly
// indefinite all along (Levenberg shift 0.1 K), a slow drift of the ply rather than a stall. The ply's length
// is a soft mode (a uniform ply trades length with the tails at equal H; only the link's twist energy and
// the ends resist it), and the mesh makes its energy ripple; which N drift is not understood. The default
// levels are the three measured to converge; other N may take minutes or fail as a level (SolverError).
//
// Checks, with nothing special-cased in the contact region (as the nodal case, ply_metrics.hpp):
//  - H (PHYSICS.md §1.2; V_eff of the line barrier included, superhelix/solution.cpp) equal on the tails and
//    through the ply: max_s |H(s) - H_tail| / T_ext;
//  - in the middle of the ply (the contacts of the root strand's Gauss points on the other strand, the
//    quarter of them nearest the loop and the quarter nearest the junction dropped): R = d / 2 and
//    theta = 1/2 acos(-t_point . t_foot) per contact, the contact force per strand length p = k (2h - d)^2
//    (the line force, half from each strand's own points), and the strand tension n.t at the element
//    midpoints there; the ply's laws (T_ext, M_t, p, n_t) at the measured R and theta.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "../case_builder.hpp"
#include "contact_profile.hpp"
#include "knot_cases.hpp"
#include "plectoneme_tying.hpp"
#include "ply_metrics.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/invariants/noether3d.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"
#include "rodvv/solvers/superhelix/solution.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"
#include "superhelix_on_curve.hpp"
#include "superhelix_trefoil.hpp"

namespace rodvv::harness::knot_cases {

namespace {

namespace sh = solvers::superhelix;
namespace ref = references;
using namespace cases;

constexpr double kPi = std::numbers::pi;
constexpr double kPlyLength = 60.0;   // the laid ply, in units of h
constexpr double kTailLength = 10.0;  // each tail, in units of h
// The sliding clamp's springs: k = 100 T_ext / h off the axis, k_r = 100 |M_t| per radian^2: the tip turns by
// about M_t / (2 k_r) = 5e-3 rad under the twisting moment (a link short by 1e-3 turns of about 4; the loads
// the clamp carries are exact whatever its compliance, tip_guide.hpp). Stiffer springs slow the relaxation
// (measured at N = 100: 312, 362, 596, 1322 Newton iterations for 30, 100, 1e3, 1e4; none in 2000 at 1e6).
constexpr double kGuideStiffness = 100.0;

LevelOutput run(const Parameters& p, double level) {
  const std::size_t n = element_count(level);
  const double B = parameter_value(p, "B"), C = parameter_value(p, "C"), h = parameter_value(p, "radius");
  const double theta0 = parameter_value(p, "helix_angle") * kPi / 180.0, barrier = parameter_value(p, "barrier");
  const ref::PlectonemeSolution laid_law = ply_law(B, h, theta0);
  // The twist that holds a left-handed ply: M_t / C > 0 (the law's M_t is a right-handed ply's).
  const double T_ext = laid_law.tail_tension, M_t0 = -laid_law.ply.twisting_moment;
  const PlyLayout layout{h, theta0, kPlyLength * h, 4.0 * h, 8.0 * h, 2.0 * h, kTailLength * h};
  const LaidSuperHelix laid = superhelix_on_curve(plectoneme_curve(layout), n, Vec3::UnitZ(), M_t0 / C);

  sh::RodModel model;
  model.length = laid.length;
  model.elements = n;
  model.stiffness = Vec3(C, B, B);
  model.root_position = laid.root_position;
  model.root_frame = laid.root_frame;
  model.end_force = Vec3(T_ext, 0.0, 0.0);
  model.self_contact = {h, barrier * T_ext / (h * h * h)};
  const sh::Kinematics as_laid(model, laid.q);
  model.tip_guide = {kGuideStiffness * T_ext / h, kGuideStiffness * M_t0, as_laid.tip_position(), as_laid.tip_frame()};

  sh::StaticOptions options;
  options.initial_q = laid.q;
  options.max_iterations = 2000;
  options.tolerance = 1e-10;
  const sh::StaticResult result = sh::solve_static(model, options);

  const sh::Kinematics kinematics(model, result.q);
  const auto contacts = sh::self_contacts(kinematics, model.self_contact);
  const SpatialRodSolution solution = sh::make_solution(model, result.q);

  PlyMeasurement ply;
  const std::size_t tail = station_nearest(solution, 0.5 * kTailLength * h);
  const Vec3 t_tail = solution.frame[tail].col(0);
  ply.tail_tension = solution.force_n[tail].dot(t_tail);
  ply.twisting_moment = solution.moment_m[tail].dot(t_tail);
  const auto flattened = invariants::noether3d_flattened(solution);
  for (double H : flattened) ply.H_deviation = std::max(ply.H_deviation, std::abs(H - flattened[tail]) / T_ext);

  // The middle of the ply: the root strand's contacts on the tip strand (first < second), by element.
  std::size_t lo = n, hi = 0;
  for (const auto& c : contacts)
    if (c.first < c.second) lo = std::min(lo, c.first), hi = std::max(hi, c.first);
  if (lo > hi)
    throw SolverError(kSuperHelixContactMethod, "the ply came undone: no contact between its strands",
                      result.iterations, result.residual);
  const std::size_t from = lo + (hi - lo) / 4, to = hi - (hi - lo) / 4;
  const double k = model.self_contact.stiffness;
  std::size_t points = 0;
  for (const auto& c : contacts) {
    if (!(c.first < c.second) || c.first < from || c.first > to) continue;
    const Vec3 t_point = kinematics.frame(c.first, c.s).col(0), t_foot = kinematics.frame(c.second, c.t).col(0);
    ply.R += 0.5 * c.distance;
    ply.theta += 0.5 * std::acos(std::clamp(-t_point.dot(t_foot), -1.0, 1.0));
    const double overlap = 2.0 * h - c.distance;
    ply.contact_force += k * overlap * overlap;
    ++points;
  }
  if (points < 3)
    throw SolverError(kSuperHelixContactMethod,
                      "no uniform ply: " + std::to_string(points) + " contact points between the strands in its middle",
                      result.iterations, result.residual);
  ply.R /= double(points);
  ply.theta /= double(points);
  ply.contact_force /= double(points);
  std::size_t stations = 0;
  for (std::size_t e = from; e <= to; ++e, ++stations)
    ply.strand_tension += solution.force_n[e].dot(solution.frame[e].col(0));
  ply.strand_tension /= double(stations);
  if (!(ply.theta < 0.25 * kPi))
    throw SolverError(kSuperHelixContactMethod,
                      "no uniform ply: the helix angle in its middle is " + std::to_string(ply.theta * 180.0 / kPi) +
                          " deg, beyond the ply's 45",
                      result.iterations, result.residual);

  LevelOutput output;
  add_ply_metrics(output, ply, B, h, T_ext);
  add_noether3d_metrics(output, solution, std::nullopt);
  output.metrics["contact_points"] = diagnostic(double(contacts.size()));
  output.series.push_back(contact_force_series(kinematics.element_length(), model.self_contact, contacts));
  output.metrics["laying_miss"] = diagnostic(laid.max_miss / h);
  output.metrics["iterations"] = diagnostic(double(result.iterations));
  output.metrics["equilibrium_residual"] = diagnostic(result.residual);
  return output;
}

}  // namespace

void add_plectoneme_superhelix(Registry& registry) {
  std::vector<MetricSpec> metrics = ply_metric_specs();
  for (auto& spec : noether3d_metric_specs(false, std::nullopt)) metrics.push_back(std::move(spec));
  metrics.push_back(diagnostic_metric("contact_points", "Gauss-point contacts (a point and a foot closer than 2h)"));
  metrics.push_back(diagnostic_metric("laying_miss", "largest miss of the laid rod's element ends from the curve / h"));
  metrics.push_back(diagnostic_metric("iterations", "Newton iterations on the potential"));
  metrics.push_back(diagnostic_metric("equilibrium_residual", "final residual |r|_inf"));
  // Measured at N = 70, 100, 200 (2026-11-27): H_deviation 0.0446, 0.0220, 0.0062 (orders 1.98, 1.82); the laws
  // of T_ext +4.7 %, +0.47 %, -1.5 %, M_t +5.8 %, +2.4 %, +0.03 %, p +3.6 %, +0.64 %, -0.55 %, n_t +1.2 %, -0.21 %,
  // -0.77 %; theta 14.70, 14.85, 14.92 deg, R = 0.981 h; 256, 362, 328 Newton iterations, 0.8, 2.8, 17 s.
  // Since the laying's Gauss-Newton is damped relative to its normal matrix (superhelix_on_curve.cpp), N = 200
  // relaxes to a neighbouring equilibrium (2026-11-28): H_deviation 0.0069, T_ext -1.59 %, M_t -0.03 %, p -0.52 %,
  // n_t -0.86 %, theta 14.92 deg, inside the envelopes below (kept: the first measurement's).
  std::vector<GateSpec> gates{
      order_range_gate("H_deviation", 1.0, 2.0,
                       "O(h^2) at the midpoint stations, O(h) from the contact forces at Gauss points and feet (as "
                       "knot/trefoil-superhelix; measured 1.98, 1.82 over N = 70 .. 200)"),
      measured_bound("H_deviation", 0.006243, 1.0 / 200.0, 1.0),
      law_envelope("tension_law", {70, 100, 200}, {0.047436, 0.004687, -0.014909}),
      law_envelope("moment_law", {70, 100, 200}, {0.058013, 0.023966, 0.000331}),
      law_envelope("contact_force_law", {70, 100, 200}, {0.036324, 0.006402, -0.005474}),
      law_envelope("strand_tension_law", {70, 100, 200}, {0.011986, -0.00213, -0.007719})};
  Case c = make_case(
      "knot",
      {"knot/plectoneme-superhelix", "Plectoneme at 15 deg: H through the ply and the ply's laws (Super-Helix)",
       "Inextensible isotropic Super-Helix (B, C) with frictionless line self-contact (barrier) of radius h, laid as "
       "a two-strand ply with a free end loop and twisted, root clamped, tip in a sliding clamp (free along its "
       "tail, frame held) under the dead pull T_ext = the tension law at the laid helix angle and R = h, relaxed to "
       "equilibrium.",
       "H(s) = H_tail through the ply (Noether, frictionless contact); T_ext R^2/B = 1/2 sin^4 theta (1 + 2/cos 2 "
       "theta) and the ply's M_t, p, n_t at the measured R, theta (PHYSICS.md §5.2)",
       "Coleman & Swigon 2004 (Phil. Trans. R. Soc. A 362:1281); Bertails et al. 2006; PHYSICS.md §1.2, §5.2",
       kSuperHelixContactMethod},
      {make_parameter("B", 1.3, 0.0, 1e12, true, false, "force length^2", "bending stiffness EI1 = EI2"),
       make_parameter("C", 0.9, 0.0, 1e12, true, false, "force length^2", "twisting stiffness GJ"),
       make_parameter("radius", 0.05, 0.0, 1e6, true, false, "length", "rod radius h (contact at distance 2h)"),
       // helix_angle in [10, 15] and barrier in [50, 2000], measured 2026-11-27 with the default levels (10, 12.5
       // deg: H_deviation's order 1.81, 1.98; barrier 50 and 2000 pass; C/B 0.66 and 100: 1.76, 1.68): at 20 deg
       // a level did not converge in 2000 iterations. Again on 2026-12-03 (after the faster contact Hessian): at
       // 20, 25 and 30 deg every level of 70, 100, 140 stops after 2000 iterations at a residual of 8e-3, 1e-3,
       // 3e-4, its largest entry at the end loop's apex (the middle elements); the steps are whole Newton steps
       // (Levenberg shift 0) on which the potential creeps down by 1e-8 a step while the residual bounces
       // between 1e-3 and 4e-2. Raising the shift when a whole step raises the residual made it worse (15 deg
       // then fails at N = 200).
       make_parameter("helix_angle", 15.0, 10.0, 15.0, false, false, "degrees",
                      "helix angle of the laid ply; T_ext is the tension law's at it and R = h"),
       make_parameter("barrier", 500.0, 50.0, 2000.0, false, false, "", "barrier stiffness k h^3 / T_ext (per unit length)")},
      element_levels("number of elements", {70, 100, 200}, {70, 100, 200}), std::move(metrics), std::move(gates),
      run);
  require(c, ratio_window("C", "B", 0.66, 100.0, "the twist-to-bending ratios at which the laid ply was measured"));
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::knot_cases
