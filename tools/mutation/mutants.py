"""@brief The mutants of the paper's code that the quick verification tier must kill.

Each mutant is a deliberate, small fault in the integrator, the contact solver or the beam model
(solver/contact, solver/integrator, solver/model): a list of exact text edits (file, old, new);
`old` must occur exactly once in the file, so a refactor that moves the code makes the mutant
fail loudly ("not applicable") instead of silently testing nothing. `ci` marks the fast subset
that CI runs (tools/mutation-test.sh without --all).
"""

CS = "solver/contact/ContactSolver.cc"
CP = "solver/contact/ContactPair.cc"
INTEG = "solver/integrator/ExplicitContactIntegrator.cc"

# The contact loop's first lines, used by the mutants that need the previous step's state.
_OPEN_LINES = (
    "    out_[c] = ContactForce{0.0, 0.0, gbar_[c], sbar_[c], ContactState::kOpen};\n"
    "    active_[c] = gbar_[c] < -tol_[c] && p.on_surface();\n")


def _scaled_force(k):
    return [(CS, "add(pairs_[c].normal_row(), out_[c].R);", f"add(pairs_[c].normal_row(), {k} * out_[c].R);"),
            (CS, "if (friction_) add(pairs_[c].tangent_row(), out_[c].tau);",
             f"if (friction_) add(pairs_[c].tangent_row(), {k} * out_[c].tau);")]


