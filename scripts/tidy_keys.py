#!/usr/bin/python3
"""Cache keys for scripts/tidy_check.sh: one line "<source> <key>" per source.

A source's key is a SHA-256 over what clang-tidy's result on it depends on:
the clang-tidy version, .clang-tidy, tidy_check.sh's own arguments, the
source's compile command, and the path and content of every file of its
translation unit (the source and every header it includes, system headers
too), as the build's dependency file for its object lists them. The key is
"-" (not cached) when that dependency file is missing or older than one of
the files it lists: then the build has not compiled the source as it is, and
its list of headers may be stale.

    tidy_keys.py COMPILE_COMMANDS CLANG_TIDY_CONFIG TIDY_ARGUMENTS SOURCE...

SOURCE is the path clang-tidy is given, as compile_commands.json names it.
"""
import hashlib
import json
import os
import shlex
import subprocess
import sys


def depfile_of(entry):
    """The dependency file the compiler writes next to the object (-o X.o -> X.o.d)."""
    words = shlex.split(entry["command"]) if "command" in entry else entry["arguments"]
    if "-o" not in words:
        return None
    return os.path.join(entry["directory"], words[words.index("-o") + 1] + ".d")


def dependencies(depfile, directory):
    """The files a make-style dependency file lists after its target."""
    with open(depfile) as f:
        text = f.read().replace("\\\n", " ")
    listed = text.split(":", 1)[1].split()
    return [os.path.normpath(os.path.join(directory, path)) for path in listed]


class ContentHashes:
    """SHA-256 of each file's content, each file read once."""

    def __init__(self):
        self.known = {}

    def __call__(self, path):
        if path not in self.known:
            with open(path, "rb") as f:
                self.known[path] = hashlib.sha256(f.read()).hexdigest()
        return self.known[path]


def main():
    database, config, tidy_arguments, sources = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    entries = {entry["file"]: entry for entry in json.load(open(database))}
    common = hashlib.sha256()
    common.update(subprocess.run(["clang-tidy", "--version"], stdout=subprocess.PIPE, check=True).stdout)
    with open(config, "rb") as f:
        common.update(f.read())
    common.update(tidy_arguments.encode())
    content_hash = ContentHashes()
    for source in sources:
        entry = entries.get(source)
        depfile = depfile_of(entry) if entry else None
        key = "-"
        if depfile and os.path.exists(depfile):
            listed = dependencies(depfile, entry["directory"])
            built = os.stat(depfile).st_mtime
            if all(os.path.exists(path) and os.stat(path).st_mtime <= built for path in listed):
                tu = common.copy()
                tu.update(json.dumps(entry, sort_keys=True).encode())
                for path in listed:
                    tu.update(("%s %s\n" % (path, content_hash(path))).encode())
                key = tu.hexdigest()
        print(source, key)


if __name__ == "__main__":
    main()
