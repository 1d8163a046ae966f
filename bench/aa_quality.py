#!/usr/bin/env python3
"""Image error against cost of anti-aliasing settings on the glass bench scene, for mjray and for
its POV-Ray twin: each program's images are compared with its own converged reference (many
samples in every pixel that varies), so that "the same quality" can be read off for both.

    bench/aa_quality.py [ROUNDS] [OUT_DIR]     (defaults: 3, build-bench/aa-quality)

Run from the repository root after building build/mjray, with povray on the path. The references
are rendered once and kept in OUT_DIR (POV-Ray's takes about 2 minutes on 2 cores). Times are
whole-process wall times, median of ROUNDS alternated runs, on 2 threads. Errors are in linear
light on an 8-bit scale: mjray writes linear values, POV-Ray's file is decoded with gamma 2.2.
Prints a Markdown table and appends JSON lines to bench/results/aa_quality.jsonl.
"""
import json
import math
import os
import statistics
import subprocess
import sys
import time

SCENE = os.path.abspath("../shared/bench/glass.lua")
POV_DIR = os.path.abspath("../shared/bench/pov")
MJRAY_BASE = ["build/mjray", "--quiet", "-j", "2", "-r", "8", "-f", "8", "-s", "4"]
POV_BASE = ["povray", "+Iglass.pov", "+W512", "+H512", "+WT2", "-D", "-V", "+FP"]

MJRAY_REFERENCE = ["-a", "8", "--aa-threshold", "0.004"]
POV_REFERENCE = ["+A0.0", "+AM1", "+R8", "+J1.0"]
MJRAY_SETTINGS = [
    ["-a", "3"],  # the scene header's
    ["-a", "3", "--aa-threshold", "0.2"],
    ["-a", "3", "--aa-threshold", "0.3"],
    ["-a", "2"],
    ["-a", "0"],
    ["-a", "3", "--aa-method", "subdivide"],
    ["-a", "3", "--aa-method", "subdivide", "--aa-threshold", "0.07"],
    ["-a", "8", "--aa-method", "subdivide"],
]
POV_SETTINGS = [
    ["+A0.3", "+AM2", "+R3"],  # the twin's header
    ["+A0.1", "+AM2", "+R3"],
    ["+A0.3", "+AM2", "+R4"],
    ["-A"],
]


def mjray_command(flags, path):
    return MJRAY_BASE + flags + [SCENE, "--output", path]


def pov_command(flags, path):
    return POV_BASE + flags + ["+O" + path]


def run(command, cwd=None):
    start = time.perf_counter()
    done = subprocess.run(command, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if done.returncode != 0:
        sys.exit(f"failed ({done.returncode}): {' '.join(command)}")
    return time.perf_counter() - start


def read_ppm(path):
    """The samples of an 8-bit binary PPM (P6), row-major RGB."""
    with open(path, "rb") as f:
        data = f.read()
    fields, at = [], 0
    while len(fields) < 4:
        while data[at:at + 1].isspace():
            at += 1
        if data[at:at + 1] == b"#":
            at = data.index(b"\n", at) + 1
            continue
        end = at
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[at:end])
        at = end
    if fields[0] != b"P6" or int(fields[3]) != 255:
        sys.exit(f"{path}: not an 8-bit binary PPM")
    return data[at + 1:at + 1 + int(fields[1]) * int(fields[2]) * 3]


def linear(samples, gamma):
    table = [255 * (v / 255) ** gamma for v in range(256)]
    return [table[v] for v in samples]


def errors(image, reference):
    """RMSE over all channels, and the pixels whose largest channel error exceeds 8 and 16."""
    squares, over8, over16 = 0.0, 0, 0
    for p in range(0, len(image), 3):
        worst = 0.0
        for c in range(3):
            d = abs(image[p + c] - reference[p + c])
            squares += d * d
            worst = max(worst, d)
        over8 += worst > 8
        over16 += worst > 16
    return math.sqrt(squares / len(image)), over8, over16


def main():
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    out = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else "build-bench/aa-quality")
    os.makedirs(out, exist_ok=True)
    reference_runs = [
        (mjray_command(MJRAY_REFERENCE, f"{out}/mjray-reference.ppm"), None, f"{out}/mjray-reference.ppm"),
        (pov_command(POV_REFERENCE, f"{out}/povray-reference.ppm"), POV_DIR, f"{out}/povray-reference.ppm"),
    ]
    for command, cwd, path in reference_runs:
        if not os.path.exists(path):
            print(f"rendering a reference once: {' '.join(command)}", file=sys.stderr)
            run(command, cwd)
    measured = []
    for i, flags in enumerate(MJRAY_SETTINGS):
        measured.append(("mjray", flags, mjray_command(flags, f"{out}/mjray-{i}.ppm"), None, f"{out}/mjray-{i}.ppm"))
    for i, flags in enumerate(POV_SETTINGS):
        measured.append(("povray", flags, pov_command(flags, f"{out}/povray-{i}.ppm"), POV_DIR, f"{out}/povray-{i}.ppm"))
    times = [[] for _ in measured]
    for _ in range(rounds):
        for k, (_, _, command, cwd, _) in enumerate(measured):
            times[k].append(run(command, cwd))
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    gammas = {"mjray": 1.0, "povray": 2.2}
    references = {p: linear(read_ppm(f"{out}/{p}-reference.ppm"), g) for p, g in gammas.items()}
    print("| program | settings | wall s (median) | RMSE | pixels off by > 8 | > 16 |")
    print("|---|---|---:|---:|---:|---:|")
    with open("bench/results/aa_quality.jsonl", "a") as log:
        for k, (program, flags, _, _, path) in enumerate(measured):
            rmse, over8, over16 = errors(linear(read_ppm(path), gammas[program]), references[program])
            seconds = statistics.median(times[k])
            print(f"| {program} | `{' '.join(flags)}` | {seconds:.2f} | {rmse:.2f} | {over8} | {over16} |")
            log.write(json.dumps({"git": commit, "program": program, "settings": flags, "seconds": seconds, "runs": times[k],
                                  "rmse": rmse, "over8": over8, "over16": over16}) + "\n")


if __name__ == "__main__":
    main()
