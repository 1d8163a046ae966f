#!/usr/bin/env python3
"""mjray against Blender's Cycles at equal wall time on the box room of cycles_twin.py: the
error of each renderer's image after 1, 2, 5, 10, 20 and 60 seconds against a long Cycles
reference. The target: mjray's error at most half of Cycles' at every budget.

Run bench/cycles_equal_time.sh (it calls this file four ways):
  python3 cycles_equal_time.py mjray OUTDIR GI OWN_SPP BUDGET...
      the room as an mjray scene; mjray's own converged image (cached); then one timed run per
      budget with --time-limit, wall time around the whole process -> OUTDIR/mjray_runs.jsonl
  python3 cycles_equal_time.py sweep OUTDIR GI...
      one timed 1 s run per photon count, to choose --gi -> OUTDIR/mjray_sweep.jsonl
  blender -b --factory-startup -P cycles_equal_time.py -- OUTDIR REF_SAMPLES BUDGET...
      the room in Cycles; the reference (cached); one render per budget with time_limit, wall
      time around the render call alone, in one Blender process so that Blender's start-up
      is not counted -> OUTDIR/cycles_runs.jsonl; then every OUTDIR/*.exr as *.npy
  python3 cycles_equal_time.py compare OUTDIR GI
      the errors -> OUTDIR/equal_time.jsonl and a markdown table

Images: both renderers write linear EXR. Debian's python3 has numpy but no EXR reader, and
Blender has both, so Blender reads every EXR (its own and mjray's half floats) into .npy files
of linear RGB, rows from the top, and the comparison reads those with numpy alone.

Error: sqrt(mean((A - R)^2)) / mean(R) over all pixels and channels of linear RGB. Each image
is compared with the Cycles reference: 4096 samples in every pixel, adaptive sampling off and
fixed seeds (Blender turns adaptive sampling on by default and always seeds 0), rendered as
two halves of 2048 samples with seeds of their own and averaged. Half the RMS of the halves'
difference is the reference's own noise; the table's last column takes it out of both errors
(in quadrature: the runs' noise is independent of the reference's), as the reference's noise
pulls the ratio towards 1 where the errors come near it. mjray's images are also compared with
its converged image (--noise-threshold 0.002 --max-spp 4096, the same photon count), whose
difference from the Cycles reference is printed as mjray's floor.

Made equal: the light (Cycles' point light of power P lights a surface P/(4 pi^2) times as
brightly as mjray's of intensity 1: the back wall's direct light agrees to 0.03 % at
P = 4 pi^2), the pixel filter (a one-pixel box, mjray's), the threads and a fresh seed per
run. Times are as measured: Cycles' time_limit counts path tracing only, so its render call
also holds the scene's sync and its EXR; mjray's --time-limit counts from its start, but the
photon pass is not cut short, so a run whose photons take longer than the budget overshoots
it. The table gives both times; a row where mjray took more than 10 % longer than Cycles is
not at equal time.
"""
import json
import math
import os
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in bench/
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cycles_twin  # noqa: E402  the room
from results import cpu_idle  # noqa: E402

THREADS = 2
MJRAY = os.environ.get("MJRAY", "build/mjray")
# mjray's noise target under --time-limit: low, so that the budget, not the target, ends a run.
NOISE_THRESHOLD = os.environ.get("NOISE_THRESHOLD", "0.01")
REFERENCE_SEED = 4096  # runs take seeds 1, 2, ...
SWEEP_BUDGET = 1


def name(renderer, budget, gi=None):
    return f"{renderer}{'' if gi is None else f'_gi{gi}'}_{budget:g}s.exr"


def run_mjray(outdir, gi, budget, seed, image):
    """One timed mjray run under --time-limit; its JSON row."""
    scene = os.path.join(outdir, "twin.lua")
    idle = cpu_idle()
    start = time.perf_counter()
    subprocess.run([MJRAY, "--quiet", "-j", str(THREADS), "--gi", str(gi), "--gather-rays", "4",
                    "--noise-threshold", NOISE_THRESHOLD, "--time-limit", f"{budget:g}", "--seed", str(seed),
                    "--output", os.path.join(outdir, image), scene], check=True)
    seconds = time.perf_counter() - start
    return {"renderer": "mjray", "gi": gi, "budget": budget, "seconds": round(seconds, 3),
            "idle": round(idle, 2), "image": image}


