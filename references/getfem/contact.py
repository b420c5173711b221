"""Contact pairs as GetFEM point rows: the striker node against the struck point of the target,
both fixed at t = 0 (linear kinematics). The gap g = g0 + n . (u_striker - u_struck) is linear in
the DOFs; the contact law is a linear penalty, lambda = kn max(0, -g), the law of GetFEM's
demo_dynamic_contact_1D (penalised contact, kn = gamma0 E A / h)."""

import math
from dataclasses import dataclass

import numpy as np

from assembly import redistribute_mass
from scene_input import Refused


@dataclass
class Pair:
    key: str
    striker: str
    target: str
    kind: str           # "end_to_end" or "node_to_surface"
    s_struck: float     # m along the target's axis
    normal: np.ndarray  # unit, from the struck point towards the striker node
    g0: float           # m, the gap at t = 0
    kn: float           # N/m, the penalty stiffness
    Pa: np.ndarray      # 2 x n: striker node's global displacement
    Pb: np.ndarray      # 2 x n: struck point's global displacement
    G: np.ndarray       # n: dg/dq


def _geometry(scene, c):
    """(struck s, normal, g0, kind) of contact c from the bodies at t = 0."""
    a, b = scene.bodies[c.striker], scene.bodies[c.target]
    ea = np.array(a.axis)
    P = np.array(a.start) + ea * a.length * c.node / a.elements
    eb, B0 = np.array(b.axis), np.array(b.start)
    nb = np.array([-eb[1], eb[0]])
    xi, d = (P - B0) @ eb, (P - B0) @ nb
    tol = 1e-9 * max(a.length, b.length)
    if -tol <= xi <= b.length + tol:
        if abs(d) <= tol:
            raise Refused(scene.file, c.key, "the striker node lies on the target's axis at t = 0 (no gap)")
        return min(max(xi, 0.0), b.length), nb * math.copysign(1.0, d), abs(d), "node_to_surface"
    s = 0.0 if xi < 0 else b.length
    r = P - (B0 + eb * s)
    return s, r / np.linalg.norm(r), float(np.linalg.norm(r)), "end_to_end"


def build_pairs(scene, model, gamma0, redistribute):
    """Every contact of the scene as a Pair; kn = gamma0 * the stiffer E A / h of the two bodies'
    elements (a rigid target gives the striker's). With `redistribute`, the striker node's axial
    mass and, end to end, the struck end node's go to their neighbours (redistribute_mass) when
    the contact's normal lies along that body's axis."""
    pairs = []
    for c in scene.contacts:
        a, b = scene.bodies[c.striker], scene.bodies[c.target]
        s, n, g0, kind = _geometry(scene, c)
        # Only a node the contact pushes along its body's axis (the axial mass is redistributed).
        if redistribute and abs(n @ np.array(a.axis)) > 1 - 1e-9:
            redistribute_mass(model, c.striker, a.length * c.node / a.elements)
        if redistribute and kind == "end_to_end" and abs(n @ np.array(b.axis)) > 1 - 1e-9:
            redistribute_mass(model, c.target, s)
        Pa = model.point(c.striker, a.length * c.node / a.elements)
        Pb = model.point(c.target, s)
        kn = gamma0 * max(x.E * x.area / (x.length / x.elements) for x in (a, b) if not x.rigid)
        pairs.append(Pair(c.key, a.name, b.name, kind, s, n, g0, kn, Pa, Pb, n @ (Pa - Pb)))
    return pairs
