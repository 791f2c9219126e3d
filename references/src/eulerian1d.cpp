#include "rodvv/references/eulerian1d.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::references {

namespace {

constexpr double kPi = std::numbers::pi;

void validate_material(const BarMaterial& m) {
  require_positive("rho0", m.rho0);
  require_positive("kappa", m.kappa);
  require_positive("length", m.length);
}

// Squeeze release: E = (F0 - 1) sqw, sqw the odd 2 L0-periodic square wave (0 at multiples of
// L0); P(y) = int_0^y E = (F0 - 1) tri(y), tri the even 2 L0-periodic triangle, tri(y) = |y| on
// [-L0, L0].
double reduce(double y, double period) {
  double r = std::fmod(y, period);
  if (r < 0) r += period;
  return r;
}
double square_wave(double y, double L0) {
  const double r = reduce(y, 2 * L0);
  if (r == 0.0 || r == L0) return 0.0;
  return r < L0 ? 1.0 : -1.0;
}
double triangle_wave(double y, double L0) {
  const double r = reduce(y, 2 * L0);
  return r <= L0 ? r : 2 * L0 - r;
}

// Impact: tau = t - t0; phase 1 (0 < c tau <= L0) the compressive front at X = L0 - c tau moves
// left; phase 2 (L0 < c tau <= 2 L0) the unloading front reflected at the free end is at
// X = c tau - L0. Material to the right of the active front is at rest and compressed (F = 1 - e,
// e = v0/c), held against the wall.
struct ImpactPhase {
  enum Kind { Before, Loading, Unloading, After } kind;
  double front = 0.0;  // X of the front
};
ImpactPhase impact_phase(const BarrierImpact& p, double t) {
  const double c = bar_wave_speed(p.material), L0 = p.material.length;
  const double tau = t - impact_summary(p).contact_start;
  if (tau <= 0) return {ImpactPhase::Before, L0};
  if (c * tau <= L0) return {ImpactPhase::Loading, L0 - c * tau};
  if (c * tau <= 2 * L0) return {ImpactPhase::Unloading, c * tau - L0};
  return {ImpactPhase::After, 0.0};
}

struct Position {
  double operator()(const RigidTranslation& p, double X, double t) const {
    return p.x_left0 + X + p.velocity * t + 0.5 * p.acceleration * t * t;
  }
  double operator()(const StandingWave& p, double X, double t) const {
    const double k = kPi / p.material.length, w = bar_wave_speed(p.material) * k;
    return p.x_left0 + X + p.amplitude * std::cos(k * X) * std::cos(w * t);
  }
  double operator()(const SqueezeRelease& p, double X, double t) const {
    const double L0 = p.material.length, ct = bar_wave_speed(p.material) * t;
    const double x_left0 = p.center - 0.5 * p.stretch0 * L0;
    return x_left0 + X + 0.5 * (p.stretch0 - 1.0) * (triangle_wave(X - ct, L0) + triangle_wave(X + ct, L0));
  }
  double operator()(const BarrierImpact& p, double X, double t) const {
    const double L0 = p.material.length, c = bar_wave_speed(p.material), v0 = p.velocity;
    const double e = v0 / c, tau = t - impact_summary(p).contact_start;
    const ImpactPhase phase = impact_phase(p, t);
    const double compressed = p.wall - (L0 - X) * (1.0 - e);
    switch (phase.kind) {
      case ImpactPhase::Before: return p.wall - L0 + X + v0 * tau;
      case ImpactPhase::Loading: return X >= phase.front ? compressed : p.wall - L0 + X + v0 * tau;
      case ImpactPhase::Unloading: {
        const double s = phase.front;
        return X >= s ? compressed : p.wall - (L0 - s) * (1.0 - e) - s + X;
      }
      case ImpactPhase::After: return p.wall - L0 + X - v0 * (tau - 2 * L0 / c);
    }
    throw std::logic_error("impact phase");
  }
};

struct Velocity {
  double operator()(const RigidTranslation& p, double, double t) const { return p.velocity + p.acceleration * t; }
  double operator()(const StandingWave& p, double X, double t) const {
    const double k = kPi / p.material.length, w = bar_wave_speed(p.material) * k;
    return -p.amplitude * w * std::cos(k * X) * std::sin(w * t);
  }
  double operator()(const SqueezeRelease& p, double X, double t) const {
    const double L0 = p.material.length, c = bar_wave_speed(p.material), ct = c * t;
    return 0.5 * c * (p.stretch0 - 1.0) * (square_wave(X + ct, L0) - square_wave(X - ct, L0));
  }
  double operator()(const BarrierImpact& p, double X, double t) const {
    const ImpactPhase phase = impact_phase(p, t);
    switch (phase.kind) {
      case ImpactPhase::Before: return p.velocity;
      case ImpactPhase::Loading: return X >= phase.front ? 0.0 : p.velocity;
      case ImpactPhase::Unloading: return X >= phase.front ? 0.0 : -p.velocity;
      case ImpactPhase::After: return -p.velocity;
    }
    throw std::logic_error("impact phase");
  }
};

struct Stretch {
  double operator()(const RigidTranslation&, double, double) const { return 1.0; }
  double operator()(const StandingWave& p, double X, double t) const {
    const double k = kPi / p.material.length, w = bar_wave_speed(p.material) * k;
    return 1.0 - p.amplitude * k * std::sin(k * X) * std::cos(w * t);
  }
  double operator()(const SqueezeRelease& p, double X, double t) const {
    const double L0 = p.material.length, ct = bar_wave_speed(p.material) * t;
    if (t == 0.0) return p.stretch0;
    // One-sided (right) values at the jumps: evaluate the square waves just right of X.
    const double h = 1e-12 * L0;
    const double E = 0.5 * (square_wave(X - ct + h, L0) + square_wave(X + ct + h, L0));
    if (E == 1.0) return p.stretch0;  // exactly F0, not 1 + (F0 - 1) rounded
    return 1.0 + (p.stretch0 - 1.0) * E;
  }
  double operator()(const BarrierImpact& p, double X, double t) const {
    const ImpactPhase phase = impact_phase(p, t);
    const double e = p.velocity / bar_wave_speed(p.material);
    switch (phase.kind) {
      case ImpactPhase::Loading:
      case ImpactPhase::Unloading: return X >= phase.front ? 1.0 - e : 1.0;
      default: return 1.0;
    }
  }
};

}  // namespace