def mjray_main(outdir, gi, own_spp, budgets):
    os.makedirs(outdir, exist_ok=True)
    scene = os.path.join(outdir, "twin.lua")
    cycles_twin.lua_scene(scene)
    own = f"mjray_gi{gi}_converged{own_spp}.exr"
    if not os.path.exists(os.path.join(outdir, own)):
        subprocess.run([MJRAY, "--quiet", "-j", str(THREADS), "--gi", str(gi), "--gather-rays", "4",
                        "--noise-threshold", "0.002", "--max-spp", str(own_spp), "--seed", str(REFERENCE_SEED),
                        "--output", os.path.join(outdir, own), scene], check=True)
    with open(os.path.join(outdir, "mjray_runs.jsonl"), "w") as f:
        for i, budget in enumerate(budgets):
            row = run_mjray(outdir, gi, budget, i + 1, name("mjray", budget, gi))
            f.write(json.dumps(dict(row, own_reference=own)) + "\n")


def sweep_main(outdir, gis):
    os.makedirs(outdir, exist_ok=True)
    cycles_twin.lua_scene(os.path.join(outdir, "twin.lua"))
    with open(os.path.join(outdir, "mjray_sweep.jsonl"), "w") as f:
        for i, gi in enumerate(gis):
            row = run_mjray(outdir, gi, SWEEP_BUDGET, i + 1, "sweep_" + name("mjray", SWEEP_BUDGET, gi))
            f.write(json.dumps(row) + "\n")


