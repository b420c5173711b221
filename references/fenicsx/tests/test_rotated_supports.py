"""S2 rotated by 37 degrees with the target's roller across it (fix = ["normal"]) is S2: the
continuum holds the roller node's normal velocity at zero (supports.py), and the mesh is the
rotated copy of S2's. The first contact (to 1.2 s, the coarse mesh) therefore has S2's interval,
impulse and peak force to the roundoff of the rotated coordinates: 1e-9 relative leaves room for
that over the run's explicit steps (measured 1.4e-13). The roller left in global axes ("y") is another
problem; at this depth it shows only as 2e-6 in the impulse, so it is not used as a control here
(the beam tests and the exact method's refusal are)."""

import os

import common

common.require_dolfinx()
work = common.work_dir()
check = common.check
rotated = os.path.join(common.SOURCE, "verification", "scenes", "extra", "s2_rotated_37.toml")
runs = {}
for name, scene in (("s2", "s2_transverse.toml"), ("s2_37", rotated)):
    s, _ = common.run(scene, os.path.join(work, name), "--mesh", "coarse", "--end", "1.2")
    runs[name] = s["contacts"][0]
a, b = runs["s2"], runs["s2_37"]
print(f"S2: {a['intervals']}, impulse {a['impulse_normal']!r}; rotated: {b['intervals']}, {b['impulse_normal']!r}")
check(len(a["intervals"]) == 1 and len(b["intervals"]) == 1, "one contact interval in both")
check(all(abs(x - y) <= 1e-9 for x, y in zip(a["intervals"][0], b["intervals"][0])), "the same interval")
check(abs(a["impulse_normal"] - b["impulse_normal"]) <= 1e-9 * a["impulse_normal"], "the same impulse")
check(abs(a["peak_R"] - b["peak_R"]) <= 1e-9 * a["peak_R"], "the same peak force")
common.finish()