double bar_wave_speed(const BarMaterial& material) { return std::sqrt(material.kappa / material.rho0); }
double bar_mass(const BarMaterial& material) { return material.rho0 * material.length; }

BarMaterial material_of(const BarMotion& motion) {
  return std::visit([](const auto& p) { return p.material; }, motion);
}

void validate(const BarMotion& motion) {
  validate_material(material_of(motion));
  std::visit(
      [](const auto& p) {
        using T = std::decay_t<decltype(p)>;
        const double L0 = p.material.length;
        if constexpr (std::is_same_v<T, RigidTranslation>) {
          require_finite("x_left0", p.x_left0);
          require_finite("velocity", p.velocity);
          require_finite("acceleration", p.acceleration);
        } else if constexpr (std::is_same_v<T, StandingWave>) {
          require_finite("x_left0", p.x_left0);
          require_open_interval("amplitude", p.amplitude, -L0 / kPi, L0 / kPi);  // F > 0
        } else if constexpr (std::is_same_v<T, SqueezeRelease>) {
          require_finite("center", p.center);
          require_open_interval("stretch0", p.stretch0, 0.0, 1.0);
        } else {
          require_finite("x_left0", p.x_left0);
          require_open_interval("velocity", p.velocity, 0.0, bar_wave_speed(p.material));  // F = 1 - v0/c > 0
          require_finite("wall", p.wall);
          if (!(p.wall >= p.x_left0 + L0))
            throw InputError("wall", "invalid parameter 'wall' = " + format_value(p.wall) +
                                         ": must be >= x_left0 + L0 = " + format_value(p.x_left0 + L0) +
                                         " (the wall may not overlap the initial bar)");
        }
      },
      motion);
}

