#!/usr/bin/env python3
"""Issue 15's model of mjray-mpi's parallel efficiency on N nodes (docs/performance.md §9).

  bench/mpi_model.py [MPI.jsonl] [OUTDIR]     table (markdown) on stdout, mpi_model.csv in OUTDIR

COSTS="mesh=0.12,0.90 glass=0.02,0.01" replaces a scene's measured load and build seconds (e.g.
with figures from a quiet machine when run_mpi.sh ran on a busy one).

A node is one host running one rank with all its cores (-j = its cores). The inputs measured on
this machine (bench/run_mpi.sh) are the per-rank start-up (script + meshes: `load`; accelerator
build per image: `build`) and the bytes sent per pixel; the rest are assumptions, written below
and in the docs. Efficiency = (time on one node) / (N x time on N nodes).
"""
import json
import math
import os
import statistics
import sys

# --- assumptions (see docs/performance.md §9) ------------------------------------------------
FRAME_SECONDS = 60.0          # one image's render on one node, start-up excluded
FRAMES = 300                  # the animation
WIDTH, HEIGHT, TILE = 1920, 1080, 16
TILES = math.ceil(WIDTH / TILE) * math.ceil(HEIGHT / TILE)
TAIL_TILES = 4.0              # the last tile handed out costs up to 4x a mean tile (uneven scenes)
PASSES = 2                    # synchronisations per still: first pass + one anti-aliasing pass
LAUNCH_SECONDS = 0.5          # mpirun + MPI_Init + MPI_Finalize, one rank (replaced by the measured "launch" runs)
LAUNCH_PER_DOUBLING = 0.05    # more per doubling of nodes (tree launch, assumed)
COORDINATOR_SECONDS = 20e-6   # rank 0's cost per unit handed out and result merged (assumed)
BANDWIDTH = 1.25e9            # bytes/s into rank 0 (10 GbE)
NODES = [1, 2, 4, 8, 16, 32, 64, 128, 256, 512]


def measured(path):
    """Slowest-rank load and build seconds, bytes per pixel, per scene, from run_mpi.sh's runs."""
    scenes = {}
    if not path or not os.path.exists(path):
        return scenes
    rows = [json.loads(l) for l in open(path) if l.strip()]
    launch = [r["wall"] for r in rows if r.get("scene") == "launch" and r.get("np") == 1 and r.get("status") == 0]
    if launch:
        global LAUNCH_SECONDS
        LAUNCH_SECONDS = statistics.median(launch)
    for r in rows:
        if r.get("scene") == "launch":
            continue
        if r.get("status") != 0 or not isinstance(r.get("ranks"), list) or r.get("np", 0) < 2:
            continue
        s = scenes.setdefault(r["scene"], {"load": [], "build": [], "bpp": []})
        s["load"].append(max(x["seconds_load"] for x in r["ranks"]))
        s["build"].append(max(x["seconds_build"] for x in r["ranks"]))
        s["bpp"].append(sum(x["bytes_sent"] for x in r["ranks"]) / (512 * 512))
    return {k: {m: statistics.median(v) for m, v in s.items()} for k, s in scenes.items()}


def launch(n):
    return LAUNCH_SECONDS + LAUNCH_PER_DOUBLING * math.log2(n)


def tiled_image(n, build, bpp):
    """One image whose tiles all N ranks share: every rank builds it, then the queue drains."""
    mean_tile = FRAME_SECONDS / TILES
    compute = FRAME_SECONDS / n + PASSES * TAIL_TILES * mean_tile if n > 1 else FRAME_SECONDS
    # Rank 0 serves every unit; it becomes the bottleneck when units come back faster than it serves.
    coordinator = TILES * PASSES * COORDINATOR_SECONDS if n > 1 else 0
    transfer = WIDTH * HEIGHT * bpp / BANDWIDTH if n > 1 else 0
    return build + max(compute, coordinator) + transfer


def still(n, load, build, bpp):
    one = load + build + FRAME_SECONDS  # plain mjray on one node: no mpirun
    return one / (n * (launch(n) + load + tiled_image(n, build, bpp)))


def animation(n, load, build, bpp):
    """--distribute auto: whole frames while every rank gets one, the rest tiled over all ranks."""
    one = load + FRAMES * (build + FRAME_SECONDS)
    whole_rounds = FRAMES // n if n > 1 else FRAMES
    rest = FRAMES - whole_rounds * n if n > 1 else 0
    t = launch(n) + load + whole_rounds * (build + FRAME_SECONDS) + rest * tiled_image(n, build, bpp)
    return one / (n * t)


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "results", "mpi.jsonl")
    outdir = sys.argv[2] if len(sys.argv) > 2 else os.path.dirname(path)
    costs = measured(path)
    for item in os.environ.get("COSTS", "").split():
        name, _, values = item.partition("=")
        load, build = (float(v) for v in values.split(","))
        costs.setdefault(name, {"bpp": 16.0}).update(load=load, build=build)
    # Scenes measured here, and a heavy one: 20x the dragon's start-up (a 17M-triangle scene).
    scenarios = dict(costs)
    if "mesh" in costs:
        scenarios["20x mesh"] = {k: v * 20 if k != "bpp" else v for k, v in costs["mesh"].items()}
    if not scenarios:
        sys.exit("mpi_model.py: no mjray-mpi runs in " + path + " (run bench/run_mpi.sh)")
    csv = ["nodes," + ",".join(f"{s} still,{s} animation" for s in scenarios)]
    print("| nodes | " + " | ".join(f"{s}: 60 s still | {s}: 300 frames" for s in scenarios) + " |")
    print("|---:|" + "---:|---:|" * len(scenarios))
    for n in NODES:
        cells, row = [], [str(n)]
        for c in scenarios.values():
            e_still, e_anim = still(n, c["load"], c["build"], c["bpp"]), animation(n, c["load"], c["build"], c["bpp"])
            cells += [f"{100 * e_still:.0f} %", f"{100 * e_anim:.0f} %"]
            row += [f"{e_still:.4f}", f"{e_anim:.4f}"]
        print(f"| {n} | " + " | ".join(cells) + " |")
        csv.append(",".join(row))
    print()
    print(f"Launch (mpirun -np 1, MPI_Init, MPI_Finalize): {LAUNCH_SECONDS:.3f} s. "
          "Inputs measured here (slowest rank, median): " + "; ".join(
        f"{s}: load {c['load']:.3f} s, build {c['build']:.3f} s, {c['bpp']:.1f} bytes sent per pixel"
        for s, c in scenarios.items()))
    with open(os.path.join(outdir, "mpi_model.csv"), "w") as f:
        f.write("\n".join(csv) + "\n")


if __name__ == "__main__":
    main()
