#!/usr/bin/env python3
"""Writes a torus as a Wavefront OBJ with per-vertex normals and UVs (for scenes/Assets/meshes/).

usage: make_torus.py OUT.obj [major_radius minor_radius rings sides]
"""
import math
import sys


def main():
    out = sys.argv[1]
    big, small, rings, sides = 1.0, 0.35, 48, 24
    if len(sys.argv) > 2:
        big, small, rings, sides = float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
    lines = [f"# torus R={big} r={small}, {rings}x{sides}, made by scripts/make_torus.py"]
    for i in range(rings):
        u = 2 * math.pi * i / rings
        for j in range(sides):
            v = 2 * math.pi * j / sides
            cx, cz = math.cos(u), math.sin(u)
            x = (big + small * math.cos(v)) * cx
            y = small * math.sin(v)
            z = (big + small * math.cos(v)) * cz
            lines.append(f"v {x:.6f} {y:.6f} {z:.6f}")
            lines.append(f"vn {math.cos(v) * cx:.6f} {math.sin(v):.6f} {math.cos(v) * cz:.6f}")
            lines.append(f"vt {i / rings:.6f} {j / sides:.6f}")
    for i in range(rings):
        for j in range(sides):
            a = i * sides + j + 1
            b = ((i + 1) % rings) * sides + j + 1
            c = ((i + 1) % rings) * sides + (j + 1) % sides + 1
            d = i * sides + (j + 1) % sides + 1
            lines.append(f"f {a}/{a}/{a} {d}/{d}/{d} {c}/{c}/{c} {b}/{b}/{b}")
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
