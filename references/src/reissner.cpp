#include "rodvv/references/reissner.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::references {

namespace {

// (0, +inf]; NaN rejected.
void require_stiffness(const char* name, double value) {
  if (value > 0.0) return;
  throw InputError(name, std::string("invalid parameter '") + name + "' = " + format_value(value) +
                             ": must be in (0, +inf] (+inf = rigid)");
}

}  // namespace

double reissner_bar_end_displacement(double force, double length, double axial_stiffness) {
  require_positive("length", length);
  require_stiffness("axial_stiffness", axial_stiffness);
  require_finite("force", force);
  if (!(force > -axial_stiffness))
    throw InputError("force", "invalid parameter 'force' = " + format_value(force) +
                                  ": must be > -axial_stiffness (stretch 1 + F/EA > 0)");
  return force * length / axial_stiffness;
}

double reissner_pinned_critical_load(double length, double bending_stiffness, double axial_stiffness,
                                     double shear_stiffness, int mode) {
  require_positive("length", length);
  require_positive("bending_stiffness", bending_stiffness);
  require_stiffness("axial_stiffness", axial_stiffness);
  require_stiffness("shear_stiffness", shear_stiffness);
  if (mode < 1)
    throw InputError("mode", "invalid parameter 'mode' = " + std::to_string(mode) + ": must be >= 1");
  const double k = static_cast<double>(mode) * std::numbers::pi / length;
  const double euler = k * k * bending_stiffness;
  const double c = 1.0 / shear_stiffness - 1.0 / axial_stiffness;
  const double discriminant = 1.0 + 4.0 * euler * c;
  if (!(discriminant >= 0.0))
    throw InputError("axial_stiffness",
                     "invalid parameter 'axial_stiffness' = " + format_value(axial_stiffness) +
                         ": no bifurcation of this mode, 1 + 4 P_k (1/GA - 1/EA) = " +
                         format_value(discriminant) + " < 0; needs 1/EA <= 1/GA + 1/(4 P_k)");
  // Smaller root of c P^2 + P - P_k = 0 in the cancellation-free form.
  return 2.0 * euler / (1.0 + std::sqrt(discriminant));
}

}  // namespace rodvv::references
