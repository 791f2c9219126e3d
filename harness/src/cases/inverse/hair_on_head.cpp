#include "hair_on_head.hpp"

#include "../case_builder.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::harness::inverse_cases {

void require_hair_on_head_windows(Case& c) {
  require_window(c, "R / L <= 100 (world positions at the rod's scale)", [](const Parameters& p) {
    const double ratio = parameter_value(p, "R") / parameter_value(p, "L");
    if (!(ratio <= 100.0))
      throw InputError("R", "invalid parameters: R / L = " + format_value(ratio) +
                                " must be <= 100 (positions of the order of R lose R / L of their relative precision)");
  });
  require_window(c, "rhoS g L^3 / EI <= 1e8 (where the forward Newton returns)", [](const Parameters& p) {
    const double L = parameter_value(p, "L");
    const double w = parameter_value(p, "rhoS") * parameter_value(p, "g") * L * L * L / parameter_value(p, "EI");
    if (!(w <= 1e8))
      throw InputError("g", "invalid parameters: the weight rhoS g L^3 / EI = " + format_value(w) + " must be <= 1e8");
  });
}

}  // namespace rodvv::harness::inverse_cases
