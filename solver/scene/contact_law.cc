#include <solver/scene/contact_law.hpp>

#include <cmath>

#include <fmt/format.h>

namespace beamimpact {

void read_contact_law(TableReader& r, Contact& c) {
  if (!r.has("law")) {
    for (const char* key : {"stiffness", "radius", "modulus"})
      if (r.has(key)) r.fail(key, "is used only with law = \"hertz\"; remove it or set law = \"hertz\"");
    return;  // the paper's hard law, the default (not written to assumed: every scene has it)
  }
  const std::string law = r.choice_or("law", "hard", {"hard", "hertz"});
  c.law = law == "hertz" ? ContactLaw::kHertz : ContactLaw::kHard;
  if (c.law == ContactLaw::kHard) {
    for (const char* key : {"stiffness", "radius", "modulus"})
      if (r.has(key)) r.fail(key, "is used only with law = \"hertz\"; remove it or set law = \"hertz\"");
    return;
  }
  const bool k = r.has("stiffness"), geo = r.has("radius") || r.has("modulus");
  if (k == geo)
    r.fail("law", "\"hertz\" expects either stiffness (N/m^1.5) or radius (m) and modulus (N/m^2), not both");
  auto positive = [&](const char* key, const char* unit) {
    const double v = r.number(key, fmt::format("a positive number ({})", unit));
    if (!(v >= 1e-30 && v <= 1e30))
      r.fail(key, fmt::format("expected a positive number between 1e-30 and 1e30 ({}), got {}", unit, v));
    return v;
  };
  if (k) {
    c.hertz_stiffness = positive("stiffness", "N/m^1.5");
    return;
  }
  const double R = positive("radius", "m"), E = positive("modulus", "N/m^2");
  c.hertz_stiffness = 4.0 / 3.0 * E * std::sqrt(R);
}

}  // namespace beamimpact
