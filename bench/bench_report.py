"""Report helpers the bench scripts share: numbers and Markdown tables, the commit and CPU a
report names, and a report's header and writing."""

import math
import os
import subprocess

from node_harness import REPO


def fmt(value, digits=1):
    """A table cell: floats to `digits` decimals, NaN as n/a, None as empty."""
    if value is None or value == "":
        return ""
    if isinstance(value, float):
        if math.isnan(value):
            return "n/a"
        return "%.*f" % (digits, value)
    return str(value)


def md_table(header, rows):
    """A Markdown table; cells that are not strings go through fmt."""
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    lines += ["| " + " | ".join(fmt(c) if not isinstance(c, str) else c for c in r) + " |" for r in rows]
    return "\n".join(lines)


def git_head():
    """The checkout's short commit hash, or "unknown"."""
    try:
        head = subprocess.run(["git", "-C", REPO, "rev-parse", "--short", "HEAD"], capture_output=True,
                              text=True).stdout.strip()
    except OSError:
        return "unknown"
    return head or "unknown"


def has_uncommitted_changes():
    """Whether a tracked file of the checkout differs from the commit."""
    try:
        return bool(subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no"],
                                   capture_output=True, text=True).stdout.strip())
    except OSError:
        return False


def commit_described():
    """The checkout's short commit hash, marked when a tracked file differs from the commit."""
    return git_head() + (" (with uncommitted changes)" if has_uncommitted_changes() else "")


def cpu_model():
    """The CPU's model name from /proc/cpuinfo, or "unknown CPU"."""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def report_header(title, script, bench_cpu, pinned=""):
    """A report's first lines: its title and the script (bench/<script>), then the commit, the CPU and
    its cores, what `pinned` says runs pinned where ("<what> pinned to core N, "), the core of the
    script and the master, and the load average (1 min) at the end of the run."""
    return ["# %s (`bench/%s`)" % (title, script), "",
            "Commit %s, %s, %d cores; %sthis script and the master on core %d. Load average (1 min) at the "
            "end: %.2f." % (commit_described(), cpu_model(), os.cpu_count(), pinned, bench_cpu,
                            os.getloadavg()[0]), ""]


def write_report(out_dir, name, lines):
    """Writes the report's `lines` to <out_dir>/<name> and prints them and the path."""
    report = "\n".join(lines)
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, name)
    with open(path, "w") as f:
        f.write(report + "\n")
    print()
    print(report)
    print("written: %s" % path)
