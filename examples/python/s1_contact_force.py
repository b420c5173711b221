"""Pu & Chi (2011) Figure 6: the contact force of the central collision (S1), the paper's
integrator against the exact d'Alembert solution, in a few lines of the Python module.
Usage: PYTHONPATH=build/python /usr/bin/python3 examples/python/s1_contact_force.py [OUT.png]"""
import sys

import matplotlib.pyplot as plt

import beamimpact

scene = beamimpact.load_scene("verification/scenes/paper/s1_central.toml")
for method, style in (("paper", "-"), ("exact", "k--")):
    run = beamimpact.run(scene, method=method)
    plt.plot(run.columns["t"], run.columns["R"], style, label=method)
plt.xlabel("t (s)"), plt.ylabel("contact force R (N)"), plt.legend()
plt.title(f"S1 central collision (Pu & Chi 2011, Fig. 6), beamimpact {beamimpact.__version__}")
plt.savefig(sys.argv[1] if len(sys.argv) > 1 else "s1_contact_force.png", dpi=120)
