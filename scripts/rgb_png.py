"""8-bit RGB PNG files from the standard library alone (zlib + struct), for the scripts that
draw the shipped textures."""
import struct
import zlib


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def to_bytes(rgb):
    """(r, g, b) floats in [0, 1] -> 8-bit values, rounded and clamped."""
    return [max(0, min(255, int(c * 255 + 0.5))) for c in rgb]


def write_png_rows(path, width, height, rows, srgb=False):
    """rows: `height` byte strings of width·3 8-bit RGB values, top row first. With `srgb` the
    file says its values are sRGB-encoded (an sRGB chunk)."""
    raw = bytearray()
    for row in rows:
        raw.append(0)  # filter type None
        raw.extend(row)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    extra = png_chunk(b"sRGB", bytes([0])) if srgb else b""
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", header) + extra +
                png_chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + png_chunk(b"IEND", b""))


def write_png(path, width, height, pixel):
    """pixel(x, y) -> (r, g, b) 8-bit values, y = 0 the top row as PNG stores rows."""
    rows = (bytes(v for x in range(width) for v in pixel(x, y)) for y in range(height))
    write_png_rows(path, width, height, rows)
