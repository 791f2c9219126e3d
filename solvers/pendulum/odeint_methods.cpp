// The three pendulum methods implemented with Boost.Odeint (Ahnert & Mulansky 2011, AIP Conf. Proc.
// 1389:1586): classic RK4, adaptive Dormand-Prince 5(4) with dense output, and McLachlan's
// symmetric 4th-order RKN. Small fixed-size std::array states keep the steppers allocation-free.
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <utility>

#include <boost/numeric/odeint.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_mclachlan.hpp>

#include "detail.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::pendulum::detail {

namespace odeint = boost::numeric::odeint;

namespace {

using State = std::array<double, 2>;  // (theta, theta_dot)
using Coordinate = std::array<double, 1>;

// First-order form x' = (theta_dot, -omega^2 sin theta); counts its evaluations.
struct FirstOrderRhs {
  double omega2;
  std::size_t* evaluations;
  void operator()(const State& x, State& dxdt, double /*t*/) const {
    ++*evaluations;
    dxdt[0] = x[1];
    dxdt[1] = -omega2 * std::sin(x[0]);
  }
};

// Coordinate-only force dp/dt = -omega^2 sin q for the symplectic RKN stepper (q' = p is implied).
struct MomentumRhs {
  double omega2;
  std::size_t* evaluations;
  void operator()(const Coordinate& q, Coordinate& dpdt) const {
    ++*evaluations;
    dpdt[0] = -omega2 * std::sin(q[0]);
  }
};

}  // namespace

Trajectory integrate_rk4(const Problem& problem, const Grid& grid) {
  std::size_t evaluations = 0;
  const FirstOrderRhs rhs{problem.omega * problem.omega, &evaluations};
  odeint::runge_kutta4<State> stepper;
  State x{};
  std::size_t step = 0;
  Trajectory out = run_fixed("rk4", problem, grid, [&](double& q, double& v) {
    x = {q, v};
    stepper.do_step(rhs, x, grid.time(step), grid.dt);
    ++step;
    q = x[0];
    v = x[1];
  });
  out.rhs_evaluations = evaluations;
  return out;
}

// Boost's symplectic_rkn_sb3a_mclachlan: McLachlan's (1995) 6-stage symmetric composition of
// order 4 (stepper order_value 4; a1 = 0.40518861839525227722, b1 = -3/73, b2 = 17/59; Boost's
// Doxygen text also says "sixth order", which is wrong: the measured order is 4, see
// tests/solvers). Odeint calls the force in every stage,
// including the last one whose weight b6 is 0, so it costs 6 evaluations per step; they are counted
// as made. (symplectic_rkn_sb3a_m4_mclachlan is the 5-stage order-4 variant.)
Trajectory integrate_rkn4_mclachlan(const Problem& problem, const Grid& grid) {
  std::size_t evaluations = 0;
  const MomentumRhs force{problem.omega * problem.omega, &evaluations};
  odeint::symplectic_rkn_sb3a_mclachlan<Coordinate> stepper;
  Coordinate qs{};
  Coordinate ps{};
  std::size_t step = 0;
  Trajectory out = run_fixed("rkn4-mclachlan", problem, grid, [&](double& q, double& v) {
    qs[0] = q;
    ps[0] = v;
    stepper.do_step(force, qs, ps, grid.time(step), grid.dt);
    ++step;
    q = qs[0];
    v = ps[0];
  });
  out.rhs_evaluations = evaluations;
  return out;
}

namespace {

using Dopri5 = odeint::runge_kutta_dopri5<State>;
using DefaultChecker =
    odeint::default_error_checker<double, Dopri5::algebra_type, Dopri5::operations_type>;

// Odeint's default error checker (abs = rel tolerance), which also stores the last normalised
// error (max_i |err_i| / (tol (1 + |x_i| + dt |x_i'|)); a step is accepted when it is <= 1) so a
// failure can report it.
class RecordingErrorChecker {
 public:
  using value_type = double;
  using algebra_type = Dopri5::algebra_type;
  using operations_type = Dopri5::operations_type;

  explicit RecordingErrorChecker(double tolerance = 1e-6, double* last_error = nullptr)
      : checker_(tolerance, tolerance), last_error_(last_error) {}

  template <class StateT, class Deriv, class Err, class Time>
  double error(algebra_type& algebra, const StateT& x_old, const Deriv& dxdt_old, Err& x_err,
               Time dt) const {
    const double e = checker_.error(algebra, x_old, dxdt_old, x_err, dt);
    if (last_error_ != nullptr) *last_error_ = e;
    return e;
  }
  template <class StateT, class Deriv, class Err, class Time>
  double error(const StateT& x_old, const Deriv& dxdt_old, Err& x_err, Time dt) const {
    algebra_type algebra;
    return error(algebra, x_old, dxdt_old, x_err, dt);
  }

 private:
  DefaultChecker checker_;
  double* last_error_;
};

using Controlled = odeint::controlled_runge_kutta<Dopri5, RecordingErrorChecker>;
using Dense = odeint::dense_output_runge_kutta<Controlled>;

}  // namespace

// Adaptive Dormand-Prince: the stepper takes its own steps and its dense output (the free
// 4th-order interpolant of Dormand & Prince; Hairer, Norsett & Wanner 1993, §II.6) is sampled at
// t_i = i dt. dt is also the initial step guess.
Trajectory integrate_dopri5(const Problem& problem, const Grid& grid, double tolerance) {
  std::size_t evaluations = 0;
  double last_error = 0.0;
  const FirstOrderRhs rhs{problem.omega * problem.omega, &evaluations};
  Dense stepper{Controlled{RecordingErrorChecker{tolerance, &last_error}}};

  Trajectory out;
  out.reserve(grid.recorded_points());
  out.record(0.0, problem.theta0, problem.theta_dot0);
  if (grid.n == 0) return out;

  const State x0{problem.theta0, problem.theta_dot0};
  stepper.initialize(x0, 0.0, grid.dt);
  // A step below this is lost in round-off of t (a few ulps of the time scale): the controller has
  // given up, and continuing would never reach t_end.
  const double t_scale = grid.time(grid.n);
  const double min_step = 64.0 * std::numeric_limits<double>::epsilon() * t_scale;

  std::size_t steps = 0;
  auto fail = [&](const std::string& what) -> SolverError {
    return SolverError("dopri5",
                       what + " after " + std::to_string(steps) + " accepted steps at t = " +
                           format_value(stepper.current_time()) + " (step size " +
                           format_value(stepper.current_time_step()) +
                           ", last normalised error estimate " + format_value(last_error) +
                           ", tolerance " + format_value(tolerance) + ")",
                       steps, last_error);
  };

  State x{};
  for (std::size_t i = 1; i <= grid.n; ++i) {
    const double t_i = grid.time(i);
    while (stepper.current_time() < t_i) {
      try {
        stepper.do_step(std::cref(rhs));
      } catch (const odeint::step_adjustment_error&) {
        throw fail("step size adjustment failed (500 consecutive rejections)");
      }
      ++steps;
      const State& xc = stepper.current_state();
      if (!std::isfinite(xc[0]) || !std::isfinite(xc[1])) throw fail("state became non-finite");
      const double next = stepper.current_time_step();
      if (!(next >= min_step) || !std::isfinite(stepper.current_time()))
        throw fail("step size underflow");
    }
    if (grid.records(i)) {
      stepper.calc_state(t_i, x);
      out.record(t_i, x[0], x[1]);
    }
  }
  out.steps = steps;
  out.rhs_evaluations = evaluations;
  return out;
}

}  // namespace rodvv::solvers::pendulum::detail
