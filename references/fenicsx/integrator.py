"""Explicit central difference with row-sum lumped mass and Lagrange-multiplier contact.

Per step n (u_n, v_{n-1/2} known; F the constant external loads, loads.py, zero without them):
  v* = v_{n-1/2} + dt M^-1 (F - K u_n),  u* = u_n + dt v*           (prediction)
  contact forces f_n from the predicted gaps (contact.py)           (correction)
  v_{n+1/2} = v* + dt M^-1 f_n,  u_{n+1} = u_n + dt v_{n+1/2}
The start is v_{-1/2} = v_0 - dt/2 M^-1 (F - K u_0) (u_0 = 0), so that the scheme's
u_{n+1} - 2 u_n + u_{n-1} = dt^2 a reproduces u = v_0 t + a t^2 / 2 exactly for a constant
acceleration a (free fall: exact up to roundoff at every step).
Reported velocities are v_n = (v_{n-1/2} + v_{n+1/2}) / 2; energies use them.
Energy bookkeeping: the central-difference quantity
  E_{n+1/2} = 1/2 v_{n+1/2}' M v_{n+1/2} + 1/2 u_n' K u_{n+1}
changes by exactly (f_n + F) . (u_{n+1} - u_{n-1}) / 2 per step. The contact part
W_n = f_n . (u_{n+1} - u_{n-1}) / 2 gives dissipated = -sum W_n; the load part sums to
F . (u_{n+1} + u_n - u_0 - u_{-1}) / 2. |E_{n-1/2} - E_{-1/2} - sum_{k<n} W_k - that load part|
is a roundoff-level self-check (summary: fenicsx.shadow_energy_error_max). The history's
load_work is F . u_n (J), the loads' work since t = 0, as the beam methods write it.
"""

import math
import sys
import time

import numpy as np
from mpi4py import MPI

from contact import Surface, gaps, solve_contact
from loads import load_vector
from output import STATE_CODES
import supports


class _ContactSetup:
    """Node sets of one contact, as indices into the gathered contact-node arrays."""

    def __init__(self, cg, slave, master, centre, tgt, tgt_w, surface):
        self.cg, self.slave, self.master, self.centre = cg, slave, master, centre
        self.tgt, self.tgt_w, self.surface = tgt, tgt_w, surface


def _floor_sig(x, digits=3):
    """x rounded down to `digits` significant digits (a readable, partition-independent dt)."""
    p = 10.0 ** (math.floor(math.log10(x)) - digits + 1)
    return math.floor(x / p) * p


def setup(scene, opts, cont, contacts):
    """Supports, initial velocity, step size and contact node sets. Raises InputError."""
    comm, rects, tol = cont.comm, cont.rects, cont.tol
    n2 = 2 * cont.n_own
    minv = 1.0 / cont.mass
    v0 = np.zeros(n2)
    for i, r in enumerate(rects):
        own = np.flatnonzero(cont.body == i)
        v0[2 * own], v0[2 * own + 1] = r.velocity[0], r.velocity[1]
    for bi, body in enumerate(scene.bodies):
        if body.rigid:   # immovable: every node held
            own = np.flatnonzero(cont.body == bi)
            minv[2 * own] = minv[2 * own + 1] = v0[2 * own] = v0[2 * own + 1] = 0.0
    rollers = supports.hold(scene, cont, tol, minv, v0)

    F = load_vector(scene, cont, scene.loads)
    dt_crit = cont.critical_dt(minv)
    dt_max = opts.fraction * dt_crit
    if opts.output_interval:
        k = math.ceil(opts.output_interval / dt_max * (1 - 1e-12))
        dt, out_every = opts.output_interval / k, k
    else:
        dt, out_every = _floor_sig(dt_max), scene.output_every
    end = opts.end or scene.end
    nsteps = max(1, round(end / dt))

    sets, all_nodes = [], []
    for cg in contacts:
        S, T = rects[cg.striker], rects[cg.target]
        slave, xs = cont.find_nodes(cg.striker, lambda s, q: abs(s - cg.face_s) < tol, lambda s, q: q)
        if cg.surf_kind == "side":
            master, _ = cont.find_nodes(cg.target, lambda s, q: abs(q - cg.side * T.h / 2) < tol,
                                        lambda s, q: s)
        else:
            s_face = 0.0 if cg.surf_kind == "start" else T.L
            master, _ = cont.find_nodes(cg.target, lambda s, q: abs(s - s_face) < tol, lambda s, q: q)
        axis, xa = cont.find_nodes(cg.target, lambda s, q: abs(q) < tol, lambda s, q: s)
        sa = T.local(xa)[0]
        j = int(np.clip(np.searchsorted(sa, cg.target_s) - 1, 0, len(sa) - 2))
        w = (cg.target_s - sa[j]) / (sa[j + 1] - sa[j])
        centre = int(np.argmin(np.abs(S.local(xs)[1])))
        sets.append((cg, slave, master, slave[centre], axis[j:j + 2], np.array([1 - w, w])))
        all_nodes += [slave, master, axis[j:j + 2]]
    cn = np.unique(np.concatenate(all_nodes))
    supports.refuse_roller_in_contact(scene, rollers, cn)
    pos = {int(g): k for k, g in enumerate(cn)}
    csets = [_ContactSetup(cg, np.array([pos[int(g)] for g in sl]), np.array([pos[int(g)] for g in ma]),
                           pos[int(ce)], np.array([pos[int(g)] for g in tg]), tw,
                           Surface(range(len(ma)), cg.n_out, 1e-12 * cont.scale))
             for cg, sl, ma, ce, tg, tw in sets]
    # v_{-1/2} from v_0 and the initial acceleration M^-1 F (u_0 = 0: no elastic force).
    vh0 = v0 if F is None else v0 - 0.5 * dt * minv * F
    supports.project(vh0, rollers)
    return dict(minv=minv, v0=v0, vh0=vh0, F=F, dt=dt, dt_crit=dt_crit, out_every=out_every,
                nsteps=nsteps, end=nsteps * dt, cn=cn, csets=csets, rollers=rollers)


