#!/usr/bin/env python3
"""Writes the hand-made seed inputs of the fuzz targets into fuzz/corpus/<target>/seed_*.

The bytes follow the generators in scene_parser_fuzzer.cpp and wrench_fuzzer.cpp
(see the comments there); service_text_fuzzer's are YAML texts. Re-run after
changing a generator:
    python3 fuzz/make_seeds.py
With --large DIR it writes instead the inputs too large to keep in the
repository (a 100,000-particle entry, a quadratic alias blow-up, ...) into DIR
as <target>-<name>; scripts/fuzz.sh runs them before fuzzing.
"""
import argparse
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

# ---- scene_parser_fuzzer ---------------------------------------------------
KEYS = ["name", "particles", "mass", "position", "orientation", "linear_velocity",
        "angular_velocity", "shape", "size", "radius", "length", "resolution"]
STRINGS = ["box", "sphere", "cylinder", "rod", "a", "b_1", "", "1x", "has space", "cube",
           "Body", "x"]


def num(v):  # Number(): small codes, else int8 / 8
    codes = {0.0: 0, 1.0: 1, -1.0: 2, 0.5: 3}
    if v in codes:
        return [codes[v]]
    return [13, int(v * 8) & 0xff]


def v_num(v):
    return [0] + num(v)


def v_int(n):
    return [1, 7] + list(struct.pack(">I", n & 0xffffffff))


def v_str(s):
    return [3, STRINGS.index(s)]


def v_list(vals):
    out = [5, len(vals)]
    for v in vals:
        out += [1] + num(v)
    return out


def member(key, value):
    return [KEYS.index(key)] + value


def struct_(members, as_value=True):
    out = ([6] if as_value else []) + [len(members)]
    for m in members:
        out += m
    return out


def bodies(*entries):
    out = [1, len(entries) - 1]
    for e in entries:
        out += struct_(e, as_value=False)
    return bytes(out)


def particle(mass, pos):
    return struct_([member("mass", v_num(mass)), member("position", v_list(pos))])


def particles(*ps):
    out = [8, len(ps)]
    for p in ps:
        out += p
    return out


SCENES = {
    "box": bodies([member("name", v_str("cube")), member("shape", v_str("box")),
                   member("mass", v_num(1.0)), member("size", v_list([0.5, 0.5, 0.5]))]),
    "rod": bodies([member("name", v_str("rod")),
                   member("particles", particles(particle(1.0, [-0.5, 0, 0]),
                                                 particle(1.0, [0.5, 0, 0])))]),
    "sphere_and_dot": bodies(
        [member("name", v_str("Body")), member("shape", v_str("sphere")),
         member("mass", v_num(2.0)), member("radius", v_num(0.5)),
         member("resolution", v_int(3)), member("orientation", v_list([0, 0, 0, 1])),
         member("angular_velocity", v_list([0.5, 1.0, 0]))],
        [member("name", v_str("x")), member("particles", particles(particle(0.5, [1, 2, 3])))]),
    "cylinder": bodies([member("name", v_str("a")), member("shape", v_str("cylinder")),
                        member("mass", v_num(1.0)), member("radius", v_num(0.5)),
                        member("length", v_num(2.0)), member("position", v_list([1, 0, -1])),
                        member("linear_velocity", v_list([0, 0.5, 0]))]),
    "duplicate": bodies([member("name", v_str("a")), member("shape", v_str("sphere")),
                         member("mass", v_num(1.0)), member("radius", v_num(1.0))],
                        [member("name", v_str("a")), member("shape", v_str("sphere")),
                         member("mass", v_num(1.0)), member("radius", v_num(1.0))]),
}

# ---- wrench_fuzzer ---------------------------------------------------------
# Number(): 0 -> 0, 2 -> 1, 3 -> -1, 4 -> 1e3, 17 -> int8 byte.
W_NUM = {0: [0], 1: [2], -1: [3], 1000: [4]}


def w_num(v):
    return W_NUM.get(v) or [17, v & 0xff]


def header(integrator=0, dt=0, gravity=None, timeout=0, prefix=False, start=0):
    out = [integrator, dt]
    if gravity is None:
        out += [1]
    else:
        out += [0] + sum((w_num(g) for g in gravity), [])
    return out + [timeout, 0 if prefix else 1, start]


def wrench(body, particle, frame=0, stamp=(0,), force=(0, 0, 0), torque=(0, 0, 0)):
    # body: index 0..4 (dot rod cube plate top); frame: FrameId() selector.
    out = [0, body, 1, particle, frame] + list(stamp)
    for v in list(force) + list(torque):
        out += w_num(v)
    return out


def steps(n):
    return [4, n - 1]


WRENCHES = {
    "push_rod": bytes(header() + wrench(1, 1, force=(0, 1, 0)) + steps(16)),
    "body_axes_torque": bytes(header(integrator=1, gravity=(0, 0, -9)) +
                              wrench(2, 0, frame=4, torque=(0, 0, 1)) + steps(8) +
                              [6, 1] + steps(4)),
    "future_stamp_timeout": bytes(header(integrator=2, timeout=3, prefix=True) +
                                  wrench(3, 2, frame=6, stamp=(2, 5), force=(1000, 0, 0)) +
                                  steps(16) + steps(16)),
    "set_state": bytes(header(integrator=3) + [7, 4] + sum((w_num(v) for v in
                       [0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 20, 1]), []) + steps(16)),
    "dot_couple": bytes(header(integrator=4) + wrench(0, 0, torque=(1, 1, 1)) + steps(4)),
}
for i in range(5, 12):
    WRENCHES["integrator_%d" % i] = bytes(
        header(integrator=i, gravity=(1, 0, -1)) + wrench(4, 3, force=(1, 0, 0)) +
        wrench(2, 1, frame=2, force=(0, 0, 1)) + steps(16))

