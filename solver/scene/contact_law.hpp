#pragma once
/// @file contact_law.hpp
/// @brief Reading a contact's law from its [[contacts]] table: law = "hard" (default, the
/// paper's) or "hertz" with `stiffness` k (N/m^1.5), or `radius` R* (m) and `modulus` E* (N/m^2)
/// giving k = 4/3 E* sqrt(R*) (a sphere of effective radius R* on a flat, Johnson 1985, Eq. 4.22;
/// 1/R* = 1/R1 + 1/R2, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2).

#include <string>

#include <solver/scene/TableReader.hpp>

namespace beamimpact {

/// @brief Reads law, stiffness, radius and modulus of contact c. InputError for an unknown law,
/// a Hertz law with neither stiffness nor radius and modulus (or both), or Hertz keys with the
/// hard law.
void read_contact_law(TableReader& r, Contact& c);

}  // namespace beamimpact
