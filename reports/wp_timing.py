"""@brief Timing for the work-precision sets: repeated in-process calls (CPU from time.process_time,
wall from time.perf_counter, the 1-minute load average before each) and child processes (CPU of the
child and its waited-for children from os.wait4), each kept as every repetition plus min and max.

In-process: at least MIN_REPEATS calls and until MIN_SECONDS of wall time have passed (at most
MAX_REPEATS). Processes: a fixed number of repetitions (a process costs its start-up each time).
"""
import os
import subprocess
import time

MIN_REPEATS = 3  # timings per point at least, whatever their length
MIN_SECONDS = 0.2  # s of wall time per point at least, so a 1 ms run is timed ~200 times
MAX_REPEATS = 200  # bounds a point of microseconds


def summary(cpus, walls, loads):
    """The kept record of one timed point: every repetition and min / max (s), load averages."""
    return {"repeats": len(cpus), "cpu_seconds_min": min(cpus), "cpu_seconds_max": max(cpus),
            "wall_seconds_min": min(walls), "wall_seconds_max": max(walls), "cpu_seconds_all": cpus,
            "wall_seconds_all": walls, "loadavg_1min": [min(loads), max(loads)]}


def time_in_process(call, min_repeats=MIN_REPEATS, min_seconds=MIN_SECONDS, max_repeats=MAX_REPEATS):
    """Calls `call()` repeatedly; returns (timing summary, the last call's result)."""
    cpus, walls, loads, result = [], [], [], None
    t_start = time.perf_counter()
    while len(cpus) < min_repeats or (time.perf_counter() - t_start < min_seconds and len(cpus) < max_repeats):
        loads.append(os.getloadavg()[0])
        c0, w0 = time.process_time(), time.perf_counter()
        result = call()
        cpus.append(time.process_time() - c0)
        walls.append(time.perf_counter() - w0)
    return summary(cpus, walls, loads), result


def run_process(cmd):
    """One child process: (exit code, CPU s of the child and its waited-for children, wall s, stderr tail)."""
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = p.stderr.read().decode(errors="replace")
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    return os.waitstatus_to_exitcode(status), ru.ru_utime + ru.ru_stime, wall, err.strip()[-400:]


def time_process(cmd, repeats):
    """`cmd` run `repeats` times one after another: (timing summary or None, failure note)."""
    cpus, walls, loads = [], [], []
    for _ in range(repeats):
        loads.append(os.getloadavg()[0])
        code, cpu, wall, err = run_process(cmd)
        if code != 0:
            return None, f"exit {code}: {err}"
        cpus.append(cpu)
        walls.append(wall)
    return summary(cpus, walls, loads), ""
