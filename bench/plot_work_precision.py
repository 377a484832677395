#!/usr/bin/python3
"""Work-precision plots from bench/results/work_precision.csv, one panel per
scene, one line per method through its dt points (ours solid, physics engines
dashed), log-log: orientation error against ns per body-step (target PNG),
and against CPU time per simulated second, ns per body-step / dt (the same
name with "_per_simulated_second")."""
import csv
import math
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

source = sys.argv[1] if len(sys.argv) > 1 else "bench/results/work_precision.csv"
target = sys.argv[2] if len(sys.argv) > 2 else "bench/results/work_precision.png"

rows = list(csv.DictReader(open(source)))
for r in rows:
    r["cpu_per_simulated_s"] = float(r["ns_per_body_step"]) * 1e-9 / float(r["dt_s"])
scenes = list(dict.fromkeys(r["scene"] for r in rows))


def draw(x_key, x_label, title, path):
    columns = 3
    lines = math.ceil(len(scenes) / columns)
    figure, axes = plt.subplots(lines, columns, figsize=(6 * columns, 4.6 * lines), squeeze=False)
    for panel, scene in zip(axes.flat, scenes):
        series = defaultdict(list)
        for r in rows:
            if r["scene"] == scene:
                # Errors at round-off are drawn at the floor to stay on a log axis.
                series[(r["engine"], r["method"])].append(
                    (float(r["dt_s"]), float(r[x_key]), max(float(r["orientation_error_rad"]), FLOOR)))
        for (engine, method), points in sorted(series.items()):
            points.sort()
            ours = engine == "rigid_body_sim"
            panel.plot([p[1] for p in points], [p[2] for p in points],
                       linestyle="-" if ours else "--", marker="o" if ours else "s", markersize=3,
                       linewidth=2.2 if method == "casimir_splitting4" else 1.0, label=method)
        panel.set_xscale("log")
        panel.set_yscale("log")
        panel.set_title(scene)
        panel.set_xlabel(x_label)
        panel.set_ylabel("orientation error at T [rad]")
        panel.grid(True, which="major", alpha=0.3)
    for panel in axes.flat[len(scenes):]:
        panel.axis("off")
    handles, labels = axes.flat[0].get_legend_handles_labels()
    figure.legend(handles, labels, loc="lower center", ncol=min(9, len(labels)), fontsize=8)
    figure.suptitle(title)
    figure.tight_layout(rect=(0, 0.06, 1, 0.96))
    figure.savefig(path, dpi=110)
    print("wrote", path)


FLOOR = 1e-16
draw("ns_per_body_step", "ns per body-step (median, 1000 bodies)",
     "Error against cost per step: each line one method over dt = 1e-2 ... 3e-5 s", target)
draw("cpu_per_simulated_s", "CPU time per simulated second per body [s]",
     "Error against cost per simulated second (ns per body-step / dt)",
     target.replace(".png", "_per_simulated_second.png"))
