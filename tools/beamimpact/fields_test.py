"""Field output (`beamimpact run --fields`): the VTK files against the run's own history.csv and
against the exact 1D wave solution of S1. The files are read with VTK's own XML reader (Debian's
python3-vtk9, the library ParaView reads them with), not with the project's reader, and the
binary and ASCII encodings are checked to hold the same bits, in double precision (the solver's
numbers, compared with history.csv exactly) and in single (the default: each value the double
rounded to nearest). Run from ctest: BEAMIMPACT_EXE and
BEAMIMPACT_SOURCE name the program and the source tree."""
import csv
import os
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_DOUBLE, VTK_FLOAT
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

EXE = os.environ["BEAMIMPACT_EXE"]
SCENES = Path(os.environ["BEAMIMPACT_SOURCE"]) / "verification" / "scenes" / "paper"
DOUBLE = ("--set", "output.field_precision=double")


def run(tmp_path, scene, *args):
    out = tmp_path / scene
    subprocess.run([EXE, "run", str(SCENES / f"{scene}.toml"), "--out", str(out), "--quiet", *args],
                   check=True)
    return out


def arrays(vtu, real=VTK_DOUBLE):
    """Every DataArray of a .vtu by name, as lists of floats, read by VTK (ParaView's reader): an
    error or warning of the reader fails the test, so does a file it cannot read whole, and so
    does a real array (points, point data) not of VTK type `real`."""
    r = vtkXMLUnstructuredGridReader()
    complaints = []
    r.AddObserver(vtkCommand.ErrorEvent, lambda *_: complaints.append("error"))
    r.AddObserver(vtkCommand.WarningEvent, lambda *_: complaints.append("warning"))
    r.SetFileName(str(vtu))
    r.Update()
    assert not complaints and r.GetErrorCode() == 0, f"VTK could not read {vtu}"
    g = r.GetOutput()
    a = {"reference_position": vtk_to_numpy(g.GetPoints().GetData()).ravel().tolist(),
         "connectivity": vtk_to_numpy(g.GetCells().GetConnectivityArray()).tolist(),
         "offsets": vtk_to_numpy(g.GetCells().GetOffsetsArray()).tolist()[1:],  # VTK keeps a leading 0
         "types": vtk_to_numpy(g.GetCellTypesArray()).tolist(),
         "body": vtk_to_numpy(g.GetCellData().GetArray("body")).tolist()}
    pd = g.GetPointData()
    assert g.GetPoints().GetDataType() == real
    for k in range(pd.GetNumberOfArrays()):
        assert pd.GetArray(k).GetDataType() == real, pd.GetArrayName(k)
        a[pd.GetArrayName(k)] = vtk_to_numpy(pd.GetArray(k)).ravel().tolist()
    a = {name: [float(x) for x in values] for name, values in a.items()}
    return g.GetNumberOfPoints(), g.GetNumberOfCells(), a


def ascii_arrays(vtu, real=float):
    """Every DataArray of an ASCII .vtu by name, parsed as XML text (parsing fails on malformed XML);
    the real arrays' text is read as `real` (float or np.float32), the others as integers."""
    root = ET.parse(vtu).getroot()
    assert root.get("type") == "UnstructuredGrid"
    piece = root.find("UnstructuredGrid/Piece")
    parse = lambda d: real if d.get("type").startswith("Float") and d.get("Name") != "TimeValue" else float
    a = {d.get("Name"): [float(parse(d)(x)) for x in d.text.split()] for d in root.iter("DataArray")}
    return int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells")), a


def history(out):
    with open(out / "history.csv") as f:
        return list(csv.DictReader(f))


def collection(out):
    root = ET.parse(out / "fields.pvd").getroot()
    return [(float(d.get("timestep")), out / d.get("file")) for d in root.iter("DataSet")]


@pytest.fixture(scope="module")
def s1(tmp_path_factory):
    """S1's fields in double precision: the solver's numbers, comparable with history.csv bit for bit."""
    return run(tmp_path_factory.mktemp("fields"), "s1_central", "--fields", *DOUBLE)


