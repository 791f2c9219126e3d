#include "plectoneme_tying.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "rodvv/common/validation.hpp"

namespace rodvv::harness::knot_cases {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSamples = 2000;  // per piece of the dense curve (chord error ~ (piece / 2000)^2 curvature)

std::vector<Vec3> dense_curve(const PlyLayout& p) {
  const double R = p.ply_radius, rho = p.junction_radius, P = p.ply_length, ramp = 0.25 * P;
  // The winding angle phi at the ply's sample heights y_k = rho + P k / kSamples (trapezoidal rule on
  // phi' = tan(theta(y)) / R, theta eased from 0 at both ends of the ply).
  std::vector<double> phi(kSamples + 1, 0.0);
  const auto rate = [&](double z) {  // z: height above the ply's base
    const double eased = ease(z / ramp) * ease((P - z) / ramp);
    return std::tan(p.helix_angle * eased) / R;
  };
  for (int k = 1; k <= kSamples; ++k) {
    const double z0 = P * (k - 1) / kSamples, z1 = P * k / kSamples;
    phi[k] = phi[k - 1] + 0.5 * (z1 - z0) * (rate(z0) + rate(z1));
  }
  std::vector<Vec3> curve;
  const double tail_end = R + rho;  // |x| where a tail meets its junction arc
  for (int k = 0; k <= kSamples; ++k) curve.emplace_back(-tail_end - p.tail_length * (1.0 - double(k) / kSamples), 0, 0);
  // Root junction: centre (-tail_end, rho), from -pi/2 to 0, ends at (-R, rho) heading +y.
  for (int k = 1; k <= kSamples; ++k) {
    const double a = -0.5 * kPi * (1.0 - double(k) / kSamples);
    curve.emplace_back(-tail_end + rho * std::cos(a), rho + rho * std::sin(a), 0.0);
  }
  for (int k = 1; k <= kSamples; ++k)  // strand 2, up
    curve.emplace_back(-R * std::cos(phi[k]), rho + P * k / kSamples, -R * std::sin(phi[k]));
  // The end loop, in the plane of e_y and the separation a = (cos phi_end, 0, sin phi_end).
  const double top = rho + P, c = std::cos(phi.back()), s = std::sin(phi.back());
  for (int k = 1; k <= kSamples; ++k) {
    const double psi = kPi * (1.0 - double(k) / kSamples);
    const double across = R * std::cos(psi) + p.loop_bulge * std::sin(psi) * std::sin(2.0 * psi);
    curve.emplace_back(across * c, top + p.loop_height * std::sin(psi), across * s);
  }
  for (int k = kSamples - 1; k >= 0; --k)  // strand 1, down
    curve.emplace_back(R * std::cos(phi[k]), rho + P * k / kSamples, R * std::sin(phi[k]));
  // Tip junction: centre (tail_end, rho), from pi to 3 pi / 2, ends at (tail_end, 0) heading +x.
  for (int k = 1; k <= kSamples; ++k) {
    const double a = kPi * (1.0 + 0.5 * double(k) / kSamples);
    curve.emplace_back(tail_end + rho * std::cos(a), rho + rho * std::sin(a), 0.0);
  }
  for (int k = 1; k <= kSamples; ++k) curve.emplace_back(tail_end + p.tail_length * double(k) / kSamples, 0, 0);
  return curve;
}

}  // namespace

std::vector<Vec3> plectoneme_curve(const PlyLayout& ply) {
  require_positive("ply_radius", ply.ply_radius);
  require_open_interval("helix_angle", ply.helix_angle, 0.0, 0.25 * kPi);
  require_positive("ply_length", ply.ply_length);
  require_positive("junction_radius", ply.junction_radius);
  require_positive("loop_height", ply.loop_height);
  require_non_negative("loop_bulge", ply.loop_bulge);
  require_positive("tail_length", ply.tail_length);
  return dense_curve(ply);
}

TiedRod lay_plectoneme(const PlyLayout& ply, std::size_t elements) {
  return rod_on_curve(plectoneme_curve(ply), elements, true);
}

void clamp_tip_with_its_turns(solvers::rod3d::RodModel& model, const solvers::rod3d::RodState& state) {
  const std::size_t last = state.elements() - 1;
  model.tip.frame.col(0) = solvers::rod3d::edge_tangent(state, last);
  model.tip.frame.col(1) = state.reference_director[last];
  model.tip.frame.col(2) = model.tip.frame.col(0).cross(model.tip.frame.col(1));
  model.tip.rotation = state.angle[last];
}

PulledPly pull_laid_ply(const TiedRod& laid, double twist_rate, double B, double C, double tension,
                        const solvers::rod3d::SelfContact& contact) {
  namespace rod = solvers::rod3d;
  require_finite("twist_rate", twist_rate);
  PulledPly ply;
  rod::RodModel& model = ply.model;
  model = isotropic_rod_on(laid, B, C, contact);
  model.end_force = Vec3(tension, 0.0, 0.0);
  model.root.support = rod::EndSupport::Clamped;
  model.tip.support = rod::EndSupport::Clamped;
  model.tip.slides = true;
  // Material angle of edge j: the twist accumulated up to its midpoint, at arclength j ebar (the
  // supports set first, so that ebar is the clamped rod's, model.hpp).
  const double ebar = rod::rest_edge_length(model);
  std::vector<double> angles(model.elements);
  for (std::size_t j = 0; j < angles.size(); ++j) angles[j] = twist_rate * double(j) * ebar;
  ply.start = rod::make_state(laid.vertices, Vec3::UnitZ(), angles);
  const std::size_t n = model.elements;
  model.root.position = 0.5 * (laid.vertices[0] + laid.vertices[1]);
  model.root.frame = rod::material_frame(ply.start, 0);
  model.tip.position = 0.5 * (laid.vertices[n - 1] + laid.vertices[n]);
  clamp_tip_with_its_turns(model, ply.start);  // the laid twist's whole angle
  return ply;
}

}  // namespace rodvv::harness::knot_cases
