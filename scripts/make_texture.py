#!/usr/bin/env python3
"""Writes the UV test texture of scenes/features/image_texture.lua as an 8-bit RGB PNG, using
only the standard library (zlib + struct).

The picture tells its orientation at a glance: an 8x8 grid whose cells grow redder with u and
greener with v, a large "F" (asymmetric both ways, so a mirrored or flipped mapping shows), an
arrow pointing up (+v) and a white square in the bottom-left corner, where (u, v) = (0, 0).

usage: make_texture.py OUT.png [size]
"""
import sys

from rgb_png import write_png


def main():
    out = sys.argv[1]
    size = int(sys.argv[2]) if len(sys.argv) > 2 else 256

    def inside(u, v, box):
        u0, v0, u1, v1 = box
        return u0 <= u < u1 and v0 <= v < v1

    # Shapes in (u, v), v up, as fractions of the image.
    letter_f = [(0.16, 0.22, 0.28, 0.80), (0.16, 0.68, 0.52, 0.80), (0.16, 0.46, 0.44, 0.57)]
    arrow_shaft = (0.70, 0.22, 0.78, 0.62)
    origin_mark = (0.0, 0.0, 0.08, 0.08)

    def arrow_head(u, v):
        # a triangle with its tip at (0.74, 0.84) and base from 0.62 to 0.86 at v = 0.62
        return 0.62 <= v < 0.84 and abs(u - 0.74) < 0.12 * (0.84 - v) / 0.22

    def pixel(x, y):
        u = (x + 0.5) / size
        v = 1 - (y + 0.5) / size
        if inside(u, v, origin_mark):
            return (255, 255, 255)
        if any(inside(u, v, b) for b in letter_f):
            return (250, 170, 30)
        if inside(u, v, arrow_shaft) or arrow_head(u, v):
            return (60, 220, 90)
        cell_u, cell_v = int(u * 8), int(v * 8)
        line = (x % (size // 8)) in (0, size // 8 - 1) or (y % (size // 8)) in (0, size // 8 - 1)
        shade = 0.55 if line else (0.85 if (cell_u + cell_v) % 2 == 0 else 0.7)
        return (int(255 * shade * (0.15 + 0.85 * cell_u / 7)), int(255 * shade * (0.15 + 0.85 * cell_v / 7)),
                int(255 * shade * 0.6))

    write_png(out, size, size, pixel)


if __name__ == "__main__":
    main()
