#include "trefoil_tying.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::harness::knot_cases {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSamples = 400;  // per piece of the dense curve (chord error ~ (arc / 400)^2 curvature)

}  // namespace

// The dense open curve, from the root tail's far end to the tip tail's far end (before the turn).
std::vector<Vec3> braid_closure_curve(const BraidClosure& k) {
  const double r = k.strand_offset, a = k.braid_half_length, rho = k.loop_radius, g = k.tail_offset;
  const double bottom = -r - 2.0 * rho;  // the lower arc's straight part
  std::vector<Vec3> core;
  // kSamples points (the start excluded) on the circle of radius rho about (cx, cy) in the plane z = 0,
  // from the angle `from` through `sweep`.
  const auto arc = [&](double cx, double cy, double from, double sweep) {
    for (int i = 1; i <= kSamples; ++i) {
      const double phi = from + sweep * double(i) / kSamples;
      core.emplace_back(cx + rho * std::cos(phi), cy + rho * std::sin(phi), 0.0);
    }
  };
  const auto strand = [&](double phase) {
    for (int i = 1; i <= kSamples; ++i) {
      const double x = -a + 2.0 * a * double(i) / kSamples;
      const double psi = phase + 0.5 * k.half_twists * kPi * (x + a) / a;
      core.emplace_back(x, r * std::cos(psi), r * std::sin(psi));
    }
  };
  // From the cut, leftwards along the lower arc, dropping from -g to the arc's plane.
  for (int i = 0; i <= kSamples; ++i) {
    const double u = double(i) / kSamples;
    core.emplace_back(-a * u, bottom, -g * (1.0 - ease(2.0 * u - 1.0)));
  }
  arc(-a, -r - rho, -0.5 * kPi, -kPi);  // up the lower arc's left end into strand 2's start (-a, -r)
  strand(kPi);                          // strand 2, starting below the axis
  // The upper arc: its right end, straight back, its left end.
  arc(a, r + rho, -0.5 * kPi, kPi);
  for (int i = 1; i <= kSamples; ++i) core.emplace_back(a - 2.0 * a * double(i) / kSamples, r + 2.0 * rho, 0.0);
  arc(-a, r + rho, 0.5 * kPi, kPi);
  strand(0.0);                          // strand 1
  arc(a, -r - rho, 0.5 * kPi, -kPi);    // the lower arc's right end
  // Leftwards to the cut, rising to +g.
  for (int i = 1; i <= kSamples; ++i) {
    const double u = double(i) / kSamples;
    core.emplace_back(a * (1.0 - u), bottom, g * ease(2.0 * u));
  }
  // The tails: the root's comes in from +x, the tip's leaves towards -x.
  std::vector<Vec3> curve;
  for (int i = 4 * kSamples; i >= 1; --i) curve.push_back(core.front() + Vec3(k.tail_length * i / (4.0 * kSamples), 0, 0));
  curve.insert(curve.end(), core.begin(), core.end());
  for (int i = 1; i <= 4 * kSamples; ++i) curve.push_back(core.back() - Vec3(k.tail_length * i / (4.0 * kSamples), 0, 0));
  for (Vec3& p : curve) p = Vec3(-p.x(), -p.y(), p.z());  // turned by pi about z: the root at -x
  return curve;
}

void validate(const BraidClosure& knot) {
  if (knot.half_twists < 1 || knot.half_twists % 2 == 0)
    throw InputError("half_twists", "invalid parameter 'half_twists': must be odd and >= 1 (got " +
                                        std::to_string(knot.half_twists) + ")");
  require_positive("strand_offset", knot.strand_offset);
  require_positive("braid_half_length", knot.braid_half_length);
  require_positive("loop_radius", knot.loop_radius);
  require_positive("tail_offset", knot.tail_offset);
  require_positive("tail_length", knot.tail_length);
}

TiedRod tie_braid_closure(const BraidClosure& knot, std::size_t elements) {
  validate(knot);
  require_at_least("elements", elements, 3);
  return rod_on_curve(braid_closure_curve(knot), elements, false);
}

PulledKnot pull_tied_rod(const TiedRod& tied, double B, double C, double T, const solvers::rod3d::SelfContact& contact) {
  namespace rod = solvers::rod3d;
  PulledKnot knot;
  rod::RodModel& model = knot.model;
  model = isotropic_rod_on(tied, B, C, contact);
  model.root.support = rod::EndSupport::Clamped;
  model.root.position = 0.5 * (tied.vertices[0] + tied.vertices[1]);
  model.root.frame << 1, 0, 0, 0, 0, -1, 0, 1, 0;  // t = e_x, m1 = e_z, m2 = t x m1 = -e_y
  model.end_force = Vec3(T, 0.0, 0.0);
  knot.start = rod::make_state(tied.vertices, Vec3::UnitZ());
  return knot;
}

}  // namespace rodvv::harness::knot_cases
