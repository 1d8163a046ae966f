#!/usr/bin/env python3
"""Writes the Cornell box of scenes/features/cornell_box.lua as an OBJ file with its MTL file,
the way a modelling program exports one: a room of 5.5 units open toward -z (red wall at
+x, on the left as seen from -z; green at -x), a ceiling with a light panel, a tall and a short block turned on the floor,
and one `usemtl` group per material. The panel's material glows (Ke), and a glass ball's is
clear glass (illum 7, Ni 1.5).

usage: scripts/make_cornell_box.py [OUTDIR]   (default scenes/Assets/meshes)
"""
import math
import os
import sys

S = 5.5  # the room's size


def block(cx, cz, w, d, h, turn_degrees):
    """The 5 visible faces of a block (no bottom) as quads, turned about its centre."""
    a = math.radians(turn_degrees)
    c, s = math.cos(a), math.sin(a)

    def at(x, y, z):
        return (cx + x * c - z * s, y, cz + x * s + z * c)

    x, z = w / 2, d / 2
    top = [at(-x, h, -z), at(-x, h, z), at(x, h, z), at(x, h, -z)]
    sides = []
    corners = [(-x, -z), (x, -z), (x, z), (-x, z)]
    for i in range(4):
        (x0, z0), (x1, z1) = corners[i], corners[(i + 1) % 4]
        sides.append([at(x0, 0, z0), at(x0, h, z0), at(x1, h, z1), at(x1, 0, z1)])
    return [top] + sides


def sphere(cx, cy, cz, r, rings=16, segments=32):
    """A UV sphere as triangles and quads, wound outward."""
    def at(i, j):
        t, p = math.pi * i / rings, 2 * math.pi * j / segments
        return (cx + r * math.sin(t) * math.cos(p), cy + r * math.cos(t), cz + r * math.sin(t) * math.sin(p))
    faces = []
    for i in range(rings):
        for j in range(segments):
            quad = [at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)]
            faces.append(quad[:3] if i == 0 else [quad[0], quad[2], quad[3]] if i == rings - 1 else quad)
    return faces


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "scenes/Assets/meshes"
    hole = 1.3  # the light panel's size
    lo, hi = (S - hole) / 2, (S + hole) / 2
    groups = {
        "floor": [[(0, 0, 0), (0, 0, S), (S, 0, S), (S, 0, 0)]],
        "back_wall": [[(0, 0, S), (0, S, S), (S, S, S), (S, 0, S)]],
        "ceiling": [[(0, S, 0), (S, S, 0), (S, S, lo), (0, S, lo)], [(0, S, hi), (S, S, hi), (S, S, S), (0, S, S)],
                    [(0, S, lo), (lo, S, lo), (lo, S, hi), (0, S, hi)], [(hi, S, lo), (S, S, lo), (S, S, hi), (hi, S, hi)]],
        "green_wall": [[(0, 0, 0), (0, S, 0), (0, S, S), (0, 0, S)]],
        "red_wall": [[(S, 0, 0), (S, 0, S), (S, S, S), (S, S, 0)]],
        "light": [[(lo, S - 0.01, lo), (hi, S - 0.01, lo), (hi, S - 0.01, hi), (lo, S - 0.01, hi)]],
        "tall_block": block(3.7, 3.6, 1.65, 1.65, 3.3, 17),
        "short_block": block(1.85, 1.7, 1.65, 1.65, 1.65, -18),
        "glass": sphere(1.85, 1.65 + 0.7, 1.7, 0.7),
    }
    materials = {
        "floor": "Kd 0.725 0.71 0.68", "back_wall": "Kd 0.725 0.71 0.68", "ceiling": "Kd 0.725 0.71 0.68",
        "red_wall": "Kd 0.63 0.065 0.05", "green_wall": "Kd 0.14 0.45 0.091",
        "light": "Kd 0.78 0.78 0.78\nKe 17 12 4", "tall_block": "Kd 0.725 0.71 0.68", "short_block": "Kd 0.725 0.71 0.68",
        "glass": "Kd 0 0 0\nKs 0.9 0.9 0.9\nNs 800\nNi 1.5\nillum 7",
    }
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "cornell_box.mtl"), "w") as f:
        f.write("# The Cornell box of scenes/features/cornell_box.lua: written by scripts/make_cornell_box.py\n")
        for name, body in materials.items():
            f.write(f"\nnewmtl {name}\nKa 0 0 0\n{body}\n")
    with open(os.path.join(out, "cornell_box.obj"), "w") as f:
        f.write("# The Cornell box of scenes/features/cornell_box.lua: written by scripts/make_cornell_box.py\n")
        f.write("mtllib cornell_box.mtl\n")
        count = 0
        for name, faces in groups.items():
            f.write(f"o {name}\nusemtl {name}\n")
            for face in faces:  # wound so that walls face into the room, blocks outward
                for v in face:
                    f.write("v %.4f %.4f %.4f\n" % v)
                f.write("f " + " ".join(str(count + 1 + i) for i in range(len(face))) + "\n")
                count += len(face)


if __name__ == "__main__":
    main()
