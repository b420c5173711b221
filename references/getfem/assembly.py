"""The semi-discrete model built with GetFEM's own finite elements: every deformable body on its
own 1D mesh along its axis (s from 0 to L), the axial displacement u in Lagrange P1
(FEM_PK(1,1)), the transverse displacement w in cubic Hermite (FEM_HERMITE(1): the
Euler-Bernoulli beam; DOFs w and dw/ds = theta at each node) when the scene bends. Mass and
stiffness are assembled from GetFEM's generic weak-form language (GWFL):

  axial:    E A Grad_u.Grad_Test_u           rho A u.Test_u   (consistent; lumped on request: Gauss-Lobatto
                                                              quadrature)
  bending:  E I Hess_w:Hess_Test_w           rho A w.Test_w   (+ rho I Grad_w.Grad_Test_w for
                                                               rotary_inertia = "section")

Point values (a striker node, a struck point) are rows of GetFEM's interpolation of the fields.
Global layout: the bodies' blocks one after the other, each [u (n+1), w (2 (n+1))]; an immovable
rigid body has no degrees of freedom."""

import getfem as gf
import numpy as np
import scipy.sparse as sp


class BodyModel:
    """One body's GetFEM mesh, fields and matrices (local coordinates)."""

    def __init__(self, body, bending, mass_kind, rotary_inertia):
        self.body, self.bending = body, bending
        n, L = body.elements, body.length
        self.e = np.array(body.axis)
        self.nrm = np.array([-self.e[1], self.e[0]])  # the body's normal: axis turned +90 deg
        self.mesh = gf.Mesh('cartesian', np.linspace(0.0, L, n + 1))
        self.mfu = gf.MeshFem(self.mesh, 1)
        self.mfu.set_fem(gf.Fem('FEM_PK(1,1)'))
        md = gf.Model('real')
        md.add_fem_variable('u', self.mfu)
        mim = gf.MeshIm(self.mesh, gf.Integ('IM_GAUSS1D(6)'))
        lumped = mass_kind == "lumped"
        mim_u = gf.MeshIm(self.mesh, gf.Integ('IM_GAUSSLOBATTO1D(1)')) if lumped else mim
        EA, rA = body.E * body.area, body.rho * body.area
        blocks_k = [_asm(mim, f'{EA!r}*Grad_u.Grad_Test_u', md, 'u')]
        blocks_m = [_asm(mim_u, f'{rA!r}*u.Test_u', md, 'u')]
        self.nu = self.mfu.nbdof()
        self.nw = 0
        if bending:
            self.mfw = gf.MeshFem(self.mesh, 1)
            self.mfw.set_fem(gf.Fem('FEM_HERMITE(1)'))
            md.add_fem_variable('w', self.mfw)
            EI, rI = body.E * body.inertia, body.rho * body.inertia
            blocks_k.append(_asm(mim, f'{EI!r}*(Hess_w:Hess_Test_w)', md, 'w'))
            mass_w = f'{rA!r}*w.Test_w' + (f'+{rI!r}*Grad_w.Grad_Test_w' if rotary_inertia == "section" else "")
            blocks_m.append(_asm(mim, mass_w, md, 'w'))
            self.nw = self.mfw.nbdof()
        self.K = sp.block_diag(blocks_k, format='csr')
        self.M = sp.block_diag(blocks_m, format='csr')
        self.ndof = self.nu + self.nw
        # Rigid translations along the axis and the normal (w = 1, dw/ds = 0): momentum rows.
        self.t_axial = np.concatenate([np.ones(self.nu), np.zeros(self.nw)])
        self.t_normal = np.concatenate([np.zeros(self.nu), self._value_dofs().astype(float) if bending else []])

    def _value_dofs(self):
        """Which Hermite DOFs are values (1 at their node) rather than slopes (checked by GetFEM's
        interpolation at the DOF nodes, not assumed from the ordering)."""
        nodes = self.mfw.basic_dof_nodes()
        vals = gf.compute_interpolate_on(self.mfw, np.eye(self.nw), nodes)
        return np.isclose(np.diag(vals), 1.0)

    def rows(self, s):
        """(axial row, normal row) of the local displacement at s (m along the axis): the global
        displacement is e * (axial row . q) + nrm * (normal row . q)."""
        ra, rn = np.zeros(self.ndof), np.zeros(self.ndof)
        pt = np.array([[min(max(s, 0.0), self.body.length)]])
        ra[:self.nu] = gf.compute_interpolate_on(self.mfu, np.eye(self.nu), pt)[:, 0]
        if self.bending:
            rn[self.nu:] = gf.compute_interpolate_on(self.mfw, np.eye(self.nw), pt)[:, 0]
        return ra, rn

    def held_dofs(self):
        """Local DOFs held by the body's supports (axial u, normal w, rotation dw/ds)."""
        held = set()
        for sup in self.body.supports:
            if sup.axial:
                held.add(sup.node)
            if self.bending:
                base = self.nu + 2 * sup.node  # Hermite DOFs of node k: [w, dw/ds] (checked below)
                if sup.normal:
                    held.add(base)
                if sup.theta:
                    held.add(base + 1)
        if self.bending and not all(self._value_dofs()[0::2]):
            raise RuntimeError("unexpected Hermite DOF order in this GetFEM version")
        return sorted(held)


