#!/usr/bin/env python3
"""Runs every reproducer of the defects listed in docs/defects.md against one or more `beamimpact`
executables and prints one Markdown row per reproducer: the command, and for each executable its
exit code and the measured quantity. Nothing is compared with a threshold: the table is the
evidence (docs/defects.md holds it for the version the defects were found on and for this one).

Usage: python3 tools/reproduce_defects.py EXE [EXE ...] [--work DIR] [--only TEXT]
Run from anywhere; scenes are the repository's. Takes about a minute per executable; a command
that does not end is stopped after its limit (the 1e10-point study after 20 s, and its memory is
capped at 4 GB) and reported as such. Commands shown use `beamimpact` for EXE and OUT for the
reproducer's output directory.
"""
import argparse
import csv
import json
import os
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
S1 = "verification/scenes/paper/s1_central.toml"
S4 = "verification/scenes/paper/s4_oblique_45.toml"


class Ran:
    """One finished command: exit code (128 + signal when killed), output, peak memory (MB)."""

    def __init__(self, code, out, peak_mb, timed_out):
        self.code, self.out, self.peak_mb, self.timed_out = code, out, peak_mb, timed_out
        self.shown = None  # an exit text other than the code's

    def exit_text(self):
        if self.shown:
            return self.shown
        if self.timed_out:
            return "stopped after its limit"
        if self.code > 128:
            return f"{self.code} ({signal.Signals(self.code - 128).name})"
        return str(self.code)

    def first_error(self):
        lines = [l for l in self.out.splitlines() if l.startswith(("error", "terminate", "what()", "warning"))]
        return lines[0][:110] if lines else ""


def run(exe, args, out=None, timeout=300, memory_gb=None):
    """Runs exe with args ({OUT} replaced by out) in the repository; waits with a time limit."""
    argv = [exe] + [a.replace("{OUT}", str(out)) for a in args]

    def limit():
        os.setsid()  # its own group: a stop takes its children too
        if memory_gb:
            b = int(memory_gb * 2**30)
            resource.setrlimit(resource.RLIMIT_AS, (b, b))

    with tempfile.TemporaryFile() as log:
        p = subprocess.Popen(argv, cwd=ROOT, stdout=log, stderr=subprocess.STDOUT, preexec_fn=limit)
        deadline, timed_out = time.monotonic() + timeout, False
        while True:
            pid, status, usage = os.wait4(p.pid, os.WNOHANG)
            if pid:
                break
            if time.monotonic() > deadline and not timed_out:
                os.killpg(p.pid, signal.SIGKILL)
                timed_out = True
            time.sleep(0.05)
        p.returncode = code = os.waitstatus_to_exitcode(status)
        log.seek(0)
        text = log.read().decode(errors="replace")
    return Ran(128 - code if code < 0 else code, text, usage.ru_maxrss / 1024.0, timed_out)


def history(out):
    with open(Path(out) / "history.csv") as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def summary(out):
    with open(Path(out) / "summary.json") as f:
        return json.load(f)


def ksd(out):
    """(K + S + D) / E0 at the end and at the lowest and highest row, and D's largest fall / E0."""
    e0 = summary(out)["energy_initial"]
    rows = history(out)
    e = [(r["kinetic"] + r["strain"] + r["dissipated"]) / e0 for r in rows]
    top, fall = -1e300, 0.0
    for r in rows:
        top = max(top, r["dissipated"])
        fall = max(fall, top - r["dissipated"])
    return e[-1], min(e), max(e), fall / e0


def exists(p):
    return "yes" if Path(p).exists() else "no"


# Each reproducer: (what, command shown, function(exe, out) -> (Ran, measured text)).
def slide_on_deflected(exe, out):
    r = run(exe, ["run", "verification/scenes/hard/slide_on_deflected.toml", "--out", "{OUT}", "--quiet",
                  "--set", "bodies.B.elements=500"], out)
    if r.code:
        return r, r.first_error()
    end, low, high, fall = ksd(out)
    w = summary(out).get("warnings", [])
    turn = summary(out)["contacts"][0].get("target_turn_max")
    turn_text = f", target_turn_max {turn:.3f} rad" if turn is not None else ""
    return r, (f"fall of D {fall:.4f} E0, (K+S+D) max {high:.4f} E0{turn_text}, "
               f"{'a warning' if w else 'no warning'}")


