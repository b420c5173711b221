#pragma once
/// @file beam_theory.hpp
/// @brief Reading a body's beam theory from its [[bodies]] table: `theory` ("euler-bernoulli",
/// the default, or "timoshenko") and, for Timoshenko, `shear_coefficient` (default 5/6, a
/// rectangular section) and `poisson` (default 0.3), both recorded as assumed when absent.

#include <solver/scene/TableReader.hpp>

namespace beamimpact {

/// @brief Reads theory, shear_coefficient and poisson of body b from its table reader.
/// InputError for an unknown theory, a Timoshenko rigid body, shear_coefficient <= 0 or above
/// 10, poisson outside (-1, 0.5], or either given without theory = "timoshenko".
void read_beam_theory(TableReader& r, Body& b);

/// @brief Refuses a Timoshenko body under model.kinematics = "corotational" (the corotational
/// element is the Euler-Bernoulli one): InputError naming bodies[i].theory.
void check_beam_theory(const Scene& sc);

}  // namespace beamimpact
