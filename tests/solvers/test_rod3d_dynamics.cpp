// The nodal 3-D rod in motion (solvers/rod3d: linearized, dynamics): natural frequencies against
// closed forms (both bending planes, torsion), the stability eigenvalue at the Euler load, the
// step's Jacobian against finite differences, the energy behaviour of implicit Euler (first-order
// loss, its magnitude on one mode) and of the implicit midpoint rule (O(h^2), no drift), momentum
// conservation of a free rod, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/rod3d.hpp"
#include "rodvv/solvers/rod3d/discrete_energy.hpp"
#include "rodvv/solvers/rod3d/dynamics.hpp"
#include "rodvv/solvers/rod3d/linearized.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/state.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace rod = rodvv::solvers::rod3d;
namespace ref = rodvv::references;
using rodvv::Mat3;
using rodvv::Vec3;
using rodvv::VecX;
constexpr double kPi = std::numbers::pi;
constexpr double kEps = 2.220446049250313e-16;

Mat3 tilted_frame(double angle) {
  return Eigen::AngleAxisd(angle, Vec3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
}

// ---- linearisation ---------------------------------------------------------------------------------

// A straight cantilever in a tilted frame with GJ, EI1, EI2, rho S, rho I0 all different and not 1.
rod::RodModel cantilever(std::size_t n) {
  rod::RodModel model;
  model.elements = n;
  model.length = 1.3;
  model.stiffness = Vec3(0.55, 1.7, 3.1);
  model.line_density = 0.8;
  model.twist_inertia = 0.03;
  model.root.support = rod::EndSupport::Clamped;
  model.root.frame = tilted_frame(0.7);
  model.root.position = Vec3(0.2, 0.4, -0.1);
  return model;
}

struct Spectrum {
  std::vector<double> bending1, bending2, torsion;  // first two of each family, ascending
};

// Sorts the modes into families by where their kinetic norm lies: translation along m2 (bending
// about m1: EI1), along m1 (EI2), rotation of the sections (torsion). A straight uniform rod
// decouples them exactly; the tilted frame mixes them only at round-off.
Spectrum classify(const rod::RodModel& model, const rod::LinearModes& modes) {
  Spectrum s;
  const Mat3& frame = model.root.frame;
  for (Eigen::Index k = 0; k < modes.frequencies.size(); ++k) {
    const auto c = rod::modal_content(model, modes.shapes.col(k), frame);
    const double omega = modes.frequencies[k];
    if (c.translation[2] > 1.0 - 1e-9 && s.bending1.size() < 2) s.bending1.push_back(omega);
    if (c.translation[1] > 1.0 - 1e-9 && s.bending2.size() < 2) s.bending2.push_back(omega);
    if (c.rotation > 1.0 - 1e-9 && s.torsion.size() < 2) s.torsion.push_back(omega);
  }
  return s;
}

struct SpectrumErrors {
  std::vector<double> relative;  // bending1 (2), bending2 (2), torsion (2)
};

SpectrumErrors spectrum_errors(std::size_t n) {
  const auto model = cantilever(n);
  const auto modes = rod::linear_modes(model, rod::make_straight_state(model));
  const Spectrum s = classify(model, modes);
  EXPECT_EQ(s.bending1.size(), 2u);
  EXPECT_EQ(s.bending2.size(), 2u);
  EXPECT_EQ(s.torsion.size(), 2u);
  SpectrumErrors e;
  const double L = model.length, rho = model.line_density;
  for (std::size_t k = 0; k < 2; ++k) {
    const double exact = ref::cantilever_frequency(k + 1, model.stiffness[1], rho, L);
    e.relative.push_back(std::abs(s.bending1.at(k) - exact) / exact);
  }
  for (std::size_t k = 0; k < 2; ++k) {
    const double exact = ref::cantilever_frequency(k + 1, model.stiffness[2], rho, L);
    e.relative.push_back(std::abs(s.bending2.at(k) - exact) / exact);
  }
  for (std::size_t k = 0; k < 2; ++k) {
    const double exact = double(2 * k + 1) * kPi / (2.0 * L) * std::sqrt(model.stiffness[0] / model.twist_inertia);
    e.relative.push_back(std::abs(s.torsion.at(k) - exact) / exact);
  }
  return e;
}

TEST(Rod3dModes, BendingAndTorsionFrequenciesConvergeAtSecondOrder) {
  const auto coarse = spectrum_errors(16), fine = spectrum_errors(32), finer = spectrum_errors(64);
  const char* names[6] = {"EI1 mode 1", "EI1 mode 2", "EI2 mode 1", "EI2 mode 2", "torsion 1", "torsion 2"};
  // Measured relative errors at N = 64: bending 3.92e-5 (mode 1), 4.72e-4 (mode 2) in both planes
  // (the same shapes, scaled); torsion 2.55e-5, 2.30e-4 (= (k ebar)^2 / 24, see below). Bounds 2x.
  const double bound[6] = {8e-5, 1e-3, 8e-5, 1e-3, 5.2e-5, 4.6e-4};
  for (std::size_t k = 0; k < 6; ++k) {
    const double order = std::log2(fine.relative[k] / finer.relative[k]);
    const double order_coarse = std::log2(coarse.relative[k] / fine.relative[k]);
    std::cout << names[k] << ": relative errors " << coarse.relative[k] << ", " << fine.relative[k] << ", "
              << finer.relative[k] << "; orders " << order_coarse << ", " << order << "\n";
    EXPECT_NEAR(order, 2.0, 0.05) << names[k];
    EXPECT_NEAR(order_coarse, 2.0, 0.1) << names[k];
    EXPECT_LT(finer.relative[k], bound[k]) << names[k];
  }
  // EI1 and EI2 modes have the same shape: the same relative error (the bending planes are not mixed
  // up), to the eigensolver's round-off: eps x the largest eigenvalue (16 EI2 / (rho S ebar^4) ~ 4e8
  // at N = 64) / omega^2 (~9) ~ 1e-8 relative in omega^2 (measured 5e-10 in omega).
  EXPECT_NEAR(finer.relative[0], finer.relative[2], 1e-8);
  EXPECT_NEAR(finer.relative[1], finer.relative[3], 1e-8);
}

// Torsion is a chain of springs GJ/ebar between the edges' angles (masses rho I0 ebar, edge 0 held
// at s = 0, the last edge's centre ebar/2 from the free end): its modes are sin(k s) at the edge
// centres with k L = (2n - 1) pi / 2 exactly, and omega = (2/ebar) sqrt(GJ/rho I0) sin(k ebar / 2),
// the continuous value times 1 - (k ebar)^2 / 24 + ...: the half-edge treatment gives order 2.
TEST(Rod3dModes, TorsionalFrequenciesMatchTheDiscreteClosedForm) {
  const auto model = cantilever(24);
  const auto modes = rod::linear_modes(model, rod::make_straight_state(model));
  const Spectrum s = classify(model, modes);
  const double ell = rod::rest_edge_length(model);
  for (std::size_t n = 1; n <= 2; ++n) {
    const double k = double(2 * n - 1) * kPi / (2.0 * model.length);
    const double discrete = 2.0 / ell * std::sqrt(model.stiffness[0] / model.twist_inertia) * std::sin(0.5 * k * ell);
    // A symmetric eigenvalue is accurate to eps times the largest (the top bending eigenvalue
    // 16 EI2 / (rho S ebar^4) ~ 7e6 here): 1.5e-9 absolute, 4e-11 relative to omega^2 >= 40; bound
    // 1e-10 on omega.
    EXPECT_TRUE(rodvv::testing::is_close(s.torsion.at(n - 1), discrete, 1e-10, 0.0)) << n;
  }
}

TEST(Rod3dModes, FreeRodHasSixRigidModes) {
  rod::RodModel model;
  model.elements = 12;
  model.length = 0.9;
  model.stiffness = Vec3(0.4, 1.1, 2.3);
  model.line_density = 1.7;
  model.twist_inertia = 0.05;
  model.root.frame = tilted_frame(1.1);
  const auto state = rod::make_straight_state(model);
  const auto modes = rod::linear_modes(model, state);
  // Rigid motions: 3 translations, 2 rotations about normals, the rotation about the axis (all
  // angles equal). Their eigenvalues are round-off of the largest (eps x 1e6 ~ 1e-9).
  const double largest = modes.omega_squared.cwiseAbs().maxCoeff();
  for (int k = 0; k < 6; ++k) EXPECT_LT(std::abs(modes.omega_squared[k]), 1e3 * kEps * largest) << k;
  EXPECT_GT(modes.omega_squared[6], 1.0);  // the first flexible mode (~(4.73/L)^4 EI/rho S ~ 1e3)
  // The shapes are M-orthonormal.
  const VecX mass = rod::lumped_mass(model);
  const rodvv::MatX gram = modes.shapes.transpose() * mass.asDiagonal() * modes.shapes;
  EXPECT_LT((gram - rodvv::MatX::Identity(gram.rows(), gram.cols())).cwiseAbs().maxCoeff(), 1e-12);
}

// A straight cantilever under a dead compressive tip load P: stable below the Euler load
// P_cr = pi^2 EI / (4 L^2), unstable above. The discrete P_cr is within O(h^2) (~1e-4 at N = 48).
TEST(Rod3dModes, StabilityEigenvalueChangesSignAtTheEulerLoad) {
  auto model = cantilever(48);
  const double EI = std::min(model.stiffness[1], model.stiffness[2]);
  const double critical = kPi * kPi * EI / (4.0 * model.length * model.length);
  rod::StaticOptions options;
  options.tolerance = 1e-12;
  std::vector<double> eigenvalues;
  for (double factor : {0.0, 0.9, 0.99, 1.01, 1.1}) {
    model.end_force = -factor * critical * model.root.frame.col(0);
    const auto result = rod::solve_static(model, rod::make_straight_state(model), options);
    eigenvalues.push_back(rod::stability_eigenvalue(model, result.state));
  }
  EXPECT_GT(eigenvalues[0], 0.0);
  EXPECT_GT(eigenvalues[1], 0.0);
  EXPECT_GT(eigenvalues[2], 0.0);
  EXPECT_LT(eigenvalues[3], 0.0);
  EXPECT_LT(eigenvalues[4], 0.0);
  // Unloaded: omega_1^2 of the weaker plane.
  const double omega1 = ref::cantilever_frequency(1, EI, model.line_density, model.length);
  EXPECT_TRUE(rodvv::testing::is_close(eigenvalues[0], omega1 * omega1, 2e-4, 0.0));
  // omega_1^2 falls nearly linearly with P (Galef: omega^2(P) ~ omega^2(0) (1 - P/P_cr)).
  EXPECT_NEAR(eigenvalues[1] / eigenvalues[0], 0.1, 0.02);
}

// A bent, loaded equilibrium: the linearisation applies at any equilibrium, here a heavy
// cantilever sagging under gravity (tension terms active) - the spectrum is real and positive.
TEST(Rod3dModes, LoadedEquilibriumIsStable) {
  auto model = cantilever(16);
  model.gravity = Vec3(0.3, -2.0, -1.2);
  rod::StaticOptions options;
  options.load_steps = 2;
  options.tolerance = 1e-12;
  const auto result = rod::solve_static(model, rod::make_straight_state(model), options);
  const auto lin = rod::linearize(model, result.state);
  EXPECT_LT(lin.asymmetry, 1e-13);
  EXPECT_EQ(lin.constraint_rank, model.elements - 1);  // the clamped edge's multiplier is held
  EXPECT_GT(rod::stability_eigenvalue(model, result.state), 0.0);
}

TEST(Rod3dModes, BadInputNamesTheParameter) {
  const auto expect_parameter = [](const auto& call, const std::string& name) {
    try {
      call();
      ADD_FAILURE() << "no InputError for " << name;
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), name) << e.what();
    }
  };
  auto model = cantilever(8);
  const auto straight = rod::make_straight_state(model);
  auto massless = model;
  massless.twist_inertia = 0.0;
  expect_parameter([&] { rod::linear_modes(massless, straight); }, "twist_inertia");
  auto loaded = model;
  loaded.gravity = Vec3(0.0, 0.0, -1.0);
  expect_parameter([&] { rod::linear_modes(loaded, straight); }, "state");  // not an equilibrium
  auto big = cantilever(rod::kMaxModalElements + 1);
  expect_parameter([&] { rod::linear_modes(big, rod::make_straight_state(big)); }, "elements");
  // A dead tip moment: the equilibrium exists, the linearised operator is not symmetric.
  auto moment = model;
  moment.end_moment = 0.8 * model.root.frame.col(1);
  rod::StaticOptions options;
  options.tolerance = 1e-12;
  const auto bent = rod::solve_static(moment, straight, options).state;
  expect_parameter([&] { rod::linear_modes(moment, bent); }, "end_moment");
}

