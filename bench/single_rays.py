#!/usr/bin/env python3
"""Single-ray throughput of two mjray-bench builds' BVH against Embree, in alternated rounds.

Each round runs, one after the other on the same rays: the baseline build's BVH, the new build's
BVH, Embree with its default scene flags and Embree with its robust ones (both inside the new
build). A row reports the median rays/s of each and the medians of the per-round ratios, new
against baseline and new against the faster Embree of that round, so that the machine's drift
cancels. Rays/s come from each run's fastest trace (`trace_seconds_min`), the one least touched
by other work on the machine.

  bench/single_rays.py BASELINE_BENCH NEW_BENCH [--rounds N] [--meshes M ...] [--kinds K ...] [--side-by-side]
  bench/single_rays.py /tmp/old/mjray-bench build/mjray-bench --rounds 5

--side-by-side (two cores or more) runs each comparison's two programs at the same time, each
pinned to a core of its own, then again with the cores swapped: baseline beside new, and new
beside each Embree. Both then meet the same moment of the machine (another guest's load, a
busier host), which alternation in time cannot give; on this 2-core guest it took the spread of
the per-round ratios from about ±15 % to ±3 %. The two runs share the last-level cache and the
memory bus, so their rays/s are lower than alone, and the ratios are what it is for.

Meshes are paths under $SHARED/models (SHARED defaults to ../shared). Takes about 12 minutes
for the defaults.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
MODELS = os.path.join(os.environ.get("SHARED", os.path.join(ROOT, "..", "shared")), "models")


BVH = ["--accel", "bvh"]
EMBREE_DEFAULT = ["--accel", "embree", "--embree-flags", "default"]
EMBREE_ROBUST = ["--accel", "embree", "--embree-flags", "robust"]


def print_header():
    print("| mesh | rays | baseline BVH | new BVH | Embree default | Embree robust | new / baseline | new / faster Embree |")
    print("|---|---|---|---|---|---|---|---|")


def print_row(mesh, kind, median, against_baseline, against_embree, faster):
    """median: rays/s of the baseline BVH, the new BVH, Embree default and Embree robust."""
    name = os.path.splitext(os.path.basename(mesh))[0]
    print(f"| {name} | {kind} | {median[0]:.2f} | {median[1]:.2f} | {median[2]:.2f} | {median[3]:.2f} "
          f"| {against_baseline:.2f}× | {against_embree:.2f}× ({faster}) |", flush=True)


def command_line(bench, mesh, kind, accel):
    return [bench, "--mesh", os.path.join(MODELS, mesh), "--rays", kind, "--threads", "1", "--build-threads", "2",
            "--repeat", "5", "--min-ms", "150", "--max-rays", "200000"] + accel


def rays_per_second_of(command, run):
    if run.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{run.stderr}")
    result = json.loads(run.stdout.strip().splitlines()[-1])
    return result["rays"] / result["trace_seconds_min"] / 1e6


def rays_per_second(bench, mesh, kind, accel):
    command = command_line(bench, mesh, kind, accel)
    return rays_per_second_of(command, subprocess.run(command, capture_output=True, text=True))


def side_by_side(first, second):
    """Rays/s of two (bench, mesh, kind, accel) runs made at once on cores 0 and 1, then on 1
    and 0: two pairs of figures."""
    pairs = []
    for cores in ((0, 1), (1, 0)):
        commands = [["taskset", "-c", str(core)] + command_line(*run) for core, run in zip(cores, (first, second))]
        running = [subprocess.Popen(c, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) for c in commands]
        results = []
        for command, process in zip(commands, running):
            stdout, stderr = process.communicate()
            results.append(rays_per_second_of(command, subprocess.CompletedProcess(command, process.returncode, stdout, stderr)))
        pairs.append(tuple(results))
    return pairs


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("baseline")
    parser.add_argument("new")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--meshes", nargs="+",
                        default=["small/teapot.obj", "small/bunny.obj", "large/dragon_vrip_res2.obj", "large/dragon_vrip.obj"])
    parser.add_argument("--kinds", nargs="+", default=["primary", "incoherent", "shadow"])
    parser.add_argument("--side-by-side", action="store_true", help="run the programs compared at the same time")
    args = parser.parse_args()
    if args.side_by_side:
        return side_by_side_table(args)
    print_header()
    for mesh in args.meshes:
        for kind in args.kinds:
            rounds = []
            for _ in range(args.rounds):
                rounds.append((rays_per_second(args.baseline, mesh, kind, BVH),
                               rays_per_second(args.new, mesh, kind, BVH),
                               rays_per_second(args.new, mesh, kind, EMBREE_DEFAULT),
                               rays_per_second(args.new, mesh, kind, EMBREE_ROBUST)))
            median = [statistics.median(r[i] for r in rounds) for i in range(4)]
            faster = "default" if median[2] >= median[3] else "robust"
            against_baseline = statistics.median(r[1] / r[0] for r in rounds)
            against_embree = statistics.median(r[1] / max(r[2], r[3]) for r in rounds)
            print_row(mesh, kind, median, against_baseline, against_embree, faster)


def side_by_side_table(args):
    print_header()
    for mesh in args.meshes:
        for kind in args.kinds:
            builds, default, robust = [], [], []
            for _ in range(args.rounds):
                builds += side_by_side((args.baseline, mesh, kind, BVH), (args.new, mesh, kind, BVH))
                default += side_by_side((args.new, mesh, kind, BVH), (args.new, mesh, kind, EMBREE_DEFAULT))
                robust += side_by_side((args.new, mesh, kind, BVH), (args.new, mesh, kind, EMBREE_ROBUST))
            median = [statistics.median(x) for x in ([b[0] for b in builds], [b[1] for b in builds],
                                                     [d[1] for d in default], [r[1] for r in robust])]
            against_baseline = statistics.median(b[1] / b[0] for b in builds)
            against_default = statistics.median(d[0] / d[1] for d in default)
            against_robust = statistics.median(r[0] / r[1] for r in robust)
            # The faster Embree is the one mjray compares worse against.
            against_embree, faster = min((against_default, "default"), (against_robust, "robust"))
            print_row(mesh, kind, median, against_baseline, against_embree, faster)


if __name__ == "__main__":
    main()
