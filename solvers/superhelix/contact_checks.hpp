#pragma once
// The checks every inverse statics with contacts applies to a contact's normal and friction coefficient
// (inverse_contact.hpp, inverse_bundle.hpp): InputError "contacts" for a normal that is not a finite unit
// vector to 1e-10, "mu" for mu not finite and > 0, naming contact k.
#include <cmath>
#include <cstddef>
#include <string>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::superhelix::detail {

inline void check_contact_normal_and_mu(std::size_t k, const Vec3& normal, double mu) {
  if (!normal.allFinite() || !(std::abs(normal.norm() - 1.0) <= 1e-10))
    throw InputError("contacts", "invalid parameter 'contacts': the normal of contact " + std::to_string(k) +
                                     " must be a finite unit vector (|n| - 1 within 1e-10)");
  if (!(std::isfinite(mu) && mu > 0.0))
    throw InputError("mu", "invalid parameter 'mu' of contact " + std::to_string(k) + " = " + format_value(mu) +
                               ": must be finite and > 0");
}

}  // namespace rodvv::solvers::superhelix::detail
