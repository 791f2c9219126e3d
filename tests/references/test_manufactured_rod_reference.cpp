// Tests of the manufactured Kirchhoff rod (references/src/manufactured_rod.cpp).
//
// Oracle: tests/data/manufactured_rod_reference.csv from tests/data/make_manufactured_rod_table.py (mpmath
// odefun, a Taylor-series integrator at 30 digits, on the same definition written out again; not GSL's
// rk8pd). Error unit: eps relative to max(|expected|, 1) (in_epsilons). Tolerance: rk8pd is driven at
// 1e-14 absolute and relative per step (45 eps) over about fifty steps of a 1.7-long rod, and the
// polar factor and the stations' rounding (0.6 L is rounded in C++, exact in mpmath) add a few eps.
// Measured (x86-64 Release, GCC 12): 21 eps; tolerance 128 eps (6 x measured: another compiler's
// rounding of the fifty steps).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/manufactured_planar_rod.hpp"
#include "rodvv/references/manufactured_rod.hpp"
#include "rodvv/testing/input_error.hpp"
#include "rodvv/testing/reference_table.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace ref = rodvv::references;
using rodvv::Mat3;
using rodvv::Vec3;
using rodvv::testing::in_epsilons;
using rodvv::testing::parse_table_number;

constexpr const char* kHeader = "s,quantity,component,value";
enum Column { kS, kQuantity, kComponent, kValue };
constexpr double kTolerance = 128.0;  // eps, see the file comment

// The table's parameter set (make_manufactured_rod_table.py), GJ scaled by (1 + twist_perturbation).
ref::ManufacturedRod table_rod(double twist_perturbation = 0.0) {
  ref::ManufacturedRod rod;
  rod.length = 1.7;
  rod.stiffness = Vec3(0.6 * (1.0 + twist_perturbation), 1.1, 2.3);
  rod.natural_strain = Vec3(0.3, -0.2, 0.5);
  rod.root_position = Vec3(0.2, -0.4, 0.9);
  rod.root_frame << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  rod.strain_mean = Vec3(0.9, 1.3, -0.7);
  rod.strain_sine = Vec3(-0.4, 0.8, 1.1);
  rod.strain_cosine = Vec3(0.25, -0.6, 0.35);
  rod.force_root = Vec3(1.5, -0.8, 0.3);
  rod.force_slope = Vec3(-1.2, 0.4, 0.9);
  rod.force_sine = Vec3(0.7, 0.5, -1.1);
  return rod;
}

// The station's value a table row names (NaN for a name the station does not have).
double value_of(const ref::ManufacturedStation& station, const std::string& name, int k) {
  if (name == "position") return station.position[k];
  if (name == "twist") return station.strain[0];
  if (name == "moment") return station.moment[k];
  if (name == "force") return station.force[k];
  if (name == "force_density") return station.force_density[k];
  if (name == "couple_density") return station.couple_density[k];
  for (int j = 0; j < 3; ++j)
    if (name == "frame_col" + std::to_string(j)) return station.frame(k, j);
  return std::nan("");
}

struct TableCheck {
  double worst = 0.0;
  int failures = 0, rows = 0, moment_failures = 0;
};

TableCheck check_table(double twist_perturbation) {
  const ref::ManufacturedRod rod = table_rod(twist_perturbation);
  const std::vector<std::string> fractions{"0.25", "0.6", "1"};
  std::vector<double> s;
  for (const auto& fraction : fractions) s.push_back(fraction == "1" ? rod.length : std::stod(fraction) * rod.length);
  const auto stations = ref::manufactured_stations(rod, s);
  TableCheck check;
  for (const auto& row : rodvv::testing::read_reference_table("manufactured_rod_reference.csv", kHeader)) {
    std::size_t at = 0;
    while (at < fractions.size() && fractions[at] != row[kS]) ++at;
    if (at == fractions.size()) {
      ADD_FAILURE() << "unknown station " << row[kS];
      continue;
    }
    const std::string& name = row[kQuantity];
    const double actual = value_of(stations[at], name, std::stoi(row[kComponent]));
    const double expected = parse_table_number(row[kValue]);
    const double error = in_epsilons(actual - expected, expected);
    check.worst = std::max(check.worst, std::isnan(error) ? 1e300 : error);
    const bool failed = !(error <= kTolerance);
    check.failures += failed;
    check.moment_failures += failed && (name == "moment" || name == "couple_density");
    ++check.rows;
  }
  return check;
}

TEST(ManufacturedRodReference, MatchesMpmathTable) {
  const TableCheck check = check_table(0.0);
  EXPECT_EQ(check.rows, 63);
  EXPECT_EQ(check.failures, 0) << "worst " << check.worst << " eps";
  std::cout << "[ summary  ] max error (eps): manufactured rod " << check.worst << "\n";
}

