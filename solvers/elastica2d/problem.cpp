#include "rodvv/solvers/elastica2d/problem.hpp"

#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::elastica2d {

double bending_stiffness_at(const Problem& problem, double s) {
  return problem.bending_stiffness ? problem.bending_stiffness(s) : 1.0;
}

double natural_curvature_at(const Problem& problem, double s) {
  return problem.natural_curvature ? problem.natural_curvature(s) : 0.0;
}

namespace {

void require_zero_load(const std::string& name, double value, const char* support) {
  require_finite(name, value);
  if (value != 0.0)
    throw InputError(name, "invalid parameter '" + name + "' = " + format_value(value) +
                               ": must be 0 at a " + support +
                               " end (that direction is prescribed; the reaction carries the load)");
}

void validate_end(const RodEnd& end, const std::string& prefix) {
  require_finite(prefix + ".x", end.x);
  require_finite(prefix + ".y", end.y);
  require_finite(prefix + ".angle", end.angle);
  const std::string fx = prefix + ".load.force_x";
  const std::string fy = prefix + ".load.force_y";
  const std::string mz = prefix + ".load.moment";
  switch (end.support) {
    case Support::Free:
      require_finite(fx, end.load.force_x);
      require_finite(fy, end.load.force_y);
      require_finite(mz, end.load.moment);
      return;
    case Support::Pinned:
      require_zero_load(fx, end.load.force_x, "pinned");
      require_zero_load(fy, end.load.force_y, "pinned");
      require_finite(mz, end.load.moment);
      return;
    case Support::Clamped:
      require_zero_load(fx, end.load.force_x, "clamped");
      require_zero_load(fy, end.load.force_y, "clamped");
      require_zero_load(mz, end.load.moment, "clamped");
      return;
    case Support::Sliding:
      require_finite(fx, end.load.force_x);
      require_zero_load(fy, end.load.force_y, "sliding");
      require_finite(mz, end.load.moment);
      return;
  }
  throw InputError(prefix + ".support", "invalid parameter '" + prefix +
                                            ".support': must be Free, Pinned, Clamped or Sliding");
}

// (0, +infinity]: +infinity is the rigid (inextensible or unshearable) limit; NaN is rejected.
void require_stiffness(const char* name, double value) {
  if (value > 0.0) return;
  throw InputError(name, std::string("invalid parameter '") + name + "' = " + format_value(value) +
                             ": must be in (0, +inf] (+inf = rigid)");
}

}  // namespace

void validate(const Problem& problem) {
  require_positive("length", problem.length);
  require_stiffness("axial_stiffness", problem.axial_stiffness);
  require_stiffness("shear_stiffness", problem.shear_stiffness);
  validate_end(problem.start, "start");
  validate_end(problem.end, "end");
  const Potential& v = problem.potential;
  if (v.active() && !(v.value && v.gradient))
    throw InputError("potential.gradient",
                     "invalid parameter 'potential': value and gradient must both be given");
}

}  // namespace rodvv::solvers::elastica2d
