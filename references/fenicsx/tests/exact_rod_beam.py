"""Independent semi-analytic solution of references.md section 2: an elastic rod (exact d'Alembert
waves with reflection memory) striking a simply supported Euler-Bernoulli beam (modal sum),
in plain numpy. Used by the S2 test when `beamimpact run --method exact` is not available.

Sign convention: the rod moves toward the beam at v0; u is the rod end's displacement toward the
beam, w the beam's deflection away from the rod (m), P >= 0 the compressive contact force (N).
RK4 with a fixed step h (T_A / h and t0 / h integers, so the wave memory is read on the grid);
contact changes are located to within one step h.
"""

import math

import numpy as np


def rod_on_beam(E_a, rho_a, A_a, L_a, v0, g0, E_b, rho_b, A_b, I_b, L_b, x_c, t_end,
                modes=61, h=1e-4):
    """Returns dict(t, P, w (deflection under the struck point), u (rod end), intervals)."""
    Z = rho_a * math.sqrt(E_a / rho_a) * A_a
    T_A = 2 * L_a / math.sqrt(E_a / rho_a)
    n = np.arange(1, modes + 1)
    Om = (n * math.pi / L_b) ** 2 * math.sqrt(E_b * I_b / (rho_b * A_b))
    phi = np.sin(n * math.pi * x_c / L_b)
    Mn = rho_b * A_b * L_b / 2
    t0 = g0 / v0
    k_mem = int(round(T_A / h))
    steps = int(math.ceil((t_end - t0) / h))
    R = np.zeros(steps + 2)                 # R(t0 + k h): reflection memory
    Rd = lambda k: R[k - k_mem] if k >= k_mem else 0.0

    q, qd, u = np.zeros(modes), np.zeros(modes), g0   # u: rod end travel; in contact u = g0 + w
    contact = True
    ts, Ps, ws, us = [t0], [Z * v0], [0.0], [g0]
    intervals, start = [], t0

    def rhs(y, rd):
        qq, qv = y[:modes], y[modes:2 * modes]
        if contact:
            P = Z * (v0 - phi @ qv) - 2 * rd
        else:
            P = 0.0
        ud = v0 - (P + 2 * rd) / Z
        return np.concatenate([qv, -Om ** 2 * qq + phi * P / Mn, [ud]]), P

    y = np.concatenate([q, qd, [u]])
    for k in range(steps):
        # Memory values at t, t + h/2, t + h (linear between grid points).
        r0, r1 = Rd(k), Rd(k + 1)
        rm = 0.5 * (r0 + r1)
        k1, _ = rhs(y, r0)
        k2, _ = rhs(y + h / 2 * k1, rm)
        k3, _ = rhs(y + h / 2 * k2, rm)
        k4, _ = rhs(y + h * k3, r1)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        t = t0 + (k + 1) * h
        w = phi @ y[:modes]
        if contact:
            P = Z * (v0 - phi @ y[modes:2 * modes]) - 2 * r1
            if P < 0:
                contact, P = False, 0.0
                intervals.append([start, t])
            else:
                y[-1] = g0 + w                 # keep the rod end on the beam (velocity matched)
        else:
            P = 0.0
            if y[-1] >= g0 + w:                 # gap g0 + w - u closed again
                contact, start = True, t
                y[-1] = g0 + w
                P = max(0.0, Z * (v0 - phi @ y[modes:2 * modes]) - 2 * r1)
        R[k + 1] = P + Rd(k + 1)
        ts.append(t); Ps.append(P); ws.append(w); us.append(y[-1])
    if contact:
        intervals.append([start, ts[-1]])
    return dict(t=np.array(ts), P=np.array(Ps), w=np.array(ws), u=np.array(us),
                intervals=intervals, modes=modes, h=h, Z=Z, T_A=T_A)


if __name__ == "__main__":
    import time
    for m, h in ((31, 1e-4), (61, 1e-4), (61, 5e-5)):
        t = time.time()
        r = rod_on_beam(100, 1, 0.4, 5, 1, 0.1, 100, 1, 0.4, 0.0053333333333333, 10, 5, 3.0, m, h)
        i1 = np.searchsorted(r["t"], r["intervals"][0][1])
        imp = np.sum(r["P"]) * h
        print(m, h, r["intervals"], "w at end of 1st:", r["w"][i1], "max w in 1st", r["w"][:i1].max(),
              "impulse", imp, "w(3)", r["w"][-1], f"{time.time() - t:.1f}s")