MUTANTS = [
    dict(name="force_x0.98", ci=True,
         what="the applied contact force (normal and friction) scaled by 0.98",
         edits=_scaled_force(0.98)),
    dict(name="force_x1.02", ci=False,
         what="the applied contact force (normal and friction) scaled by 1.02",
         edits=_scaled_force(1.02)),
    dict(name="contact_late", ci=True,
         what="a contact closes one step late: only once U^p itself penetrates, not the prediction",
         edits=[(CS, _OPEN_LINES,
                 "    const bool was_open = out_[c].state == ContactState::kOpen;\n"
                 "    out_[c] = ContactForce{0.0, 0.0, gbar_[c], sbar_[c], ContactState::kOpen};\n"
                 "    active_[c] = gbar_[c] < -tol_[c] && p.on_surface() &&\n"
                 "                 (!was_open || p.g0() + ContactPair::eval(p.normal_row(), U) < -tol_[c]);\n")]),
    dict(name="nts_weights_swapped", ci=False,
         what="node-to-surface (both weights non-zero): the target nodes' weights xi1, xi2 swapped",
         edits=[(CP, "    if (xi1_ != 0.0) model_.append_projection(n1, d, -xi1_, out);\n"
                     "    if (xi2_ != 0.0) model_.append_projection(n1 + 1, d, -xi2_, out);",
                 "    const bool nts = xi1_ != 0.0 && xi2_ != 0.0;  // node-to-node and end-to-end untouched\n"
                 "    if (xi1_ != 0.0) model_.append_projection(nts ? n1 + 1 : n1, d, -xi1_, out);\n"
                 "    if (xi2_ != 0.0) model_.append_projection(nts ? n1 : n1 + 1, d, -xi2_, out);")]),
    dict(name="friction_sign", ci=False,
         what="slip friction acts along the sliding instead of against it",
         edits=[(CS, "return Rs > 0.0 ? (Ts >= 0 ? 1.0 : -1.0) : (s > 0 ? -1.0 : 1.0);",
                 "return Rs > 0.0 ? (Ts >= 0 ? -1.0 : 1.0) : (s > 0 ? 1.0 : -1.0);")]),
    dict(name="no_half_step_velocity", ci=False,
         what="the dt/2 M^-1 f_c velocity correction of V^p dropped (V^p = Vbar^p during contact)",
         edits=[(INTEG, "  V_.noalias() = Vbar_ + (0.5 * dt_) * vwork_;", "  V_.noalias() = Vbar_;")]),
    dict(name="stale_response", ci=False,
         what="the response columns H n, H t are not recomputed after the contact point moves",
         edits=[(CS, "if (out_[c].state != ContactState::kStick && pairs_[c].relocate(Ubar)) fresh_[c] = 0;",
                 "if (out_[c].state != ContactState::kStick) pairs_[c].relocate(Ubar);")]),
    dict(name="hrz_rotary_x2", ci=False,
         what="HRZ rotary inertia m L^2/78 replaced by m L^2/39",
         edits=[("solver/model/frame_element.cc", "m * L * L / 78.0", "m * L * L / 39.0")]),
    dict(name="release_eps", ci=False,
         what="release on R <= 0 replaced by R < -eps: a closed contact holds while its gap is below "
              "1e-4 x the largest body length (a tensile multiplier up to that gap / A_nn)",
         edits=[(CS, _OPEN_LINES,
                 "    const bool was_open = out_[c].state == ContactState::kOpen;\n"
                 "    out_[c] = ContactForce{0.0, 0.0, gbar_[c], sbar_[c], ContactState::kOpen};\n"
                 "    const double hold = was_open ? -tol_[c] : 1e6 * tol_[c];\n"
                 "    active_[c] = gbar_[c] < hold && p.on_surface();\n"),
                (CS, "      ContactForce f{0.0, 0.0, g, s, ContactState::kOpen};\n      if (g < -tol_[c]) {",
                 "      ContactForce f{0.0, 0.0, g, s, ContactState::kOpen};\n      if (g < -tol_[c] || active_[c]) {"),
                (CS, "            if (R > 0.0) {", "            if (R > -1e6 * tol_[c] / Ann) {")]),
    dict(name="damping_sign", ci=False,
         what="Rayleigh damping force sign flipped (C v added instead of subtracted)",
         edits=[(INTEG, "  f -= model_.rayleigh_mass() * scratch_;", "  f += model_.rayleigh_mass() * scratch_;"),
                (INTEG, "  f -= model_.rayleigh_stiffness() * scratch_;", "  f += model_.rayleigh_stiffness() * scratch_;")]),
    dict(name="critical_dt_x2", ci=False,
         what="the critical step doubled (2/omega_max -> 4/omega_max): dt = fraction x critical is 2x too large",
         edits=[("solver/model/critical_dt.cc", "return 2.0 / omega * (std::sqrt(1 + xi * xi) - xi);",
                 "return 4.0 / omega * (std::sqrt(1 + xi * xi) - xi);")]),
    dict(name="never_stick", ci=True,
         what="stick is never chosen: every closed frictional contact slips",
         edits=[(CS, "if (Rs > 0.0 && std::abs(Ts) <= mu_[c] * Rs) {", "if (false && Rs > 0.0 && std::abs(Ts) <= mu_[c] * Rs) {")]),
    dict(name="timoshenko_shear_x2", ci=False,
         what="the Timoshenko element's shear stiffness kappa G A doubled (phi halved)",
         edits=[("solver/model/timoshenko_element.cc", "return 24.0 * (1.0 + nu) * I / (kappa * A * L * L);",
                 "return 12.0 * (1.0 + nu) * I / (kappa * A * L * L);")]),
    dict(name="timoshenko_no_rotary_inertia", ci=False,
         what="the Timoshenko element's consistent rotary inertia rho I int N_theta^T N_theta dropped",
         edits=[("solver/model/timoshenko_element.cc", "(rho * A * nv[i] * nv[j] + rho * I * nt[i] * nt[j])",
                 "(rho * A * nv[i] * nv[j])")]),
    dict(name="hertz_exponent_1", ci=False,
         what="the Hertz law's exponent 3/2 replaced by 1 (a linear spring k delta)",
         edits=[("solver/contact/hertz_law.cc", "  return k * x * std::sqrt(x);\n", "  return k * x;\n")]),
    dict(name="hertz_one_sided_force", ci=False,
         what="the Hertz force applied is the spring's at U^{p+1} alone, not the mean with U^{p-1}",
         edits=[("solver/contact/ContactSolver.cc", "  f.R = 0.5 * (S + sp);\n", "  f.R = S;\n")]),
]
