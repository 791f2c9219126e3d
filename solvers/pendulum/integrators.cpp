#include "rodvv/solvers/pendulum/integrators.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "detail.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::pendulum {

namespace {

constexpr std::array<MethodInfo, 6> kMethods{{
    {Method::ExplicitEuler, "explicit-euler", "explicit Euler", 1, false, false,
     "Hairer, Norsett & Wanner, Solving ODEs I, 2nd ed., Springer 1993, §I.7 (own code)"},
    {Method::SymplecticEuler, "symplectic-euler", "symplectic Euler (kick-drift)", 1, true, false,
     "Hairer, Lubich & Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, "
     "§VI.3 Thm 3.3 (own code)"},
    {Method::StormerVerlet, "stormer-verlet", "Stoermer-Verlet (velocity Verlet, kick-drift-kick)",
     2, true, false,
     "Hairer, Lubich & Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, "
     "§I.3.1 and §VI.3 (own code)"},
    {Method::RungeKutta4, "rk4", "classic Runge-Kutta 4", 4, false, false,
     "Kutta 1901; implementation Boost.Odeint runge_kutta4 (Ahnert & Mulansky 2011)"},
    {Method::DormandPrince5, "dopri5", "Dormand-Prince 5(4), adaptive, dense output", 5, false, true,
     "Dormand & Prince 1980, J. Comput. Appl. Math. 6:19; implementation Boost.Odeint "
     "runge_kutta_dopri5 (Ahnert & Mulansky 2011)"},
    {Method::McLachlanRkn4, "rkn4-mclachlan", "McLachlan symmetric RKN 4 (SB3A, 6 stages)", 4, true,
     false,
     "McLachlan 1995, SIAM J. Sci. Comput. 16:151; implementation Boost.Odeint "
     "symplectic_rkn_sb3a_mclachlan (Ahnert & Mulansky 2011)"},
}};

// Largest permitted number of output points (header contract).
constexpr double kMaxPoints = 1e9;

std::string known_ids() {
  std::string ids;
  for (const MethodInfo& m : kMethods) {
    if (!ids.empty()) ids += ", ";
    ids += m.id;
  }
  return ids;
}

// n = ceil(t_end / dt). A quotient within 4 ulps of an integer is taken as that integer, so that
// t_end = 2, dt = 0.02 gives 100 steps even if the decimal values round the quotient up.
std::size_t step_count(double t_end, double dt) {
  const double quotient = t_end / dt;
  if (!(quotient + 1.0 <= kMaxPoints))
    throw InputError("dt", "invalid parameter 'dt' = " + format_value(dt) + ": t_end / dt = " +
                               format_value(t_end) + " / " + format_value(dt) +
                               " gives more than 1e9 output points; increase dt or reduce t_end");
  const double nearest = std::round(quotient);
  const double ulps = 4.0 * std::numeric_limits<double>::epsilon() * nearest;
  const double n = std::abs(quotient - nearest) <= ulps ? nearest : std::ceil(quotient);
  return static_cast<std::size_t>(n);
}

// theta'' = -omega^2 sin(theta): the only force evaluation in the own-code methods.
struct Force {
  double omega2;
  double operator()(double q) const noexcept { return -omega2 * std::sin(q); }
};

Trajectory explicit_euler(const Problem& p, const detail::Grid& g) {
  const Force f{p.omega * p.omega};
  const double h = g.dt;
  Trajectory out = detail::run_fixed("explicit-euler", p, g, [&](double& q, double& v) {
    const double a = f(q);
    q += h * v;  // both updates use the old state
    v += h * a;
  });
  out.rhs_evaluations = g.n;
  return out;
}

// Kick then drift (HLW 2006 §VI.3, the variant updating the momentum first).
Trajectory symplectic_euler(const Problem& p, const detail::Grid& g) {
  const Force f{p.omega * p.omega};
  const double h = g.dt;
  Trajectory out = detail::run_fixed("symplectic-euler", p, g, [&](double& q, double& v) {
    v += h * f(q);
    q += h * v;
  });
  out.rhs_evaluations = g.n;
  return out;
}

// Velocity Verlet, kick-drift-kick; the force at the end of a step is the force at the start of
// the next, so one evaluation per step plus one to start.
Trajectory stormer_verlet(const Problem& p, const detail::Grid& g) {
  const Force f{p.omega * p.omega};
  const double h = g.dt;
  const double half = 0.5 * g.dt;
  double a = g.n > 0 ? f(p.theta0) : 0.0;
  Trajectory out = detail::run_fixed("stormer-verlet", p, g, [&](double& q, double& v) {
    v += half * a;
    q += h * v;
    a = f(q);
    v += half * a;
  });
  out.rhs_evaluations = g.n > 0 ? g.n + 1 : 0;
  return out;
}

}  // namespace

const MethodInfo& info(Method method) {
  for (const MethodInfo& m : kMethods)
    if (m.method == method) return m;
  throw InputError("method", "invalid parameter 'method' = " +
                                 std::to_string(static_cast<int>(method)) + ": not a known Method");
}

std::span<const MethodInfo> all_methods() { return kMethods; }

Method method_from_id(std::string_view id) {
  for (const MethodInfo& m : kMethods)
    if (m.id == id) return m.method;
  throw InputError("method", "invalid parameter 'method' = '" + std::string(id) +
                                 "': must be one of " + known_ids());
}

Trajectory integrate(const Problem& problem, const Settings& settings) {
  require_positive("omega", problem.omega);
  require_finite("theta0", problem.theta0);
  require_finite("theta_dot0", problem.theta_dot0);
  require_non_negative("t_end", problem.t_end);
  require_positive("dt", settings.dt);
  require_open_interval("tolerance", settings.tolerance, 0.0, 1.0);
  require_at_least("record_every", settings.record_every, 1);
  const MethodInfo& method = info(settings.method);  // rejects an out-of-range enum value

  const detail::Grid grid{step_count(problem.t_end, settings.dt), settings.dt, settings.record_every};
  switch (method.method) {
    case Method::ExplicitEuler: return explicit_euler(problem, grid);
    case Method::SymplecticEuler: return symplectic_euler(problem, grid);
    case Method::StormerVerlet: return stormer_verlet(problem, grid);
    case Method::RungeKutta4: return detail::integrate_rk4(problem, grid);
    case Method::DormandPrince5: return detail::integrate_dopri5(problem, grid, settings.tolerance);
    case Method::McLachlanRkn4: return detail::integrate_rkn4_mclachlan(problem, grid);
  }
  throw InputError("method", "invalid parameter 'method': not a known Method");  // unreachable
}

}  // namespace rodvv::solvers::pendulum
