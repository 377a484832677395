#!/usr/bin/python3
"""Work-precision plots from bench/results/work_precision.csv, one panel per
scene, log-log, one line per method:
- the target PNG: orientation error against ns per body-step, for the
  fixed-step methods (ours solid, peer engines dashed) through their dt;
- the same name with "_per_simulated_second": error against CPU time per
  simulated second (ns per body-step / dt), which also places the adaptive
  peers (dotted, through their tolerances, 1 ms outputs) and the closed form
  evaluated on the 1 ms grid (a star). Each category has its own marker and
  legend group."""
import csv
import math
import sys
from collections import defaultdict

from matplotlib import colormaps
from matplotlib.figure import Figure

source = sys.argv[1] if len(sys.argv) > 1 else "bench/results/work_precision.csv"
target = sys.argv[2] if len(sys.argv) > 2 else "bench/results/work_precision.png"

rows = list(csv.DictReader(open(source)))
for r in rows:
    r["cpu_per_simulated_s"] = float(r["ns_per_body_step"]) * 1e-9 / float(r["dt_s"])
    r["stepping"] = r.get("stepping") or "fixed"
    # The order along a method's line: coarse to fine.
    r["coarseness"] = float(r["tolerance"]) if r["stepping"] == "adaptive" else float(r["dt_s"])
scenes = list(dict.fromkeys(r["scene"] for r in rows))

# Category: its legend title, line style and marker.
CATEGORIES = {
    "ours": ("ours (fixed step)", "-", "o"),
    "fixed": ("peers, fixed step", "--", "s"),
    "adaptive": ("peers, adaptive (1 ms outputs)", ":", "^"),
    "closed_form": ("closed form (1 ms outputs)", "none", "*"),
}


def category(r):
    return "ours" if r["engine"] == "rigid_body_sim" else r["stepping"]


# Colours distinct within each category (the line style and marker tell the
# categories apart): ten for ours, twenty for the peers.
colours = {}
for kind, palette, size in (("ours", "tab10", 10), ("fixed", "tab20", 20), ("adaptive", "Dark2", 8),
                            ("closed_form", "Set1", 9)):
    methods = list(dict.fromkeys(r["method"] for r in rows if category(r) == kind))
    colours.update({m: colormaps[palette](i % size) for i, m in enumerate(methods)})


def draw(x_key, x_label, title, path, kept):
    columns = 3
    lines = math.ceil(len(scenes) / columns)
    # A Figure of its own (no pyplot): saved through Agg, no display needed.
    figure = Figure(figsize=(6 * columns, 4.6 * lines + 1.2))
    axes = figure.subplots(lines, columns, squeeze=False)
    legend = {}  # category → {method: handle}
    for panel, scene in zip(axes.flat, scenes):
        series = defaultdict(list)
        for r in rows:
            if r["scene"] == scene and category(r) in kept:
                # Errors at round-off are drawn at the floor to stay on a log axis.
                series[(category(r), r["method"])].append(
                    (-r["coarseness"], float(r[x_key]), max(float(r["orientation_error_rad"]), FLOOR)))
        for (kind, method), points in sorted(series.items()):
            points.sort()
            _, style, marker = CATEGORIES[kind]
            (handle,) = panel.plot([p[1] for p in points], [p[2] for p in points], linestyle=style,
                                   marker=marker, markersize=9 if marker == "*" else 3, color=colours[method],
                                   linewidth=2.2 if method == "casimir_splitting4" else 1.0, label=method)
            legend.setdefault(kind, {})[method] = handle
        panel.set_xscale("log")
        panel.set_yscale("log")
        panel.set_title(scene)
        panel.set_xlabel(x_label)
        panel.set_ylabel("orientation error at T [rad]")
        panel.grid(True, which="major", alpha=0.3)
    for panel in axes.flat[len(scenes):]:
        panel.axis("off")
    groups = [kind for kind in CATEGORIES if kind in legend]
    for i, kind in enumerate(groups):
        handles = legend[kind]
        figure.legend(list(handles.values()), list(handles.keys()), title=CATEGORIES[kind][0],
                      loc="lower left", bbox_to_anchor=(0.02 + i * 0.96 / len(groups), 0.0),
                      ncol=2 if len(handles) > 5 else 1, fontsize=8, title_fontsize=9)
    figure.suptitle(title)
    figure.tight_layout(rect=(0, 0.2 * 2 / (lines + 1), 1, 0.96))
    figure.savefig(path, dpi=110)
    print("wrote", path)


FLOOR = 1e-16
draw("ns_per_body_step", "ns per body-step (median, 1000 bodies)",
     "Error against cost per step, fixed-step methods: each line one method over dt = 3e-1 ... 3e-5 s",
     target, {"ours", "fixed"})
draw("cpu_per_simulated_s", "CPU time per simulated second per body [s]",
     "Error against cost per simulated second (fixed steps: ns per body-step / dt; "
     "adaptive and closed form: ns per 1 ms output / 1 ms)",
     target.replace(".png", "_per_simulated_second.png"), set(CATEGORIES))