def energy_case(args):
    def measure(exe, out):
        r = run(exe, args + ["--out", "{OUT}", "--quiet"], out)
        if r.code:
            return r, r.first_error()
        end, low, high, fall = ksd(out)
        return r, f"K+S+D end {end:.4f} E0, lowest {low:.4f}, highest {high:.4f}; fall of D {fall:.2e} E0"
    return measure


def ida_grazing(exe, out):
    r, text = energy_case(["run", "verification/scenes/hard/grazing_slide.toml", "--method", "ida"])(exe, out)
    if r.code == 0:
        bad = sum(1 for row in history(out) if row["R"] > 0 and row["gap"] > 1e-9)
        text += f"; {bad} rows with R > 0 and gap > 1e-9 m"
    return r, text


def energy_initial(exe, out):
    r = run(exe, ["run", S1, "--out", "{OUT}", "--quiet", "--set", "bodies.B.start=[10.001, 0.0]",
                  "--set", "bodies.B.end=[20.001, 0.0]"], out)
    return r, (f"energy_initial {summary(out)['energy_initial']:.4f} J (true 2 J)" if r.code == 0 else r.first_error())


def dt_on_auto_scene(exe, out):
    r = run(exe, ["run", S4, "--out", "{OUT}", "--quiet", "--set", "time.dt=0.00005"], out)
    if r.code:
        return r, r.first_error()
    s = summary(out)
    return r, f"ran: dt {s['dt']:g} s, {s['steps']} steps"


def sweep_out(kind):
    def measure(exe, out):
        out.mkdir(parents=True, exist_ok=True)
        target = out / "a_file" if kind == "file" else read_only_dir(out)
        if kind == "file":
            target.write_text("not a directory\n")
        r = run(exe, ["sweep", S1, "--dt", "0.01", "--out", str(target)], out)
        return r, r.first_error()
    return measure


def read_only_dir(out):
    """A directory that cannot be written: mode 555, or (root ignores modes) one under /sys."""
    if os.geteuid() == 0:
        return Path("/sys/beamimpact_reproducer")
    d = out / "read_only"
    d.mkdir(exist_ok=True)
    d.chmod(0o555)
    return d


def huge_study(exe, out):
    out.mkdir(parents=True, exist_ok=True)
    grid = "".join(f'[[parameter]]\nname = "p{i}"\nkey = "contacts[0].friction"\n'
                   f"values = [0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9]\n" for i in range(10))
    study = out / "huge.toml"
    study.write_text(f'name = "huge"\nscene = "{ROOT / S4}"\nmethods = ["paper"]\n'
                     f'reference = {{ method = "ida" }}\n' + grid)
    r = run(exe, ["study", str(study), "--out", str(out / "o")], out, timeout=20, memory_gb=4)
    return r, f"peak memory {r.peak_mb:.0f} MB; {r.first_error()}"


def exit_code_case(args):
    def measure(exe, out):
        r = run(exe, args, out)
        return r, r.first_error() or r.out.strip().splitlines()[-1][:110]
    return measure


CASE = ('[[case]]\nscene = "s1"\nmethod = "paper"\nreference = {{ method = "exact" }}{extra}\n'
        'gates = [{{ metric = "impulse", tol = 0.04, why = "S1 at 10 elements: 4 % mesh error" }}]\n')


def matrix(out, settings="", extra=""):
    """A small matrix of its own (the shipped one may hold keys an older version does not know):
    S1, paper against exact, one impulse gate."""
    out.mkdir(parents=True, exist_ok=True)
    m = out / "m.toml"
    m.write_text(f'[settings]\nroot = "{ROOT}"\n{settings}[scenes]\ns1 = "{S1}"\n' + CASE.format(extra=extra))
    return str(m)


def verify_case(settings="", extra="", only=None):
    def measure(exe, out):
        r = run(exe, ["verify", matrix(out, settings, extra), "--out", str(out / "v")]
                + (["--only", only] if only else []), out)
        return r, r.first_error() or r.out.strip().splitlines()[-3][:110]
    return measure


