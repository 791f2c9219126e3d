#pragma once
// The Bathe-Bolourchi 45-degree bend solved on the nodal rod, for rod3d/bathe-bolourchi and as the
// independent oracle of its Super-Helix counterpart (superhelix/bathe-bolourchi).
#include <cstddef>

namespace rodvv::harness::rod3d_cases {

// The tip displacement's frame-free parts: along the load, and its magnitude in the arc's plane.
struct BatheBolourchiTip {
  double along_load = 0.0, in_plane = 0.0;
};

// A 45-degree arc of radius R, EI1 = EI2 = GJ = EI, inextensible, clamped (tilted plane), dead tip
// force P normal to its plane, on N edges.
BatheBolourchiTip nodal_bathe_bolourchi_tip(double R, double EI, double P, std::size_t elements);

}  // namespace rodvv::harness::rod3d_cases
