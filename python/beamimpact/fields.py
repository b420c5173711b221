"""Reading the VTK fields of a run directory (fields.pvd and fields/*.vtu, written by
`beamimpact run --fields`, layout in solver/record/FieldWriter.hpp), one step at a time.

Pure Python (xml, numpy): reports/animate.py loads this file without the compiled module.
"""
import os
import xml.etree.ElementTree as ET

import numpy as np


def steps(run_dir):
    """[(t, path of the .vtu)] of every step fields.pvd lists, in order."""
    pvd = os.path.join(run_dir, "fields.pvd")
    if not os.path.exists(pvd):
        raise FileNotFoundError(f"{pvd}: no fields in this run directory; run with --fields "
                                "(or [output] fields = true in the scene)")
    root = ET.parse(pvd).getroot()
    return [(float(d.get("timestep")), os.path.join(run_dir, d.get("file"))) for d in root.iter("DataSet")]


def read_vtu(path):
    """One step: {"points": (n, 3) reference positions, "bodies": [node index arrays], and each
    point-data array by name as (n, components)}."""
    root = ET.parse(path).getroot()
    piece = root.find("UnstructuredGrid/Piece")
    n = int(piece.get("NumberOfPoints"))
    frame = {}
    for d in piece.iter("DataArray"):
        k = int(d.get("NumberOfComponents", "1"))
        a = np.array(d.text.split(), dtype=float)
        frame[d.get("Name")] = a.reshape(-1, k) if k > 1 else a
    conn = frame.pop("connectivity").astype(int)
    ends = frame.pop("offsets").astype(int)
    frame["bodies"] = np.split(conn, ends[:-1])
    frame["points"] = frame.pop("reference_position").reshape(n, 3)
    return frame


def read_fields(run_dir):
    """Yields (t, frame) for every step of a run's fields, reading one file at a time."""
    for t, path in steps(run_dir):
        yield t, read_vtu(path)
