"""Continuum geometry derived from a beam scene (pure numpy, no dolfinx).

Each beam becomes a rectangle along its axis, of depth h = sqrt(12 I / A) and thickness
b = A / h: the one rectangle whose area and second moment match the beam's section. A rod (a
body without I, in a scene of rods on one line, scene.py) and an immovable rigid body without I
get the square section h = b = sqrt(A).

Where the striker meets the target's side (S2-S4), the beam scene's gap is measured from the
striker node to the target's axis; the continuum's gap is measured between surfaces. The striker
is therefore translated along the target's normal so that its lowest face point is exactly the
beam gap away from the target's surface (for an oblique striker that point is a corner). End-on
contacts (S1) need no translation: the end faces already lie where the end nodes are.
"""

import math
from dataclasses import dataclass

import numpy as np

from scene import InputError


@dataclass
class Rect:
    """One body's rectangle: axis from p0 along unit e (length L), unit normal n, depth h, thickness b."""
    name: str
    p0: np.ndarray
    e: np.ndarray
    n: np.ndarray
    L: float
    h: float
    b: float
    nx: int
    ny: int
    E: float
    rho: float
    velocity: np.ndarray

    def point(self, s, r):
        """Reference position at axis coordinate s (m) and depth coordinate r (m, 0 = axis)."""
        return self.p0 + s * self.e + r * self.n

    def local(self, x):
        """(s, r) of global points x (k x 2)."""
        d = np.atleast_2d(x) - self.p0
        return d @ self.e, d @ self.n

    def contains(self, x, tol):
        s, r = self.local(x)
        return (s > -tol) & (s < self.L + tol) & (np.abs(r) < self.h / 2 + tol)


@dataclass
class ContactGeom:
    """A contact in the continuum: the striker's end face against one face of the target.

    face: striker face as (s fixed, r from -h/2..h/2); surface: target face, either an end face
    ("start"/"end", s fixed) or a side face (r = side * h/2). n_out is the target surface's outward
    normal (toward the striker) and t the target tangent (unit axis of the target), both reference.
    """
    striker: int
    target: int
    face_s: float
    kind: str               # "end_to_end" | "node_to_surface"
    surf_kind: str          # "start" | "end" | "side"
    side: float             # +1/-1 for a side surface (sign of r), 0 for end faces
    n_out: np.ndarray
    t: np.ndarray
    target_s: float         # axis coordinate (m) of the target point (struck point on the axis)
    friction: float
    gap0: float             # m, beam scene's initial gap = continuum gap after translation


def build_geometry(scene, opts):
    """Rectangles (with striker translations) and contact geometries; raises InputError."""
    rects = []
    for b in scene.bodies:
        h = math.sqrt(12.0 * b.inertia / b.area) if b.inertia > 0 else math.sqrt(b.area)
        p0, p1 = np.array(b.start), np.array(b.end)
        e = (p1 - p0) / b.length
        ny = opts.elements_depth
        nx = opts.elements_length.get(b.name, max(1, round(b.length / (h / ny))))
        rects.append(Rect(b.name, p0, e, np.array([-e[1], e[0]]), b.length, h, b.area / h, nx, ny,
                          b.E, b.rho, np.array(b.velocity, dtype=float)))
    contacts = []
    for c in scene.contacts:
        S, T = rects[c.striker], rects[c.target]
        face_s = S.L if c.end == "end" else 0.0
        P = S.point(face_s, 0.0)
        s_t, d_t = T.local(P)
        s_t, d_t = float(s_t[0]), float(d_t[0])
        corners = [S.point(face_s, -S.h / 2), S.point(face_s, S.h / 2)]
        if 0.0 < s_t < T.L:
            if abs(d_t) <= 1e-12 * T.L:
                raise InputError(scene.file, c.key + ".node", "the striker node lies on the target's "
                                 "axis; expected it on one side of the target (a positive gap)")
            side = math.copysign(1.0, d_t)
            n_out = side * T.n
            lowest = min(float((q - T.p0) @ n_out) for q in corners)
            shift = abs(d_t) + T.h / 2 - lowest
            S.p0 = S.p0 + shift * n_out
            P = S.point(face_s, 0.0)
            target_s = float(T.local(P)[0][0])
            kind, surf_kind, gap0 = "node_to_surface", "side", abs(d_t)
            for q in corners:
                sq = float((q - T.p0) @ T.e)
                if not 0.0 < sq < T.L:
                    raise InputError(scene.file, c.key + ".node", "the striker's end face (depth "
                                     f"{S.h:.4g} m) reaches past the target's end; expected it to "
                                     "meet the target's side within its length")
        else:
            surf_kind = "start" if s_t <= 0 else "end"
            n_out = -T.e if surf_kind == "start" else T.e
            gap0 = -s_t if surf_kind == "start" else s_t - T.L
            if abs(d_t) + S.h / 2 > T.h / 2 + 1e-12 or abs(float(S.e @ T.e)) < 1 - 1e-9:
                raise InputError(scene.file, c.key + ".node", "an end-on contact needs the striker "
                                 "coaxial with the target and its end face within the target's "
                                 "end face; expected that")
            side, kind, target_s = 0.0, "end_to_end", 0.0 if surf_kind == "start" else T.L
            lowest = min(float((q - T.point(target_s, 0.0)) @ n_out) for q in corners)
            gap0 = lowest
        if gap0 <= 0:
            raise InputError(scene.file, c.key + ".node", "the bodies touch or overlap at t = 0; "
                             "expected a positive initial gap")
        # The face is resolved only if the target's surface elements are no longer than it.
        seg = T.L / T.nx if surf_kind == "side" else T.h / T.ny
        if seg > S.h * (1 + 1e-9):
            raise InputError(scene.file, f"fenicsx.elements_length.{T.name}",
                             f"the target's surface elements ({seg:.4g} m) are longer than the "
                             f"striker's contact face ({S.h:.4g} m), which would not be resolved; "
                             f"expected at least {math.ceil(T.L / S.h)} elements along {T.name}")
        contacts.append(ContactGeom(c.striker, c.target, face_s, kind, surf_kind, side, n_out,
                                    T.e.copy(), target_s, c.friction, gap0))
    # Bodies must not overlap at t = 0 (checked on a grid of points of each rectangle).
    for i, A in enumerate(rects):
        for B in rects[i + 1:]:
            pts = np.array([A.point(s, r) for s in np.linspace(0, A.L, 4 * A.nx + 1)
                            for r in np.linspace(-A.h / 2, A.h / 2, 5)])
            if np.any(B.contains(pts, -1e-12)):
                raise InputError(scene.file, "bodies", f"bodies {A.name} and {B.name} overlap at "
                                 "t = 0 as continua (depth sqrt(12 I/A)); expected disjoint bodies")
    return rects, contacts
