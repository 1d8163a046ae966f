#!/usr/bin/env python3
"""Times commands in alternated rounds (A, B, A, B, ...) and prints, for each, the median wall
time and the median of its per-round speed-up against the first command. On a machine whose
speed drifts from minute to minute, only such side-by-side ratios mean much.

    bench/alternate.py 40 'old/mjray --quiet -r 4 -j 2 ../shared/bench/spheres.lua --output /tmp/a.png' \\
                          'build/mjray --quiet -r 4 -j 2 ../shared/bench/spheres.lua --output /tmp/b.png'
"""
import statistics
import subprocess
import sys
import time


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    rounds, commands = int(sys.argv[1]), sys.argv[2:]
    times = [[] for _ in commands]
    for _ in range(rounds):
        for i, command in enumerate(commands):
            start = time.perf_counter()
            done = subprocess.run(command, shell=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            times[i].append(time.perf_counter() - start)
            if done.returncode != 0:
                sys.exit(f"failed ({done.returncode}): {command}")
    for i, command in enumerate(commands):
        speedup = statistics.median(times[0][k] / times[i][k] for k in range(rounds))
        print(f"{statistics.median(times[i]) * 1000:8.1f} ms median  {speedup:.3f}x the first  {command}")


if __name__ == "__main__":
    main()