@pytest.fixture(scope="module")
def s1_single(tmp_path_factory):
    """The same run's fields as written by default (single precision)."""
    return run(tmp_path_factory.mktemp("fields_single"), "s1_central", "--fields")


def test_pvd_lists_every_output_row_with_its_time(s1):
    rows, steps = history(s1), collection(s1)
    assert len(steps) == len(rows) == 401  # 4 s / 0.01 s + the initial row
    assert [t for t, _ in steps] == [float(r["t"]) for r in rows]
    assert all(f.exists() for _, f in steps)


def test_node_counts_and_cells(s1):
    # S1: two bodies of 10 elements each -> 11 + 11 nodes, one polyline per body.
    for _, f in collection(s1)[::50]:
        n, cells, a = arrays(f)
        assert (n, cells) == (22, 2)
        assert len(a["displacement"]) == len(a["contact_force"]) == 3 * n
        assert len(a["axial_force"]) == len(a["bending_moment"]) == n
        assert a["offsets"] == [11, 22]


def test_struck_and_striker_node_displacements_equal_history(s1):
    # The striker is A's end node (global node 10), the struck point B's start node (node 11).
    # Both files print doubles in shortest round-trip form. The striker node is read straight
    # from U for both: exactly equal. history's ub is the striker's displacement minus the gap
    # row (ContactPair::target_vector), so it carries that subtraction's rounding: a few ulp of
    # the displacements involved (|u| <= 4 m here), hence 8 ulp of their size.
    for row, (_, f) in zip(history(s1), collection(s1)):
        _, _, a = arrays(f)
        u, v = a["displacement"], a["velocity"]
        assert (u[3 * 10], u[3 * 10 + 1]) == (float(row["ua_x"]), float(row["ua_y"]))
        assert (v[3 * 10], v[3 * 10 + 1]) == (float(row["va_x"]), float(row["va_y"]))
        scale = abs(u[3 * 10]) + abs(u[3 * 11])
        assert u[3 * 11] == pytest.approx(float(row["ub_x"]), rel=0, abs=8 * 2.2e-16 * scale)
        assert u[3 * 11 + 1] == float(row["ub_y"]) == 0.0  # central impact: nothing moves across


def test_contact_forces_balance_and_carry_R(s1):
    for row, (_, f) in zip(history(s1), collection(s1)):
        _, _, a = arrays(f)
        fx = a["contact_force"][0::3]
        assert sum(fx) == pytest.approx(0.0, abs=1e-12)  # action = reaction
        assert fx[10] == -float(row["R"])  # on the striker, against its motion (+x)


def test_a_rigid_striker_carries_the_force_at_its_contact_node(tmp_path):
    # rigid_rod_oblique: a rigid rod (nodes 0-2, contact node 0) falls onto a rigid horizontal
    # surface (nodes 3-7; the struck point is its middle node 5), normal (0, 1), tangent (1, 0).
    # The force R n + tau t acts on node 0 and its reaction on node 5; the rod's other nodes
    # carry none (a rigid body's centre force is not a nodal force). Exact: weights 1 and 0.
    out = tmp_path / "rigid"
    subprocess.run([EXE, "run", str(SCENES.parent / "extra" / "rigid_rod_oblique.toml"), "--out", str(out),
                    "--quiet", "--fields", *DOUBLE], check=True)
    loaded = 0
    for row, (_, f) in zip(history(out), collection(out)):
        _, _, a = arrays(f)
        fx, fy = a["contact_force"][0::3], a["contact_force"][1::3]
        R, tau = float(row["R"]), float(row["tau"])
        assert (fx[0], fy[0]) == (tau, R)
        assert (fx[5], fy[5]) == (-tau, -R)
        assert len(fx) == 8 and all(fx[i] == fy[i] == 0.0 for i in (1, 2, 3, 4, 6, 7))
        loaded += R > 0
    assert loaded > 0  # the impact is among the rows


