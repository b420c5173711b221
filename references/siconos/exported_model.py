"""The semi-discrete model `beamimpact model` exports (see model.json's "files"), read into numpy:
M, K, C, F, the initial state, each equation's body, the momentum covectors and each contact's
rows as dense vectors. Nothing of the paper's contact or time stepping is used: only its model."""

import json
import os
import subprocess
import tempfile

import numpy as np
import scipy.io


class Refused(Exception):
    """The scene (or an option) is one this adapter does not model: exit 2 with this reason."""


class ExportedModel:
    """One exported model. Attributes: doc (model.json), M, K, C (scipy CSR, equations x equations),
    F, u0, v0 (vectors), body_of (body index of each equation), momentum (equations x 2 bodies),
    rows (per contact: dict of dense row vectors: normal, tangent, striker_x, ... target_y)."""

    def __init__(self, folder):
        with open(os.path.join(folder, "model.json")) as f:
            self.doc = json.load(f)
        files = self.doc["files"]
        path = lambda key: os.path.join(folder, files[key]["path"])
        matrix = lambda key: scipy.io.mmread(path(key)).tocsr()
        table = lambda key: np.loadtxt(path(key), delimiter=",", skiprows=1, ndmin=2)
        self.M, self.K, self.C = matrix("M"), matrix("K"), matrix("C")
        n = self.n = self.M.shape[0]
        state = table("initial_state")
        self.u0, self.v0 = state[:, 1].copy(), state[:, 2].copy()
        self.F = table("load")[:, 1].copy()
        self.momentum = table("momentum")[:, 1:]
        self.body_of = np.full(n, -1, dtype=int)
        for r in table("dofs"):
            for eq in r[4:7]:
                if eq >= 0:
                    self.body_of[int(eq)] = int(r[0])
        if (self.body_of < 0).any():
            raise RuntimeError(f"{folder}/dofs.csv: equations {np.flatnonzero(self.body_of < 0)[:5]} have no body")
        self.rows = []
        for c in self.doc["contacts"]:
            rows = {}
            for key, terms in c["rows"].items():
                rows[key] = np.zeros(n)
                for eq, coeff in terms:
                    rows[key][eq] += coeff
            self.rows.append(rows)

    @property
    def contacts(self):
        return self.doc["contacts"]

    @property
    def bodies(self):
        return self.doc["bodies"]

    def final_velocities(self, v):
        """Centre-of-mass velocity of each body (m/s) from the velocity vector v."""
        return {b["name"]: [float(self.momentum[:, 2 * i] @ v / b["mass"]),
                            float(self.momentum[:, 2 * i + 1] @ v / b["mass"])]
                for i, b in enumerate(self.bodies)}

    def total_momentum(self, v):
        """Total linear momentum (N s) along x and y."""
        return self.momentum[:, 0::2].sum(axis=1) @ v, self.momentum[:, 1::2].sum(axis=1) @ v


def export(beamimpact, scene, folder, dt=None, mesh=None, sets=()):
    """Runs `beamimpact model` into folder and reads it. Raises Refused with the program's one-line
    reason when it refuses the scene (exit 2), RuntimeError when it fails otherwise."""
    cmd = [beamimpact, "model", scene, "--out", folder, "--quiet"]
    if dt:
        cmd += ["--set", f"time.dt={dt}"]
    if mesh:
        cmd += ["--mesh-factor", str(mesh)]
    for s in sets:
        cmd += ["--set", s]
    try:
        r = subprocess.run(cmd, capture_output=True, text=True)
    except OSError as e:
        raise Refused(f"cannot run {beamimpact}: {e.strerror} (expected the beamimpact program)") from e
    if r.returncode == 2:
        lines = r.stderr.strip().splitlines() or ["the model export refused the scene"]
        raise Refused(lines[-1].removeprefix("error: "))
    if r.returncode != 0:
        raise RuntimeError(f"'{' '.join(cmd)}' failed (exit {r.returncode}): {r.stderr.strip()}")
    return ExportedModel(folder)


def load(beamimpact, scene, dt=None, mesh=None, sets=()):
    """export() into a temporary folder that is removed afterwards."""
    with tempfile.TemporaryDirectory(prefix="beamimpact_model_") as folder:
        return export(beamimpact, scene, folder, dt, mesh, sets)
