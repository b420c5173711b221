# %% [markdown]
# # S2 against the exact solution
#
# Notebook-style (cells marked `# %%`: Jupyter and VS Code open it as a notebook; it also runs as
# a script). A 5 m rod falls end-on at 1 m/s onto the midspan of a simply supported 10 m beam
# (Pu & Chi 2011, section 3.2). We run it with the paper's integrator and with the exact
# rod-on-beam solution (d'Alembert rod waves plus a converged modal sum of the beam), compare the
# two, and plot the contact force and the struck point's displacement.
#
# Usage: `PYTHONPATH=build/python /usr/bin/python3 examples/python/s2_against_exact.py [OUT_DIR]`
# (run from the repository root; writes OUT_DIR/s2_against_exact.png and .json, default out/).

# %%
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # a file, no window: the same in a notebook and on a server
import matplotlib.pyplot as plt

import beamimpact

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
out.mkdir(parents=True, exist_ok=True)
# The first impact only (2.5 s): the span the matrix's S2 mesh ladder measures.
scene = beamimpact.load_scene("verification/scenes/paper/s2_transverse.toml", overrides={"time.end": 2.5})

# %% Run both methods on the same scene file.
paper = beamimpact.run(scene, method="paper", progress=False)
exact = beamimpact.run(scene, method="exact", progress=False)

# %% Compare: the norms of `beamimpact compare` (the same C++ code), and the contact intervals.
comparison = beamimpact.compare(paper, exact)
result = {
    "impulse_paper": paper.summary["contacts"][0]["impulse_normal"],
    "impulse_exact": exact.summary["contacts"][0]["impulse_normal"],
    "impulse_rel_error": beamimpact.norm(comparison, "impulse"),
    "ub_rel_l2": beamimpact.norm(comparison, "ub.rel_l2"),
    "intervals_paper": paper.summary["contacts"][0]["intervals"],
    "intervals_exact": exact.summary["contacts"][0]["intervals"],
}
for key, value in result.items():
    print(f"{key:18s} {value}")

# %% Plot the contact force and the struck point's vertical displacement.
fig, (ax_r, ax_u) = plt.subplots(1, 2, figsize=(11, 4))
for r, style, label in ((paper, "-", "paper (10 + 5 elements)"), (exact, "k--", "exact")):
    ax_r.plot(r.columns["t"], r.columns["R"], style, label=label)
    ax_u.plot(r.columns["t"], r.columns["ub_y"], style, label=label)
ax_r.set(xlabel="t (s)", ylabel="contact force R (N)", title="contact force")
ax_u.set(xlabel="t (s)", ylabel="u_y of the struck point (m)", title="struck point")
ax_r.legend()
fig.suptitle(f"S2: paper vs exact, impulse error {100 * result['impulse_rel_error']:.2f} %, "
             f"beamimpact {beamimpact.__version__}")
fig.tight_layout()
fig.savefig(out / "s2_against_exact.png", dpi=110)
(out / "s2_against_exact.json").write_text(json.dumps(result, indent=1))
