"""@brief Where the method breaks down over a parameter study, in one sentence: from a study's table
(reports/figures/study_*.csv, written with the maps by reports/study_maps.py from `beamimpact
study`), how many cases broke (status not ok, or a `breaks` rule such as the contact-interval count
differing from the reference's) and the range of the first parameter that concentrates them."""
import csv


def excess_range(xs, broke, total):
    """@brief The contiguous range of x values holding the largest excess of breakdowns over the
    study-wide rate (the maximum-sum run of broke(x) - rate * cases(x)): (lo, hi, broke, cases).
    @param xs sorted x values; @param broke, total per x value."""
    rate = sum(broke) / max(sum(total), 1)
    best, start, acc = (0.0, 0, -1), 0, 0.0
    for i, (b, n) in enumerate(zip(broke, total)):
        if acc <= 0.0:
            start, acc = i, 0.0
        acc += b - rate * n
        if acc > best[0]:
            best = (acc, start, i)
    _, i, j = best
    if j < 0:
        return None
    return xs[i], xs[j], sum(broke[i:j + 1]), sum(total[i:j + 1])


def summarize(csv_path, x, y):
    """@brief The study's breakdown summary: cases, broke, diverged (status not ok), the worst
    impulse error, and the x range concentrating the breakdowns with its rate inside and outside.
    @param x, y the study's two mapped parameters (columns of the CSV)."""
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or x not in rows[0] or "broke" not in rows[0]:
        raise ValueError(f"{csv_path}: expected a study table with columns '{x}' and 'broke'")
    xs = sorted({float(r[x]) for r in rows})
    broke = [sum(r["broke"] == "yes" for r in rows if float(r[x]) == v) for v in xs]
    total = [sum(float(r[x]) == v for r in rows) for v in xs]
    rng = excess_range(xs, broke, total)
    imp = [float(r["impulse"]) for r in rows if r.get("impulse") not in (None, "", "nan")]
    differs = sum(r["broke"] == "yes" and r["status"] == "ok" and float(r.get("impacts") or 0) > 0.5 for r in rows)
    out = {"cases": len(rows), "broke": sum(broke), "not_ok": sum(r["status"] != "ok" for r in rows),
           "count_differs": differs,
           "x": x, "y": y, "x_min": xs[0], "x_max": xs[-1],
           "y_min": min(float(r[y]) for r in rows), "y_max": max(float(r[y]) for r in rows),
           "worst_impulse": max(imp) if imp else None}
    if rng:
        lo, hi, b_in, n_in = rng
        out.update({"lo": lo, "hi": hi, "rate_in": b_in / n_in,
                    "rate_out": (out["broke"] - b_in) / max(len(rows) - n_in, 1), "broke_in": b_in})
    return out
