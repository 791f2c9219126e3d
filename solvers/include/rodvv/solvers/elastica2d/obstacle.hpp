#pragma once
// Rigid, frictionless obstacles for the planar rod, given by a signed distance (gap) g(r): the
// admissible side is g >= 0, and a node touching the obstacle feels the force lambda grad g(r)
// with lambda >= 0 (Signorini: 0 <= g _|_ lambda >= 0; PHYSICS.md §1.2, ALGORITHMS.md §4.3 (a)).
//
// Shapes (g is an exact signed distance in each case, so |grad g| = 1):
//   HalfPlane   g = normal . (r - point), normal a unit vector into the admissible side
//               (the walls y = +a and y = -a of the cavity, PHYSICS.md §4.1; a floor or a prop);
//   DiskOutside g = |r - centre| - radius (the rod stays outside a rigid circular post);
//   DiskInside  g = radius - |r - centre| (the rod stays inside a rigid ring).
// An obstacle acts only on the nodes with s in [s_min, s_max] (a frictionless prop under the tip of
// a cantilever is a half-plane acting at s = L alone).
//
// The soft wall of PHYSICS.md §4.2 is a distributed potential, not an obstacle: see soft_wall.hpp.
#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "rodvv/solvers/elastica2d/problem.hpp"

namespace rodvv::solvers::elastica2d {

struct Obstacle {
  enum class Shape { HalfPlane, DiskOutside, DiskInside };
  Shape shape = Shape::HalfPlane;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();   // HalfPlane: a boundary point; disks: centre
  Eigen::Vector2d normal = Eigen::Vector2d::UnitY();  // HalfPlane: unit normal into the admissible side
  double radius = 0.0;                                // disks: > 0
  double s_min = 0.0;                                 // acts on nodes with s_min <= s <= s_max
  double s_max = std::numeric_limits<double>::infinity();
};

// Convenience constructors.
Obstacle floor_at(double level);    // admissible y >= level
Obstacle ceiling_at(double level);  // admissible y <= level
Obstacle disk_outside(const Eigen::Vector2d& centre, double radius);
Obstacle disk_inside(const Eigen::Vector2d& centre, double radius);
// The two frictionless walls y = -gap and y = +gap of PHYSICS.md §4.1; InputError "wall_gap" unless
// gap is finite and > 0.
std::vector<Obstacle> cavity_walls(double gap);

// Signed distance, its gradient and Hessian at r.
double gap(const Obstacle& obstacle, const Eigen::Vector2d& r);
Eigen::Vector2d gap_gradient(const Obstacle& obstacle, const Eigen::Vector2d& r);
Eigen::Matrix2d gap_hessian(const Obstacle& obstacle, const Eigen::Vector2d& r);

// InputError naming "<name>.normal" (not a finite unit vector within 1e-12), "<name>.radius"
// (disks: finite and > 0), "<name>.point", "<name>.s_min" / "<name>.s_max" (s_min <= s_max, s_min
// finite).
void validate(const Obstacle& obstacle, const std::string& name);

}  // namespace rodvv::solvers::elastica2d
