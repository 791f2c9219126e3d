#include "rodvv/references/manufactured_rod.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_odeiv2.h>

#include "gsl_checked.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::references {

namespace {

constexpr double kPi = std::numbers::pi;

Mat3 skew(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v[2], v[1], v[2], 0.0, -v[0], -v[1], v[0], 0.0;
  return m;
}

// The chosen parts of u, u', u'' (closed forms); in couple_free the twist entries are replaced by the
// integrated twist and its rates (twist_rate, twist_second).
Vec3 chosen_strain(const ManufacturedRod& rod, double s) {
  const double L = rod.length;
  return rod.strain_mean + rod.strain_sine * std::sin(kPi * s / L) + rod.strain_cosine * std::cos(2.0 * kPi * s / L);
}

Vec3 chosen_strain_rate(const ManufacturedRod& rod, double s) {
  const double L = rod.length;
  return rod.strain_sine * (kPi / L) * std::cos(kPi * s / L) - rod.strain_cosine * (2.0 * kPi / L) * std::sin(2.0 * kPi * s / L);
}

Vec3 chosen_strain_second(const ManufacturedRod& rod, double s) {
  const double L = rod.length, k = kPi / L;
  return -rod.strain_sine * (k * k) * std::sin(kPi * s / L) - rod.strain_cosine * (4.0 * k * k) * std::cos(2.0 * kPi * s / L);
}

// Kirchhoff's twist equation GJ u0' = -(u x K (u - u_hat))_0 and its derivative along s.
double twist_rate(const ManufacturedRod& rod, const Vec3& u) {
  const Vec3& K = rod.stiffness;
  const Vec3 a = K.cwiseProduct(u - rod.natural_strain);
  return -(u[1] * a[2] - u[2] * a[1]) / K[0];
}

double twist_second(const ManufacturedRod& rod, const Vec3& u, const Vec3& du) {
  const Vec3& K = rod.stiffness;
  const Vec3 a = K.cwiseProduct(u - rod.natural_strain), da = K.cwiseProduct(du);
  return -(du[1] * a[2] + u[1] * da[2] - du[2] * a[1] - u[2] * da[1]) / K[0];
}

Vec3 chosen_force(const ManufacturedRod& rod, double s) {
  const double L = rod.length;
  return rod.force_root + rod.force_slope * (s / L) + rod.force_sine * std::sin(kPi * s / L);
}

Vec3 chosen_force_rate(const ManufacturedRod& rod, double s) {
  const double L = rod.length;
  return rod.force_slope / L + rod.force_sine * (kPi / L) * std::cos(kPi * s / L);
}

void validate(const ManufacturedRod& rod) {
  require_positive("length", rod.length);
  require_positive("stiffness.twist (GJ)", rod.stiffness[0]);
  require_positive("stiffness.bending1 (EI1)", rod.stiffness[1]);
  require_positive("stiffness.bending2 (EI2)", rod.stiffness[2]);
  require_finite_vector("natural_strain", rod.natural_strain);
  require_finite_vector("root_position", rod.root_position);
  for (const auto& [name, v] : {std::pair{"strain_mean", rod.strain_mean}, {"strain_sine", rod.strain_sine},
                                {"strain_cosine", rod.strain_cosine}, {"force_root", rod.force_root},
                                {"force_slope", rod.force_slope}, {"force_sine", rod.force_sine}})
    require_finite_vector(name, v);
  require_finite("tension_root", rod.tension_root);
  require_finite("tension_slope", rod.tension_slope);
  require_finite("tension_sine", rod.tension_sine);
  if (!rod.root_frame.allFinite() || !((rod.root_frame.transpose() * rod.root_frame - Mat3::Identity()).norm() <= 1e-12) ||
      !(rod.root_frame.determinant() > 0.0))
    throw InputError("root_frame", "invalid parameter 'root_frame': must be a rotation (orthonormal to 1e-12, det +1)");
}

void validate_stations(const ManufacturedRod& rod, const std::vector<double>& s, const char* name) {
  for (std::size_t k = 0; k < s.size(); ++k)
    if (!(s[k] >= 0.0 && s[k] <= rod.length) || (k > 0 && !(s[k] >= s[k - 1])))
      throw InputError(name, std::string("invalid parameter '") + name + "': stations must ascend in [0, L = " +
                                 format_value(rod.length) + "]; entry " + std::to_string(k) + " is " +
                                 format_value(s[k]));
}

// y = (r, R column-major, u0): r' = R e1, R' = R [u]x, and u0' from the chosen u0 or, couple_free, from
// Kirchhoff's twist equation.
Vec3 strain_of(const ManufacturedRod& rod, double s, double twist) {
  Vec3 u = chosen_strain(rod, s);
  if (rod.couple_free) u[0] = twist;
  return u;
}

int centreline_rhs(double s, const double y[], double dyds[], void* params) {
  const auto& rod = *static_cast<const ManufacturedRod*>(params);
  const Eigen::Map<const Mat3> R(y + 3);
  Eigen::Map<Mat3> dR(dyds + 3);
  const Vec3 u = strain_of(rod, s, y[12]);
  dyds[0] = R(0, 0);
  dyds[1] = R(1, 0);
  dyds[2] = R(2, 0);
  dR = R * skew(u);
  dyds[12] = rod.couple_free ? twist_rate(rod, u) : chosen_strain_rate(rod, s)[0];
  return GSL_SUCCESS;
}

}  // namespace

