#!/usr/bin/env python3
"""Writes listings/scenes/sign.png, the small PNG scene of listings/scenes/sign.json.

A 160x96 RGBA image: a dark wall (alpha 0: lit, does not glow), a pink neon frame and a
cyan bar (alpha 255: glow), three small lamps (alpha 255) and an amber panel at half alpha
(alpha 128: glows at half strength). Only python3's zlib and struct, so that anyone can
re-make the file: python3 scripts/make_scene_png.py
"""
import os
import struct
import zlib

WIDTH, HEIGHT = 160, 96


def chunk(kind: bytes, data: bytes) -> bytes:
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def png_bytes(pixels) -> bytes:
    rows = b"".join(b"\x00" + bytes(v for px in row for v in px) for row in pixels)
    header = struct.pack(">IIBBBBB", WIDTH, HEIGHT, 8, 6, 0, 0, 0)  # 8-bit RGBA
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def make_pixels():
    wall = (24, 20, 30, 0)
    px = [[wall for _ in range(WIDTH)] for _ in range(HEIGHT)]

    def fill(x0, y0, x1, y1, colour):
        for y in range(max(0, y0), min(HEIGHT, y1)):
            for x in range(max(0, x0), min(WIDTH, x1)):
                px[y][x] = colour

    fill(36, 50, 124, 80, (200, 140, 40, 128))  # amber panel, half glow
    pink = (255, 60, 170, 255)
    fill(20, 12, 140, 14, pink)  # the frame, 2 px thick
    fill(20, 40, 140, 42, pink)
    fill(20, 12, 22, 42, pink)
    fill(138, 12, 140, 42, pink)
    fill(40, 25, 120, 28, (60, 230, 255, 255))  # cyan bar
    for cx, cy in ((12, 86), (80, 88), (150, 86)):  # lamps, radius 3
        for y in range(cy - 3, cy + 4):
            for x in range(cx - 3, cx + 4):
                if (x - cx) ** 2 + (y - cy) ** 2 <= 9:
                    fill(x, y, x + 1, y + 1, (255, 250, 220, 255))
    return px


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = os.path.join(root, "listings", "scenes", "sign.png")
    with open(out, "wb") as f:
        f.write(png_bytes(make_pixels()))
    print(out)


if __name__ == "__main__":
    main()
