"""Bad input gives one clear message naming the file, the key and what was expected, exit
code 2, and no summary.json (docs/scene-format.md, "Exit codes of beamimpact run")."""

import os

import common

work = common.work_dir()
check = common.check
with open(os.path.join(common.SCENES, "s2_transverse.toml")) as f:
    S2 = f.read()


def variant(name, old, new, *more):
    """S2 with `old` replaced by `new` (and further old, new pairs), written as NAME.toml."""
    text = S2
    for o, n in zip((old,) + more[0::2], (new,) + more[1::2]):
        assert o in text, o
        text = text.replace(o, n, 1)
    path = os.path.join(work, name + ".toml")
    with open(path, "w") as f:
        f.write(text)
    return path


cases = [
    ("unknown fenicsx key", variant("fenicsx_key", "[time]", "[fenicsx]\nbogus = 1\n\n[time]"), [],
     "fenicsx.bogus"),
    ("unknown top-level key", variant("top_key", "[time]", "colour = 1\n[time]"), [], "colour"),
    ("typo in a body key", variant("body_key", "elements = 10", "elemnts = 10"), [], "'elemnts'"),
    ("rotation support", variant("theta", 'fix = ["x", "y"] }', 'fix = ["x", "y", "theta"] }'), [],
     "bodies[1].supports[0].fix"),
    ("unknown support direction", variant("fix_entry", 'fix = ["y"] }', 'fix = ["across"] }'), [],
     "bodies[1].supports[1].fix"),
    ("Timoshenko body", variant("timoshenko", "elements = 10", 'elements = 10\ntheory = "timoshenko"'), [],
     "bodies[1].theory"),
    ("Hertz contact", variant("hertz", 'node = "end"', 'node = "end"\nlaw = "hertz"\nstiffness = 50.0'), [],
     "contacts[0].law"),
    ("interior striker node", variant("interior", 'node = "end"', "node = 2"), [], "contacts[0].node"),
    ("overlap at t = 0", variant("overlap", "end = [5.0, 0.1]", "end = [5.0, -0.1]"), [], "'bodies'"),
    ("contact face not resolved", os.path.join(common.SCENES, "s2_transverse.toml"),
     ["--elements-length", "A=25,B=5"], "fenicsx.elements_length.B"),
    ("bad mesh option", os.path.join(common.SCENES, "s2_transverse.toml"), ["--elements-depth", "0"],
     "--elements-depth"),
    ("missing file", os.path.join(work, "nope.toml"), [], "cannot read"),
    ("bending body without inertia", variant("no_inertia", "inertia = 0.0053333333333333 # m^4 (assumed: 1 m x 0.4 m rectangle)", ""), [],
     "bodies[0].inertia"),
    ("free rigid body", variant("free_rigid", 'supports = [{ at = "start", fix = ["x", "y"] }, { at = "end", fix = ["y"] }]',
                                'rigid = true\nsupports = []'), [], "bodies[1].supports"),
    ("rigid striker", variant("rigid_striker", "velocity = [0.0, -1.0]       # m/s\nsupports = []",
                              'velocity = [0.0, 0.0]\nrigid = true\nsupports = [{ at = "start", fix = ["x", "y", "theta"] }]'),
     [], "contacts[0].striker"),
    ("point force on an immovable body", variant("point_rigid", "[time]", '[[loads.point]]\nbody = "B"\n'
     'node = 5\nforce = [0.0, 1.0]\n\n[time]', 'supports = [{ at = "start", fix = ["x", "y"] }, '
     '{ at = "end", fix = ["y"] }]', 'rigid = true\nsupports = [{ at = "start", fix = ["x", "y", "theta"] }]'),
     [], "loads.point[0].body"),
    ("load across a rod scene's axis", variant("rod_across", "[time]", "[loads]\ngravity = [1.0, -10.0]\n\n[time]",
     "inertia = 0.0053333333333333 # m^4 (assumed: 1 m x 0.4 m rectangle)", "",
     "inertia = 0.0053333333333333 # m^4 (assumed)", "", "[[contacts]]", "[effects]\nbending = false\n\n[[contacts]]",
     "start = [5.0, 5.1]            # m, upper end\nend = [5.0, 0.1]", "start = [-6.0, 0.0]\nend = [-1.0, 0.0]",
     'supports = [{ at = "start", fix = ["x", "y"] }, { at = "end", fix = ["y"] }]', "supports = []"),
     [], "loads.gravity"),
    ("loads not a table", variant("loads_scalar", "[time]", "loads = 1\n[time]"), [], "'loads'"),
    ("gravity not two numbers", variant("gravity", "[time]", "[loads]\ngravity = [0.0]\n\n[time]"), [],
     "loads.gravity"),
    ("typo in [loads]", variant("loads_key", "[time]", "[loads]\ngravty = [0.0, -1.0]\n\n[time]"), [],
     "loads.gravty"),
    ("point force on an unknown body", variant("point_body", "[time]", '[[loads.point]]\nbody = "C"\n'
     'node = "end"\nforce = [0.0, 1.0]\n\n[time]'), [], "loads.point[0].body"),
    ("point force node out of range", variant("point_node", "[time]", '[[loads.point]]\nbody = "B"\n'
     'node = 11\nforce = [0.0, 1.0]\n\n[time]'), [], "loads.point[0].node"),
    ("point force without force", variant("point_force", "[time]", '[[loads.point]]\nbody = "B"\n'
     'node = 5\n\n[time]'), [], "loads.point[0].force"),
]
for what, scene, args, key in cases:
    out = os.path.join(work, "out_" + what.replace(" ", "_"))
    rc, err = common.run(scene, out, *args, expect=2)
    lines = [l for l in err.strip().splitlines() if l.strip()]
    ok = (rc == 2 and len(lines) == 1 and key in lines[0]
          and (os.path.basename(scene) in lines[0] or what == "bad mesh option")
          and not os.path.exists(os.path.join(out, "summary.json")))
    check(ok, f"{what}: exit {rc}, message: {lines[-1] if lines else ''}")

# A support that is not a node of the continuum mesh (needs dolfinx: checked on the mesh).
common.require_dolfinx()
scene = variant("support_off_node", '{ at = "end", fix = ["y"] }', '{ at = 3, fix = ["y"] }')
out = os.path.join(work, "out_support")
rc, err = common.run(scene, out, "--elements-length", "A=25,B=32", expect=2)
lines = [l for l in err.strip().splitlines() if l.strip() and not l.startswith("INFO")]
check(rc == 2 and "bodies[1].supports[1].at" in err and not os.path.exists(os.path.join(out, "summary.json")),
      f"support off the mesh nodes: exit {rc}, message: {lines[-1] if lines else ''}")

# A point force at a beam node that is not on a line of continuum nodes (B's node 3 at 3 m with
# 32 Q2 elements of 0.3125 m: 3 m is not a multiple of half an element).
scene = variant("point_off_node", "[time]", '[[loads.point]]\nbody = "B"\nnode = 3\nforce = [0.0, -1.0]\n\n[time]')
out = os.path.join(work, "out_point")
rc, err = common.run(scene, out, "--elements-length", "A=25,B=32", expect=2)
lines = [l for l in err.strip().splitlines() if l.strip() and not l.startswith("INFO")]
check(rc == 2 and len(lines) == 1 and "loads.point[0].node" in err
      and not os.path.exists(os.path.join(out, "summary.json")),
      f"point force off the mesh nodes: exit {rc}, message: {lines[-1] if lines else ''}")
common.finish()
