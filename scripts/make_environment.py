#!/usr/bin/env python3
"""Writes the environment of docs/images/gr_background.lua: an equirectangular (latitude-
longitude) 8-bit RGB PNG of a clear sky over a checkered plain with hills, using only the
standard library (zlib + struct).

Its layout is gr.background's: the centre column looks along -z, the right quarter along +x,
the top row straight up. The sun stands high on the right (+x side, towards -z), so that a
mirror ball shows where each part of the sky went.

usage: make_environment.py OUT.png [width]
"""
import math
import sys

from rgb_png import write_png, to_bytes


def direction(x, y, width, height):
    theta = math.pi * (y + 0.5) / height
    phi = 2 * math.pi * ((x + 0.5) / width - 0.5)
    return (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi)), phi


def mix(a, b, t):
    return tuple(p + (q - p) * t for p, q in zip(a, b))


def main():
    out = sys.argv[1]
    width = int(sys.argv[2]) if len(sys.argv) > 2 else 512
    height = width // 2
    sun = (0.55, 0.6, -0.58)
    norm = math.sqrt(sum(c * c for c in sun))
    sun = tuple(c / norm for c in sun)

    def pixel(x, y):
        (dx, dy, dz), phi = direction(x, y, width, height)
        hills = 0.06 + 0.04 * math.sin(3 * phi + 1) + 0.025 * math.sin(7 * phi + 2) + 0.015 * math.sin(17 * phi)
        if dy > hills:
            # Sky: deep blue overhead, pale at the horizon, a sun with a glow.
            colour = mix((0.75, 0.85, 0.95), (0.18, 0.36, 0.72), min(1, max(0, dy) / 0.7) ** 0.6)
            cos_sun = dx * sun[0] + dy * sun[1] + dz * sun[2]
            if cos_sun > math.cos(math.radians(3)):
                return (1, 0.98, 0.9)
            glow = max(0, cos_sun) ** 40 * 0.5
            return tuple(min(1, c + glow) for c in colour)
        if dy > 0:
            return mix((0.3, 0.45, 0.3), (0.22, 0.35, 0.24), dy / max(hills, 1e-6))  # hills
        # Ground: a checkered plain, its squares shrinking towards the horizon.
        t = 1 / max(-dy, 1e-3)
        u, v = dx * t, dz * t
        check = (math.floor(u) + math.floor(v)) % 2
        base = (0.55, 0.5, 0.38) if check else (0.35, 0.42, 0.28)
        return mix(base, (0.6, 0.66, 0.7), min(1, max(0, (t - 6) / 40)))

    write_png(out, width, height, lambda x, y: to_bytes(pixel(x, y)))


if __name__ == "__main__":
    main()