# ---- service_text_fuzzer ---------------------------------------------------
# One ~spawn_body entry as YAML text. The harness's world already has a body
# named "box". Each text stays within FUZZ_MAX_LEN (1024 bytes).
def billion_laughs(levels=9, fan_out=10):
    lines = ["a0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol, lol]"]
    for i in range(1, levels):
        lines.append("a%d: &a%d [%s]" % (i, i, ", ".join(["*a%d" % (i - 1)] * fan_out)))
    return "\n".join(lines + ["name: lol", "particles: *a%d" % (levels - 1)]) + "\n"


def quadratic(string_len, aliases):
    return ('s: &s "%s"\nname: q\nparticles: [%s]\n' %
            ("x" * string_len, ", ".join(["*s"] * aliases)))


def nested_lists(depth):
    return "name: n\nparticles: " + "[" * depth + "]" * depth + "\n"


def nested_maps(depth):
    return "name: n\nshape: " + "{a: " * depth + "1" + "}" * depth + "\n"


def particles_entry(count):
    return ("name: many\nparticles:\n" +
            "".join("  - {mass: 1.0, position: [%d.0, 0.5, -0.5]}\n" % (i % 100) for i in range(count)))


TEXTS = {
    "particles": ("name: t_handle\nparticles:\n"
                  "  - {mass: 0.5, position: [0.0, -0.15, 0.0]}\n"
                  "  - {mass: 0.5, position: [0.0, 0.15, 0.0]}\n"
                  "  - {mass: 0.3, position: [0.12, 0.0, 0.0]}\n"
                  "position: [-1.2, 0.0, 1.0]\nangular_velocity: [0.03, 6.0, 0.03]\n"),
    "box": ("name: crate\nshape: box\nmass: 2.0\nsize: [0.3, 0.2, 0.1]\nresolution: 3\n"
            "position: [1.2, 0.0, 1.0]\nangular_velocity: [0.3, 0.0, 2.5]\n"),
    "sphere": ("{name: ball, shape: sphere, mass: 0.5, radius: 0.08, position: [0.0, -0.8, 1.0], "
               "angular_velocity: [0.0, 0.0, 2.0]}"),
    "cylinder": ("name: top\nshape: cylinder\nmass: 1.0\nradius: 0.2\nlength: 0.05\nresolution: 7\n"
                 "orientation: [0.0, 0.2588190, 0.0, 0.9659258]\nlinear_velocity: [0.1, 0, 0]\n"),
    "properties": ("name: damped\nshape: sphere\nmass: 1\nradius: 0.1\ngravity_scale: 0.5\n"
                   "linear_damping: 0.1\nangular_damping: 2.0\n"),
    "name_in_use": "{name: box, shape: box, mass: 1.0, size: [1, 1, 1]}",
    "tags": ("name: !!str tagged\nshape: !!str sphere\nmass: !!float 1\nradius: !!int 1\n"
             "position: !!seq [0, 0, 0]\n"),
    # Texts built to cost memory or time, and the odd corners of YAML.
    "billion_laughs": billion_laughs(),
    "quadratic": quadratic(600, 90),
    "nested_lists": nested_lists(500),
    "nested_maps": nested_maps(200),
    "merge_keys": ("base: &base {shape: box, mass: 1.0, size: [1, 1, 1]}\n"
                   "name: merged\n<<: *base\nmore: &more {<<: [*base, *base], resolution: 2}\n"
                   "<<: *more\n"),
    "repeated_keys": ("name: a\nname: b\nshape: box\nshape: sphere\nmass: 1\nmass: -1\n"
                      "radius: 1\nradius: 2\nsize: [1, 1, 1]\nname: [c]\n"),
    "huge_numbers": ("name: big\nshape: sphere\nmass: 1e999999\nradius: 99999999999999999999\n"
                     "resolution: 99999999999999999999\nposition: [1e308, -1e999999, 1e-999999]\n"
                     "angular_velocity: [.inf, -.inf, .nan]\nlinear_velocity: [0x7fffffffffffffff, 0o777, 1_000]\n"),
}

LARGE_TEXTS = {
    "particles-100000": particles_entry(100000),  # the most a body may have
    "particles-100001": particles_entry(100001),
    "quadratic-large": quadratic(65536, 32768),  # ~200 KB that aliases 2 GiB
    "nested-lists-large": nested_lists(100000),
}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--large", metavar="DIR", help="write the large inputs into DIR")
    args = parser.parse_args()
    if args.large:
        os.makedirs(args.large, exist_ok=True)
        for name, text in LARGE_TEXTS.items():
            with open(os.path.join(args.large, "service_text_fuzzer-" + name), "w") as f:
                f.write(text)
        return
    texts = {name: text.encode() for name, text in TEXTS.items()}
    for target, seeds in (("scene_parser_fuzzer", SCENES), ("wrench_fuzzer", WRENCHES),
                          ("service_text_fuzzer", texts)):
        d = os.path.join(HERE, "corpus", target)
        os.makedirs(d, exist_ok=True)
        for name, data in seeds.items():
            assert len(data) <= 1024, (target, name, len(data))
            with open(os.path.join(d, "seed_" + name), "wb") as f:
                f.write(data)


main()