def _asm(mim, expr, md, var):
    """A GWFL bilinear form assembled on the whole mesh, as a scipy CSR matrix."""
    K = gf.asm_generic(mim, 2, expr, -1, md, 'select_output', var, var)
    K.to_csc()
    indptr, indices = K.csc_ind()
    return sp.csc_matrix((K.csc_val(), indices, indptr), shape=K.size()).tocsr()


class GlobalModel:
    """Every body's block, the global M, K, the free DOFs after supports, rigid initial velocities."""

    def __init__(self, scene, mass="consistent"):
        self.scene = scene
        self.parts, self.offset = [], []
        n = 0
        for b in scene.bodies:
            self.offset.append(n)
            if b.rigid:
                self.parts.append(None)
                continue
            bm = BodyModel(b, scene.bending, mass, scene.rotary_inertia)
            self.parts.append(bm)
            n += bm.ndof
        self.n = n
        live = [p for p in self.parts if p is not None]
        self.M = sp.block_diag([p.M for p in live], format='csr')
        self.K = sp.block_diag([p.K for p in live], format='csr')
        held = [o + d for p, o in zip(self.parts, self.offset) if p is not None for d in p.held_dofs()]
        self.free = np.setdiff1d(np.arange(n), held)
        self.massless = []  # global DOFs whose mass was redistributed (redistribute_mass)
        self._momentum = None  # momentum covectors, built from M at first use

    def point(self, body, s):
        """2 x n matrix: the global (x, y) displacement of body's point at s (m along its axis)."""
        P = np.zeros((2, self.n))
        p, o = self.parts[body], self.offset[body]
        if p is None:
            return P  # immovable
        ra, rn = p.rows(s)
        P[:, o:o + p.ndof] = np.outer(p.e, ra) + np.outer(p.nrm, rn)
        return P

    def initial_velocity(self):
        v = np.zeros(self.n)
        for p, o in zip(self.parts, self.offset):
            if p is None:
                continue
            v0 = np.array(p.body.velocity)
            v[o:o + p.ndof] = (p.e @ v0) * p.t_axial + (p.nrm @ v0) * p.t_normal
        return v

    def _momentum_rows(self):
        """Each body's momentum covectors (2 x n, global x and y) and mass (kg), from the global
        mass matrix as it is now (after any redistribution)."""
        rows = []
        for b, p, o in zip(self.scene.bodies, self.parts, self.offset):
            if p is None:
                rows.append((b.name, None, 0.0))
                continue
            ta, tn = np.zeros(self.n), np.zeros(self.n)
            ta[o:o + p.ndof], tn[o:o + p.ndof] = p.t_axial, p.t_normal
            Ma, Mn = self.M @ ta, self.M @ tn  # M is symmetric: t^T M as a column
            rows.append((b.name, np.outer(p.e, Ma) + np.outer(p.nrm, Mn), float(ta @ Ma)))
        return rows

    def momentum(self, v):
        """Total linear momentum (N s) and each body's centre-of-mass velocity (m/s)."""
        if self._momentum is None:
            self._momentum = self._momentum_rows()
        total, vcm = np.zeros(2), {}
        for name, P, mass in self._momentum:
            if P is None:
                vcm[name] = [0.0, 0.0]
                continue
            pb = P @ v
            total += pb
            vcm[name] = [float(x) for x in pb / mass]
        return total, vcm

def redistribute_mass(model, body, s):
    """The mass redistribution of Khenous, Laborde and Renard (the `redistributed mass matrix` of
    GetFEM's demo_dynamic_contact_1D): the axial mass of body's node at s (m along its axis) moves
    to its neighbouring node(s), so that the contact node carries none and a penalty contact does
    not make it bounce. Total mass and the momentum of rigid motions are kept. Returns the global
    DOF made massless, or None (an immovable body, or no node at s)."""
    p, o = model.parts[body], model.offset[body]
    if p is None:
        return None
    nodes = p.mfu.basic_dof_nodes()[0]
    d = int(np.argmin(np.abs(nodes - s)))
    if abs(nodes[d] - s) > 1e-9 * p.body.length:
        return None
    order = np.argsort(nodes)
    k = int(np.flatnonzero(order == d)[0])
    neighbours = [int(order[j]) for j in (k - 1, k + 1) if 0 <= j < len(order)]
    M = model.M.tolil()
    g, row = o + d, model.M[o + d].toarray()[0]
    moved = row.sum() + model.M[:, o + d].toarray()[:, 0].sum() - row[g]
    M[g, :] = 0.0
    M[:, g] = 0.0
    for nb in neighbours:
        M[o + nb, o + nb] += moved / len(neighbours)
    model.M = M.tocsr()
    model._momentum = None
    model.massless.append(g)
    return g
