#!/usr/bin/env python3
"""Records benchmark runs as JSON lines and turns them into markdown tables and CSV files.

The run_*.sh scripts call it; it needs only the Python standard library.

  results.py idle [SECONDS]                                   wait up to SECONDS for an idle machine;
                                                              print the idle fraction of all cores
  results.py record FILE key=value... [--stats STATS.json]   append one run to FILE (JSON lines)
  results.py accel ACCEL.jsonl OUTDIR                         accelerator tables + accel.csv
  results.py render RENDER.jsonl OUTDIR                       render tables + sweep/threads CSVs
  results.py povray POVRAY.jsonl OUTDIR                       mjray vs POV-Ray table + povray.csv
  results.py mpi MPI.jsonl OUTDIR                             ranks x threads table + mpi.csv
"""
import json
import os
import statistics
import sys
import time

# Targets, used to mark rows: those of the speed issue (12), which raised the acceleration
# issue's (0.8x, 2x, 3x, 1.85x).
BVH_RATE_TARGET = 1.0      # BVH rays/s >= Embree's
BVH_BUILD_TARGET = 1.5     # BVH build <= 1.5x Embree's
BVH_BYTES_TARGET = 70.0    # BVH bytes per triangle
GRID_VS_NONE_TARGET = 10.0
POVRAY_TARGET = 5.0
THREADS_TARGET = 1.9
MPI_TARGET = 0.95          # mpirun -np 2 -j 1 >= 0.95x the speed of mjray -j 2


def load(path):
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def median(values):
    return statistics.median(values) if values else float("nan")


