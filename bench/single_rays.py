#!/usr/bin/env python3
"""Single-ray throughput of two mjray-bench builds' BVH against Embree, in alternated rounds.

Each round runs, one after the other on the same rays: the baseline build's BVH, the new build's
BVH, Embree with its default scene flags and Embree with its robust ones (both inside the new
build). A row reports the median rays/s of each and the medians of the per-round ratios, new
against baseline and new against the faster Embree of that round, so that the machine's drift
cancels. Rays/s come from each run's fastest trace (`trace_seconds_min`), the one least touched
by other work on the machine.

  bench/single_rays.py BASELINE_BENCH NEW_BENCH [--rounds N] [--meshes M ...] [--kinds K ...]
  bench/single_rays.py /tmp/old/mjray-bench build/mjray-bench --rounds 5

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


def rays_per_second(bench, mesh, kind, accel):
    command = [bench, "--mesh", os.path.join(MODELS, mesh), "--rays", kind, "--threads", "1", "--build-threads", "2",
               "--repeat", "5", "--min-ms", "150", "--max-rays", "200000"] + accel
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{run.stderr}")
    result = json.loads(run.stdout.strip().splitlines()[-1])
    return result["rays"] / result["trace_seconds_min"] / 1e6


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("baseline")
    parser.add_argument("new")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--meshes", nargs="+",
                        default=["small/teapot.obj", "small/bunny.obj", "large/dragon_vrip_res2.obj", "large/dragon_vrip.obj"])
    parser.add_argument("--kinds", nargs="+", default=["primary", "incoherent", "shadow"])
    args = parser.parse_args()
    print("| mesh | rays | baseline BVH | new BVH | Embree default | Embree robust | new / baseline | new / faster Embree |")
    print("|---|---|---|---|---|---|---|---|")
    for mesh in args.meshes:
        for kind in args.kinds:
            rounds = []
            for _ in range(args.rounds):
                rounds.append((rays_per_second(args.baseline, mesh, kind, ["--accel", "bvh"]),
                               rays_per_second(args.new, mesh, kind, ["--accel", "bvh"]),
                               rays_per_second(args.new, mesh, kind, ["--accel", "embree", "--embree-flags", "default"]),
                               rays_per_second(args.new, mesh, kind, ["--accel", "embree", "--embree-flags", "robust"])))
            median = [statistics.median(r[i] for r in rounds) for i in range(4)]
            faster = "default" if median[2] >= median[3] else "robust"
            against_baseline = statistics.median(r[1] / r[0] for r in rounds)
            against_embree = statistics.median(r[1] / max(r[2], r[3]) for r in rounds)
            name = os.path.splitext(os.path.basename(mesh))[0]
            print(f"| {name} | {kind} | {median[0]:.2f} | {median[1]:.2f} | {median[2]:.2f} | {median[3]:.2f} "
                  f"| {against_baseline:.2f}× | {against_embree:.2f}× ({faster}) |", flush=True)


if __name__ == "__main__":
    main()
