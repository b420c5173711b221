"""Field output of the FEniCSx reference for ParaView ([output] fields = true in the scene, the
option of `beamimpact run`): displacement (m) and plane-stress Cauchy stress (N/m^2) on the Q2
mesh at every output row, written with dolfinx's own VTK writer (dolfinx.io.VTKFile) as
OUT/fields.pvd, the same name as the beam methods' fields, so both open side by side.

The stress is sigma = E/(1+nu) eps + E nu/(1-nu^2) tr(eps) I of the Q2 displacement, evaluated at
the nodes of a Q2 tensor space (each node takes one neighbouring cell's value: for viewing, not a
smoothed recovery).
"""

import ufl
from dolfinx import fem, io


class FieldOutput:
    """Writes u and sigma of a Continuum at chosen times into OUT/fields.pvd."""

    def __init__(self, cont, out_dir):
        self.cont = cont
        self.u = fem.Function(cont.V, name="displacement")
        T = fem.TensorFunctionSpace(cont.mesh, ("Lagrange", 2))
        self.stress = fem.Function(T, name="stress")
        eps = ufl.sym(ufl.grad(self.u))
        E, nu = cont.E, cont.nu
        sigma = E / (1 + nu) * eps + E * nu / (1 - nu ** 2) * ufl.tr(eps) * ufl.Identity(2)
        self.expr = fem.Expression(sigma, T.element.interpolation_points())
        self.file = io.VTKFile(cont.comm, f"{out_dir}/fields.pvd", "w")

    def write(self, t, u_owned):
        """Writes the fields at time t (s) from the owned displacement DOFs (2 per node)."""
        self.u.x.array[: u_owned.size] = u_owned
        self.u.x.scatter_forward()
        self.stress.interpolate(self.expr)
        self.file.write_function([self.u, self.stress], float(t))

    def close(self):
        self.file.close()
