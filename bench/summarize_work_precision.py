#!/usr/bin/python3
"""Tables for the README from bench/results/work_precision.csv:
1. every method on the headline scene at dt = 1 ms (error, ns per body-step);
2. per scene, the CPU time per simulated second each method needs for an
   orientation error of 1e-6 rad (log-log interpolation between the dt
   points), ours against the best peer (a lower bound where no peer gets
   there at the dt tried);
3. dominance: how many peer points have one of our points that is both more
   accurate and faster;
4. per scene, each of our integrators: the CPU time per simulated second for
   1e-6 and 1e-10 rad (the cheapest marked) and its error floor, the smallest
   error over the dt tried.
Writes Markdown to stdout."""
import csv
import math
import sys
from collections import defaultdict

source = sys.argv[1] if len(sys.argv) > 1 else "bench/results/work_precision.csv"
rows = list(csv.DictReader(open(source)))
TARGET = 1e-6


def number(text):
    try:
        value = float(text)
    except ValueError:
        return math.nan
    return value


for r in rows:
    r["err"] = number(r["orientation_error_rad"])
    r["ns"] = number(r["ns_per_body_step"])
    r["dt"] = number(r["dt_s"])
    # CPU time per simulated second per body [s]: ns per step / dt.
    r["cpu"] = r["ns"] * 1e-9 / r["dt"]

print("### Headline scene (Dzhanibekov near the separatrix, T = 20 s) at dt = 1 ms\n")
print("| engine | method | orientation error [rad] | ns per body-step |")
print("|---|---|---|---|")
for r in sorted((r for r in rows if r["scene"] == "dzhanibekov_headline" and abs(r["dt"] - 1e-3) < 1e-12),
                key=lambda r: (r["engine"] != "rigid_body_sim", r["err"] if not math.isnan(r["err"]) else 1e9)):
    print("| %s | %s | %.2e | %.0f |" % (r["engine"], r["method"], r["err"], r["ns"]))


def cpu_at(points, target):
    """CPU per simulated second at `target` error, interpolated in log-log
    between the two dt points that bracket it; None when no point reaches it."""
    points = sorted((p for p in points if not math.isnan(p["err"]) and p["err"] > 0), key=lambda p: p["dt"])
    best = None
    for a, b in zip(points, points[1:]):
        lo, hi = sorted((a, b), key=lambda p: p["err"])
        if lo["err"] <= target <= hi["err"]:
            t = (math.log(target) - math.log(lo["err"])) / (math.log(hi["err"]) - math.log(lo["err"]))
            cpu = math.exp(math.log(lo["cpu"]) + t * (math.log(hi["cpu"]) - math.log(lo["cpu"])))
            best = cpu if best is None else min(best, cpu)
    for p in points:  # a point already below the target at its own cost
        if p["err"] <= target:
            best = p["cpu"] if best is None else min(best, p["cpu"])
    return best


print("\n### CPU time per simulated second for an orientation error of 1e-6 rad\n")
print("| scene | best of ours | its CPU [µs/s] | best peer | its CPU [µs/s] | ratio |")
print("|---|---|---|---|---|---|")
scenes = list(dict.fromkeys(r["scene"] for r in rows))
for scene in scenes:
    series = defaultdict(list)
    for r in rows:
        if r["scene"] == scene:
            series[(r["engine"], r["method"])].append(r)
    ours = [(cpu_at(p, TARGET), m) for (e, m), p in series.items() if e == "rigid_body_sim"]
    peers = [(cpu_at(p, TARGET), m) for (e, m), p in series.items() if e != "rigid_body_sim"]
    ours = sorted((c, m) for c, m in ours if c is not None)
    peers = sorted((c, m) for c, m in peers if c is not None)
    if not ours:
        continue
    if peers:
        print("| %s | %s | %.3g | %s | %.3g | %.0f× |" % (scene, ours[0][1], ours[0][0] * 1e6, peers[0][1],
                                                        peers[0][0] * 1e6, peers[0][0] / ours[0][0]))
    else:
        # No peer gets to 1e-6 at the dt tried: it would need a smaller dt, so
        # more CPU than at its smallest dt (error falling with dt). The
        # cheapest peer there bounds the best peer's CPU from below.
        smallest_dt = min(r["dt"] for r in rows if r["scene"] == scene)
        bound = min((r for r in rows if r["scene"] == scene and r["engine"] != "rigid_body_sim"
                     and r["dt"] == smallest_dt), key=lambda r: r["cpu"], default=None)
        if bound is None:
            print("| %s | %s | %.3g | none | – | – |" % (scene, ours[0][1], ours[0][0] * 1e6))
        else:
            print("| %s | %s | %.3g | none reaches 1e-6; at dt = %g the cheapest, %s, has %.1e rad at | > %.3g | > %.0f× |"
                  % (scene, ours[0][1], ours[0][0] * 1e6, smallest_dt, bound["method"], bound["err"],
                     bound["cpu"] * 1e6, bound["cpu"] / ours[0][0]))

print("\n### Dominance: peer points beaten on both error and time by one of ours\n")
print("| scene | peer points | dominated | not dominated |")
print("|---|---|---|---|")
for scene in scenes:
    ours = [r for r in rows if r["scene"] == scene and r["engine"] == "rigid_body_sim" and not math.isnan(r["err"])]
    peers = [r for r in rows if r["scene"] == scene and r["engine"] != "rigid_body_sim"]
    beaten, left = 0, []
    for p in peers:
        if any(o["err"] < p["err"] and o["ns"] < p["ns"] for o in ours) or math.isnan(p["err"]):
            beaten += 1
        else:
            left.append("%s@%g" % (p["method"], p["dt"]))
    print("| %s | %d | %d | %s |" % (scene, len(peers), beaten, ", ".join(left) or "–"))

print("\n### Our integrators: CPU time per simulated second [µs/s] for 1e-6 and 1e-10 rad\n")
print("Bold: the cheapest of ours at that accuracy on that scene; \"–\": not reached at the dt tried. "
      "The floor is the smallest error over the dt tried (round-off and, on the forced scene, the "
      "reference's own error).\n")
methods = list(dict.fromkeys(r["method"] for r in rows if r["engine"] == "rigid_body_sim"))
print("| scene | " + " | ".join("`%s`" % m for m in methods) + " |")
print("|---|" + "---|" * len(methods))
for scene in scenes:
    series = {m: [r for r in rows if r["scene"] == scene and r["engine"] == "rigid_body_sim" and r["method"] == m]
              for m in methods}
    cells = {m: [] for m in methods}
    for target in (1e-6, 1e-10):
        cpu = {m: cpu_at(p, target) for m, p in series.items() if p}
        reached = [c for c in cpu.values() if c is not None]
        best = min(reached) if reached else None
        for m in methods:
            c = cpu.get(m)
            text = "–" if c is None else "%.3g" % (c * 1e6)
            cells[m].append("**%s**" % text if c is not None and c == best else text)
    for m in methods:
        errors = [p["err"] for p in series[m] if not math.isnan(p["err"])]
        cells[m].append("%.0e" % min(errors) if errors else "–")
    print("| %s | " % scene + " | ".join("%s / %s / %s" % tuple(cells[m]) for m in methods) + " |")
print("\n(each cell: 1e-6 rad / 1e-10 rad / floor)")
