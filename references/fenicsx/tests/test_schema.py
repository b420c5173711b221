"""The FEniCSx reference's history.csv follows the output schema that the C++ writer and reader
share (solver/schema/output_schema.hpp), as printed by `beamimpact schema`: the same columns in
the same order, and a `state` column whose values mean what the schema says. The script itself
shares nothing with the C++ code; this test is where the two are held to one contract.

Usage: test_schema.py [--work DIR]   (env BEAMIMPACT_BINARY_DIR: the build folder)"""

import json
import os
import subprocess

import numpy as np

import common

common.require_dolfinx()
work = common.work_dir()
exe = os.path.join(os.environ["BEAMIMPACT_BINARY_DIR"], "beamimpact")
schema = json.loads(subprocess.run([exe, "schema"], capture_output=True, text=True, check=True).stdout)

# S1 to 2.6 s: one contact, closed from 0.5 s to 2.5 s without friction.
out = os.path.join(work, "s1")
s, h = common.run("s1_central.toml", out, "--end", "2.6")
with open(os.path.join(out, "history.csv")) as f:
    header = f.readline().strip().split(",")
expected = [schema["time_column"], *schema["contact_columns"], *schema["model_columns"]]
common.check(header == expected, f"history.csv columns {header} == the schema's {expected}")
state = h["state"]
codes = {int(k): v for k, v in schema["state_values"].items()}
common.check(set(np.unique(state)) <= set(codes), f"state values {sorted(set(np.unique(state)))} are schema codes")
# Frictionless contact: closed rows (R > 0) are "closed", open rows are "open" (schema names).
closed = h["R"] > 0
common.check(closed.any() and all(codes[int(x)] == "closed" for x in state[closed]), "R > 0 rows have state closed")
common.check(all(codes[int(x)] == "open" for x in state[~closed]), "R = 0 rows have state open")
missing = [k for k in schema["summary_keys"] if k not in s]
common.check(not missing, f"summary.json has every schema key (missing: {missing})")
missing = [k for k in schema["contact_summary_keys"] if k not in s["contacts"][0]]
common.check(not missing, f"contacts[0] has every schema contact key (missing: {missing})")
common.check(s["contacts"][0]["kind"] in schema["contact_kinds"], f"kind {s['contacts'][0]['kind']} is a schema kind")
common.finish()
