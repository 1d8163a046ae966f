"""8-bit RGB PNG files from the standard library alone (zlib + struct), for the scripts that
draw the shipped textures."""
import struct
import zlib


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def to_bytes(rgb):
    """(r, g, b) floats in [0, 1] -> 8-bit values, rounded and clamped."""
    return [max(0, min(255, int(c * 255 + 0.5))) for c in rgb]


def write_png(path, width, height, pixel):
    """pixel(x, y) -> (r, g, b) 8-bit values, y = 0 the top row as PNG stores rows."""
    raw = bytearray()
    for y in range(height):
        raw.append(0)  # filter type None
        for x in range(width):
            raw.extend(pixel(x, y))
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", header) +
                png_chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + png_chunk(b"IEND", b""))
