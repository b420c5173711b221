"""Newmark time stepping on the GetFEM-assembled M and K (the scheme of GetFEM's own
add_Newmark_scheme and of demo_dynamic_contact_1D, written on the assembled matrices): implicit,
beta = 1/4, gamma = 1/2 by default (average acceleration: unconditionally stable, no numerical
damping). Each step solves

  M a1 + C v1 + K u1 = sum_k G_k^T lambda_k,   lambda_k = kn_k max(0, -(g0_k + G_k u1)),
  u1 = u* + beta dt^2 a1,  v1 = v* + gamma dt a1

exactly for the penalty's active set: one sparse LU of the Newmark matrix, and per step a small
dense system on the active contacts (a Woodbury update), iterated until the active set holds."""

from dataclasses import dataclass

import numpy as np
import scipy.sparse.linalg as spla


@dataclass
class Options:
    beta: float = 0.25
    gamma: float = 0.5
    penalty: float = 10.0  # gamma0: kn = gamma0 E A / h
    redistribute: bool = True  # the contact nodes' mass moved to their neighbours
    mass: str = "consistent"  # the axial mass: "consistent" (GetFEM's mass brick) or "lumped"

    def check(self):
        if not (0.0 < self.beta <= 0.5 and 0.5 <= self.gamma <= 1.0 and self.beta >= self.gamma / 4 - 1e-15):
            raise ValueError(f"newmark beta = {self.beta}, gamma = {self.gamma}: expected 0.5 <= gamma <= 1 and "
                             "gamma / 4 <= beta <= 0.5 (the unconditionally stable range)")
        if self.mass not in ("consistent", "lumped"):
            raise ValueError(f"mass = {self.mass!r}: expected \"consistent\" or \"lumped\"")
        if not self.penalty > 0:
            raise ValueError(f"penalty = {self.penalty}: expected gamma0 > 0")


class Stepper:
    """Advances (u, v, a) on the free DOFs; yields the contact forces of each step."""

    def __init__(self, model, pairs, dt, opts, rayleigh):
        f = model.free
        self.M = model.M[f][:, f].tocsc()
        self.K = model.K[f][:, f].tocsc()
        self.C = rayleigh[0] * self.M + rayleigh[1] * self.K
        self.dt, self.o = dt, opts
        b, g = opts.beta, opts.gamma
        A = (self.M / (b * dt * dt) + self.C * (g / (b * dt)) + self.K).tocsc()
        self.lu = spla.splu(A)
        self.G = np.array([p.G[f] for p in pairs]).reshape(len(pairs), len(f))
        self.g0 = np.array([p.g0 for p in pairs])
        self.kn = np.array([p.kn for p in pairs])
        pos = {int(d): i for i, d in enumerate(f)}
        self.massless = np.array([pos[d] for d in model.massless if d in pos], dtype=int)
        self.Z = np.column_stack([self.lu.solve(row) for row in self.G]) if len(pairs) else np.zeros((len(f), 0))

    def initial_acceleration(self, u, v):
        """M a0 = -K u0 - C v0 on the DOFs that carry mass (a massless DOF has no acceleration)."""
        rhs = -(self.K @ u) - (self.C @ v)
        a = np.zeros_like(u)
        if np.any(rhs):
            live = np.setdiff1d(np.arange(len(u)), self.massless)
            a[live] = spla.spsolve(self.M[live][:, live].tocsc(), rhs[live])
        return a

    def _contact(self, u0):
        """lambda on the active set for the trial solution u0 = A^-1 b (Woodbury), and u1."""
        g_trial = self.g0 + self.G @ u0
        active = g_trial < 0
        lam = np.zeros(len(self.g0))
        for _ in range(100):
            lam[:] = 0.0
            idx = np.flatnonzero(active)
            if len(idx):
                S = self.G[idx] @ self.Z[:, idx] + np.diag(1.0 / self.kn[idx])
                lam[idx] = np.linalg.solve(S, -g_trial[idx])
            u1 = u0 + self.Z @ lam
            g = self.g0 + self.G @ u1
            new = g < 0  # the penalty is on exactly where the step ends with a penetration
            if np.array_equal(new, active):
                return np.maximum(lam, 0.0), u1
            active = new
        raise RuntimeError("the penalty's active set did not settle in 100 iterations")

    def step(self, u, v, a):
        dt, b, g = self.dt, self.o.beta, self.o.gamma
        us = u + dt * v + dt * dt * (0.5 - b) * a
        vs = v + dt * (1.0 - g) * a
        rhs = self.M @ (us / (b * dt * dt)) + self.C @ (us * (g / (b * dt)) - vs)
        lam, u1 = self._contact(self.lu.solve(rhs))
        a1 = (u1 - us) / (b * dt * dt)
        v1 = vs + g * dt * a1
        # A massless DOF follows the statics of its step: its velocity is its displacement's rate,
        # as in demo_dynamic_contact_1D, and it carries no acceleration into the next predictor.
        v1[self.massless] = (u1[self.massless] - u[self.massless]) / dt
        a1[self.massless] = 0.0
        return u1, v1, a1, lam
