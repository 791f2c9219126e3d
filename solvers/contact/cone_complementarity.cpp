#include "rodvv/solvers/contact/cone_complementarity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <boost/math/tools/toms748_solve.hpp>
#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "block_gauss_seidel.hpp"

namespace rodvv::solvers::contact {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr int kPhiIntervals = 256;
constexpr double kWarmBracket = 0.05;  // radians
constexpr int kNewtonSteps = 8;

// sqrt, not hypot: the Gauss-Seidel's innermost call (hypot was 12 % of a bundle's solve); forces and
// velocities of contact problems are far from the squares' overflow.
double tangential_norm(const Vec3& x) { return std::sqrt(x[1] * x[1] + x[2] * x[2]); }

// The velocity the cone law pairs with r: u + mu |u_T| e_N (Coulomb, De Saxce) or u (SOC).
Vec3 paired_velocity(const Vec3& u, double mu, ConeLaw law) {
  Vec3 v = u;
  if (law == ConeLaw::Coulomb) v[0] += mu * tangential_norm(u);
  return v;
}

// Sliding / boundary solution of the local problem (header): r_N W d(phi) + t g(phi) = -b.
struct Boundary {
  Vec3 r = Vec3::Zero();
  double residual = std::numeric_limits<double>::infinity();
  bool found = false;
};

Boundary boundary_solution(const Mat3& W, const Vec3& b, double mu, ConeLaw law, const Vec3* guess) {
  const double gamma = law == ConeLaw::Coulomb ? 0.0 : -mu;
  // The sliding direction as a unit vector (c, s) = (cos phi, sin phi): the warm start below moves it
  // without trigonometric calls.
  const auto consistency_at = [&](double c, double s) { return (W * Vec3(1.0, mu * c, mu * s)).dot(Vec3(gamma, c, s).cross(b)); };
  const auto consistency = [&](double phi) { return consistency_at(std::cos(phi), std::sin(phi)); };
  Boundary best;
  const auto consider_at = [&](double c, double s) {
    const Vec3 a = W * Vec3(1.0, mu * c, mu * s), g(gamma, c, s);
    const Vec3 ag = a.cross(g);
    const double norm2 = ag.squaredNorm();
    if (!(norm2 > 0.0)) return;
    const double inverse_norm2 = 1.0 / norm2;
    const double rN = -b.cross(g).dot(ag) * inverse_norm2;
    const double t = b.cross(a).dot(ag) * inverse_norm2;  // from t (g x a) = -(b x a), g x a = -(a x g)
    // t >= 0 up to the rounding of b (t has the units of u)
    if (!(rN > 0.0) || t < -64.0 * kEps * b.norm()) return;
    const Vec3 r(rN, mu * rN * c, mu * rN * s);
    const double residual = (W * r + b + std::max(t, 0.0) * g).norm();  // u = -t g
    if (residual < best.residual) best = {r, residual, true};
  };
  const auto consider = [&](double phi) { consider_at(std::cos(phi), std::sin(phi)); };
  const auto refine = [&](double low, double high, double f_low, double f_high) {
    std::uintmax_t iterations = 200;
    const auto bracket = boost::math::tools::toms748_solve(consistency, low, high, f_low, f_high,
                                                           boost::math::tools::eps_tolerance<double>(), iterations);
    consider(0.5 * (bracket.first + bracket.second));
  };
  // Warm start (the Gauss-Seidel's previous force of this contact). Any root with r_N > 0, t >= 0 near
  // its angle solves the local problem (for the SOC law the solution is unique: a strictly convex QP),
  // so the scan below is needed only without one. First Newton from the previous angle: once the
  // sweeps settle it converges in one or two steps (the bracketed TOMS 748 took ~10 evaluations, each
  // a sincos: two thirds of a bundle's solve); it gives up on a step longer than kWarmBracket (another
  // root may be nearer) or after kNewtonSteps, and the bracket of +-kWarmBracket then the scan follow.
  if (guess != nullptr && (*guess)[0] > 0.0) {
    const double tangential = tangential_norm(*guess);
    double c = tangential > 0.0 ? (*guess)[1] / tangential : 1.0, s = tangential > 0.0 ? (*guess)[2] / tangential : 0.0;
    double turned = 0.0;      // the angle moved so far (to first order in each step)
    bool polishing = false;   // the last step was below 1e-9
    for (int i = 0; i < kNewtonSteps; ++i) {
      // f = a . (g x b) and its derivative along phi: a' = W (0, -mu s, mu c), g' = (0, -s, c).
      const Vec3 a = W * Vec3(1.0, mu * c, mu * s), gb = Vec3(gamma, c, s).cross(b);
      const double f = a.dot(gb);
      if (f == 0.0) {
        consider_at(c, s);
        break;
      }
      const double slope = (W * Vec3(0.0, -mu * s, mu * c)).dot(gb) + a.dot(Vec3(0.0, -s, c).cross(b));
      const double step = -f / slope;
      turned += step;
      if (!(std::abs(turned) < kWarmBracket)) break;  // also a zero slope (inf, nan)
      // Rotate by atan(step) (= step to second order, which keeps Newton quadratic) and renormalise.
      const double inverse_norm = 1.0 / std::sqrt(1.0 + step * step);
      const double c_next = (c - step * s) * inverse_norm;
      s = (s + step * c) * inverse_norm;
      c = c_next;
      // Quadratic convergence: after a step below 1e-12 the angle's error is ~ (f''/f') 1e-24, below
      // 1e-9 one more step takes it there.
      if (polishing || std::abs(step) <= 1e-12) {
        consider_at(c, s);
        break;
      }
      polishing = std::abs(step) <= 1e-9;
    }
    if (best.found) return best;
    const double phi0 = std::atan2((*guess)[2], (*guess)[1]);
    const double low = phi0 - kWarmBracket, high = phi0 + kWarmBracket;
    const double f_low = consistency(low), f_high = consistency(high);
    if ((f_low < 0.0 && f_high > 0.0) || (f_low > 0.0 && f_high < 0.0)) refine(low, high, f_low, f_high);
    if (best.found) return best;
  }
  // The scan closes on the value at 0 (the function is 2 pi-periodic): evaluated at 2 pi, sin(2 pi) =
  // -2.4e-16 != sin(0) could put a root within 1e-16 of 0 (a planar problem, b_T2 = 0: the function is
  // odd about 0 and pi) between the two ends, where no interval sees its sign change.
  const double first = consistency(0.0);
  double previous_phi = 0.0, previous = first;
  for (int i = 1; i <= kPhiIntervals; ++i) {
    const double phi = 2.0 * std::numbers::pi * i / kPhiIntervals;
    const double value = i == kPhiIntervals ? first : consistency(phi);
    if (previous == 0.0) consider(previous_phi);
    if ((previous < 0.0 && value > 0.0) || (previous > 0.0 && value < 0.0)) refine(previous_phi, phi, previous, value);
    previous_phi = phi;
    previous = value;
  }
  return best;
}

void check_block_count(const MatX& W, const VecX& b, const VecX& mu) {
  if (W.rows() != W.cols() || W.rows() % 3 != 0)
    throw InputError("W", "invalid parameter 'W': must be square with 3 rows per contact, got " +
                              std::to_string(W.rows()) + " x " + std::to_string(W.cols()));
  if (b.size() != W.rows())
    throw InputError("b", "invalid parameter 'b': must hold " + std::to_string(W.rows()) + " values (3 per contact)");
  if (mu.size() != W.rows() / 3)
    throw InputError("mu", "invalid parameter 'mu': must hold one friction coefficient per contact (" +
                               std::to_string(W.rows() / 3) + ")");
}

void validate_problem(const MatX& W, const VecX& b, const VecX& mu) {
  check_block_count(W, b, mu);
  if (!W.allFinite()) throw InputError("W", "invalid parameter 'W': must be finite");
  if (!b.allFinite()) throw InputError("b", "invalid parameter 'b': must be finite");
  for (Eigen::Index k = 0; k < mu.size(); ++k)
    if (!(std::isfinite(mu[k]) && mu[k] >= 0.0))
      throw InputError("mu", "invalid parameter 'mu': friction coefficient of contact " + std::to_string(k) +
                                 " must be finite and >= 0, got " + format_value(mu[k]));
  const double largest = W.cwiseAbs().maxCoeff();
  if ((W - W.transpose()).cwiseAbs().maxCoeff() > 100 * kEps * largest)
    throw InputError("W", "invalid parameter 'W': must be symmetric (to 100 eps max|W|)");
  for (Eigen::Index k = 0; k < mu.size(); ++k) {
    Eigen::LLT<Mat3> llt(W.block<3, 3>(3 * k, 3 * k));
    if (llt.info() != Eigen::Success)
      throw InputError("W", "invalid parameter 'W': the diagonal block of contact " + std::to_string(k) +
                                " is not positive definite");
  }
}

// The dense W as block_gauss_seidel.hpp's operator.
struct DenseDelassus {
  const MatX& W;
  Eigen::Index contacts() const { return W.rows() / 3; }
  Mat3 block(Eigen::Index k) const { return W.block<3, 3>(3 * k, 3 * k); }
  Vec3 product(Eigen::Index k, const VecX& r) const { return W.middleRows(3 * k, 3) * r; }
  void changed(Eigen::Index, const Vec3&) const {}
  VecX velocities(const VecX& r) const { return W * r; }
};

}  // namespace