// ---- dynamics ----------------------------------------------------------------------------------------

// A curved, twisted free rod with anisotropic stiffness and natural strains, moving: every term of the
// step residual is active.
rod::RodModel general_model(std::size_t n, bool inextensible) {
  rod::RodModel model;
  model.elements = n;
  model.length = 1.7;
  model.stiffness = Vec3(0.61, 1.3, 2.1);
  model.natural_strain = Vec3(0.4, -0.7, 1.1);
  if (!inextensible) model.extensional_stiffness = 45.0;
  model.line_density = 0.8;
  model.twist_inertia = 0.07;
  return model;
}

rod::DynamicState general_dynamic_state(const rod::RodModel& model) {
  std::vector<Vec3> x(model.elements + 1);
  const double ell = rod::rest_edge_length(model);
  // A helix parametrised by arclength: chords close to ebar (an inextensible rod starts near its manifold).
  const double speed = std::sqrt(0.9 * 0.9 * 1.1 * 1.1 + 0.6 * 0.6);
  for (std::size_t i = 0; i <= model.elements; ++i) {
    const double s = double(i) * ell / speed;
    x[i] = Vec3(0.9 * std::cos(1.1 * s), 0.9 * std::sin(1.1 * s), 0.6 * s);
  }
  const Vec3 t0 = (x[1] - x[0]).normalized();
  std::vector<double> angles(model.elements);
  for (std::size_t j = 0; j < angles.size(); ++j) angles[j] = 0.3 * std::sin(double(j) + 0.5);
  auto rod_state = rod::make_state(x, t0.cross(Vec3(0.2, 0.1, 1.0)).normalized(), angles);
  if (rod::is_inextensible(model))
    for (std::size_t j = 0; j < model.elements; ++j) rod_state.multiplier.push_back(0.7 - 0.1 * double(j));
  const rod::DofLayout layout(model);
  VecX v = VecX::Zero(Eigen::Index(layout.size()));
  for (std::size_t i = 0; i <= model.elements; ++i)
    v.segment<3>(Eigen::Index(layout.vertex(i))) = Vec3(0.3 + 0.1 * std::sin(double(i)), -0.2, 0.15 * std::cos(2.0 * double(i)));
  for (std::size_t j = 0; j < model.elements; ++j) v[Eigen::Index(layout.angle(j))] = 0.5 * std::cos(double(j));
  return rod::make_dynamic_state(model, rod_state, v);
}