// The couple-free variant (tests/data/manufactured_rod_couple_free_reference.csv: the twist from Kirchhoff's
// equation integrated by odefun, n and f = -n' by central differences of the integrated fields, to about
// 1e-18; make_manufactured_rod_table.py): the C++ closed forms of m'' and u0'' against it, to 26 eps. Same tolerance.
TableCheck check_couple_free_table(double twist_perturbation) {
  ref::ManufacturedRod rod = table_rod(twist_perturbation);
  rod.couple_free = true;
  rod.tension_root = 0.9;
  rod.tension_slope = -0.6;
  rod.tension_sine = 0.45;
  const auto stations = ref::manufactured_stations(rod, {0.25 * rod.length, 0.6 * rod.length});
  TableCheck check;
  for (const auto& row : rodvv::testing::read_reference_table("manufactured_rod_couple_free_reference.csv", kHeader)) {
    const std::string& name = row[kQuantity];
    const double actual = value_of(stations[row[kS] == "0.25" ? 0 : 1], name, std::stoi(row[kComponent]));
    const double expected = parse_table_number(row[kValue]);
    const double error = in_epsilons(actual - expected, expected);
    check.worst = std::max(check.worst, std::isnan(error) ? 1e300 : error);
    const bool failed = !(error <= kTolerance);
    check.failures += failed;
    check.moment_failures += failed && (name == "force_density" || name == "twist");
    ++check.rows;
  }
  return check;
}

TEST(ManufacturedRodReference, CoupleFreeVariantMatchesMpmathTable) {
  const TableCheck check = check_couple_free_table(0.0);
  EXPECT_EQ(check.rows, 2 * 25);
  EXPECT_EQ(check.failures, 0) << "worst " << check.worst << " eps";
  std::cout << "[ summary  ] max error (eps): manufactured rod, couple-free " << check.worst << "\n";
  // GJ 1e-9 off moves the integrated twist (u0' = .../GJ) and f at both stations.
  EXPECT_GE(check_couple_free_table(1e-9).moment_failures, 2);
}

// The planar manufactured elastica (tests/data/manufactured_planar_rod_reference.csv: r(L) by mp.quad of the
// closed-form tangent, n and m by odefun from the tip; make_manufactured_planar_rod_table.py), with the
// field's xy coupling scaled by (1 + perturbation). Same tolerance (the backward integration returns to the
// root's x to the table's rounding: the closure is a check of its own).
struct PlanarCheck {
  double worst = 0.0;
  int failures = 0, rows = 0;
};

PlanarCheck check_planar_table(double field_perturbation) {
  ref::ManufacturedPlanarRod rod;
  rod.length = 1.6;
  rod.root_x = 0.3;
  rod.root_y = -0.5;
  rod.theta_root = 0.4;
  rod.theta_slope = 1.1;
  rod.theta_sine = -0.7;
  rod.theta_cosine = 0.35;
  rod.stiffness = 0.9;
  rod.stiffness_variation = 0.25;
  rod.field_xx = 1.3;
  rod.field_xy = -0.6 * (1.0 + field_perturbation);
  rod.field_y = 2.2;
  rod.tip_force_x = -0.8;
  rod.tip_force_y = 1.7;
  rod.tip_moment = 0.45;
  const std::vector<std::string> fractions{"0", "0.35", "0.8"};
  std::vector<double> s;
  for (const auto& fraction : fractions) s.push_back(std::stod(fraction) * rod.length);
  const auto stations = ref::manufactured_planar_stations(rod, s);
  PlanarCheck check;
  for (const auto& row : rodvv::testing::read_reference_table("manufactured_planar_rod_reference.csv", "s,quantity,value")) {
    std::size_t at = 0;
    while (at < fractions.size() && fractions[at] != row[0]) ++at;
    if (at == fractions.size()) {
      ADD_FAILURE() << "unknown station " << row[0];
      continue;
    }
    const auto& station = stations[at];
    const std::string& name = row[1];
    double actual = std::nan("");
    if (name == "x") actual = station.x;
    if (name == "y") actual = station.y;
    if (name == "force_x") actual = station.force_x;
    if (name == "force_y") actual = station.force_y;
    if (name == "moment") actual = station.moment;
    if (name == "natural_curvature") actual = station.natural_curvature;
    const double expected = parse_table_number(row[2]);
    const double error = in_epsilons(actual - expected, expected);
    check.worst = std::max(check.worst, std::isnan(error) ? 1e300 : error);
    check.failures += !(error <= kTolerance);
    ++check.rows;
  }
  return check;
}

TEST(ManufacturedRodReference, PlanarVariantMatchesMpmathTable) {
  const PlanarCheck check = check_planar_table(0.0);
  EXPECT_EQ(check.rows, 18);
  EXPECT_EQ(check.failures, 0) << "worst " << check.worst << " eps";
  std::cout << "[ summary  ] max error (eps): manufactured planar rod " << check.worst << "\n";
  EXPECT_GE(check_planar_table(1e-9).failures, 4);  // the field's coupling 1e-9 off moves n and m
}

TEST(ManufacturedRodReference, PerturbedTwistStiffnessTurnsTheMomentsRed) {
  // GJ (1 + 1e-9) moves m and c by about 1e-9 of their twist parts (1e6 eps): at every station.
  EXPECT_GE(check_table(1e-9).moment_failures, 3);
}