def value(text):
    """key=value arguments: numbers become numbers, true/false booleans."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return {"true": True, "false": False}.get(text, text)


def record(argv):
    path, rest = argv[0], argv[1:]
    row = {}
    i = 0
    while i < len(rest):
        if rest[i] == "--stats":
            stats_path = rest[i + 1]
            i += 2
            if os.path.exists(stats_path) and os.path.getsize(stats_path) > 0:
                jobs = json.load(open(stats_path))
                if jobs:
                    row.update(jobs[0])
            continue
        key, _, text = rest[i].partition("=")
        row[key] = value(text)
        i += 1
    with open(path, "a") as f:
        f.write(json.dumps(row) + "\n")


def cpu_idle(interval=0.5):
    """Fraction of all cores idle over `interval` seconds (from /proc/stat)."""
    def sample():
        with open("/proc/stat") as f:
            fields = [int(x) for x in f.readline().split()[1:]]
        return sum(fields), fields[3] + fields[4]  # total, idle + iowait
    t0, i0 = sample()
    time.sleep(interval)
    t1, i1 = sample()
    return (i1 - i0) / max(1, t1 - t0)


def idle(argv):
    """Waits up to argv[0] seconds for the machine to be at least 90 % idle; prints the idle
    fraction last seen (the scripts record it beside each run)."""
    deadline = time.time() + float(argv[0]) if argv else 0
    while True:
        fraction = cpu_idle()
        if fraction >= 0.9 or time.time() >= deadline:
            print(f"{fraction:.2f}")
            return


def mesh_name(path):
    return os.path.splitext(os.path.basename(path))[0]


def idle_note(rows):
    """A sentence on how idle the machine was before the runs (recorded by the scripts)."""
    idles = sorted(r["idle"] for r in rows if "idle" in r)
    if not idles:
        return ""
    return (f" Machine idle before the runs: median {100 * median(idles):.0f} %, lowest {100 * idles[0]:.0f} % "
            "(2 cores; 50 % = one core busy with other work).")


def fmt(x, digits=2):
    if x is None or x != x:
        return "—"
    return f"{x:.{digits}f}"


def times(x):
    """A ratio as '1.23×', or a dash when unknown."""
    return "—" if x is None or x != x else f"{x:.2f}×"


def mark(ok):
    return "" if ok else " ✗"


def accel_tables(argv):
    rows, outdir = load(argv[0]), argv[1]
    meshes = sorted({(r["triangles"], r["mesh"]) for r in rows})
    accels = [a for a in ("bvh", "grid", "embree", "none") if any(r["accel"] == a for r in rows)]
    threads = sorted({r["threads"] for r in rows})
    kinds = [k for k in ("primary", "incoherent", "shadow") if any(r["ray_kind"] == k for r in rows)]

    def pick(mesh, accel, kind=None, j=None):
        return [r for r in rows if r["mesh"] == mesh and r["accel"] == accel
                and (kind is None or r["ray_kind"] == kind) and (j is None or r["threads"] == j)]

    out = []
    # Tracing: Mrays/s per accelerator and the ratio to Embree.
    out.append("| mesh | triangles | rays | -j | " + " | ".join(f"{a} Mrays/s" for a in accels) + " | "
               + " | ".join(f"{a}/embree" for a in accels if a != "embree") + " |")
    out.append("|---|---:|---|---:|" + "---:|" * len(accels) + "---:|" * (len(accels) - 1))
    csv = ["mesh,triangles,rays,threads," + ",".join(f"{a}_mrays" for a in accels)]
    for tris, mesh in meshes:
        for kind in kinds:
            for j in threads:
                rate = {a: median([r["rays_per_second"] for r in pick(mesh, a, kind, j)]) / 1e6 for a in accels}
                ratios = []
                for a in accels:
                    if a == "embree":
                        continue
                    ratio = rate[a] / rate["embree"] if "embree" in rate and rate["embree"] else float("nan")
                    ok = a != "bvh" or not ratio == ratio or ratio >= BVH_RATE_TARGET
                    ratios.append(fmt(ratio) + mark(ok))
                out.append(f"| {mesh_name(mesh)} | {tris:,} | {kind} | {j} | "
                           + " | ".join(fmt(rate[a], 2) for a in accels) + " | " + " | ".join(ratios) + " |")
                csv.append(f"{mesh_name(mesh)},{tris},{kind},{j}," + ",".join(f"{rate[a]:.4f}" for a in accels))
    out.append("")
    # Building and memory.
    out.append("| mesh | triangles | -j | " + " | ".join(f"{a} build s" for a in accels) + " | bvh/embree build | "
               + " | ".join(f"{a} B/tri" for a in accels) + " |")
    out.append("|---|---:|---:|" + "---:|" * len(accels) + "---:|" + "---:|" * len(accels))
    for tris, mesh in meshes:
        for j in threads:
            build = {a: median([r["build_seconds"] for r in pick(mesh, a, None, j)]) for a in accels}
            per_tri = {a: median([r["bytes_per_triangle"] for r in pick(mesh, a, None, j)]) for a in accels}
            ratio = build["bvh"] / build["embree"] if "bvh" in build and build.get("embree") else float("nan")
            bytes_cells = [fmt(per_tri[a], 1) + (mark(per_tri[a] <= BVH_BYTES_TARGET) if a == "bvh" else "")
                           for a in accels]
            out.append(f"| {mesh_name(mesh)} | {tris:,} | {j} | " + " | ".join(fmt(build[a], 4) for a in accels)
                       + f" | {fmt(ratio)}{mark(not ratio == ratio or ratio <= BVH_BUILD_TARGET)} | "
                       + " | ".join(bytes_cells) + " |")
    out.append("")
    out.append(f"✗ = misses its target (BVH rays/s ≥ {BVH_RATE_TARGET}× Embree, BVH build ≤ {BVH_BUILD_TARGET}× "
               f"Embree, BVH ≤ {BVH_BYTES_TARGET:.0f} B/triangle). Medians of each run's median-of-K."
               + idle_note(rows))
    # Consistency: every accelerator must report the same number of hits for the same rays.
    problems = []
    for tris, mesh in meshes:
        for kind in kinds:
            hits = {(r["accel"], r["rays"]): r["hits"] for r in rows if r["mesh"] == mesh and r["ray_kind"] == kind}
            by_count = {}
            for (a, n), h in hits.items():
                by_count.setdefault(n, {})[a] = h
            for n, per in by_count.items():
                if len(set(per.values())) > 1:
                    spread = max(per.values()) - min(per.values())
                    problems.append(f"{mesh_name(mesh)} {kind}: " + ", ".join(f"{a} {h:,}" for a, h in per.items())
                                    + f" of {n:,} rays ({spread} differ)")
    out.append("")
    if problems:
        out.append("Hit counts that differ between accelerators (rays grazing an edge or vertex; a large "
                   "difference would be a bug): " + "; ".join(problems) + ".")
    else:
        out.append("Every accelerator reported the same number of hits for the same rays.")
    write(outdir, "accel.md", out)
    write(outdir, "accel.csv", csv)


def render_tables(argv):
    rows, outdir = load(argv[0]), argv[1]

    def runs(experiment, scene, variant, threads=None):
        return [r for r in rows if r["experiment"] == experiment and r["scene"] == scene
                and r["variant"] == variant and (threads is None or r["threads"] == threads)]

    def summary(rs):
        """(median wall, median render, timed out limit or None)"""
        done = [r for r in rs if not r.get("timed_out")]
        if not done:
            return None, None, max((r.get("limit", 0) for r in rs), default=None)
        return median([r["wall"] for r in done]), median([r["seconds_render"] for r in done]), None

    def cell(wall, limit):
        return f"> {limit:g} (stopped)" if wall is None else fmt(wall, 3)

    out = []
    # Brute force vs grid vs BVH.
    compare = [r for r in rows if r["experiment"] == "compare"]
    scenes = list(dict.fromkeys(r["scene"] for r in compare))
    out.append("### Brute force vs grid (-o) vs BVH (whole-process seconds, median)")
    out.append("")
    note = idle_note(rows)
    if note:
        out.append(note.strip())
        out.append("")
    out.append("| scene | primitives | -j | none (-g 0) | grid (-o) | bvh | none / grid | grid / bvh |")
    out.append("|---|---:|---:|---:|---:|---:|---:|---:|")
    for scene in scenes:
        rs = [r for r in compare if r["scene"] == scene]
        prims = max((r.get("primitives", 0) for r in rs), default=0)
        j = rs[0]["threads"]
        w = {v: summary(runs("compare", scene, v)) for v in ("none", "grid-o", "bvh")}
        none, grid, bvh = (w[v][0] for v in ("none", "grid-o", "bvh"))
        if none is not None and grid:
            speedup = fmt(none / grid, 0) + "×" + mark(none / grid >= GRID_VS_NONE_TARGET)
        elif w["none"][2] is not None and grid:
            speedup = f"> {w['none'][2] / grid:.0f}×"
        else:
            speedup = "—"
        gb = fmt(grid / bvh, 1) + "×" if grid and bvh else (f"> {w['grid-o'][2] / bvh:.0f}×" if bvh and w["grid-o"][2] else "—")
        out.append(f"| {scene} | {prims:,} | {j} | {cell(none, w['none'][2]) if runs('compare', scene, 'none') else 'not run'} | "
                   f"{cell(grid, w['grid-o'][2])} | {cell(bvh, w['bvh'][2])} | {speedup} | {gb} |")
    out.append("")

    # Grid-size sweeps.
    sweep = [r for r in rows if r["experiment"] == "sweep"]
    for scene in dict.fromkeys(r["scene"] for r in sweep):
        rs = [r for r in sweep if r["scene"] == scene]
        out.append(f"### Render time vs grid size: {scene} (whole-process and render-only seconds, median)")
        out.append("")
        out.append("| -g | voxels | wall s | render s |")
        out.append("|---|---:|---:|---:|")
        csv = ["grid,wall,render,kind"]  # kind: 0 = -g N, 1 = -o, 2 = bvh (grid 0)
        variants = sorted({r["variant"] for r in rs}, key=lambda v: (v.startswith("grid-o"), v == "bvh", r_grid(v)))
        for v in variants:
            wall, render, limit = summary(runs("sweep", scene, v))
            g = r_grid(v)
            label = {"grid-o": "-o", "bvh": "bvh (reference)", "none": "0 (none)"}.get(v, str(g))
            res = grid_resolution(v, runs("sweep", scene, v))
            out.append(f"| {label} | {res or ''} | {cell(wall, limit)} | {fmt(render, 3) if render is not None else '—'} |")
            if v.startswith("g=") and wall is not None:
                csv.append(f"{g},{wall:.4f},{render:.4f},0")
            if v == "grid-o" and wall is not None and res:
                csv.append(f"{res},{wall:.4f},{render:.4f},1")
            if v == "bvh" and wall is not None:
                csv.append(f"0,{wall:.4f},{render:.4f},2")
        out.append("")
        write(outdir, f"sweep_{scene}.csv", csv)

    # Threads.
    threads = [r for r in rows if r["experiment"] == "threads"]
    if threads:
        out.append("### Time vs threads (bvh; medians)")
        out.append("")
        js = sorted({r["threads"] for r in threads})
        lo, hi = js[0], js[-1]
        out.append("| scene | " + " | ".join(f"-j {j} wall s" for j in js) + " | "
                   + " | ".join(f"-j {j} render s" for j in js) + " | " + " | ".join(f"-j {j} CPU s" for j in js)
                   + f" | wall speed-up | render speed-up | CPU -j {lo} / -j {hi} |")
        out.append("|---|" + "---:|" * (3 * len(js) + 3))
        csv = ["scene,threads,wall,render"]
        for scene in dict.fromkeys(r["scene"] for r in threads):
            walls, renders, cpus, limits = {}, {}, {}, {}
            for j in js:
                rs = [r for r in threads if r["scene"] == scene and r["threads"] == j]
                walls[j], renders[j], limits[j] = summary(rs)
                done = [r["cpu"] for r in rs if not r.get("timed_out") and "cpu" in r]
                cpus[j] = median(done) if done else None
                if walls[j] is not None:
                    csv.append(f"{scene},{j},{walls[j]:.4f},{renders[j]:.4f}")

            def ratio(a, b):
                return a / b if a is not None and b else None
            ws, rs_, cs = ratio(walls[lo], walls[hi]), ratio(renders[lo], renders[hi]), ratio(cpus[lo], cpus[hi])
            out.append(f"| {scene} | " + " | ".join(cell(walls[j], limits[j]) for j in js) + " | "
                       + " | ".join(fmt(renders[j], 3) for j in js) + " | " + " | ".join(fmt(cpus[j], 2) for j in js)
                       + f" | {times(ws)} | {times(rs_)}{mark(rs_ is None or rs_ >= THREADS_TARGET)} | {fmt(cs)} |")
        out.append("")
        out.append(f"✗ = render speed-up below the {THREADS_TARGET}× target. CPU = user + system seconds of the "
                   f"process; a CPU ratio near 1 means the {hi}-thread run does no more work than the 1-thread "
                   "one, so its wall-clock speed-up is limited by the cores it gets, not by the code."
                   + idle_note(threads))
        out.append("")
        write(outdir, "threads.csv", csv)
    write(outdir, "render.md", out)


def grid_resolution(variant, rs):
    """Voxels per axis the grid builds: -g N or 3·∛primitives for -o, capped at 256 (the grid
    may halve it further when the voxel lists would exceed its memory budget)."""
    if variant.startswith("g="):
        return min(256, int(variant[2:]))
    if variant == "grid-o":
        prims = max((r.get("primitives", 0) for r in rs), default=0)
        return min(256, max(1, round(3 * prims ** (1 / 3)))) if prims else None
    return None


def r_grid(variant):
    return int(variant[2:]) if variant.startswith("g=") else 10 ** 6


def povray_tables(argv):
    rows, outdir = load(argv[0]), argv[1]
    out = ["| scene | -j | mjray s | POV-Ray s | POV-Ray / mjray | mjray CPU s | POV-Ray CPU s | CPU ratio |",
           "|---|---:|---:|---:|---:|---:|---:|---:|"]
    csv = ["scene,threads,mjray,povray"]
    for scene in dict.fromkeys(r["scene"] for r in rows):
        for j in sorted({r["threads"] for r in rows if r["scene"] == scene}):
            t, cpu, failed = {}, {}, {}
            for program in ("mjray", "povray"):
                rs = [r for r in rows if r["scene"] == scene and r["threads"] == j and r["program"] == program]
                ok = [r for r in rs if r.get("status", 0) == 0]
                t[program] = median([r["wall"] for r in ok]) if ok else None
                cpus = [r["cpu"] for r in ok if "cpu" in r]
                cpu[program] = median(cpus) if cpus else None
                failed[program] = len(rs) - len(ok)
            if t["mjray"] is None or t["povray"] is None:
                out.append(f"| {scene} | {j} | {cell_or_fail(t['mjray'], failed['mjray'])} | "
                           f"{cell_or_fail(t['povray'], failed['povray'])} | — |")
                continue
            ratio = t["povray"] / t["mjray"]
            cpu_ratio = cpu["povray"] / cpu["mjray"] if cpu["mjray"] and cpu["povray"] else None
            out.append(f"| {scene} | {j} | {fmt(t['mjray'], 3)} | {fmt(t['povray'], 3)} | {fmt(ratio)}×{mark(ratio >= POVRAY_TARGET)} | "
                       f"{fmt(cpu['mjray'])} | {fmt(cpu['povray'])} | {times(cpu_ratio)} |")
            csv.append(f"{scene},{j},{t['mjray']:.4f},{t['povray']:.4f}")
    out.append("")
    out.append(f"Whole-process wall time and CPU time (user + system), medians of the runs; ✗ = below the "
               f"{POVRAY_TARGET:.0f}× target." + idle_note(rows))
    write(outdir, "povray.md", out)
    write(outdir, "povray.csv", csv)


def mpi_tables(argv):
    """Issue 15: speed-up and efficiency against ranks x threads, per-rank start-up and bytes."""
    rows, outdir = load(argv[0]), argv[1]
    cores = os.cpu_count() or 1
    out, csv = [], ["scene,ranks,threads,wall,speedup,efficiency"]
    launch = [r for r in rows if r["scene"] == "launch" and r["status"] == 0]
    if launch:
        out += ["Open MPI's fixed cost, `mpirun -np R mjray-mpi --version` (start R ranks, MPI_Init, "
                "MPI_Finalize): " + ", ".join(
                    f"R = {n}: {median([r['wall'] for r in launch if r['np'] == n]):.3f} s"
                    for n in dict.fromkeys(r["np"] for r in launch)) + ".", ""]
    for scene in dict.fromkeys(r["scene"] for r in rows if r["scene"] != "launch"):
        rs = [r for r in rows if r["scene"] == scene and r["status"] == 0]
        configs = list(dict.fromkeys((r["np"], r["j"]) for r in rs))
        wall = {c: median([r["wall"] for r in rs if (r["np"], r["j"]) == c]) for c in configs}
        base = wall.get((0, 1))
        out += [f"### {scene}", "",
                "| program | ranks × threads | wall s | CPU s | speed-up vs mjray -j 1 | efficiency (per thread) | "
                "efficiency (per core) | load s (slowest rank) | build s (slowest rank) | MB sent (all ranks) | same bytes |",
                "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
        for c in configs:
            ranks, threads = c
            runs = [r for r in rs if (r["np"], r["j"]) == c]
            per = [r["ranks"] for r in runs if isinstance(r.get("ranks"), list)]
            def slowest(key, local_key):
                values = [max(x[key] for x in p) for p in per] or [r[local_key] for r in runs if local_key in r]
                return fmt(median(values), 3)
            sent = [sum(x["bytes_sent"] for x in p) / 1e6 for p in per]
            workers = max(ranks, 1) * threads
            speedup = base / wall[c] if base else float("nan")
            program = "mjray" if ranks == 0 else "mjray-mpi"
            same = all(r.get("same_image") for r in runs)
            cpu = median([r["cpu"] for r in runs if "cpu" in r])
            out.append(f"| {program} | {max(ranks, 1)} × {threads} | {fmt(wall[c], 3)} | {fmt(cpu)} | {times(speedup)} | "
                       f"{fmt(speedup / workers)} | {fmt(speedup / min(workers, cores))} | {slowest('seconds_load', 'seconds_parse')} | "
                       f"{slowest('seconds_build', 'seconds_build')} | {fmt(median(sent), 3) if sent else '–'} | {'yes' if same else 'NO'} |")
            csv.append(f"{scene},{ranks},{threads},{wall[c]:.4f},{speedup:.4f},{speedup / workers:.4f}")
        if (0, 2) in wall and (2, 1) in wall:
            ratio = wall[(0, 2)] / wall[(2, 1)]
            out += ["", f"mpirun -np 2 -j 1 against mjray -j 2: {ratio:.3f}× the speed "
                    f"(target ≥ {MPI_TARGET}){mark(ratio >= MPI_TARGET)}"]
        out.append("")
    out.append("Whole-process wall time and CPU time (user + system of mpirun and every rank), medians of "
               "the runs; ✗ = below the target; "
               "per-core efficiency divides by min(ranks × threads, cores)." + idle_note(rows))
    write(outdir, "mpi.md", out)
    write(outdir, "mpi.csv", csv)


def cell_or_fail(t, failed):
    return fmt(t, 3) if t is not None else f"failed ({failed} runs)"


def write(outdir, name, lines):
    os.makedirs(outdir, exist_ok=True)
    with open(os.path.join(outdir, name), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    commands = {"idle": idle, "record": record, "accel": accel_tables, "render": render_tables, "povray": povray_tables,
                "mpi": mpi_tables}
    if len(sys.argv) < 2 or sys.argv[1] not in commands or (sys.argv[1] != "idle" and len(sys.argv) < 3):
        sys.exit(__doc__)
    commands[sys.argv[1]](sys.argv[2:])