void expect_step_jacobian_matches(const rod::RodModel& model, rod::TimeIntegrator method) {
  const auto state = general_dynamic_state(model);
  const rod::DofLayout layout(model);
  const double h = 0.01;
  VecX y(Eigen::Index(layout.size()));
  for (Eigen::Index k = 0; k < y.size(); ++k) y[k] = 2e-3 * std::sin(0.7 * double(k) + 0.3);
  const Eigen::MatrixXd J(rod::step_jacobian(model, state, h, method, y));
  const double fd = 1e-6 * model.length;
  double worst = 0.0;
  for (Eigen::Index k = 0; k < y.size(); ++k) {
    VecX plus = y, minus = y;
    plus[k] += fd;
    minus[k] -= fd;
    const VecX diff = (rod::step_residual(model, state, h, method, plus) - rod::step_residual(model, state, h, method, minus)) /
                          (2.0 * fd) -
                      J.col(k);
    worst = std::max(worst, diff.cwiseAbs().maxCoeff());
  }
  // Central differences: truncation fd^2 r'''/6 and round-off eps |r| / fd, with |r| dominated by the
  // inertia term M |y - h v| / h^2 ~ 1e-1: 1e-10 / 1e-6 -> a few 1e-8 of entries up to M/h^2 ~ 1e3.
  EXPECT_LT(worst, 1e-9 * J.cwiseAbs().maxCoeff()) << rod::integrator_name(method) << ": " << worst;
}