std::vector<ManufacturedStation> manufactured_stations(const ManufacturedRod& rod, const std::vector<double>& s) {
  validate(rod);
  validate_stations(rod, s, "stations");
  detail::gsl_handler_off();
  gsl_odeiv2_system system{centreline_rhs, nullptr, 13, const_cast<ManufacturedRod*>(&rod)};
  const std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> driver(
      gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, 1e-3 * rod.length, 1e-14, 1e-14),
      gsl_odeiv2_driver_free);
  std::array<double, 13> y{};
  Eigen::Map<Vec3>(y.data()) = rod.root_position;
  Eigen::Map<Mat3>(y.data() + 3) = rod.root_frame;
  y[12] = chosen_strain(rod, 0.0)[0];
  double at = 0.0;
  const Mat3 K = rod.stiffness.asDiagonal();
  const double L = rod.length;
  std::vector<ManufacturedStation> out;
  out.reserve(s.size());
  for (double target : s) {
    if (target > at) detail::check_gsl(gsl_odeiv2_driver_apply(driver.get(), &at, target, y.data()), "gsl_odeiv2_driver_apply");
    ManufacturedStation station;
    station.s = target;
    station.position = Eigen::Map<const Vec3>(y.data());
    // The nearest rotation (polar factor): the integration keeps R orthonormal to its tolerance only.
    const Eigen::JacobiSVD<Mat3> svd(Eigen::Map<const Mat3>(y.data() + 3), Eigen::ComputeFullU | Eigen::ComputeFullV);
    station.frame = svd.matrixU() * svd.matrixV().transpose();
    const Mat3& R = station.frame;
    const Vec3 u = strain_of(rod, target, y[12]);
    Vec3 du = chosen_strain_rate(rod, target), ddu = chosen_strain_second(rod, target);
    if (rod.couple_free) {
      du[0] = twist_rate(rod, u);
      ddu[0] = twist_second(rod, u, du);
    }
    const Vec3 a = K * (u - rod.natural_strain);
    const Vec3 t = R.col(0);
    const Vec3 moment_rate = R * (u.cross(a) + K * du);
    station.strain = u;
    station.moment = R * a;
    if (rod.couple_free) {
      const double S = std::sin(kPi * target / L), C = std::cos(kPi * target / L);
      const double T = rod.tension_root + rod.tension_slope * target / L + rod.tension_sine * S;
      const double dT = rod.tension_slope / L + rod.tension_sine * (kPi / L) * C;
      const Vec3 dt = R * u.cross(Vec3::UnitX());
      const Vec3 moment_second = R * (u.cross(u.cross(a) + K * du) + du.cross(a) + u.cross(K * du) + K * ddu);
      station.force = T * t + t.cross(moment_rate);
      station.force_density = -(dT * t + T * dt + dt.cross(moment_rate) + t.cross(moment_second));
    } else {
      station.force = chosen_force(rod, target);
      station.force_density = -chosen_force_rate(rod, target);
    }
    station.couple_density = -moment_rate - t.cross(station.force);
    out.push_back(station);
  }
  return out;
}

std::vector<Vec3> manufactured_cell_forces(const ManufacturedRod& rod, const std::vector<double>& breaks) {
  validate(rod);
  validate_stations(rod, breaks, "breaks");
  const auto at = manufactured_stations(rod, breaks);
  std::vector<Vec3> forces;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) forces.push_back(at[k].force - at[k + 1].force);
  return forces;
}

std::vector<Vec3> manufactured_cell_couples(const ManufacturedRod& rod, const std::vector<double>& breaks) {
  validate(rod);
  validate_stations(rod, breaks, "breaks");
  constexpr std::size_t kPoints = 8;
  const std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)> table(
      gsl_integration_glfixed_table_alloc(kPoints), gsl_integration_glfixed_table_free);
  std::vector<double> stations, weights;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
    for (std::size_t i = 0; i < kPoints; ++i) {
      double x = 0.0, w = 0.0;
      gsl_integration_glfixed_point(breaks[k], breaks[k + 1], i, &x, &w, table.get());
      stations.push_back(x);
      weights.push_back(w);
    }
  // glfixed's points of one cell are not in ascending order: integrate over the sorted stations.
  std::vector<std::size_t> order(stations.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return stations[a] < stations[b]; });
  std::vector<double> sorted;
  for (std::size_t i : order) sorted.push_back(stations[i]);
  const auto fields = manufactured_stations(rod, sorted);
  std::vector<Vec3> couples(breaks.empty() ? 0 : breaks.size() - 1, Vec3::Zero());
  for (std::size_t j = 0; j < order.size(); ++j)
    couples[order[j] / kPoints] += weights[order[j]] * fields[j].couple_density;
  return couples;
}

}  // namespace rodvv::references
