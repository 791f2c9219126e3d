#include "rodvv/references/knot_and_ply.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "bracketed_root.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::references {

namespace {

void validate(const LooseKnot& knot) {
  require_positive("B", knot.B);
  require_positive("T", knot.T);
}

void validate(const UniformPly& ply) {
  require_positive("B", ply.B);
  require_positive("R", ply.R);
  require_finite("F", ply.F);
  require_finite("M", ply.M);
  if (!(ply.theta > 0.0 && ply.theta < std::numbers::pi / 4))
    throw InputError("theta", "invalid parameter 'theta' = " + format_value(ply.theta) +
                                  ": must be in (0, pi/4) (the uniform ply diverges as theta -> 45 degrees)");
}

}  // namespace

double loose_knot_crossing_parameter() {
  // f(u) = u - 2 tanh u: f(1) < 0 < f(3), one root there (f is convex for u > 0, f(0) = 0, f'(0) = -1).
  const auto f = [](double u) { return u - 2.0 * std::tanh(u); };
  return detail::solve_bracketed("loose-knot crossing", f, 1.0, 3.0, f(1.0), f(3.0));
}

LooseKnotSolution loose_knot(const LooseKnot& knot) {
  validate(knot);
  LooseKnotSolution out;
  out.lambda = std::sqrt(knot.B / knot.T);
  out.radius_perpendicular = out.lambda / std::numbers::sqrt2;
  out.apex_radius = 0.5 * out.lambda;
  out.end_shortening = 4.0 * out.lambda;
  const double uc = loose_knot_crossing_parameter();
  out.crossing_arclength = uc * out.lambda;
  out.crossing_height = 2.0 * out.lambda / std::cosh(uc);
  return out;
}

LooseKnotPoint loose_knot_point(const LooseKnot& knot, double s) {
  validate(knot);
  require_finite("s", s);
  const double lambda = std::sqrt(knot.B / knot.T), u = s / lambda;
  // sech u = 1/cosh u underflows to 0 in the tails (|u| > 710), where the rod is straight.
  const double sech = 1.0 / std::cosh(u), tanh = std::tanh(u);
  LooseKnotPoint p;
  p.theta = 4.0 * std::atan(std::exp(u));
  p.curvature = 2.0 * sech / lambda;
  p.x = s - 2.0 * lambda * tanh;
  p.y = 2.0 * lambda * sech;
  // cos theta = 1 - 2 sech^2 u (tan(theta/4) = e^u), so H = 2 B sech^2/lambda^2 + T (1 - 2 sech^2) = T
  // in exact arithmetic; it is evaluated from theta here so that it tests the formulas above.
  p.H = 0.5 * knot.B * p.curvature * p.curvature + knot.T * std::cos(p.theta);
  return p;
}

UniformPlySolution uniform_ply(const UniformPly& ply) {
  validate(ply);
  const double B = ply.B, R = ply.R, s = std::sin(ply.theta), c = std::cos(ply.theta);
  UniformPlySolution out;
  out.curvature = s * s / R;
  out.torsion = s * c / R;
  out.twisting_moment = -(0.5 * ply.F * R * s - 0.5 * ply.M * c + 2.0 * B * s * s * s * c / R) / std::cos(2.0 * ply.theta);
  const double G = (0.5 * ply.M - B * out.curvature * s - out.twisting_moment * c) / R;
  out.tension = 0.5 * ply.F * c + G * s;
  out.binormal_force = 0.5 * ply.F * s - G * c;
  out.contact_force = out.tension * out.curvature - out.binormal_force * out.torsion;
  return out;
}

PlectonemeSolution plectoneme(const UniformPly& ply) {
  if (ply.F != 0.0)
    throw InputError("F", "invalid parameter 'F' = " + format_value(ply.F) + ": must be 0 for a plectoneme (free end loop)");
  if (ply.M != 0.0)
    throw InputError("M", "invalid parameter 'M' = " + format_value(ply.M) + ": must be 0 for a plectoneme (free end loop)");
  PlectonemeSolution out;
  out.ply = uniform_ply(ply);
  const double s2 = std::sin(ply.theta) * std::sin(ply.theta);
  out.tail_tension = ply.B / (ply.R * ply.R) * 0.5 * s2 * s2 * (1.0 + 2.0 / std::cos(2.0 * ply.theta));
  return out;
}

}  // namespace rodvv::references