TEST(Rod3dDynamics, StepJacobianIsTheDerivativeOfTheStepResidual) {
  for (auto method : {rod::TimeIntegrator::ImplicitEuler, rod::TimeIntegrator::ImplicitMidpoint}) {
    expect_step_jacobian_matches(general_model(6, true), method);
    expect_step_jacobian_matches(general_model(6, false), method);
    auto moment = general_model(6, true);
    moment.end_moment = Vec3(0.3, -0.8, 0.45);
    moment.gravity = Vec3(0.2, -1.0, 0.5);
    moment.end_force = Vec3(-0.4, 0.9, 0.25);
    expect_step_jacobian_matches(moment, method);
  }
}

// No supports, no gravity: the internal forces sum to zero in every configuration and the Newton
// matrix's position rows inherit it, so sum m v is conserved to round-off by both methods.
TEST(Rod3dDynamics, FreeRodConservesLinearMomentum) {
  for (bool inextensible : {true, false}) {
    const auto model = general_model(10, inextensible);
    for (auto method : {rod::TimeIntegrator::ImplicitEuler, rod::TimeIntegrator::ImplicitMidpoint}) {
      auto state = general_dynamic_state(model);
      const Vec3 p0 = rod::linear_momentum(model, state);
      double worst = 0.0;
      for (int n = 0; n < 40; ++n) {
        state = rod::step(model, state, 0.01, method);
        worst = std::max(worst, (rod::linear_momentum(model, state) - p0).norm());
      }
      // 40 steps, each rounding N + 1 vertex momenta of ~0.3 |p|/N: measured ~1e-16 per step; bound 1e-14 |p|.
      std::cout << rod::integrator_name(method) << (inextensible ? " inextensible" : " extensible")
                << ": momentum drift " << worst / p0.norm() << "\n";
      EXPECT_LT(worst, 1e-14 * p0.norm()) << rod::integrator_name(method);
    }
  }
}

