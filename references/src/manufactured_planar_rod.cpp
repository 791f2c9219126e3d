#include "rodvv/references/manufactured_planar_rod.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <utility>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "gsl_checked.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::references {

namespace {

constexpr double kPi = std::numbers::pi;

double theta_at(const ManufacturedPlanarRod& rod, double s) {
  const double L = rod.length;
  return rod.theta_root + rod.theta_slope * s / L + rod.theta_sine * std::sin(kPi * s / L) +
         rod.theta_cosine * (std::cos(2.0 * kPi * s / L) - 1.0);
}

double kappa_at(const ManufacturedPlanarRod& rod, double s) {
  const double L = rod.length;
  return rod.theta_slope / L + rod.theta_sine * (kPi / L) * std::cos(kPi * s / L) -
         rod.theta_cosine * (2.0 * kPi / L) * std::sin(2.0 * kPi * s / L);
}

// y = (x, y, n_x, n_y, m): r' = t, n' = grad V(r), m' = -(t x n)_z.
int planar_rhs(double s, const double y[], double dyds[], void* params) {
  const auto& rod = *static_cast<const ManufacturedPlanarRod*>(params);
  const double theta = theta_at(rod, s), c = std::cos(theta), sn = std::sin(theta);
  dyds[0] = c;
  dyds[1] = sn;
  dyds[2] = rod.field_xx * y[0] + rod.field_xy * y[1];
  dyds[3] = rod.field_xy * y[0] + rod.field_y;
  dyds[4] = -(c * y[3] - sn * y[2]);
  return GSL_SUCCESS;
}

using Driver = std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)>;

Driver make_driver(gsl_odeiv2_system& system, double L, double direction) {
  return Driver(gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, direction * 1e-3 * L, 1e-14, 1e-14),
                gsl_odeiv2_driver_free);
}

void validate(const ManufacturedPlanarRod& rod) {
  require_positive("length", rod.length);
  require_positive("stiffness", rod.stiffness);
  for (const auto& [name, value] :
       {std::pair{"root_x", rod.root_x}, {"root_y", rod.root_y}, {"theta_root", rod.theta_root},
        {"theta_slope", rod.theta_slope}, {"theta_sine", rod.theta_sine}, {"theta_cosine", rod.theta_cosine},
        {"field_xx", rod.field_xx}, {"field_xy", rod.field_xy}, {"field_y", rod.field_y},
        {"tip_force_x", rod.tip_force_x}, {"tip_force_y", rod.tip_force_y}, {"tip_moment", rod.tip_moment}})
    require_finite(name, value);
  if (!(std::abs(rod.stiffness_variation) < 1.0))
    throw InputError("stiffness_variation", "invalid parameter 'stiffness_variation' = " +
                                                format_value(rod.stiffness_variation) +
                                                ": must be a finite number in (-1, 1) (EI(s) > 0)");
}

}  // namespace

std::vector<ManufacturedPlanarStation> manufactured_planar_stations(const ManufacturedPlanarRod& rod,
                                                                    const std::vector<double>& s) {
  validate(rod);
  const double L = rod.length;
  for (std::size_t k = 0; k < s.size(); ++k)
    if (!(s[k] >= 0.0 && s[k] <= L))
      throw InputError("stations", "invalid parameter 'stations': entry " + std::to_string(k) + " = " +
                                       format_value(s[k]) + " is outside [0, L = " + format_value(L) + "]");
  detail::gsl_handler_off();
  gsl_odeiv2_system system{planar_rhs, nullptr, 5, const_cast<ManufacturedPlanarRod*>(&rod)};
  // Forward to the tip (n and m are carried along at zero: only r(L) is kept).
  std::array<double, 5> tip{rod.root_x, rod.root_y, 0.0, 0.0, 0.0};
  {
    const Driver forward = make_driver(system, L, 1.0);
    double at = 0.0;
    detail::check_gsl(gsl_odeiv2_driver_apply(forward.get(), &at, L, tip.data()), "gsl_odeiv2_driver_apply");
  }
  tip[2] = rod.tip_force_x;
  tip[3] = rod.tip_force_y;
  tip[4] = rod.tip_moment;
  std::vector<ManufacturedPlanarStation> out;
  out.reserve(s.size());
  for (double target : s) {  // backward from the tip to each station
    std::array<double, 5> y = tip;
    if (target < L) {
      const Driver backward = make_driver(system, L, -1.0);
      double at = L;
      detail::check_gsl(gsl_odeiv2_driver_apply(backward.get(), &at, target, y.data()), "gsl_odeiv2_driver_apply");
    }
    ManufacturedPlanarStation station;
    station.s = target;
    station.x = y[0];
    station.y = y[1];
    station.theta = theta_at(rod, target);
    station.kappa = kappa_at(rod, target);
    station.force_x = y[2];
    station.force_y = y[3];
    station.moment = y[4];
    station.bending_stiffness = rod.stiffness * (1.0 + rod.stiffness_variation * std::sin(kPi * target / L));
    station.natural_curvature = station.kappa - station.moment / station.bending_stiffness;
    out.push_back(station);
  }
  return out;
}

}  // namespace rodvv::references
