"""Moreau-Jean time stepping of an exported model with Siconos 4.4 (Debian python3-siconos).

Each body with free equations is one LagrangianLinearTIDS (its block of M, K, C and F; the bodies
are coupled only through contact). Each contact is one Interaction on the striker's and the
target's systems: a LagrangianLinearTIR y = H q + b with H the exported normal row (and the
tangential row with friction), b = (g0, 0). Without friction the law is NewtonImpactNSL(e) and
the one-step problem an LCP (Lemke); with friction NewtonImpactFrictionNSL(e, 0, mu, 2) and a
FrictionContact(2) problem (the 2D Coulomb law, NSGS). The integrator is MoreauJeanOSI(theta):
theta = 0.5 is the trapezoidal rule on the smooth part; the unilateral constraint acts at the
velocity level (Newton's impact law), so an impact with e = 0 is perfectly plastic.

The contact rows are those of t = 0 (the struck point does not move along the target): the
run reports how far it slid (struck_point_slide_max) so that a reader can judge the frozen point."""

import numpy as np


class Options:
    """Adapter options with their defaults (written into summary.json)."""

    def __init__(self, theta=0.5, restitution=0.0, tolerance=1e-10, max_iterations=10000):
        if not 0.5 <= theta <= 1.0:
            raise ValueError(f"--theta: expected 0.5 <= theta <= 1, got {theta}")
        if not 0.0 <= restitution <= 1.0:
            raise ValueError(f"--restitution: expected 0 <= e <= 1, got {restitution}")
        self.theta, self.restitution = theta, restitution
        self.tolerance, self.max_iterations = tolerance, max_iterations

    def as_dict(self):
        return {"theta": self.theta, "restitution": self.restitution,
                "solver_tolerance": self.tolerance, "solver_max_iterations": self.max_iterations}


def _bodies(model):
    """Per body with free equations: (index, equations). Equations of a body in ascending order."""
    return [(b, np.flatnonzero(model.body_of == b)) for b in range(len(model.bodies))
            if (model.body_of == b).any()]


def _interaction(sk, model, k, friction, opts, systems):
    """The Interaction of contact k and the (one or two) systems it links."""
    rows = model.rows[k]
    H = np.vstack([rows["normal"], rows["tangent"]]) if friction else rows["normal"][None, :]
    touched = [s for s in systems if np.any(H[:, s[1]] != 0.0)]
    if not touched:
        raise ValueError(f"contacts[{k}]: expected a striker or target that can move (both are immovable)")
    Hs = np.hstack([H[:, eqs] for _, eqs, _ in touched])
    b = np.zeros(H.shape[0])
    b[0] = model.contacts[k]["g0"]
    if friction:
        law = sk.NewtonImpactFrictionNSL(opts.restitution, 0.0, model.contacts[k]["friction"], 2)
    else:
        law = sk.NewtonImpactNSL(opts.restitution)
    return sk.Interaction(law, sk.LagrangianLinearTIR(Hs, b)), [ds for _, _, ds in touched]


class Simulation:
    """The Siconos model of an exported model, built on construction (ValueError for a contact
    it cannot link); steps() runs it."""

    def __init__(self, model, opts, steps, dt):
        import siconos.kernel as sk
        import siconos.numerics as sn

        self.model, self.steps, self.dt = model, steps, dt
        self.friction = "friction" in model.doc["effects"]
        self.nsds = sk.NonSmoothDynamicalSystem(0.0, steps * dt)
        self.systems = []
        for b, eqs in _bodies(model):
            sub = np.ix_(eqs, eqs)
            ds = sk.LagrangianLinearTIDS(model.u0[eqs], model.v0[eqs], model.M[sub].toarray(),
                                         model.K[sub].toarray(), model.C[sub].toarray())
            if np.any(model.F[eqs] != 0.0):
                ds.setFExtPtr(model.F[eqs].copy())
            self.nsds.insertDynamicalSystem(ds)
            self.systems.append((b, eqs, ds))
        self.interactions = []
        for k in range(len(model.contacts)):
            inter, linked = _interaction(sk, model, k, self.friction, opts, self.systems)
            self.nsds.link(inter, *linked)
            self.interactions.append(inter)
        problem = sk.FrictionContact(2) if self.friction else sk.LCP()
        so = problem.numericsSolverOptions()
        so.dparam[sn.SICONOS_DPARAM_TOL] = opts.tolerance
        so.iparam[sn.SICONOS_IPARAM_MAX_ITER] = opts.max_iterations
        self.sim = sk.TimeStepping(self.nsds, sk.TimeDiscretisation(0.0, dt), sk.MoreauJeanOSI(opts.theta),
                                   problem)

    def run(self):
        """Yields, for k = 0 .. steps, (t_k, u_k, v_k, R, tau): R and tau lists (one per contact)
        of the mean forces over [t_k, t_k + dt] (N), None at k = steps."""
        u, v = self.model.u0.copy(), self.model.v0.copy()
        for k in range(self.steps):
            u_k, v_k = u.copy(), v.copy()
            self.sim.computeOneStep()
            R, tau = [], []
            for inter in self.interactions:  # lambda(1): the impulse over the step (N s)
                lam = inter.lambda_(1)
                R.append(float(lam[0]) / self.dt)
                tau.append(float(lam[1]) / self.dt if self.friction else 0.0)
            for _, eqs, ds in self.systems:
                u[eqs], v[eqs] = ds.q(), ds.velocity()
            self.sim.nextStep()
            yield k * self.dt, u_k, v_k, R, tau
        yield self.steps * self.dt, u, v, None, None