Vec3 project_onto_friction_cone(const Vec3& x, double mu) {
  const double tangential = tangential_norm(x);
  if (tangential <= mu * x[0]) return x;
  if (mu * tangential <= -x[0]) return Vec3::Zero();
  const double normal = (x[0] + mu * tangential) / (1.0 + mu * mu);
  return Vec3(normal, mu * normal * x[1] / tangential, mu * normal * x[2] / tangential);
}

Vec3 solve_local_cone_problem(const Mat3& W, const Vec3& b, double mu, ConeLaw law, const Vec3* guess) {
  return solve_local_cone_problem(W, W.inverse(), b, mu, law, guess);
}

Vec3 solve_local_cone_problem(const Mat3& W, const Mat3& W_inverse, const Vec3& b, double mu, ConeLaw law,
                              const Vec3* guess) {
  if (mu == 0.0) return Vec3(std::max(0.0, -b[0] / W(0, 0)), 0.0, 0.0);
  // The cone tests squared (no square root in the Gauss-Seidel's innermost call).
  const double mu2 = mu * mu;
  const bool takes_off = law == ConeLaw::Coulomb ? b[0] >= 0.0 : b[0] >= 0.0 && mu2 * (b[1] * b[1] + b[2] * b[2]) <= b[0] * b[0];
  if (takes_off) return Vec3::Zero();
  const Vec3 stick = -(W_inverse * b);
  if (stick[0] >= 0.0 && stick[1] * stick[1] + stick[2] * stick[2] <= mu2 * stick[0] * stick[0]) return stick;
  const Boundary slide = boundary_solution(W, b, mu, law, guess);
  if (!slide.found)
    throw SolverError(law == ConeLaw::Coulomb ? "local Coulomb solver" : "local SOC solver",
                      "no sliding solution on the cone's boundary", kPhiIntervals, b.norm());
  return slide.r;
}

double contact_natural_map(const Mat3& W_kk, const Vec3& r, const Vec3& u, double mu, ConeLaw law) {
  const double rho = 1.0 / W_kk.norm();
  return (r - project_onto_friction_cone(r - rho * paired_velocity(u, mu, law), mu)).norm();
}

double cone_residual(const MatX& W, const VecX& b, const VecX& mu, const VecX& r, ConeLaw law) {
  const DenseDelassus op{W};
  return detail::natural_map_residual(op, b, mu, r, VecX(W * r + b), law);
}

ConeSolution solve_cone_complementarity(const MatX& W, const VecX& b, const VecX& mu, ConeLaw law,
                                        const ConeSettings& settings) {
  validate_problem(W, b, mu);
  DenseDelassus op{W};
  return detail::block_gauss_seidel(op, b, mu, law, settings);
}

}  // namespace rodvv::solvers::contact
