"""Report helpers the bench scripts share: numbers and Markdown tables, and the commit and CPU a
report names."""

import math
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
