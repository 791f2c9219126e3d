#include "rodvv/solvers/elastica2d/discretisation.hpp"

#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::elastica2d {

std::string_view scheme_id(Scheme scheme) {
  return scheme == Scheme::Polygon ? "polygon" : "arcs";
}

Scheme scheme_from_id(std::string_view id) {
  if (id == "polygon") return Scheme::Polygon;
  if (id == "arcs") return Scheme::Arcs;
  throw InputError("scheme", "invalid parameter 'scheme' = " + std::string(id) +
                                 ": must be one of polygon, arcs");
}

void validate(const Discretisation& discretisation) {
  require_at_least("elements", discretisation.elements, 2);
  constexpr std::size_t kMaxElements = std::size_t{1} << 24;
  if (discretisation.elements > kMaxElements)
    throw InputError("elements", "invalid parameter 'elements' = " +
                                     std::to_string(discretisation.elements) +
                                     ": must be <= 16777216");
  if (discretisation.scheme != Scheme::Polygon && discretisation.scheme != Scheme::Arcs)
    throw InputError("scheme", "invalid parameter 'scheme': must be Polygon or Arcs");
}

}  // namespace rodvv::solvers::elastica2d