def two_runs_one_out(exe, out):
    """A slow S2 (400 target elements, dt = 2e-5 s, rows every 2 ms), and 0.3 s later S2 as
    shipped (rows every 10 ms) into the same directory: whose files are left?"""
    args = ["run", "verification/scenes/paper/s2_transverse.toml", "--out", str(out), "--quiet"]
    slow = ["--set", "bodies.B.elements=400", "--set", "time.dt=0.00002", "--set", "time.output_every=100"]
    first = subprocess.Popen([exe] + args + slow, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(0.3)
    r = run(exe, args, out)
    r.shown = f"{first.wait()} / {r.exit_text()}"  # both runs' exit codes
    dt = summary(out)["dt"] if (out / "summary.json").exists() else None
    rows = history(out) if (out / "history.csv").exists() else []
    spacing = f"{rows[1]['t'] - rows[0]['t']:.4g} s" if len(rows) > 1 else "none"
    return r, (f"summary.json dt {dt} s, history.csv rows every {spacing}; second: "
               f"{r.first_error() or 'accepted, wrote into the same directory'}")


def refused_rerun(exe, out):
    run(exe, ["run", S1, "--out", "{OUT}", "--quiet"], out)
    r = run(exe, ["run", S1, "--out", "{OUT}", "--quiet", "--set", "time.end=-1"], out)
    return r, f"the earlier summary.json left: {exists(out / 'summary.json')}"


def refused_verify(exe, out):
    run(exe, ["verify", matrix(out), "--out", str(out / "v")], out)
    before = exists(out / "v" / "report.md")
    r = run(exe, ["verify", matrix(out, extra="\nbroken = ["), "--out", str(out / "v")], out)
    return r, f"report.md of the earlier verify (made: {before}) left: {exists(out / 'v' / 'report.md')}"


def compare_json_dir(exe, out):
    run(exe, ["run", S1, "--out", str(out / "a"), "--quiet"], out)
    (out / "j").mkdir(parents=True, exist_ok=True)
    r = run(exe, ["compare", str(out / "a"), str(out / "a"), "--json", str(out / "j")], out)
    partial = [p.name for p in out.iterdir() if p.name.endswith(".partial")]
    return r, f".partial files left: {partial or 'none'}; compare.json in DIR: {exists(out / 'j' / 'compare.json')}"


def sweep_refused_row(exe, out):
    r = run(exe, ["sweep", S1, "--dt", "0.01,1", "--reference", "exact", "--out", "{OUT}"], out)
    rows = list(csv.DictReader(open(out / "sweep.csv"))) if (out / "sweep.csv").exists() else []
    status = [row.get("status", "?") for row in rows]
    return r, f"sweep.csv status column: {status}"


def fields_size(exe, out):
    """S1 with fields to 4e4 s: 4e6 files of 4.6 kB; stopped after 10 s, the bytes written so far."""
    r = run(exe, ["run", S1, "--out", "{OUT}", "--quiet", "--fields", "--set", "time.end=4e4"], out, timeout=10)
    size = sum(f.stat().st_size for f in out.rglob("*") if f.is_file()) if out.exists() else 0
    return r, f"{size / 1e6:.0f} MB written in {'10 s, still writing' if r.timed_out else 'all'}; {r.first_error()}"


REPRODUCERS = [
    ("energy: block sliding on a deflected soft beam (500 elements)",
     "run hard/slide_on_deflected.toml --set bodies.B.elements=500", slide_on_deflected),
    ("energy: s2_damped with stiffness damping",
     "run extra/s2_damped.toml --set model.rayleigh_mass=0 --set model.rayleigh_stiffness=0.1",
     energy_case(["run", "verification/scenes/extra/s2_damped.toml", "--set", "model.rayleigh_mass=0",
                  "--set", "model.rayleigh_stiffness=0.1"])),
    ("energy and gap: IDA on a sliding contact", "run hard/grazing_slide.toml --method ida", ida_grazing),
    ("energy_initial: contact closing in the first step",
     'run paper/s1_central.toml --set "bodies.B.start=[10.001, 0.0]" --set "bodies.B.end=[20.001, 0.0]"',
     energy_initial),
    ("--set time.dt on a dt = \"auto\" scene", "run paper/s4_oblique_45.toml --set time.dt=0.00005",
     dt_on_auto_scene),
    ("sweep --out FILE", "sweep paper/s1_central.toml --dt 0.01 --out A_FILE", sweep_out("file")),
    ("sweep --out a read-only directory", "sweep paper/s1_central.toml --dt 0.01 --out READ_ONLY_DIR",
     sweep_out("read-only")),
    ("study of 1e10 points (10 parameters x 10 values)", "study HUGE.toml --out OUT (20 s, 4 GB cap)",
     huge_study),
    ("exit code: sweep --fraction 2", "sweep paper/s4_oblique_45.toml --fraction 2 --out OUT",
     exit_code_case(["sweep", S4, "--fraction", "2", "--out", "{OUT}"])),
    ("exit code: verify --only NOMATCH", "verify M.toml --only NOMATCH --out OUT", verify_case(only="NOMATCH")),
    ("exit code: sweep dt above the critical step", "sweep paper/s1_central.toml --dt 1 --out OUT",
     exit_code_case(["sweep", S1, "--dt", "1", "--out", "{OUT}"])),
    ("exit code: ida.rtol = 1e-30", "run paper/s1_central.toml --method ida --set ida.rtol=1e-30",
     exit_code_case(["run", S1, "--method", "ida", "--set", "ida.rtol=1e-30", "--out", "{OUT}", "--quiet"])),
    ("exit code: matrix timeout = -5", "verify M.toml ([settings] timeout = -5)",
     verify_case(settings="timeout = -5\n")),
    ("exit code: matrix case mesh = 0", "verify M.toml ([[case]] mesh = 0)", verify_case(extra="\nmesh = 0")),
    ("outputs: two runs into one --out",
     "run paper/s2_transverse.toml --out OUT with a slow mesh and step, and 0.3 s later as shipped",
     two_runs_one_out),
    ("outputs: a refused re-run", "run paper/s1_central.toml --out OUT, then again with --set time.end=-1",
     refused_rerun),
    ("outputs: a refused verify", "verify M.toml --out OUT, then a matrix with a TOML error --out OUT",
     refused_verify),
    ("outputs: compare --json DIR", "compare A A --json DIR", compare_json_dir),
    ("outputs: sweep table for a refused run", "sweep paper/s1_central.toml --dt 0.01,1 --reference exact",
     sweep_refused_row),
    ("outputs: field files' size", "run paper/s1_central.toml --fields --set time.end=4e4 (10 s limit)",
     fields_size),
]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("exe", nargs="+", help="beamimpact executables (each gets its own columns)")
    ap.add_argument("--work", help="scratch directory (default: a temporary one, removed after)")
    ap.add_argument("--only", default="", help="only reproducers whose description contains this text")
    a = ap.parse_args()
    work = Path(a.work or tempfile.mkdtemp(prefix="beamimpact_defects_"))
    exes = [str(Path(e).resolve()) for e in a.exe]
    versions = [subprocess.run([e, "--version"], capture_output=True, text=True).stdout.strip() for e in exes]
    head = "| reproducer | command |" + "".join(f" exit ({v}) | measured ({v}) |" for v in versions)
    print(head)
    print("|" + "---|" * (2 + 2 * len(exes)))
    for i, (what, shown, measure) in enumerate(REPRODUCERS):
        if a.only not in what:
            continue
        cells = []
        for k, exe in enumerate(exes):
            out = work / f"{k}_{i}"
            shutil.rmtree(out, ignore_errors=True)
            try:
                r, text = measure(exe, out)
                code = r.exit_text()
            except Exception as e:  # an output missing where the reproducer reads it
                code, text = "?", f"not measured: {type(e).__name__}: {e}"[:110]
            cells += [code, text.replace("|", "\\|")]
        print(f"| {what} | `beamimpact {shown}` | " + " | ".join(cells) + " |", flush=True)
    if not a.work:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
