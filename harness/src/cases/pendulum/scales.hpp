#pragma once
// The pendulum's physical scales: gravity g and the length l, so that a user types the numbers of their
// pendulum. The equation theta'' = -(g/l) sin theta has the one time scale 1/omega, omega = sqrt(g/l),
// and the cases state their levels and measured windows in it (pendulum_cases.cpp, Units): the step
// omega dt, the rotation's start rate v0 / omega, the separatrix horizon omega t_end. Physical inputs in
// time units (v0, t_end, dopri5's output interval) are parameters; their groups with omega are windows.
#include <string>

#include "../case_builder.hpp"
#include "rodvv/harness/case.hpp"

namespace rodvv::harness::pendulum_cases {

// g = 9.477 and l = 1.3 (omega = 2.7, not 1: a solver that uses omega where it needs omega^2 is right at
// omega = 1 only). unit_scale: the case's results depend on g and l through omega alone, and on omega
// only through its time unit (case_info.hpp: Parameter::unit_scale).
Parameters frequency_parameters(bool unit_scale);

// sqrt(g / l).
double natural_frequency(const Parameters& parameters);

// A window on the group value x omega^power of the parameter `name` (power -1: a rate over omega; +1: a
// time times omega), e.g. "v0 / omega in [2.01, 10] (...)"; the error names `name`, the group and omega.
cases::Window frequency_group_window(std::string name, int power, double low, double high, std::string why);

}  // namespace rodvv::harness::pendulum_cases