// One small-amplitude mode of the cantilever: implicit Euler maps the complex amplitude omega x + i v
// to itself over (1 + i omega h), so E_n = E_0 (1 + omega^2 h^2)^-n exactly for the linearised rod
// (omega: the discrete frequency of linear_modes); the midpoint rule keeps |omega x + i v|: E_n = E_0.
struct ModeRun {
  double euler_ratio, expected_ratio, midpoint_drift;
};

ModeRun single_mode(double h, int steps) {
  const auto model = cantilever(12);
  const auto straight = rod::make_straight_state(model);
  const auto modes = rod::linear_modes(model, straight);
  const double omega = modes.frequencies[0];
  // Nonlinear corrections O(amplitude^2) = 1e-8 relative. The Newton tolerance is tightened to
  // 1e-14 of the force scale EI/L^2: the work of a residual r over a step, r x amplitude, must stay
  // far below the modal energy amplitude^2 omega^2 / 2 (~5e-8).
  const double amplitude = 1e-4;
  rod::DynamicOptions options;
  options.tolerance = 1e-14;
  // The mode satisfies the constraints to first order only: the edges are put back to length ebar
  // (O(amplitude^2) moves), else the first step's projection is an impulse of kinetic energy
  // ~ (amplitude^2 / h)^2, relative amplitude^2 / h^2 (measured 3e-5 at h = 0.01).
  const rod::RodState moved = rod::displaced(model, straight, amplitude * modes.shapes.col(0));
  std::vector<Vec3> x = moved.position;
  const double ell = rod::rest_edge_length(model);
  for (std::size_t j = 1; j < model.elements; ++j) x[j + 1] = x[j] + ell * (moved.position[j + 1] - moved.position[j]).normalized();
  rod::RodState projected = rod::make_state(x, model.root.frame.col(1), moved.angle);
  projected.multiplier.assign(model.elements, 0.0);
  const auto start = rod::make_dynamic_state(model, projected);
  const double e0 = rod::dynamic_energy(model, start).total();
  ModeRun run{};
  auto euler = start, midpoint = start;
  for (int n = 0; n < steps; ++n) {
    euler = rod::step(model, euler, h, rod::TimeIntegrator::ImplicitEuler, options);
    midpoint = rod::step(model, midpoint, h, rod::TimeIntegrator::ImplicitMidpoint, options);
    run.midpoint_drift = std::max(run.midpoint_drift, std::abs(rod::dynamic_energy(model, midpoint).total() - e0) / e0);
  }
  run.euler_ratio = rod::dynamic_energy(model, euler).total() / e0;
  run.expected_ratio = std::pow(1.0 + omega * omega * h * h, -double(steps));
  return run;
}

