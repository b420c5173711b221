"""The dolfinx part: one mesh of all bodies' rectangles, Q2 plane-stress stiffness K, row-sum
lumped mass, and lookups of nodes by position (partition-independent, so serial and MPI runs
take identical decisions).

dolfinx 0.5.2 API (see docs/toolchain.md). Displacement DOFs are blocked by node:
global PETSc index = 2 * global node + component, owned nodes first on every rank.
"""

import numpy as np
from mpi4py import MPI
from petsc4py import PETSc

import dolfinx
import dolfinx.fem.petsc
import ufl
from dolfinx import fem, mesh as dmesh


class Continuum:
    """Mesh, function space and assembled operators of all bodies (Q2 quadrilaterals)."""

    def __init__(self, comm, rects, poisson):
        self.comm, self.rects = comm, rects
        self.mesh = self._build_mesh(rects)
        self.V = fem.VectorFunctionSpace(self.mesh, ("Lagrange", 2))
        imap = self.V.dofmap.index_map
        self.n_own = imap.size_local
        self.node_start = imap.local_range[0]
        self.X = self.V.tabulate_dof_coordinates()[: self.n_own, :2].copy()
        self.scale = max(r.L for r in rects)
        self.tol = 1e-9 * self.scale
        # Which body each owned node belongs to (bodies are disjoint rectangles).
        self.body = np.full(self.n_own, -1, dtype=np.int64)
        for i, r in enumerate(rects):
            self.body[r.contains(self.X, self.tol)] = i
        assert np.all(self.body >= 0), "a mesh node outside every body"
        self._assemble(poisson)

    def _build_mesh(self, rects):
        cells, xs, off = [], [], 0
        for r in rects:
            s = np.linspace(0.0, r.L, r.nx + 1)
            q = np.linspace(-r.h / 2, r.h / 2, r.ny + 1)
            S, Q = np.meshgrid(s, q, indexing="ij")            # vertex (i, j) -> i * (ny+1) + j
            xs.append(r.p0 + S.reshape(-1, 1) * r.e + Q.reshape(-1, 1) * r.n)
            i, j = np.meshgrid(np.arange(r.nx), np.arange(r.ny), indexing="ij")
            v = off + i.ravel() * (r.ny + 1) + j.ravel()
            # Tensor-product vertex order: (s0,r0), (s1,r0), (s0,r1), (s1,r1).
            cells.append(np.stack([v, v + r.ny + 1, v + 1, v + r.ny + 2], axis=1))
            off += (r.nx + 1) * (r.ny + 1)
        if self.comm.rank == 0:
            cells, x = np.vstack(cells).astype(np.int64), np.vstack(xs)
        else:
            cells, x = np.empty((0, 4), dtype=np.int64), np.empty((0, 2))
        domain = ufl.Mesh(ufl.VectorElement("Lagrange", ufl.quadrilateral, 1))
        return dmesh.create_mesh(self.comm, cells, x, domain)

    def _assemble(self, nu):
        msh = self.mesh
        W = fem.FunctionSpace(msh, ("DG", 0))
        Eb, rhob = fem.Function(W), fem.Function(W)            # E * b (N/m), rho * b (kg/m^2)
        self.E, self.nu = fem.Function(W), nu                 # E (N/m^2) and nu, for the stress field
        mid = W.tabulate_dof_coordinates()[:, :2]             # DG0 dofs sit at cell midpoints
        for r in self.rects:
            inside = r.contains(mid, self.tol)
            self.E.x.array[inside] = r.E
            Eb.x.array[inside] = r.E * r.b
            rhob.x.array[inside] = r.rho * r.b
        u, v = ufl.TrialFunction(self.V), ufl.TestFunction(self.V)
        eps = lambda w: ufl.sym(ufl.grad(w))
        # Plane stress: sigma = E/(1+nu) eps + E nu/(1-nu^2) tr(eps) I, times the thickness b.
        nu = fem.Constant(msh, PETSc.ScalarType(nu))          # a Constant: one compiled form for all nu
        sigma = Eb / (1 + nu) * eps(u) + Eb * nu / (1 - nu ** 2) * ufl.tr(eps(u)) * ufl.Identity(2)
        self.K = dolfinx.fem.petsc.assemble_matrix(fem.form(ufl.inner(sigma, eps(v)) * ufl.dx))
        self.K.assemble()
        # int rho b a . v dx for a constant vector a: with a = (1, 1) the row-sum lumped mass
        # sum_j M_ij = int rho b N_i dx (positive for Lagrange Q2 quads); with a = g the weak form's
        # body force of gravity (body_force). One compiled form serves both.
        self._accel = fem.Constant(msh, PETSc.ScalarType((1.0, 1.0)))
        self._rho_a = fem.form(ufl.inner(rhob * self._accel, v) * ufl.dx)
        self.mass = self._assemble_rho_a((1.0, 1.0))
        assert np.all(self.mass > 0), "row-sum lumping gave a non-positive mass"

    def _assemble_rho_a(self, a):
        self._accel.value[:] = a
        vec = dolfinx.fem.petsc.assemble_vector(self._rho_a)
        vec.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        return vec.getArray(readonly=True)[: 2 * self.n_own].copy()

    def body_force(self, g):
        """Nodal forces (N) of gravity g (m/s^2) on every body: int rho b g . v dx, owned DOFs."""
        return self._assemble_rho_a(g)

    # -- node lookup ------------------------------------------------------------------------
    def find_nodes(self, body, predicate, key):
        """Global node ids and reference coordinates of all nodes of `body` where predicate(s, r)
        holds, sorted by key(s, r); identical on every rank."""
        r = self.rects[body]
        own = np.flatnonzero(self.body == body)
        s, q = r.local(self.X[own])
        sel = own[predicate(s, q)]
        s, q = r.local(self.X[sel])
        mine = [(float(k), int(self.node_start + i), tuple(self.X[i]))
                for k, i in zip(key(s, q), sel)]
        allv = sorted(sum(self.comm.allgather(mine), []))
        return np.array([a[1] for a in allv], dtype=np.int64), np.array([a[2] for a in allv]).reshape(-1, 2)

    def owned_local(self, nodes):
        """For global nodes: (mask of those owned here, their local node indices)."""
        loc = np.asarray(nodes) - self.node_start
        mask = (loc >= 0) & (loc < self.n_own)
        return mask, loc[mask]

    # -- stability ------------------------------------------------------------------------
    def critical_dt(self, minv, iterations=3000):
        """2 / sqrt(lambda_max(M^-1 K)) over the free DOFs, by power iteration on the symmetric
        M^-1/2 K M^-1/2 with a coordinate-seeded start vector (partition-independent). The
        Rayleigh quotient approaches lambda_max from below; the caller's fraction < 1 covers it."""
        sq = np.sqrt(minv)
        x = np.sin(9631.7 * self.X[:, 0:1] + 4172.3 * self.X[:, 1:2] + np.array([[0.0, 1.3]])).ravel() * sq
        xv, yv = self.vec(x.copy()), self.vec(np.zeros_like(x))
        lam = 0.0
        for k in range(iterations):
            nrm = xv.norm()
            xv.scale(1.0 / nrm)
            xv.array[:] *= sq
            self.K.mult(xv, yv)
            xv.array[:] /= np.where(sq > 0, sq, 1.0)
            yv.array[:] *= sq
            new = xv.dot(yv)
            xv.array[:] = yv.array
            if k > 50 and abs(new - lam) < 1e-10 * new:
                lam = new
                break
            lam = new
        return 2.0 / np.sqrt(lam)

    def vec(self, arr):
        """A PETSc vector sharing memory with the owned-DOF numpy array `arr`."""
        return PETSc.Vec().createWithArray(arr, size=(arr.size, PETSc.DECIDE), comm=self.comm)
