#!/usr/bin/env python3
"""A stand-in external method for the protocol tests (docs/protocol.md): it reads the scene, lets
every body fly freely (no contact force: R = 0) and writes history.csv and summary.json as the
protocol asks. It does not model friction and says so (exit 2). --break MODE makes it break one
rule on purpose: column (a wrong column name), summary-on-failure (summary.json on a refusal),
exit-code (exit 1 instead of 2 on a refusal)."""
import argparse
import hashlib
import json
import os
import sys
import tomllib


def refuse(args, why):
    """Exit 2 with one line saying why (the protocol's refusal), or break it as asked."""
    if args.break_ == "summary-on-failure":
        with open(os.path.join(args.out, "summary.json"), "w") as f:
            json.dump({"complete": False}, f)
    print(f"standin: {why}", file=sys.stderr)
    sys.exit(1 if args.break_ == "exit-code" else 2)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("--out", required=True)
    p.add_argument("--dt", type=float)
    p.add_argument("--break", dest="break_", default="")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    data = open(args.scene, "rb").read()
    try:
        scene = tomllib.loads(data.decode())
        bodies, contacts, end = scene["bodies"], scene["contacts"], float(scene["time"]["end"])
    except (tomllib.TOMLDecodeError, KeyError, ValueError, UnicodeDecodeError) as e:
        refuse(args, f"{args.scene}: not a valid scene: {e}")
    if any(float(c.get("friction", 0.0)) > 0.0 for c in contacts):
        refuse(args, f"{args.scene}: friction > 0: this method does not model friction")
    dt = args.dt or end / 200.0
    steps = int(round(end / dt))
    names = ["t"]
    for k in range(1, len(contacts) + 1):
        suffix = "" if k == 1 else f"_{k}"
        names += ["Force" if (args.break_ == "column" and k == 1) else "R" + suffix, "gap" + suffix]
    rows = [",".join(names)]
    for n in range(steps + 1):
        rows.append(",".join([f"{n * dt:.10g}"] + ["0,1"] * len(contacts)))
    with open(os.path.join(args.out, "history.csv"), "w") as f:
        f.write("\n".join(rows) + "\n")
    summary = {
        "method": "standin", "scene": scene.get("name", ""), "scene_sha256": hashlib.sha256(data).hexdigest(),
        "dt": dt, "steps": steps, "end_time": end, "wall_seconds": 0.0,
        "contacts": [{"striker": c["striker"], "target": c["target"], "impulse_normal": 0.0, "intervals": []}
                     for c in contacts],
        "bodies": {b["name"]: {"final_velocity": b.get("velocity", [0.0, 0.0])} for b in bodies},
        "units": {"t": "s", "R": "N", "tau": "N", "gap": "m", "u": "m", "v": "m/s", "energy": "J",
                  "momentum": "N s", "impulse": "N s"},
        "complete": True,
    }
    tmp = os.path.join(args.out, "summary.json.tmp")
    with open(tmp, "w") as f:
        json.dump(summary, f, indent=1)
    os.replace(tmp, os.path.join(args.out, "summary.json"))  # last and atomically
    return 0


if __name__ == "__main__":
    sys.exit(main())
