#!/usr/bin/python3
"""Tables for the README from bench/results/work_precision.csv:
1. every method on the headline scene at dt = 1 ms (error, ns per body-step;
   per 1 ms output for the adaptive peers and the closed form);
2. per scene and for 1e-6 and 1e-10 rad, the CPU time per simulated second
   each method needs for that orientation error (log-log interpolation
   between its points: dt for fixed steps, tolerance for adaptive solvers),
   the best of ours against the best peer (a lower bound where no peer gets
   there at the dt tried); the closed form evaluated on the 1 ms grid is
   listed beside them, not as a peer: its error is round-off;
3. dominance: how many peer points (fixed-step and adaptive) have one of our
   points that is both more accurate and cheaper per simulated second
   (errors below ROUND_OFF tie), and for those that have none, the cheapest
   of ours at their error;
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
TARGETS = (1e-6, 1e-10)


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
    r["stepping"] = r.get("stepping") or "fixed"
    r["tolerance"] = r.get("tolerance") or ""
    # The order along a method's line: coarse to fine.
    r["coarseness"] = number(r["tolerance"]) if r["stepping"] == "adaptive" else r["dt"]
    # CPU time per simulated second per body [s]: ns per step / dt.
    r["cpu"] = r["ns"] * 1e-9 / r["dt"]

print("### Headline scene (Dzhanibekov near the separatrix, T = 20 s) at dt = 1 ms\n")
print("| engine | method | tolerance | orientation error [rad] | ns per body-step or output |")
print("|---|---|---|---|---|")
for r in sorted((r for r in rows if r["scene"] == "dzhanibekov_headline" and abs(r["dt"] - 1e-3) < 1e-12),
                key=lambda r: (r["engine"] != "rigid_body_sim", r["stepping"] != "fixed",
                               r["err"] if not math.isnan(r["err"]) else 1e9)):
    print("| %s | %s | %s | %.2e | %.0f |" % (r["engine"], r["method"], r["tolerance"] or "–", r["err"], r["ns"]))


def cpu_at(points, target):
    """CPU per simulated second at `target` error, interpolated in log-log
    between two neighbouring points (in dt or tolerance) that bracket it;
    None when no point reaches it."""
    points = sorted((p for p in points if not math.isnan(p["err"]) and p["err"] > 0),
                    key=lambda p: p["coarseness"])
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


def is_peer(r):
    return r["engine"] != "rigid_body_sim" and r["stepping"] != "closed_form"


scenes = list(dict.fromkeys(r["scene"] for r in rows))
for target in TARGETS:
    print("\n### CPU time per simulated second for an orientation error of %g rad\n" % target)
    print("| scene | best of ours | its CPU [µs/s] | best peer | its CPU [µs/s] | ratio | closed form, 1 ms grid [µs/s] |")
    print("|---|---|---|---|---|---|---|")
    notes = []
    for scene in scenes:
        series = defaultdict(list)
        for r in rows:
            if r["scene"] == scene:
                series[(r["engine"], r["method"])].append(r)
        ours = sorted((c, m) for c, m in ((cpu_at(p, target), m) for (e, m), p in series.items()
                                          if e == "rigid_body_sim") if c is not None)
        peers = sorted((c, m) for c, m in ((cpu_at(p, target), m) for (e, m), p in series.items()
                                           if is_peer(p[0])) if c is not None)
        closed = [p[0] for p in series.values() if p[0]["stepping"] == "closed_form"]
        closed_text = "%.3g" % (closed[0]["cpu"] * 1e6) if closed else "–"
        if not ours:
            print("| %s | none reaches %g | – | %s | %s | – | %s |" % (
                scene, target, peers[0][1] if peers else "none", "%.3g" % (peers[0][0] * 1e6) if peers else "–",
                closed_text))
            continue
        if peers:
            print("| %s | %s | %.3g | %s | %.3g | %.3g× | %s |" % (scene, ours[0][1], ours[0][0] * 1e6, peers[0][1],
                                                              peers[0][0] * 1e6, peers[0][0] / ours[0][0], closed_text))
            continue
        # No peer gets there at the dt tried: it would need a smaller dt, so
        # more CPU than at its smallest dt (error falling with dt). The
        # cheapest fixed-step peer there bounds the best peer's CPU from below.
        smallest_dt = min(r["dt"] for r in rows if r["scene"] == scene)
        bound = min((r for r in rows if r["scene"] == scene and is_peer(r) and r["stepping"] == "fixed"
                     and r["dt"] == smallest_dt), key=lambda r: r["cpu"], default=None)
        if bound is None:
            print("| %s | %s | %.3g | none | – | – | %s |" % (scene, ours[0][1], ours[0][0] * 1e6, closed_text))
        else:
            print("| %s | %s | %.3g | none reaches %g (*) | > %.3g | > %.3g× | %s |"
                  % (scene, ours[0][1], ours[0][0] * 1e6, target, bound["cpu"] * 1e6, bound["cpu"] / ours[0][0],
                     closed_text))
            notes.append("(*) %s: no peer reaches %g rad at any dt or tolerance tried; at dt = %g s the cheapest "
                         "fixed-step peer, %s, has %.1e rad at %.3g µs/s, which bounds the peers' CPU from below."
                         % (scene, target, smallest_dt, bound["method"], bound["err"], bound["cpu"] * 1e6))
    if notes:
        print("\n" + "\n".join(notes))

# A peer point this far off has no accuracy to compare: it is counted, not listed.
WRONG = 1e-2
# Errors below this are round-off (of the method and of the reference, whose
# own error reaches 3e-13 rad on the forced scene): two of them tie.
ROUND_OFF = 1e-12
print("\n### Dominance: peer points beaten on both error and CPU per simulated second by one of ours\n")
print("Not dominated: the peer point (method, dt or tolerance, its error and CPU), then the cheapest of ours "
      "at least as accurate (or, where none is, our most accurate point) and its CPU as a multiple of the "
      "peer's. Points with errors of %g rad or more are only counted.\n" % WRONG)
print("| scene | peer points (fixed / adaptive) | dominated | not dominated |")
print("|---|---|---|---|")
for scene in scenes:
    ours = [r for r in rows if r["scene"] == scene and r["engine"] == "rigid_body_sim" and not math.isnan(r["err"])]
    peers = [r for r in rows if r["scene"] == scene and is_peer(r)]
    beaten, left, wrong = 0, [], []
    for p in peers:
        if math.isnan(p["err"]) or any(o["err"] < max(p["err"], ROUND_OFF) and o["cpu"] < p["cpu"] for o in ours):
            beaten += 1
            continue
        if p["err"] >= WRONG:
            wrong.append(p)
            continue
        setting = "tol %s" % p["tolerance"] if p["stepping"] == "adaptive" else "dt %g" % p["dt"]
        match = min((o for o in ours if o["err"] <= max(p["err"], ROUND_OFF)), key=lambda o: o["cpu"], default=None)
        if match is None:  # the peer is below every error of ours: name our most accurate point
            match = min(ours, key=lambda o: (o["err"], o["cpu"]))
        against = "%s@%g %.1e rad, %.3g µs/s, %.2g×" % (match["method"], match["dt"], match["err"],
                                                        match["cpu"] * 1e6, match["cpu"] / p["cpu"])
        left.append("%s %s (%.1e rad, %.3g µs/s): %s" % (p["method"], setting, p["err"], p["cpu"] * 1e6, against))
    if wrong:
        # Cheaper than any step of ours, with no accuracy to speak of: counted, not listed.
        cheapest = min(o["cpu"] for o in ours)
        left.append("%d points with errors of %.1g to %.1g rad, at down to %.2g× our cheapest step's CPU"
                    % (len(wrong), min(p["err"] for p in wrong), max(p["err"] for p in wrong),
                       min(p["cpu"] for p in wrong) / cheapest))
    fixed = sum(1 for p in peers if p["stepping"] == "fixed")
    print("| %s | %d (%d / %d) | %d | %s |" % (scene, len(peers), fixed, len(peers) - fixed, beaten,
                                              "; ".join(left) or "–"))

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
