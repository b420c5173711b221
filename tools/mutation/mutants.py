"""@brief The mutants the test command must kill, in every layer of the code.

Each mutant is a deliberate, small fault: a list of exact text edits (file, old, new); `old` must
occur exactly once in the file, so a refactor that moves the code makes the mutant fail loudly
("not applicable") instead of silently testing nothing. Keys: `layer` (the report's grouping),
`what`, `edits`, `ci` (the fast subset CI runs: tools/mutation-test.sh without --all);
`verify` (default True: the quick verification tier and the real-gap tests judge it, for faults
in the paper's code and what its runs pass through); `tests` (ctest names of the test command
that judge it besides: regular expressions matched whole) and `targets` (the build targets those tests need).
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
    dict(name="force_x0.98", layer="contact", ci=True,
         what="the applied contact force (normal and friction) scaled by 0.98",
         edits=_scaled_force(0.98)),
    dict(name="force_x1.02", layer="contact", ci=False,
         what="the applied contact force (normal and friction) scaled by 1.02",
         edits=_scaled_force(1.02)),
    dict(name="contact_late", layer="contact", ci=True,
         what="a contact closes one step late: only once U^p itself penetrates, not the prediction",
         edits=[(CS, _OPEN_LINES,
                 "    const bool was_open = out_[c].state == ContactState::kOpen;\n"
                 "    out_[c] = ContactForce{0.0, 0.0, gbar_[c], sbar_[c], ContactState::kOpen};\n"
                 "    active_[c] = gbar_[c] < -tol_[c] && p.on_surface() &&\n"
                 "                 (!was_open || p.g0() + ContactPair::eval(p.normal_row(), U) < -tol_[c]);\n")]),
    dict(name="nts_weights_swapped", layer="contact", ci=False,
         what="node-to-surface (both weights non-zero): the target nodes' weights xi1, xi2 swapped",
         edits=[(CP, "    if (xi1_ != 0.0) model_.append_projection(n1, d, -xi1_, out);\n"
                     "    if (xi2_ != 0.0) model_.append_projection(n1 + 1, d, -xi2_, out);",
                 "    const bool nts = xi1_ != 0.0 && xi2_ != 0.0;  // node-to-node and end-to-end untouched\n"
                 "    if (xi1_ != 0.0) model_.append_projection(nts ? n1 + 1 : n1, d, -xi1_, out);\n"
                 "    if (xi2_ != 0.0) model_.append_projection(nts ? n1 : n1 + 1, d, -xi2_, out);")]),
    dict(name="friction_sign", layer="contact", ci=False,
         what="slip friction acts along the sliding instead of against it",
         edits=[(CS, "return Rs > 0.0 ? (Ts >= 0 ? 1.0 : -1.0) : (s > 0 ? -1.0 : 1.0);",
                 "return Rs > 0.0 ? (Ts >= 0 ? -1.0 : 1.0) : (s > 0 ? 1.0 : -1.0);")]),
    dict(name="no_half_step_velocity", layer="integrator", ci=False,
         what="the dt/2 M^-1 f_c velocity correction of V^p dropped (V^p = Vbar^p during contact)",
         edits=[(INTEG, "  V_.noalias() = Vbar_ + (0.5 * dt_) * vwork_;", "  V_.noalias() = Vbar_;")]),
    dict(name="stale_response", layer="contact", ci=False,
         what="the response columns H n, H t are not recomputed after the contact point moves",
         edits=[(CS, "if (out_[c].state != ContactState::kStick && pairs_[c].relocate(Ubar)) fresh_[c] = 0;",
                 "if (out_[c].state != ContactState::kStick) pairs_[c].relocate(Ubar);")]),
    dict(name="hrz_rotary_x2", layer="model", ci=False,
         what="HRZ rotary inertia m L^2/78 replaced by m L^2/39",
         edits=[("solver/model/frame_element.cc", "m * L * L / 78.0", "m * L * L / 39.0")]),
    dict(name="release_eps", layer="contact", ci=False,
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
    dict(name="damping_sign", layer="integrator", ci=False,
         what="Rayleigh damping force sign flipped (C v added instead of subtracted)",
         edits=[(INTEG, "  f -= model_.rayleigh_mass() * scratch_;", "  f += model_.rayleigh_mass() * scratch_;"),
                (INTEG, "  f -= model_.rayleigh_stiffness() * scratch_;", "  f += model_.rayleigh_stiffness() * scratch_;")]),
    dict(name="critical_dt_x2", layer="critical step", ci=False,
         what="the critical step doubled (2/omega_max -> 4/omega_max): dt = fraction x critical is 2x too large",
         edits=[("solver/model/critical_dt.cc", "return 2.0 / omega * (std::sqrt(1 + xi * xi) - xi);",
                 "return 4.0 / omega * (std::sqrt(1 + xi * xi) - xi);")]),
    dict(name="never_stick", layer="contact", ci=True,
         what="stick is never chosen: every closed frictional contact slips",
         edits=[(CS, "if (Rs > 0.0 && std::abs(Ts) <= mu_[c] * Rs) {", "if (false && Rs > 0.0 && std::abs(Ts) <= mu_[c] * Rs) {")]),
    dict(name="timoshenko_shear_x2", layer="model", ci=False,
         what="the Timoshenko element's shear stiffness kappa G A doubled (phi halved)",
         edits=[("solver/model/timoshenko_element.cc", "return 24.0 * (1.0 + nu) * I / (kappa * A * L * L);",
                 "return 12.0 * (1.0 + nu) * I / (kappa * A * L * L);")]),
    dict(name="timoshenko_no_rotary_inertia", layer="model", ci=False,
         what="the Timoshenko element's consistent rotary inertia rho I int N_theta^T N_theta dropped",
         edits=[("solver/model/timoshenko_element.cc", "(rho * A * nv[i] * nv[j] + rho * I * nt[i] * nt[j])",
                 "(rho * A * nv[i] * nv[j])")]),
    dict(name="hertz_exponent_1", layer="contact", ci=False,
         what="the Hertz law's exponent 3/2 replaced by 1 (a linear spring k delta)",
         edits=[("solver/contact/hertz_law.cc", "  return k * x * std::sqrt(x);\n", "  return k * x;\n")]),
    dict(name="hertz_one_sided_force", layer="contact", ci=False,
         what="the Hertz force applied is the spring's at U^{p+1} alone, not the mean with U^{p-1}",
         edits=[("solver/contact/ContactSolver.cc", "  f.R = 0.5 * (S + sp);\n", "  f.R = S;\n")]),
    # --- beyond the paper's contact and integrator ---------------------------------------------
    dict(name="search_skips_target_end", layer="contact search", ci=False,
         verify=False,
         what="the contact search pairs only the target's first end node with the striker, not its last",
         edits=[("solver/contact/contact_search.cc", "for (int e : {0, B.elements})", "for (int e : {0})")],
         tests=["ContactSearch.TheTargetsEndNodeIsCheckedAgainstTheStriker"], targets=["contact_search_test"]),
    dict(name="real_gap_cubic_sign", layer="real gap", ci=False,
         what="the deformed surface's Hermite cubic: the second node's rotation term with the wrong sign",
         edits=[("solver/model/deformed_geometry.cc", "(-xi * xi + xi * xi * xi) * s.phi2",
                 "(xi * xi - xi * xi * xi) * s.phi2")],
         verify=False, tests=[r"DeformedGeometry\..*"], targets=["deformed_geometry_test"]),
    dict(name="rigid_inertia_x2", layer="rigid bodies", ci=False,
         verify=False,
         what="a rigid body's rotary inertia m L^2/12 replaced by m L^2/6",
         edits=[("solver/model/Model.cc", "const double masses[3] = {m, m, m * L * L / 12.0};",
                 "const double masses[3] = {m, m, m * L * L / 6.0};")],
         tests=["RigidBodies.ObliqueRodOnARigidSurfaceMatchesTheClosedForm",
                "RigidBodies.NodesFollowTheCentreAndMassIsTheRodsOwn"], targets=["rigid_body_test"]),
    dict(name="corotational_mass_frozen", layer="corotational", ci=False,
         verify=False,
         what="the corotational mass is formed at the reference angles, not the elements' current ones",
         edits=[("solver/integrator/CorotationalMass.cc", "dir_[k] = fint_.chord_direction(e, U);",
                 "dir_[k] = fint_.chord_direction(e, Eigen::VectorXd::Zero(U.size()));")],
         tests=["CorotationalMass.RigidlyRotatedBodyHasTheMassOfTheRotatedModel"],
         targets=["CorotationalMass_test"]),
    dict(name="drift_one_component", layer="record", ci=False,
         what="the momentum drift ignores the x component (|p_y(t) - p_y(0)| instead of |p(t) - p(0)|)",
         edits=[("solver/record/ResultRecorder.cc", "std::hypot(p[0] - p0_[0], p[1] - p0_[1])",
                 "std::abs(p[1] - p0_[1])")],
         verify=False, tests=["RigidBodies.MomentumDriftIsTheSupportsImpulse"], targets=["rigid_body_test"]),
    dict(name="intervals_merge_at_equal_gap", layer="record", ci=False,
         verify=False,
         what="the contact-interval rule also joins a phase that begins exactly merge_gap after the last end",
         edits=[("solver/record/ContactIntervals.cc", "t - intervals_.back()[1] < merge_gap_",
                 "t - intervals_.back()[1] <= merge_gap_")],
         tests=[r"ContactIntervals\..*"], targets=["ContactIntervals_test"]),
    dict(name="compare_peak_with_closure", layer="compare", ci=False,
         what="compare's peak force keeps the closure samples (the sample after an open one)",
         edits=[("verification/compare/compare_runs.cc", "if (R[r - 1] > threshold) p = std::max(p, R[r]);",
                 "if (R[r] > threshold) p = std::max(p, R[r]);")],
         verify=False, tests=[r"CompareRuns\..*"], targets=["verification_compare_test"]),
    dict(name="gate_tol_plus_1pct", layer="evaluate", ci=True,
         what="a gate passes up to 1.01 x its tolerance",
         edits=[("verification/matrix/evaluate.cc", "if (*n->value <= *gate.tol) {",
                 "if (*n->value <= 1.01 * *gate.tol) {")],
         verify=False, tests=["Evaluate.GatePassesAtOrBelowTolerance"], targets=["verification_compare_test"]),
    dict(name="exact_rigid_spin_sign", layer="exact", ci=False,
         what="the exact rigid-rod impact: the tangential impulse's moment about the centre with the wrong sign",
         edits=[("references/exact/RigidRodImpact.cc", "(c * r.p_n - s * r.p_t)", "(c * r.p_n + s * r.p_t)")],
         verify=False, tests=[r"RigidRodImpact\..*", r"RunExact\..*"], targets=["exact_test"]),
    dict(name="exact_recontact_at_breakpoint", layer="exact", ci=False,
         what="the exact coaxial rods: a gap that closes inside a piece re-contacts at the piece's end (the next "
              "wave arrival) instead of at the crossing time",
         edits=[("references/exact/CoaxialRods.cc",
                 "      if (te < nb - eps) {\n        end = te;\n        recontact = true;",
                 "      if (te < nb - eps) {\n        recontact = true;")],
         verify=False, tests=[r"CoaxialRods.*\..*", r"RunExact\..*"], targets=["exact_test"]),
    dict(name="ida_struck_point_sign", layer="IDA", ci=False,
         what="IDA's struck point follows the target's axial displacement with the wrong sign",
         edits=[("references/ida/ContactKinematics.cc", "s = sa - dot(t_, ub);", "s = sa + dot(t_, ub);")],
         verify=False, tests=["IdaFrictionSoftTarget.SlideOffTheRollerAgreesWithThePaper"],
         targets=["ida_friction_soft_target_test"]),
    dict(name="node_axes_rotated_back", layer="model", ci=False,
         what="a node in its body's axes: the element matrices rotated by minus the body's angle (T^T K T with T transposed)",
         edits=[("solver/model/Model.cc", "R << a[0], -a[1], a[1], a[0];", "R << a[0], a[1], -a[1], a[0];")],
         verify=False, tests=[r"RotatedScene\..*", r"ModelBodyAxes\..*"], targets=["rotated_scene_test", "Model_test"]),
    dict(name="critical_dt_no_damping", layer="critical step", ci=False,
         verify=False,
         what="the critical step ignores stiffness-proportional damping (xi from a0 only)",
         edits=[("solver/model/critical_dt.cc",
                 "const double xi = model.rayleigh_mass() / (2 * omega) + model.rayleigh_stiffness() * omega / 2;",
                 "const double xi = model.rayleigh_mass() / (2 * omega);")],
         tests=[r"CriticalStep\..*"], targets=["critical_dt_test"]),
    dict(name="python_merge_gets_window", layer="Python", ci=False,
         what="the Python module hands compare()'s window to the merge gap",
         edits=[("python/src/module.cc", "o.merge_gap = merge_gap;", "o.merge_gap = window;")],
         verify=False, tests=["python_options_test"], targets=["beamimpact_python"]),
    dict(name="study_swaps_run_and_reference", layer="study", ci=False,
         what="the study compares the reference against the run instead of the run against the reference",
         edits=[("verification/study/run_point.cc", "compare_runs(*run, *reference);",
                 "compare_runs(*reference, *run);")],
         verify=False, tests=["StudyCommand.EachRowEqualsTheCompareCommandOnTheSameRuns"],
         targets=["cli_study_test"]),
]
