"""Supports of the continuum: each acts on the body's axis node at its position. Held directions
are global x, y or the body's own axial (start -> end) and normal (axial turned +90 deg) ones; a
node holds what its supports' directions span. Both components held, or one exactly along x or
y: those components' inverse masses are zeroed. One other direction d (a roller across an
inclined body): the node's velocity is kept orthogonal to d, v <- v - (v . d) d after every
update. With the node's lumped mass the same on both components, that is the reaction along d
that keeps d . u = 0, and it does no work."""

import math

import numpy as np

from scene import InputError

PARALLEL_TOL = 1e-9   # |sin| between two held directions below which they are one


def _directions(body, sup):
    """Unit directions (global axes) a support holds."""
    ax = ((body.end[0] - body.start[0]) / body.length, (body.end[1] - body.start[1]) / body.length)
    d = []
    if sup.fix_x:
        d.append((1.0, 0.0))
    if sup.fix_y:
        d.append((0.0, 1.0))
    if sup.fix_axial:
        d.append(ax)
    if sup.fix_normal:
        d.append((-ax[1], ax[0]))
    return d


def _held(dirs):
    """(count held: 1 or 2, the direction when 1); body directions come last and are kept when
    parallel to a global one, as the beam model does."""
    first = dirs[0]
    for d in dirs[1:]:
        if abs(first[0] * d[1] - first[1] * d[0]) > PARALLEL_TOL:
            return 2, None
    return 1, dirs[-1]


def hold(scene, cont, tol, minv, v0):
    """Applies the supports to the inverse masses and the initial velocity (in place). Returns the
    rollers in body axes as [(key, global node, local index or None when not owned, d)]."""
    rollers = []
    for bi, body in enumerate(scene.bodies):
        at = {}
        for sup in body.supports:
            nodes, _ = cont.find_nodes(bi, lambda s, q, s0=sup.s: (abs(s - s0) < tol) & (abs(q) < tol),
                                       lambda s, q: s)
            if len(nodes) != 1:
                raise InputError(scene.file, sup.key + ".at", f"the support at {sup.s:.6g} m along "
                                 f"{body.name} is not a node of the continuum mesh; expected a position "
                                 "at a multiple of half a Q2 element (change fenicsx.elements_length)")
            entry = at.setdefault(int(nodes[0]), [sup.key, nodes, []])
            entry[2] += _directions(body, sup)
        for node, (key, nodes, dirs) in at.items():
            mask, loc = cont.owned_local(nodes)
            count, d = _held(dirs)
            comps = (0, 1) if count == 2 else (0,) if d[1] == 0.0 else (1,) if d[0] == 0.0 else ()
            for comp in comps:
                minv[2 * loc + comp] = 0.0
                v0[2 * loc + comp] = 0.0
            if comps:
                continue
            d = np.array(d) / math.hypot(*d)
            own = int(loc[0]) if len(loc) else None
            if own is not None:
                v0[2 * own:2 * own + 2] -= (v0[2 * own:2 * own + 2] @ d) * d
            rollers.append((key, node, own, d))
    return rollers


def refuse_roller_in_contact(scene, rollers, contact_nodes):
    """A roller in body axes on a node of a contact set is refused: the contact solver takes each
    component's inverse mass, which has no such constraint."""
    for key, node, _, _ in rollers:
        if node in set(int(n) for n in contact_nodes):
            raise InputError(scene.file, key + ".fix", "a roller in body axes on a node of the contact "
                             "surface is not modelled by the FEniCSx method; expected the support away from "
                             "the contact, or fix in global x, y")


def project(v, rollers):
    """Keeps each roller node's velocity orthogonal to its held direction (in place)."""
    for _, _, own, d in rollers:
        if own is not None:
            v[2 * own:2 * own + 2] -= (v[2 * own:2 * own + 2] @ d) * d