def test_axial_force_matches_the_wave_solution(s1):
    # d'Alembert: while in contact both rods carry the compressive force EA v0 / (2c) = 2 N
    # (E = 100, A = 0.4, v0 = 1, c = 10 m/s) behind the fronts that leave the contact at
    # t = 0.5 s: at t = 1.25 s they are 7.5 m into each rod (A: x = 2.5 m, B: x = 18 m). The
    # lumped-mass central difference smears a front over ~3 elements with a Gibbs overshoot
    # (up to 13 % within 3 m of it; the paper's Figure 7 rings the same way), so the nodes checked
    # are those at least 3.5 m behind the fronts, where the ringing is below 5 %: tolerance 0.1 N.
    steps = collection(s1)
    _, _, a = arrays(steps[125][1])
    assert steps[125][0] == 1.25
    for i in list(range(6, 10)) + list(range(12, 16)):
        assert a["axial_force"][i] == pytest.approx(-2.0, abs=0.1)
    # Ahead of the fronts the rods are still unloaded (exactly 0 in the wave solution; the
    # smeared front leaves < 5 % there).
    for i in (0, 21):
        assert abs(a["axial_force"][i]) < 0.1
    assert a["bending_moment"] == [0.0] * 22  # a rod scene: no bending
    # At the end (A at rest, B moving off at 1 m/s as a free rod): no force remains.
    _, _, end = arrays(steps[-1][1])
    assert max(abs(x) for x in end["contact_force"]) == 0.0


def test_bending_scene_writes_rotations_and_moments(tmp_path):
    out = run(tmp_path, "s4_oblique_45", "--fields")
    rows, steps = history(out), collection(out)
    assert len(steps) == len(rows)
    n, _, a = arrays(steps[-1][1], VTK_FLOAT)
    assert any(x != 0.0 for x in a["rotation"]) and any(x != 0.0 for x in a["bending_moment"])


def test_no_fields_unless_asked_and_no_stale_collection(tmp_path):
    out = run(tmp_path, "s1_central", "--fields", "--set", "time.end=0.1")
    assert (out / "fields.pvd").exists()
    run(tmp_path, "s1_central", "--set", "time.end=0.1")  # same directory, no fields this time
    assert not (out / "fields.pvd").exists()


def test_fields_refused_for_a_method_without_them(tmp_path):
    p = subprocess.run([EXE, "run", str(SCENES / "s1_central.toml"), "--out", str(tmp_path / "x"),
                        "--method", "ida", "--fields"], capture_output=True, text=True)
    assert p.returncode == 2
    assert "output.fields" in p.stderr and "expected false for method 'ida'" in p.stderr


def test_history_false_keeps_no_rows_but_the_same_energies(tmp_path, s1):
    import json
    out = run(tmp_path, "s1_central", "--set", "output.history=false")
    assert not (out / "history.csv").exists()
    lean, full = (json.loads((d / "summary.json").read_text()) for d in (out, s1))
    assert lean["settings"]["output"] == {"history": False, "fields": False, "field_format": "binary",
                                          "field_precision": "single"}  # the defaults, written out
    for key in ("energy_initial", "energy_final", "momentum_drift_max"):
        assert lean[key] == full[key]  # the same run; only the rows were not kept
    assert lean["contacts"][0]["impulse_normal"] == full["contacts"][0]["impulse_normal"]


@pytest.mark.parametrize("precision", ["double", "single"])
def test_binary_and_ascii_files_hold_the_same_bits(tmp_path, s1, s1_single, precision):
    # The same run written in both encodings: the binary file is the default (appended raw,
    # UInt64 block headers); the ASCII one prints shortest round-trip decimals of the stored type.
    # Every value of every array must be the same number (single: the same float, so the ASCII
    # text is read as float32 before the comparison in double).
    out = run(tmp_path, "s1_central", "--fields", "--set", "output.field_format=ascii",
              "--set", f"output.field_precision={precision}")
    text, binary = collection(out), collection(s1 if precision == "double" else s1_single)
    real = VTK_DOUBLE if precision == "double" else VTK_FLOAT
    assert len(text) == len(binary)
    for (t1, f1), (t2, f2) in list(zip(text, binary))[::40]:
        assert t1 == t2
        n1, c1, a1 = ascii_arrays(f1, np.float32 if precision == "single" else float)
        n2, c2, a2 = arrays(f2, real)
        assert (n1, c1) == (n2, c2)
        for name in a1:
            if name != "TimeValue":
                assert a1[name] == a2[name], name


