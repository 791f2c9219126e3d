#include "rodvv/harness/registry.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <stdexcept>

#include "rodvv/common/errors.hpp"
#include "rodvv/harness/gate.hpp"

namespace rodvv::harness {

void Registry::add(Case c) {
  if (find(c.info.name)) throw std::logic_error("duplicate case name: " + c.info.name);
  if (c.info.resolution.scale == ResolutionScale::Parameter)
    for (const auto& gate : c.gates)
      if (gate.kind == GateKind::Order)
        throw std::logic_error("case " + c.info.name + " gates an order, but its levels are a parameter study");
  add_resolution_gates(c.gates);  // every order gate gets its magnitude beside it, at any parameters
  cases_.push_back(std::move(c));
}

const Case* Registry::find(std::string_view name) const noexcept {
  for (const auto& c : cases_)
    if (c.info.name == name) return &c;
  return nullptr;
}

namespace {
bool selects(const std::string& pattern, const std::string& name) {
  if (name == pattern) return true;
  if (name.size() > pattern.size() && name.compare(0, pattern.size(), pattern) == 0 &&
      (pattern.back() == '/' || name[pattern.size()] == '/'))
    return true;
  return fnmatch(pattern.c_str(), name.c_str(), 0) == 0;
}
}  // namespace

std::vector<const Case*> Registry::select(std::span<const std::string> patterns) const {
  std::vector<const Case*> selected;
  if (patterns.empty()) {
    for (const auto& c : cases_) selected.push_back(&c);
    return selected;
  }
  std::vector<bool> chosen(cases_.size(), false);
  for (const auto& pattern : patterns) {
    bool any = false;
    for (std::size_t i = 0; i < cases_.size(); ++i)
      if (selects(pattern, cases_[i].info.name)) chosen[i] = any = true;
    if (!any)
      throw InputError("case", "unknown case '" + pattern + "': no case name, family or glob matches it (" +
                                   std::to_string(cases_.size()) + " cases; `rodvv list` shows them)");
  }
  for (std::size_t i = 0; i < cases_.size(); ++i)
    if (chosen[i]) selected.push_back(&cases_[i]);
  return selected;
}

const Registry& default_registry() {
  static const Registry registry = [] {
    Registry r;
    register_pendulum_cases(r);
    register_elastica_cases(r);
    register_eulerian_cases(r);
    register_reissner_cases(r);
    register_superhelix_cases(r);
    register_buckling_cases(r);
    register_contact_cases(r);
    register_sleeve_cases(r);
    register_rod3d_cases(r);
    register_knot_cases(r);
    register_inverse_cases(r);
    return r;
  }();
  return registry;
}

}  // namespace rodvv::harness