def run(cont, st, stats, progress=True, fields=None):
    """The time loop. Returns history rows, summaries of energy/momentum and final velocities.
    fields: a fields.FieldOutput that receives the displacement at every output row, or None."""
    comm, n2 = cont.comm, 2 * cont.n_own
    dt, minv, mass = st["dt"], st["minv"], cont.mass
    cn, csets = st["cn"], st["csets"]
    own_mask, own_loc = cont.owned_local(cn)
    own_dofs = np.stack([2 * own_loc, 2 * own_loc + 1], axis=1)
    # Reference coordinates and inverse masses of the contact nodes (identical on all ranks).
    ref = np.zeros((len(cn), 2))
    ref[own_mask] = cont.X[own_loc]
    mi = np.zeros((len(cn), 2))
    mi[own_mask] = minv[own_dofs]
    both = np.concatenate([ref, mi])
    comm.Allreduce(MPI.IN_PLACE, both, op=MPI.SUM)
    ref, mi = both[: len(cn)], both[len(cn):]

    F = st["F"]
    u, vh, ku, u_prev = np.zeros(n2), st["vh0"].copy(), np.zeros(n2), np.zeros(n2)
    u_prev[:] = -dt * vh
    uv, kuv = cont.vec(u), cont.vec(ku)
    comp = np.tile([1.0, 0.0], cont.n_own), np.tile([0.0, 1.0], cont.n_own)
    body_dofs = [np.repeat(cont.body == b, 2) for b in range(len(cont.rects))]
    rows, E0, p0 = [], None, None
    diss, work_sum, shadow_err, drift, fric_max = 0.0, 0.0, 0.0, 0.0, -math.inf
    t_wall, t_last = time.time(), time.time()
    nc = len(csets)
    for n in range(st["nsteps"] + 1):
        t = n * dt
        cont.K.mult(uv, kuv)
        v_pred = vh - dt * minv * ku if F is None else vh + dt * minv * (F - ku)
        g = np.zeros((3, len(cn), 2))
        g[0, own_mask], g[1, own_mask], g[2, own_mask] = u[own_dofs], vh[own_dofs], v_pred[own_dofs]
        if comm.size > 1:
            comm.Allreduce(MPI.IN_PLACE, g, op=MPI.SUM)
        uc, vhc, vpc = g
        upc = uc + dt * vpc
        fc = np.zeros((len(cn), 2))
        infos = []
        for c in csets:
            fs, fm, info = solve_contact(ref[c.slave] + upc[c.slave], ref[c.master] + upc[c.master],
                                         vpc[c.slave], vpc[c.master], mi[c.slave], mi[c.master],
                                         c.surface, c.cg.t, c.cg.friction, dt)
            np.add.at(fc, c.slave, fs)
            np.add.at(fc, c.master, fm)
            infos.append(info)
            fric_max = max(fric_max, info["friction_power"]) if info["R"] > 0 else fric_max
        v_new = v_pred
        v_new[own_dofs] += dt * minv[own_dofs] * fc[own_mask]
        supports.project(v_new, st["rollers"])
        vnc = vpc + dt * mi * fc
        unc = uc + dt * vnc                      # u_{n+1} at the contact nodes
        u_prevc = g_prev if n > 0 else uc - dt * vhc
        w_n = float(np.sum(fc * (unc - u_prevc)) / 2)
        vn = 0.5 * (vh + v_new)
        loc = np.array([0.5 * np.sum(mass * vn * vn), 0.5 * (u @ ku), np.sum(mass * vn * comp[0]),
                        np.sum(mass * vn * comp[1]), 0.5 * np.sum(mass * vh * vh) + 0.5 * (u_prev @ ku),
                        0.0 if F is None else F @ u, 0.0 if F is None else F @ u_prev])
        if comm.size > 1:
            comm.Allreduce(MPI.IN_PLACE, loc, op=MPI.SUM)
        kin, strain, px, py, shadow, load_work, load_work_prev = loc
        load_part = 0.5 * (load_work + load_work_prev)   # F . (u_n + u_{n-1}) / 2
        if n == 0:
            E0, p0 = kin + strain, np.array([px, py])
            shadow0 = shadow - load_part
        shadow_err = max(shadow_err, abs(shadow - work_sum - load_part - shadow0))
        drift = max(drift, float(np.hypot(px - p0[0], py - p0[1])))
        # Row n: forces of step n, gap after the step, fields at t_n.
        diss_row = 0.0 - (work_sum + float(np.sum(fc * (uc - u_prevc)) / 2))
        for k, c in enumerate(csets):
            stats[k].add(t, infos[k]["R"], infos[k]["tau"], dt, infos[k]["state"])
        if n % st["out_every"] == 0 or n == st["nsteps"]:
            row = [t]
            for k, c in enumerate(csets):
                xs_new = ref[c.slave] + unc[c.slave]
                gs = gaps(xs_new, ref[c.master] + unc[c.master], c.surface)
                gap = float(gs.min()) if np.isfinite(gs).any() else float(
                    gaps(xs_new, ref[c.master] + unc[c.master], c.surface, clamp=True)[
                        list(c.slave).index(c.centre)])
                vnc_mid = 0.5 * (vhc + vnc)
                ub, vb = c.tgt_w @ uc[c.tgt], c.tgt_w @ vnc_mid[c.tgt]
                row += [infos[k]["R"], infos[k]["tau"], gap, *uc[c.centre], *vnc_mid[c.centre], *ub, *vb,
                        STATE_CODES[infos[k]["state"]]]
            rows.append(row + [kin, strain, diss_row, load_work, px, py])
            if fields is not None:
                fields.write(t, u)
        work_sum += w_n
        g_prev = uc
        u_prev[:] = u
        u += dt * v_new
        vh[:] = v_new
        if progress and comm.rank == 0 and time.time() - t_last > 10:
            t_last = time.time()
            print(f"[fenicsx] t = {t:.6g} of {st['end']:.6g} s (step {n} of {st['nsteps']}), "
                  f"R = {[round(i['R'], 6) for i in infos]}, {t_last - t_wall:.0f} s elapsed",
                  file=sys.stderr, flush=True)
    # Centre-of-mass velocities from the last v_n.
    loc = np.array([[np.sum((mass * vn * comp[0])[d]), np.sum((mass * vn * comp[1])[d]),
                     np.sum((mass * comp[0])[d])] for d in body_dofs])
    if comm.size > 1:
        comm.Allreduce(MPI.IN_PLACE, loc, op=MPI.SUM)
    return dict(rows=rows, E0=E0, E_final=kin + strain, load_work=load_work, drift=drift,
                shadow_err=shadow_err, friction_power_max=fric_max if nc and fric_max > -math.inf else 0.0,
                final_velocity={r.name: [loc[i, 0] / loc[i, 2], loc[i, 1] / loc[i, 2]]
                                for i, r in enumerate(cont.rects)})