def test_single_precision_values_are_the_doubles_rounded_to_nearest(s1, s1_single):
    # The default field files hold float32: each value must be the double-precision file's value
    # rounded to the nearest float (numpy's float64 -> float32 cast is IEEE round-to-nearest-even),
    # not truncated and not computed separately; node indices and cells are the same.
    double, single = collection(s1), collection(s1_single)
    assert [t for t, _ in double] == [t for t, _ in single]
    checked = 0
    for (_, fd), (_, fs) in list(zip(double, single))[::20]:
        nd, cd, ad = arrays(fd, VTK_DOUBLE)
        ns, cs, as_ = arrays(fs, VTK_FLOAT)
        assert (nd, cd) == (ns, cs) and ad.keys() == as_.keys()
        for name, values in ad.items():
            rounded = np.asarray(values, dtype=np.float64).astype(np.float32).astype(np.float64)
            assert as_[name] == rounded.tolist(), name
            checked += sum(1 for x in values if x != float(np.float32(x)))
    assert checked > 0  # some doubles were not floats: the rounding was exercised
    # Binary sizes: a node carries 15 real numbers (point 3, displacement 3, velocity 3, rotation,
    # axial force, bending moment, contact force 3), each 4 bytes smaller in single precision, so
    # the files differ by 60 bytes a node; the headers differ only in a few offset digits (1 byte
    # a node of S1's 22 allowed).
    saved = double[-1][1].stat().st_size - single[-1][1].stat().st_size
    assert saved / 22 == pytest.approx(60, abs=1)


def test_the_python_reader_reads_both_encodings_as_vtk_does(tmp_path, s1, s1_single):
    # python/beamimpact/fields.py (used by reports/animate.py and beamimpact.read_fields) against
    # VTK's reader on the same binary file, and on the ASCII file of the same run, in both precisions.
    import sys
    sys.path.insert(0, str(Path(os.environ["BEAMIMPACT_SOURCE"]) / "python" / "beamimpact"))
    import fields as reader
    text = run(tmp_path, "s1_central", "--fields", "--set", "output.field_format=ascii", "--set", "time.end=0.6",
               *DOUBLE)
    text32 = run(tmp_path / "single", "s1_central", "--fields", "--set", "output.field_format=ascii",
                 "--set", "time.end=0.6")
    files = [(collection(s1)[55][1], VTK_DOUBLE), (collection(text)[55][1], VTK_DOUBLE),
             (collection(s1_single)[55][1], VTK_FLOAT), (collection(text32)[55][1], VTK_FLOAT)]
    for f, real in files:
        _, _, a = arrays(f, real)
        frame = reader.read_vtu(f)
        assert frame["displacement"].ravel().tolist() == a["displacement"]
        assert frame["contact_force"].ravel().tolist() == a["contact_force"]
        assert [b.tolist() for b in frame["bodies"]] == [list(range(11)), list(range(11, 22))]


def test_a_bad_field_format_is_refused_with_the_key(tmp_path):
    p = subprocess.run([EXE, "run", str(SCENES / "s1_central.toml"), "--out", str(tmp_path / "x"), "--fields",
                        "--set", "output.field_format=hdf5"], capture_output=True, text=True)
    assert p.returncode == 2
    assert "output.field_format" in p.stderr and "binary" in p.stderr


def test_a_bad_field_precision_is_refused_with_the_key(tmp_path):
    p = subprocess.run([EXE, "run", str(SCENES / "s1_central.toml"), "--out", str(tmp_path / "x"), "--fields",
                        "--set", "output.field_precision=half"], capture_output=True, text=True)
    assert p.returncode == 2
    assert "output.field_precision" in p.stderr and "single" in p.stderr and "double" in p.stderr
