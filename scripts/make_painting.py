#!/usr/bin/env python3
"""Writes the painting that hangs in scenes/final_scene.lua: a lake under an evening sky, with
mountains, hills and trees, in loose brush strokes. An 8-bit sRGB PNG made with the standard
library only (zlib + struct); deterministic.

usage: make_painting.py [OUT.png] [width height]   (default scenes/Assets/textures/painting.png 480 360)
"""
import math
import os
import sys

from rgb_png import write_png_rows


def lattice(ix, iy, seed):
    """A repeatable pseudo-random value in [0, 1) for a lattice point."""
    h = (ix * 374761393 + iy * 668265263 + seed * 2147483647) & 0xFFFFFFFF
    h = ((h ^ (h >> 13)) * 1274126177) & 0xFFFFFFFF
    return ((h ^ (h >> 16)) & 0xFFFFFF) / float(1 << 24)


def noise(x, y, seed=0):
    """Smooth value noise in [0, 1)."""
    ix, iy = math.floor(x), math.floor(y)
    fx, fy = x - ix, y - iy
    sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
    a, b = lattice(ix, iy, seed), lattice(ix + 1, iy, seed)
    c, d = lattice(ix, iy + 1, seed), lattice(ix + 1, iy + 1, seed)
    return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy


def fbm(x, y, octaves, seed=0):
    total, amplitude, scale, norm = 0.0, 1.0, 1.0, 0.0
    for o in range(octaves):
        total += amplitude * noise(x * scale, y * scale, seed + o)
        norm += amplitude
        amplitude *= 0.5
        scale *= 2.03
    return total / norm


def mix(a, b, t):
    return tuple(a[i] + (b[i] - a[i]) * t for i in range(3))


def clamp01(v):
    return 0.0 if v < 0 else 1.0 if v > 1 else v


def sky(u, v):
    """Evening sky: warm at the horizon (v = 0.62), deep blue above; a low sun."""
    t = clamp01((0.62 - v) / 0.62)
    colour = mix((0.98, 0.72, 0.42), (0.97, 0.55, 0.38), clamp01(t * 3))
    colour = mix(colour, (0.45, 0.55, 0.78), clamp01((t - 0.25) * 1.6))
    colour = mix(colour, (0.22, 0.3, 0.58), clamp01((t - 0.7) * 2.5))
    # The sun and its glow.
    d = math.hypot((u - 0.66) * 1.333, v - 0.41)
    glow = math.exp(-d * 9) * 0.7
    colour = mix(colour, (1.0, 0.92, 0.7), clamp01(glow))
    if d < 0.045:
        colour = mix(colour, (1.0, 0.97, 0.85), 0.9)
    # Streaks of cloud, stretched sideways.
    c = fbm(u * 3, v * 14, 4, 11)
    if c > 0.55 and v < 0.55:
        colour = mix(colour, (0.95, 0.62, 0.55), clamp01((c - 0.55) * 3) * 0.7)
    return colour


def ridge(u, base, height, frequency, seed):
    return base - height * fbm(u * frequency, 0.5, 5, seed)


def landscape(u, v):
    """The colour at (u, v), u to the right and v down, both in [0, 1)."""
    horizon = 0.62
    far = ridge(u, 0.63, 0.17, 3.0, 3)
    mid = ridge(u, 0.66, 0.12, 5.0, 5)
    if v < far:
        return sky(u, v)
    if v < horizon:
        haze = clamp01((v - far) / max(horizon - far, 1e-3))
        colour = mix((0.52, 0.5, 0.68), (0.42, 0.44, 0.6), haze)
        if v > mid:
            colour = mix((0.28, 0.42, 0.3), (0.2, 0.33, 0.22), fbm(u * 20, v * 20, 3, 7))
        return colour
    # The lake: the sky and hills mirrored, broken by ripples, darker toward the shore.
    shore = 0.86 + 0.03 * math.sin(u * 9) + 0.03 * fbm(u * 6, 0.1, 3, 9)
    if v < shore:
        mirrored = 2 * horizon - v + 0.01 * math.sin(v * 180 + fbm(u * 8, v * 40, 2, 13) * 6)
        colour = landscape(u, min(max(mirrored, 0.0), horizon - 1e-4))
        colour = mix(colour, (0.2, 0.3, 0.42), 0.35 + 0.3 * (v - horizon) / (shore - horizon))
        return colour
    # The meadow in front, with a few dark trees on the left.
    grass = mix((0.36, 0.46, 0.18), (0.2, 0.3, 0.12), fbm(u * 30, v * 12, 4, 17))
    return grass


def trees(u, v, colour):
    for cx, top, width in ((0.12, 0.5, 0.05), (0.19, 0.56, 0.04), (0.06, 0.58, 0.035)):
        if top < v < 0.9 and abs(u - cx) < width * (v - top) / (0.9 - top) * 1.6 + 0.004:
            shade = 0.12 + 0.08 * fbm(u * 60, v * 60, 2, 19)
            return (shade * 0.7, shade * 1.2, shade * 0.8)
    return colour


def brush(u, v, colour):
    """Loose strokes: short diagonal dabs that lighten or darken the paint a little."""
    stroke = fbm(u * 60 + v * 25, v * 90 - u * 10, 2, 23) - 0.5
    grain = noise(u * 400, v * 400, 29) - 0.5
    return tuple(clamp01(c * (1 + 0.22 * stroke) + 0.03 * grain) for c in colour)


def to_srgb8(linear):
    v = clamp01(linear)
    v = 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055
    return int(v * 255 + 0.5)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "scenes", "Assets", "textures", "painting.png")
    width = int(sys.argv[2]) if len(sys.argv) > 3 else 480
    height = int(sys.argv[3]) if len(sys.argv) > 3 else 360
    rows = []
    for y in range(height):
        row = bytearray()
        for x in range(width):
            u, v = (x + 0.5) / width, (y + 0.5) / height
            # The colours above are display (sRGB-looking) values: encode them as given.
            colour = brush(u, v, trees(u, v, landscape(u, v)))
            row.extend(int(clamp01(c) * 255 + 0.5) for c in colour)
        rows.append(row)
    # An sRGB chunk: the values are sRGB-encoded, as a painting photographed would be.
    write_png_rows(out, width, height, rows, srgb=True)
    print("wrote", out)


if __name__ == "__main__":
    main()
