#include "lagrangian_oracle.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <map>
#include <mutex>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"

namespace rodvv::harness::superhelix_cases {

namespace {

namespace sh = solvers::superhelix;
namespace odeint = boost::numeric::odeint;
constexpr double kCbrtEps = 6.0554544523933395e-6;  // cbrt(2^-52)
using Quadrature = boost::math::quadrature::gauss<double, 6>;

// The rod's shape at (q, t), sampled at the oracle's quadrature points: what T and V need.
struct Sample {
  double weight;    // quadrature weight x ds
  Vec3 position;    // r
  Vec3 transport;   // Omega(t) a x (r - x0): the velocity of a point carried by the root's turn
  Mat3 frame;       // R = [n0 n1 n2]
  MatX position_jacobian, rotation_jacobian;  // J, Theta (3 x 3N)
};

struct Shape {
  std::vector<Sample> samples;
  Vec3 root_spin;  // Omega(t) a
};

double spin_rate(const OracleRod& rod, double t) { return rod.spin_rate + rod.spin_acceleration * t; }

Shape shape_at(const OracleRod& rod, const VecX& q, double t) {
  sh::RodModel model = rod.model;
  model.root_frame = oracle_root_frame(rod, t);
  const sh::Kinematics kinematics(model, q);
  Shape shape;
  shape.root_spin = spin_rate(rod, t) * rod.spin_axis;
  const double ell = sh::element_length(model);
  const auto& nodes = Quadrature::abscissa();
  const auto& weights = Quadrature::weights();
  for (std::size_t e = 0; e < model.elements; ++e)
    for (std::size_t k = 0; k < nodes.size(); ++k)
      for (const double side : {-1.0, 1.0}) {
        if (nodes[k] == 0.0 && side > 0.0) continue;  // the middle node (odd rules) once
        const double sigma = 0.5 * ell * (1.0 + side * nodes[k]);
        Sample sample;
        sample.weight = 0.5 * ell * weights[k];
        sample.position = kinematics.position(e, sigma);
        sample.transport = shape.root_spin.cross(sample.position - model.root_position);
        sample.frame = kinematics.frame(e, sigma);
        sample.position_jacobian = kinematics.position_jacobian(e, sigma);
        sample.rotation_jacobian = kinematics.rotation_jacobian(e, sigma);
        shape.samples.push_back(std::move(sample));
      }
  return shape;
}

// rho S (a^2 + b^2, b^2, a^2) / 4: the solid ellipse's second moments per unit area about n0 (polar),
// n1 (the extent b along n2 bends about n1) and n2.
Vec3 section_inertia(const OracleRod& rod) {
  const double a2 = rod.section_a * rod.section_a, b2 = rod.section_b * rod.section_b;
  return 0.25 * rod.model.line_density * Vec3(a2 + b2, b2, a2);
}

double kinetic_energy(const OracleRod& rod, const Shape& shape, const VecX& qdot) {
  const Vec3 J = section_inertia(rod);
  double T = 0.0;
  for (const auto& s : shape.samples) {
    const Vec3 v = s.transport + s.position_jacobian * qdot;
    const Vec3 Omega = s.frame.transpose() * (shape.root_spin + s.rotation_jacobian * qdot);
    T += s.weight * (0.5 * rod.model.line_density * v.squaredNorm() + 0.5 * Omega.dot(J.cwiseProduct(Omega)));
  }
  return T;
}

double gravity_energy(const OracleRod& rod, const Shape& shape) {
  double V = 0.0;
  for (const auto& s : shape.samples) V -= s.weight * rod.model.line_density * rod.model.gravity.dot(s.position);
  return V;
}

// M = d2T/dq'^2 (exact: T is quadratic in q').
MatX mass_matrix(const OracleRod& rod, const Shape& shape, Eigen::Index n) {
  const Vec3 J = section_inertia(rod);
  MatX M = MatX::Zero(n, n);
  for (const auto& s : shape.samples) {
    const MatX material = s.frame.transpose() * s.rotation_jacobian;  // R^T Theta
    M += s.weight * (rod.model.line_density * s.position_jacobian.transpose() * s.position_jacobian +
                     material.transpose() * J.asDiagonal() * material);
  }
  return M;
}

// p = dT/dq' (exact).
VecX momentum(const OracleRod& rod, const Shape& shape, const VecX& qdot) {
  const Vec3 J = section_inertia(rod);
  VecX p = VecX::Zero(qdot.size());
  for (const auto& s : shape.samples) {
    const Vec3 v = s.transport + s.position_jacobian * qdot;
    const Vec3 Omega = s.frame.transpose() * (shape.root_spin + s.rotation_jacobian * qdot);
    p += s.weight * (rod.model.line_density * s.position_jacobian.transpose() * v +
                     (s.frame.transpose() * s.rotation_jacobian).transpose() * J.cwiseProduct(Omega));
  }
  return p;
}

VecX momentum(const OracleRod& rod, const VecX& q, const VecX& qdot, double t) {
  return momentum(rod, shape_at(rod, q, t), qdot);
}

}  // namespace

Mat3 oracle_root_frame(const OracleRod& rod, double t) {
  const double angle = rod.spin_rate * t + 0.5 * rod.spin_acceleration * t * t;
  return Eigen::AngleAxisd(angle, rod.spin_axis).toRotationMatrix() * rod.model.root_frame;
}

VecX oracle_acceleration(const OracleRod& rod, const VecX& q, const VecX& qdot, double t) {
  const auto n = q.size();
  const double L = rod.model.length;
  const MatX M = mass_matrix(rod, shape_at(rod, q, t), n);

  // dp/dq q' along q' (a central difference of step delta |q'| L = cbrt(eps)).
  VecX p_rate = VecX::Zero(n);
  if (const double speed = qdot.lpNorm<Eigen::Infinity>(); speed > 0.0) {
    const double delta = kCbrtEps / (L * speed);
    p_rate = (momentum(rod, q + delta * qdot, qdot, t) - momentum(rod, q - delta * qdot, qdot, t)) / (2.0 * delta);
  }
  // dp/dt at fixed (q, q'): only through the root's turn.
  if (const double rate = std::max(std::abs(spin_rate(rod, t)), std::sqrt(std::abs(rod.spin_acceleration)));
      rate > 0.0) {
    const double tau = kCbrtEps / rate;
    p_rate += (momentum(rod, q, qdot, t + tau) - momentum(rod, q, qdot, t - tau)) / (2.0 * tau);
  }
  // dT/dq - dV/dq: central differences of step cbrt(eps) / L for T and the weight; the elastic
  // energy's gradient exactly.
  VecX force(n);
  const double h = kCbrtEps / L;
  VecX shifted = q;
  for (Eigen::Index i = 0; i < n; ++i) {
    shifted[i] = q[i] + h;
    const Shape plus = shape_at(rod, shifted, t);
    shifted[i] = q[i] - h;
    const Shape minus = shape_at(rod, shifted, t);
    shifted[i] = q[i];
    force[i] = ((kinetic_energy(rod, plus, qdot) - gravity_energy(rod, plus)) -
                (kinetic_energy(rod, minus, qdot) - gravity_energy(rod, minus))) /
               (2.0 * h);
  }
  const double ell = sh::element_length(rod.model);
  for (std::size_t e = 0; e < rod.model.elements; ++e) {
    const auto i = static_cast<Eigen::Index>(3 * e);
    const Vec3 strain = q.segment<3>(i) - sh::natural_strain(rod.model, e);
    force.segment<3>(i) -= ell * rod.model.stiffness.cwiseProduct(strain);
  }
  const Eigen::LDLT<MatX> factor(M);
  if (factor.info() != Eigen::Success)
    throw SolverError("Lagrangian oracle", "mass matrix not positive definite", 0, 0.0);
  return factor.solve(force - p_rate);
}

namespace {

std::vector<OracleState> integrate(const OracleRod& rod, const OracleState& start, const std::vector<double>& times) {
  using State = std::vector<double>;
  const auto n = start.q.size();
  State y(static_cast<std::size_t>(2 * n));
  VecX::Map(y.data(), n) = start.q;
  VecX::Map(y.data() + n, n) = start.qdot;
  const auto rhs = [&](const State& x, State& dxdt, double t) {
    const VecX q = VecX::Map(x.data(), n), qdot = VecX::Map(x.data() + n, n);
    VecX::Map(dxdt.data(), n) = qdot;
    VecX::Map(dxdt.data() + n, n) = oracle_acceleration(rod, q, qdot, t);
  };
  std::vector<OracleState> states;
  const auto observe = [&](const State& x, double) {
    states.push_back({VecX::Map(x.data(), n), VecX::Map(x.data() + n, n)});
  };
  std::vector<double> at{0.0};
  at.insert(at.end(), times.begin(), times.end());
  auto stepper = odeint::make_controlled(1e-10, 1e-10, odeint::runge_kutta_fehlberg78<State>());
  try {
    odeint::integrate_times(stepper, rhs, y, at.begin(), at.end(), 1e-3 * times.back(), observe,
                            odeint::max_step_checker(100000));
  } catch (const odeint::step_adjustment_error& error) {
    throw SolverError("Lagrangian oracle (RKF78)", error.what(), 0, 0.0);
  } catch (const odeint::no_progress_error& error) {
    throw SolverError("Lagrangian oracle (RKF78)", error.what(), 0, 0.0);
  }
  states.erase(states.begin());  // t = 0
  return states;
}

// Everything the trajectory depends on, as numbers.
std::vector<double> key_of(const OracleRod& rod, const OracleState& start, const std::vector<double>& times) {
  const sh::RodModel& m = rod.model;
  std::vector<double> key{m.length, double(m.elements), m.line_density, rod.section_a, rod.section_b,
                          rod.spin_rate, rod.spin_acceleration};
  const auto append = [&key](const auto& values) {
    for (Eigen::Index i = 0; i < values.size(); ++i) key.push_back(values.data()[i]);
  };
  append(m.stiffness), append(m.natural_strain), append(m.gravity), append(m.root_position), append(m.root_frame);
  append(rod.spin_axis), append(start.q), append(start.qdot);
  for (const Vec3& strain : m.natural_strain_per_element) append(strain);
  key.insert(key.end(), times.begin(), times.end());
  return key;
}

}  // namespace

std::vector<OracleState> oracle_trajectory(const OracleRod& rod, const OracleState& start,
                                           const std::vector<double>& times) {
  // One computation per key: the first caller integrates, concurrent callers of the same key wait
  // for its result (or its SolverError); a pure function of the key, so sharing changes no result.
  static std::mutex mutex;
  static std::map<std::vector<double>, std::shared_future<std::vector<OracleState>>> cache;
  const std::vector<double> key = key_of(rod, start, times);
  std::promise<std::vector<OracleState>> promise;
  std::shared_future<std::vector<OracleState>> result;
  bool mine = false;
  {
    const std::lock_guard lock(mutex);
    if (const auto it = cache.find(key); it != cache.end()) {
      result = it->second;
    } else {
      result = promise.get_future().share();
      cache.emplace(key, result);
      mine = true;
    }
  }
  if (mine) {
    try {
      promise.set_value(integrate(rod, start, times));
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  return result.get();
}

}  // namespace rodvv::harness::superhelix_cases
