"""Node-to-segment contact with per-node Lagrange multipliers and Coulomb friction, for the
explicit central-difference step (pure numpy; every rank solves the same small problem).

Slave nodes: the striker's contact face. Master surface: the polyline through the target face's
Q2 nodes (linear between consecutive nodes, so a node's force goes to the two nearest master
nodes with positive weights; quadratic edge weights would be negative at the corners, which an
explicit lumped-mass scheme does not tolerate). Normals and tangents are taken from the
predicted configuration and held fixed within the step.

Normal: find forces lam_n >= 0 so that the predicted gaps become zero where they were negative
(forward-increment multipliers: the force of step n closes the gap of step n+1; no penalty).
Tangential (mu > 0): forces lam_t that stop the relative tangential motion over the step (stick),
capped per node at mu lam_n; a capped node slips with lam_t = -mu lam_n sign(slip).
"""

import numpy as np

END_TOL = 0.1   # fraction of the end segment beyond the surface's ends still counted as on it


class Surface:
    """A target face as an ordered list of master nodes (indices into the gathered node arrays)."""

    def __init__(self, master, n_ref, gtol):
        self.master = np.asarray(master)
        self.n_ref = np.asarray(n_ref, dtype=float)
        self.gtol = gtol    # m: predicted gaps above -gtol count as closed, not penetrating (roundoff)

    def project(self, x, xm):
        """For points x (k x 2) against master positions xm (m x 2): segment index, xi in [0, 1]
        (clamped), whether the unclamped xi was inside, unit normal (outward) and tangent."""
        a, b = xm[:-1], xm[1:]
        d = b - a
        len2 = np.einsum("ij,ij->i", d, d)
        rel = x[:, None, :] - a[None, :, :]                       # slaves x segments x 2
        raw = np.einsum("kij,ij->ki", rel, d) / len2[None, :]
        c = np.clip(raw, 0.0, 1.0)
        off = rel - c[:, :, None] * d[None, :, :]
        seg = np.argmin(np.einsum("kij,kij->ki", off, off), axis=1)
        rows = np.arange(len(x))
        xi, r = c[rows, seg], raw[rows, seg]
        # Outside only beyond the surface's two ends (by more than END_TOL of the end segment);
        # at an interior vertex the node belongs to the surface whichever side of the kink it
        # lies on (else roundoff could let it slip through the surface).
        inside = ~(((seg == 0) & (r < -END_TOL)) | ((seg == len(d) - 1) & (r > 1 + END_TOL)))
        t = d[seg] / np.sqrt(len2[seg])[:, None]
        nrm = np.stack([-t[:, 1], t[:, 0]], axis=1)
        flip = np.sign(nrm @ self.n_ref)
        return seg, xi, inside, nrm * flip[:, None], t * np.sign(t @ self._t_ref())[:, None]

    def _t_ref(self):
        return np.array([self.n_ref[1], -self.n_ref[0]])


def gaps(x_slave, x_master, surface, clamp=False):
    """Normal gaps (m) of the slave nodes; nodes that project outside the surface get +inf
    (or, with clamp, the gap to the nearest segment's line)."""
    seg, xi, inside, nrm, _ = surface.project(x_slave, x_master)
    xm = (1 - xi)[:, None] * x_master[seg] + xi[:, None] * x_master[seg + 1]
    g = np.einsum("ij,ij->i", x_slave - xm, nrm)
    return g if clamp else np.where(inside, g, np.inf)


def solve_contact(xs, xm, vs, vm, minv_s, minv_m, surface, t_dir, mu, dt):
    """One step's contact forces.

    xs, xm: predicted positions of slave / master nodes (k x 2); vs, vm: predicted velocities
    (m/s); minv_*: inverse lumped masses per DOF (k x 2, 0 where a support holds the DOF);
    t_dir: the target tangent defining the sign of tau. Returns (fs, fm, info): forces (N) on
    slave and master nodes and a dict with R, tau, state, friction power (W)."""
    ns, nm = len(xs), len(xm)
    seg, xi, inside, nrm, tan = surface.project(xs, xm)
    xp = (1 - xi)[:, None] * xm[seg] + xi[:, None] * xm[seg + 1]
    g = np.einsum("ij,ij->i", xs - xp, nrm)
    valid = np.flatnonzero(inside)
    fs, fm = np.zeros((ns, 2)), np.zeros((nm, 2))
    info = {"R": 0.0, "tau": 0.0, "state": "open", "friction_power": 0.0, "active": 0}
    if not np.any(g[valid] < -surface.gtol):
        return fs, fm, info

    # Constraint rows over the DOF vector [slave nodes, master nodes] x 2 components.
    minv = np.concatenate([minv_s, minv_m]).ravel()

    def rows(dirs):
        C = np.zeros((len(valid), 2 * (ns + nm)))
        for r, i in enumerate(valid):
            a, b = ns + seg[i], ns + seg[i] + 1
            C[r, 2 * i:2 * i + 2] = dirs[i]
            C[r, 2 * a:2 * a + 2] -= (1 - xi[i]) * dirs[i]
            C[r, 2 * b:2 * b + 2] -= xi[i] * dirs[i]
        return C

    G = rows(nrm)
    A = dt * dt * (G * minv) @ G.T
    gv = g[valid]
    lam = np.zeros(len(valid))
    act = gv < -surface.gtol
    tol = surface.gtol
    for _ in range(100):
        lam[:] = 0.0
        idx = np.flatnonzero(act)
        lam[idx] = np.linalg.solve(A[np.ix_(idx, idx)], -gv[idx])
        if np.any(lam[idx] < 0):
            act[idx[np.argmin(lam[idx])]] = False
            continue
        gn = gv + A @ lam
        grow = (~act) & (gn < -tol)
        if not np.any(grow):
            break
        act |= grow
    f = G.T @ lam
    dv = dt * minv * f

    lt = np.zeros(len(valid))
    slipping = np.zeros(len(valid), dtype=bool)
    if mu > 0:
        T = rows(tan)
        v_all = np.concatenate([vs, vm]).ravel() + dv
        w = T @ v_all                                  # relative tangential velocities, m/s
        B = dt * (T * minv) @ T.T
        on = lam > 0
        fixed = np.zeros(len(valid), dtype=bool)       # nodes already set to slip
        for _ in range(100):
            free = np.flatnonzero(on & ~fixed)
            lt[~on] = 0.0
            if len(free):
                rhs = -w[free] - B[np.ix_(free, np.flatnonzero(fixed))] @ lt[fixed]
                lt[free] = np.linalg.solve(B[np.ix_(free, free)], rhs)
            over = free[np.abs(lt[free]) > mu * lam[free] * (1 + 1e-12)]
            if len(over) == 0:
                break
            fixed[over] = True
            lt[over] = np.sign(lt[over]) * mu * lam[over]
        slipping = fixed
        ft = T.T @ lt
        f = f + ft
        dv = dt * minv * f
        w_after = T @ (np.concatenate([vs, vm]).ravel() + dv)
        info["friction_power"] = float(lt @ w_after)

    fs[:] = f[: 2 * ns].reshape(ns, 2)
    fm[:] = f[2 * ns:].reshape(nm, 2)
    sgn = np.sign(tan[valid] @ t_dir)
    info.update(R=float(lam.sum()), tau=float((lt * sgn).sum()), active=int((lam > 0).sum()),
                state="open" if lam.sum() <= 0 else ("frictionless" if mu == 0 else
                                                     "slip" if slipping.any() else "stick"))
    return fs, fm, info