double bar_energy(const BarMotion& motion) {
  validate(motion);
  return std::visit(
      [](const auto& p) -> double {
        using T = std::decay_t<decltype(p)>;
        const BarMaterial& m = p.material;
        if constexpr (std::is_same_v<T, RigidTranslation>)  // the body force's potential: - M a x_centre
          return 0.5 * bar_mass(m) * p.velocity * p.velocity - bar_mass(m) * p.acceleration * (p.x_left0 + 0.5 * m.length);
        else if constexpr (std::is_same_v<T, StandingWave>) {
          // All elastic at t = 0: int_0^L0 kappa/2 (A pi/L0)^2 sin^2(pi X/L0) dX.
          const double k = kPi / m.length;
          return 0.25 * m.kappa * p.amplitude * p.amplitude * k * k * m.length;
        } else if constexpr (std::is_same_v<T, SqueezeRelease>) {
          return 0.5 * m.kappa * (p.stretch0 - 1.0) * (p.stretch0 - 1.0) * m.length;
        } else {
          return 0.5 * bar_mass(m) * p.velocity * p.velocity;
        }
      },
      motion);
}

double bar_position(const BarMotion& motion, double X, double t) {
  return std::visit([X, t](const auto& p) { return Position{}(p, X, t); }, motion);
}
double bar_velocity(const BarMotion& motion, double X, double t) {
  return std::visit([X, t](const auto& p) { return Velocity{}(p, X, t); }, motion);
}
double bar_stretch(const BarMotion& motion, double X, double t) {
  return std::visit([X, t](const auto& p) { return Stretch{}(p, X, t); }, motion);
}

BarEnds bar_ends(const BarMotion& motion, double t) {
  const double L0 = material_of(motion).length;
  return {bar_position(motion, 0.0, t), bar_position(motion, L0, t)};
}

BarPoint bar_eulerian_state(const BarMotion& motion, double x, double t) {
  validate(motion);
  require_finite("x", x);
  require_non_negative("t", t);
  const BarMaterial m = material_of(motion);
  const double L0 = m.length;
  const BarEnds ends = bar_ends(motion, t);
  BarPoint point;
  if (x < ends.left || x > ends.right) {
    // Outside: continue linearly with the end stretch; the velocity is the end's.
    const bool left = x < ends.left;
    const double X = left ? 0.0 : L0, end = left ? ends.left : ends.right;
    point.stretch = bar_stretch(motion, X, t);
    point.xi = X + (x - end) / point.stretch;
    point.velocity = bar_velocity(motion, X, t);
    return point;
  }
  // Bisection for x(X, t) = x on [0, L0]: x(., t) is increasing because F > 0.
  double lo = 0.0, hi = L0;
  for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (bar_position(motion, mid, t) < x ? lo : hi) = mid;
  }
  const double X = bar_position(motion, hi, t) - x <= x - bar_position(motion, lo, t) ? hi : lo;
  point.solid = true;
  point.xi = X;
  point.velocity = bar_velocity(motion, X, t);
  point.stretch = bar_stretch(motion, X, t);
  point.density = m.rho0 / point.stretch;
  return point;
}

ImpactSummary impact_summary(const BarrierImpact& impact) {
  const BarMaterial& m = impact.material;
  const double c = bar_wave_speed(m);
  ImpactSummary s;
  s.contact_start = (impact.wall - impact.x_left0 - m.length) / impact.velocity;
  s.contact_duration = 2.0 * m.length / c;
  s.wall_force = m.rho0 * c * impact.velocity;
  s.impulse = 2.0 * m.rho0 * m.length * impact.velocity;
  s.rebound_velocity = -impact.velocity;
  return s;
}

double impact_wall_force(const BarrierImpact& impact, double t) {
  const ImpactSummary s = impact_summary(impact);
  const double tau = t - s.contact_start;
  return tau > 0.0 && tau < s.contact_duration ? s.wall_force : 0.0;
}

}  // namespace rodvv::references