TEST(Rod3dDynamics, ImplicitEulerLossOfOneModeHasTheLinearMagnitudeAndFirstOrder) {
  // omega_1 ~ 3.0 at N = 12; over t = 2: E/E0 = (1 + omega^2 h^2)^(-2/h) ~ exp(-2 omega^2 h).
  const ModeRun coarse = single_mode(0.02, 100), fine = single_mode(0.01, 200);
  std::cout << "one mode: Euler E/E0 " << coarse.euler_ratio << " (linear " << coarse.expected_ratio << "), "
            << fine.euler_ratio << " (linear " << fine.expected_ratio << "); midpoint drift " << coarse.midpoint_drift
            << ", " << fine.midpoint_drift << "; Euler vs linear " << std::abs(coarse.euler_ratio / coarse.expected_ratio - 1.0)
            << ", " << std::abs(fine.euler_ratio / fine.expected_ratio - 1.0) << "\n";
  // Agreement with the linearisation: relative O(amplitude^2) = 1e-8 (measured 6.7e-9, 3.7e-9), the
  // Newton floor and the energy's round-off (strains of 1e-4 from positions of 1: 1e-12): bound 1e-7.
  EXPECT_TRUE(rodvv::testing::is_close(coarse.euler_ratio, coarse.expected_ratio, 1e-7, 0.0));
  EXPECT_TRUE(rodvv::testing::is_close(fine.euler_ratio, fine.expected_ratio, 1e-7, 0.0));
  // First order: -log(E/E0) = (t/h) log(1 + omega^2 h^2) = t omega^2 h (1 - omega^2 h^2 / 2 + ...).
  const double log_order = std::log2(std::log(coarse.euler_ratio) / std::log(fine.euler_ratio));
  const double predicted = std::log2(std::log(coarse.expected_ratio) / std::log(fine.expected_ratio));
  EXPECT_NEAR(predicted, 1.0, 0.01);
  EXPECT_NEAR(log_order, predicted, 1e-5);
  // Midpoint: the quadratic (linearised) energy is conserved exactly; what is left is the midpoint
  // error of the quartic part, amplitude^2 (omega h)^2 ~ 4e-11, and round-off (measured 4.5e-12,
  // 1.4e-12): bound 1e-10, against Euler's loss of 0.3.
  EXPECT_LT(coarse.midpoint_drift, 1e-10);
  EXPECT_LT(fine.midpoint_drift, 1e-10);
}

// The swinging, twisting cantilever of rod3d/energy-in-time (shorter): implicit Euler loses energy
// at first order, the midpoint rule keeps an O(h^2) error that does not drift.
struct SwingRun {
  double euler_loss = 0.0, midpoint_error = 0.0, midpoint_error_first_half = 0.0, max_euler_increase = 0.0;
};

rod::RodModel swing_model() {
  rod::RodModel model;
  model.elements = 8;
  model.length = 1.1;
  model.stiffness = Vec3(0.6, 0.9, 1.6);
  model.line_density = 0.7;
  model.twist_inertia = 0.1;
  model.root.support = rod::EndSupport::Clamped;
  model.root.frame = tilted_frame(0.7);
  model.gravity = 3.0 * Vec3(0.2, -0.3, -1.0).normalized();
  return model;
}

SwingRun swing(double h, double t_end) {
  const auto model = swing_model();
  auto rod_state = rod::make_straight_state(model);
  for (std::size_t j = 1; j < model.elements; ++j) {
    const double s = 0.5 * (rod::vertex_arclength(model, j) + rod::vertex_arclength(model, j + 1));
    rod_state.angle[j] += std::sin(0.5 * kPi * s / model.length);  // the first torsional mode, 1 rad at the tip
  }
  const auto start = rod::make_dynamic_state(model, rod_state);
  const double e0 = rod::dynamic_energy(model, start).total();
  const double scale = model.line_density * model.gravity.norm() * model.length * model.length;
  const auto steps = static_cast<int>(std::lround(t_end / h));
  SwingRun run;
  auto euler = start, midpoint = start;
  double previous = e0;
  for (int n = 0; n < steps; ++n) {
    euler = rod::step(model, euler, h, rod::TimeIntegrator::ImplicitEuler);
    midpoint = rod::step(model, midpoint, h, rod::TimeIntegrator::ImplicitMidpoint);
    const double e = rod::dynamic_energy(model, euler).total();
    run.max_euler_increase = std::max(run.max_euler_increase, (e - previous) / scale);
    previous = e;
    const double error = std::abs(rod::dynamic_energy(model, midpoint).total() - e0) / scale;
    run.midpoint_error = std::max(run.midpoint_error, error);
    if (2 * n < steps) run.midpoint_error_first_half = run.midpoint_error;
  }
  run.euler_loss = (e0 - previous) / scale;
  return run;
}

