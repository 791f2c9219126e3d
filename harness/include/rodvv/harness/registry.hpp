#pragma once
// The catalogue of every case, and selection of cases by name, family/group prefix or glob.
#include <span>
#include <string>
#include <vector>

#include "rodvv/harness/case.hpp"

namespace rodvv::harness {

class Registry {
 public:
  // Throws std::logic_error on a duplicate name or an order gate on a parameter study (programming errors,
  // not user input).
  void add(Case c);
  const std::vector<Case>& cases() const noexcept { return cases_; }
  const Case* find(std::string_view name) const noexcept;

  // Each pattern selects: the case of that exact name; or every case whose name starts with
  // "pattern/" (a family or a group); or every case matching it as a shell glob ("*/rk4").
  // Result in registry order without duplicates; empty patterns select everything. A pattern that
  // selects nothing throws InputError naming it.
  std::vector<const Case*> select(std::span<const std::string> patterns) const;

 private:
  std::vector<Case> cases_;
};

// Every case rodvv knows, family by family.
const Registry& default_registry();

void register_pendulum_cases(Registry& registry);
void register_elastica_cases(Registry& registry);
void register_eulerian_cases(Registry& registry);  // eulerian1d/*: reference-map solid, barriers
void register_reissner_cases(Registry& registry);  // elastica/reissner-*: extensible, shearable rod
void register_superhelix_cases(Registry& registry);  // superhelix/*: 3-D Super-Helix rods
void register_buckling_cases(Registry& registry);  // elastica/euler-*: Euler loads, eigenproblem
void register_contact_cases(Registry& registry);  // elastica-contact/*: cavity, soft walls, prop
void register_sleeve_cases(Registry& registry);  // sleeve/*: Eshelby-like force, elastica arm scale
void register_rod3d_cases(Registry& registry);   // rod3d/*: the nodal 3-D rod (discrete elastic rod)
void register_knot_cases(Registry& registry);    // knot/*: knots tied in rods with self-contact
void register_inverse_cases(Registry& registry);  // inverse/*: Super-Helix inverse statics

}  // namespace rodvv::harness