def blender_main(outdir, reference_samples, budgets):
    import bpy
    import numpy as np

    # The twin builds the room and renders it twice at one sample (which also warms Cycles up).
    os.makedirs(os.path.join(outdir, "twin"), exist_ok=True)
    cycles_twin.blender_main(os.path.join(outdir, "twin"), 1)
    scene = bpy.context.scene
    scene.objects["lamp"].data.energy = 4 * math.pi ** 2  # mjray's intensity 1 (see above)
    scene.cycles.max_bounces = 64  # the twin leaves it at 0, from its direct-only render
    scene.cycles.pixel_filter_type = "BOX"  # mjray's pixel: a one-pixel box
    scene.cycles.filter_width = 1.0
    scene.render.threads_mode = "FIXED"
    scene.render.threads = THREADS

    def render(image, samples, adaptive, seed, time_limit):
        scene.cycles.samples = samples
        scene.cycles.use_adaptive_sampling = adaptive  # at its default threshold, 0.01
        scene.cycles.seed = seed
        scene.cycles.time_limit = time_limit
        scene.render.filepath = os.path.join(outdir, image)
        start = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        return time.perf_counter() - start

    # The reference in two halves of different seeds, whose difference measures its own noise.
    reference = f"cycles_reference{reference_samples}"
    for seed, half in enumerate("ab", REFERENCE_SEED):
        if not os.path.exists(os.path.join(outdir, f"{reference}_{half}.exr")):
            render(f"{reference}_{half}.exr", reference_samples // 2, False, seed, 0)
    with open(os.path.join(outdir, "cycles_runs.jsonl"), "w") as f:
        for i, budget in enumerate(budgets):
            image = name("cycles", budget)
            idle = cpu_idle()
            seconds = render(image, 1 << 20, True, i + 1, budget)
            f.write(json.dumps({"renderer": "cycles", "budget": budget, "seconds": round(seconds, 3),
                                "idle": round(idle, 2), "image": image, "reference": reference}) + "\n")

    for file in sorted(os.listdir(outdir)):
        if file.endswith(".exr"):
            image = bpy.data.images.load(os.path.join(outdir, file))
            width, height = image.size
            pixels = np.empty(width * height * 4, np.float32)
            image.pixels.foreach_get(pixels)  # RGBA, rows from the bottom
            np.save(os.path.join(outdir, file[:-4] + ".npy"), pixels.reshape(height, width, 4)[::-1, :, :3])
            bpy.data.images.remove(image)


def load_rows(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def compare(outdir, gi):
    import numpy as np

    def pixels(image):
        return np.load(os.path.join(outdir, image.removesuffix(".exr") + ".npy")).astype(np.float64)

    def error(image, against):
        """sqrt(mean((A - R)^2)) / mean(R), A the image named, R the array `against`."""
        return float(np.sqrt(np.mean((pixels(image) - against) ** 2)) / np.mean(against))

    cycles_runs = {r["budget"]: r for r in load_rows(os.path.join(outdir, "cycles_runs.jsonl"))}
    mjray_runs = {r["budget"]: r for r in load_rows(os.path.join(outdir, "mjray_runs.jsonl")) if r["gi"] == gi}
    reference_name = next(iter(cycles_runs.values()))["reference"]
    a, b = pixels(reference_name + "_a"), pixels(reference_name + "_b")
    reference = (a + b) / 2
    # The noise of the mean of two independent halves: half the RMS of their difference.
    noise = float(np.sqrt(np.mean((a - b) ** 2)) / 2 / np.mean(reference))
    own_name = next(iter(mjray_runs.values()))["own_reference"]
    own = pixels(own_name)

    def net(e):
        """An error less the reference's own noise (independent of it, so in quadrature)."""
        return math.sqrt(max(e * e - noise * noise, 0))

    print(f"Cycles reference {reference_name}_a/_b.exr, its own noise {noise:.4f}; "
          f"mjray --gi {gi}, its own reference {own_name}.")
    print(f"mean of the Cycles reference over mjray's: {np.mean(reference) / np.mean(own):.4f}; "
          f"mjray's floor (its own reference against Cycles'): {error(own_name, reference):.4f}\n")
    print("| budget s | Cycles s | mjray s | Cycles error | mjray error | mjray error (own) | ratio | ratio ≤ 0.5 "
          "| ratio less the reference's noise |")
    print("|---|---|---|---|---|---|---|---|---|")
    lines, late = [], []
    for budget in sorted(set(cycles_runs) & set(mjray_runs)):
        c, m = cycles_runs[budget], mjray_runs[budget]
        row = {"budget": budget, "cycles_seconds": c["seconds"], "mjray_seconds": m["seconds"],
               "cycles_error": round(error(c["image"], reference), 5),
               "mjray_error": round(error(m["image"], reference), 5),
               "mjray_error_own": round(error(m["image"], own), 5), "gi": gi,
               "reference_noise": round(noise, 5), "cycles_idle": c["idle"], "mjray_idle": m["idle"]}
        row["ratio"] = round(row["mjray_error"] / row["cycles_error"], 4)
        row["ratio_ok"] = row["ratio"] <= 0.5
        row["ratio_net"] = round(net(row["mjray_error"]) / net(row["cycles_error"]), 4)
        row["equal_time"] = m["seconds"] <= 1.1 * c["seconds"]
        lines.append(row)
        if not row["equal_time"]:
            late.append(f"{budget:g}")
        print(f"| {budget:g} | {c['seconds']:.2f} | {m['seconds']:.2f} | {row['cycles_error']:.4f} | "
              f"{row['mjray_error']:.4f} | {row['mjray_error_own']:.4f} | {row['ratio']:.3f} | "
              f"{'yes' if row['ratio_ok'] else 'no'} | {row['ratio_net']:.3f} |")
    if late:
        print(f"\nNot at equal time (mjray took over 10 % longer than Cycles) at: {', '.join(late)} s.")

    sweep = load_rows(os.path.join(outdir, "mjray_sweep.jsonl"))
    if sweep:
        print(f"\nPhoton counts at {SWEEP_BUDGET:g} s (error against the Cycles reference):\n")
        print("| --gi | mjray s | mjray error |")
        print("|---|---|---|")
        for s in sweep:
            s["mjray_error"] = round(error(s["image"], reference), 5)
            lines.append({"sweep_budget": s["budget"], "gi": s["gi"], "mjray_seconds": s["seconds"],
                          "mjray_error": s["mjray_error"], "mjray_idle": s["idle"]})
            print(f"| {s['gi']} | {s['seconds']:.2f} | {s['mjray_error']:.4f} |")

    with open(os.path.join(outdir, "equal_time.jsonl"), "w") as f:
        for row in lines:
            f.write(json.dumps(row) + "\n")


if __name__ == "__main__":
    if "--" in sys.argv:  # inside Blender
        args = sys.argv[sys.argv.index("--") + 1:]
        blender_main(args[0], int(args[1]), [float(b) for b in args[2:]])
    elif sys.argv[1] == "mjray":
        mjray_main(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), [float(b) for b in sys.argv[5:]])
    elif sys.argv[1] == "sweep":
        sweep_main(sys.argv[2], [int(n) for n in sys.argv[3:]])
    elif sys.argv[1] == "compare":
        compare(sys.argv[2], int(sys.argv[3]))