TEST(Rod3dDynamics, SwingingRodEnergyOrders) {
  const SwingRun coarse = swing(0.02, 1.0), fine = swing(0.01, 1.0), finer = swing(0.005, 1.0);
  const double euler_order = std::log2(fine.euler_loss / finer.euler_loss);
  const double midpoint_order = std::log2(fine.midpoint_error / finer.midpoint_error);
  std::cout << "swing: Euler loss " << coarse.euler_loss << ", " << fine.euler_loss << ", " << finer.euler_loss
            << " (order " << euler_order << "); midpoint max error " << coarse.midpoint_error << ", "
            << fine.midpoint_error << ", " << finer.midpoint_error << " (order " << midpoint_order
            << "); Euler max increase " << finer.max_euler_increase << "\n";
  // First order with an O(h^2) part of relative size ~ omega^2 h t / 2 (the decay saturates): the
  // pairwise order tends to 1 from below (0.93 -> 0.95 measured).
  EXPECT_NEAR(euler_order, 1.0, 0.1);
  EXPECT_NEAR(midpoint_order, 2.0, 0.1);
  // Dissipation: implicit Euler's energy decreases monotonically here (round-off aside).
  EXPECT_LT(finer.max_euler_increase, 1e-12);
  // Magnitudes (scale rho S |g| L^2): measured Euler loss 3.2e-2 at h = 5e-3, midpoint 1.9e-6; bounds 2x.
  EXPECT_LT(finer.euler_loss, 6.4e-2);
  EXPECT_LT(finer.midpoint_error, 3.8e-6);
}

TEST(Rod3dDynamics, MidpointEnergyErrorDoesNotDrift) {
  // Over 4 time units (about two bending periods and four torsional ones) the midpoint energy error
  // over the whole run stays at the level of the first half: bounded, no secular growth.
  const SwingRun run = swing(0.02, 4.0);
  std::cout << "midpoint error first half " << run.midpoint_error_first_half << ", whole run " << run.midpoint_error << "\n";
  EXPECT_LT(run.midpoint_error, 1.5 * run.midpoint_error_first_half);
}

TEST(Rod3dDynamics, HeldDofsStayFixed) {
  const auto model = swing_model();
  const auto start = rod::make_dynamic_state(model, rod::make_straight_state(model));
  auto state = start;
  for (int n = 0; n < 10; ++n) state = rod::step(model, state, 0.02, rod::TimeIntegrator::ImplicitMidpoint);
  const rod::DofLayout layout(model);
  for (std::size_t k : rod::held_dofs(model)) {
    EXPECT_EQ(state.velocity[Eigen::Index(k)], 0.0);
    const std::size_t slot = k % layout.stride(), index = k / layout.stride();
    if (slot < 3) {
      EXPECT_EQ(state.rod.position[index][Eigen::Index(slot)], start.rod.position[index][Eigen::Index(slot)]);
    } else if (slot == 3) {
      EXPECT_EQ(state.rod.angle[index], start.rod.angle[index]);
    }
  }
  EXPECT_GT((state.rod.position.back() - start.rod.position.back()).norm(), 1e-4);
}

TEST(Rod3dDynamics, FailureAndBadInput) {
  const auto model = swing_model();
  const auto start = rod::make_dynamic_state(model, rod::make_straight_state(model));
  rod::DynamicOptions options;
  options.max_iterations = 1;
  options.tolerance = 1e-15;
  try {
    (void)rod::step(model, start, 0.05, rod::TimeIntegrator::ImplicitEuler, options);
    ADD_FAILURE() << "no SolverError";
  } catch (const rodvv::SolverError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("implicit Euler"), std::string::npos) << what;
    EXPECT_NE(what.find("step 1"), std::string::npos) << what;
    EXPECT_EQ(e.iterations(), 1u);
  }
  EXPECT_THROW((void)rod::step(model, start, 0.0, rod::TimeIntegrator::ImplicitMidpoint), rodvv::InputError);
  auto massless = model;
  massless.twist_inertia = 0.0;
  EXPECT_THROW((void)rod::make_dynamic_state(massless, rod::make_straight_state(massless)), rodvv::InputError);
  VecX v = VecX::Zero(Eigen::Index(rod::DofLayout(model).size()));
  v[0] = 1.0;  // vertex 0 is held by the clamp
  try {
    (void)rod::make_dynamic_state(model, rod::make_straight_state(model), v);
    ADD_FAILURE() << "no InputError";
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "velocity");
  }
}

}  // namespace
