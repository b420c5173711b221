"""Reading the VTK fields of a run directory (``fields.pvd`` and ``fields/*.vtu``, written by
``beamimpact run --fields``, layout in solver/record/FieldWriter.hpp), one step at a time.

Pure Python (xml, numpy): reports/animate.py loads this file without the compiled module.
"""
from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from typing import Any, Iterator, Union

import numpy as np


def steps(run_dir: Union[str, os.PathLike]) -> list[tuple[float, str]]:
    """[(t, path of the .vtu)] of every step fields.pvd lists, in order."""
    pvd = os.path.join(run_dir, "fields.pvd")
    if not os.path.exists(pvd):
        raise FileNotFoundError(f"{pvd}: no fields in this run directory; run with --fields "
                                "(or [output] fields = true in the scene)")
    root = ET.parse(pvd).getroot()
    return [(float(d.get("timestep")), os.path.join(run_dir, d.get("file"))) for d in root.iter("DataSet")]


_DTYPES = {"Float64": "<f8", "Float32": "<f4", "Int64": "<i8", "Int32": "<i4", "UInt8": "u1"}
_APPENDED = b'<AppendedData encoding="raw">'


def _parse(path):
    """(XML root, appended raw bytes or None) of a .vtu: the binary files carry their arrays
    after the XML header (VTK's appended raw encoding), which an XML parser cannot read."""
    with open(path, "rb") as f:
        data = f.read()
    cut = data.find(_APPENDED)
    if cut < 0:
        return ET.fromstring(data), None
    start = data.index(b"_", cut + len(_APPENDED)) + 1
    return ET.fromstring(data[:cut] + b"</VTKFile>"), memoryview(data)[start:]


def _values(d, raw):
    """The values of one DataArray, inline (ascii) or from the appended block at its offset."""
    if d.get("format") != "appended":  # Float32 text is read as float32: its shortest decimals
        return np.array(d.text.split(), dtype=_DTYPES[d.get("type")]).astype(float)  # name that float
    at = int(d.get("offset"))
    nbytes = int(np.frombuffer(raw[at:at + 8], dtype="<u8")[0])
    return np.frombuffer(raw[at + 8:at + 8 + nbytes], dtype=_DTYPES[d.get("type")]).astype(float)


def read_vtu(path: Union[str, os.PathLike]) -> dict[str, Any]:
    """One step: {"points": (n, 3) reference positions, "bodies": [node index arrays], and each
    point-data array by name as (n, components)} as doubles. Reads both encodings
    (output.field_format) and both precisions (output.field_precision)."""
    root, raw = _parse(path)
    piece = root.find("UnstructuredGrid/Piece")
    n = int(piece.get("NumberOfPoints"))
    frame = {}
    for d in piece.iter("DataArray"):
        k = int(d.get("NumberOfComponents", "1"))
        a = _values(d, raw)
        frame[d.get("Name")] = a.reshape(-1, k) if k > 1 else a
    conn = frame.pop("connectivity").astype(int)
    ends = frame.pop("offsets").astype(int)
    frame["bodies"] = np.split(conn, ends[:-1])
    frame["points"] = frame.pop("reference_position").reshape(n, 3)
    return frame


def read_fields(run_dir: Union[str, os.PathLike]) -> Iterator[tuple[float, dict[str, Any]]]:
    """Yields (t, frame) for every step of a run's fields, reading one file at a time."""
    for t, path in steps(run_dir):
        yield t, read_vtu(path)
