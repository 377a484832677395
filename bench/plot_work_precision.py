#!/usr/bin/python3
"""Work-precision plots from bench/results/work_precision.csv: orientation
error against ns per body-step, log-log, one line per method (ours solid,
physics engines dashed), one panel per scene, one PNG for all."""
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
scenes = list(dict.fromkeys(r["scene"] for r in rows))
columns = 3
lines = math.ceil(len(scenes) / columns)
figure, axes = plt.subplots(lines, columns, figsize=(6 * columns, 4.6 * lines), squeeze=False)
# Errors at round-off are drawn at this floor so they stay on a log axis.
floor = 1e-16
for panel, scene in zip(axes.flat, scenes):
    series = defaultdict(list)
    for r in rows:
        if r["scene"] == scene:
            series[(r["engine"], r["method"])].append(
                (float(r["ns_per_body_step"]), max(float(r["orientation_error_rad"]), floor), r["dt_s"]))
    for (engine, method), points in sorted(series.items()):
        points.sort()
        ours = engine == "rigid_body_sim"
        panel.plot([p[0] for p in points], [p[1] for p in points],
                   linestyle="-" if ours else "--", marker="o" if ours else "s", markersize=3,
                   linewidth=2.0 if method == "casimir_splitting4" else 1.0, label=method)
    panel.set_xscale("log")
    panel.set_yscale("log")
    panel.set_title(scene)
    panel.set_xlabel("ns per body-step (median, 1000 bodies)")
    panel.set_ylabel("orientation error at T [rad]")
    panel.grid(True, which="major", alpha=0.3)
for panel in axes.flat[len(scenes):]:
    panel.axis("off")
handles, labels = axes.flat[0].get_legend_handles_labels()
figure.legend(handles, labels, loc="lower center", ncol=min(8, len(labels)), fontsize=8)
figure.suptitle("rigid_body_sim work-precision: each line one method over dt = 1e-2 ... 3e-5 s "
                "(points further left are larger dt)")
figure.tight_layout(rect=(0, 0.05, 1, 0.96))
figure.savefig(target, dpi=110)
print("wrote", target)