TEST(ManufacturedRodReference, CellLoadsAddUpToTheRodsResultants) {
  const ref::ManufacturedRod rod = table_rod();
  const double L = rod.length;
  const std::vector<double> one{0.0, L}, seven{0.0, 0.1 * L, 0.2 * L, 0.35 * L, 0.5 * L, 0.7 * L, 0.9 * L, L};
  std::vector<double> fourteen;  // each of the seven cells halved
  for (std::size_t k = 0; k + 1 < seven.size(); ++k) fourteen.insert(fourteen.end(), {seven[k], 0.5 * (seven[k] + seven[k + 1])});
  fourteen.push_back(L);
  // Forces: n(a) - n(b) cell by cell, so the cells add up to n(0) - n(L) to round-off.
  Vec3 forces = Vec3::Zero();
  for (const Vec3& f : ref::manufactured_cell_forces(rod, seven)) forces += f;
  EXPECT_LT((forces - ref::manufactured_cell_forces(rod, one)[0]).norm(), 16 * 2.2e-16 * 4.0);
  // Couples: 8-point Gauss (degree 15) on cells of 0.1 - 0.2 L against the same cells halved: the smooth
  // integrand's remainder falls as (cell / 2)^16, so the two agree to round-off (one cell over the whole
  // rod, where the frame turns by about 3 rad, is off by 4e-4: Gauss needs the cells). Then the moment
  // balance m(L) - m(0) + int t x n ds + int c ds = 0 with int t x n ds by the trapezoidal rule on 4000
  // stations (O(h^2): 1e-8).
  Vec3 couples = Vec3::Zero(), halved = Vec3::Zero();
  for (const Vec3& c : ref::manufactured_cell_couples(rod, seven)) couples += c;
  for (const Vec3& c : ref::manufactured_cell_couples(rod, fourteen)) halved += c;
  EXPECT_LT((couples - halved).norm(), 1e-13 * (1.0 + halved.norm())) << couples.transpose() << " vs " << halved.transpose();
  const auto ends = ref::manufactured_stations(rod, {0.0, L});
  std::vector<double> s;
  for (int i = 0; i <= 4000; ++i) s.push_back(L * i / 4000.0);
  const auto fine = ref::manufactured_stations(rod, s);
  Vec3 t_cross_n = Vec3::Zero();
  for (std::size_t i = 0; i + 1 < fine.size(); ++i)
    t_cross_n += 0.5 * (s[i + 1] - s[i]) *
                 (fine[i].frame.col(0).cross(fine[i].force) + fine[i + 1].frame.col(0).cross(fine[i + 1].force));
  const Vec3 balance = ends[1].moment - ends[0].moment + t_cross_n + halved;
  EXPECT_LT(balance.norm(), 1e-6) << balance.transpose();
}

TEST(ManufacturedRodReference, FramesStayRotationsAndTheCentrelineUnitSpeed) {
  const ref::ManufacturedRod rod = table_rod();
  std::vector<double> s;
  for (int i = 0; i <= 200; ++i) s.push_back(rod.length * i / 200.0);
  const auto stations = ref::manufactured_stations(rod, s);
  double worst_speed = 0.0;
  for (std::size_t i = 0; i < stations.size(); ++i) {
    EXPECT_LT((stations[i].frame.transpose() * stations[i].frame - Mat3::Identity()).norm(), 1e-14);
    if (i + 1 < stations.size()) {  // the chord of a unit-speed curve over ds: ds (1 - kappa^2 ds^2 / 24)
      const double ds = s[i + 1] - s[i];
      worst_speed = std::max(worst_speed, std::abs((stations[i + 1].position - stations[i].position).norm() / ds - 1.0));
    }
  }
  EXPECT_LT(worst_speed, 1e-4);  // kappa <= 4: 16 ds^2 / 24 = 5e-5
}

TEST(ManufacturedRodReference, RefusesBadInput) {
  const auto parameter_of = [](ref::ManufacturedRod rod, std::vector<double> s = {0.0}) {
    return rodvv::testing::input_error_parameter_of([&] { ref::manufactured_stations(rod, s); });
  };
  EXPECT_EQ(parameter_of(table_rod()), "<no InputError>");
  ref::ManufacturedRod rod = table_rod();
  rod.length = 0.0;
  EXPECT_EQ(parameter_of(rod), "length");
  rod = table_rod();
  rod.stiffness[2] = -1.0;
  EXPECT_EQ(parameter_of(rod), "stiffness.bending2 (EI2)");
  rod = table_rod();
  rod.root_frame(0, 0) = 0.5;
  EXPECT_EQ(parameter_of(rod), "root_frame");
  rod = table_rod();
  rod.force_sine[1] = std::nan("");
  EXPECT_EQ(parameter_of(rod), "force_sine[1]");
  EXPECT_EQ(parameter_of(table_rod(), {0.5, 0.2}), "stations");
  EXPECT_EQ(parameter_of(table_rod(), {2.0}), "stations");
  EXPECT_EQ(rodvv::testing::input_error_parameter_of([] { ref::manufactured_cell_couples(table_rod(), {0.0, -1.0}); }),
            "breaks");
}

}  // namespace
