#!/usr/bin/env python3
"""Writes listings/scenes/lamp.png, the sparse scene of listings/scenes/lamp.json.

A 1280x720 RGBA image: a dark room (alpha 0: does not glow) with one warm 60x40 lamp near
the top-right corner (alpha 255: glows). The glow's pruning limits every pass to the lamp's
neighbourhood on this scene (docs/command-line.md, `tierlift glow --explain`). Only
python3's zlib and struct, so that anyone can re-make the file:
python3 scripts/make_lamp_png.py
"""
import os
import struct
import zlib

from make_scene_png import chunk

WIDTH, HEIGHT = 1280, 720
LAMP = (1080, 80, 1140, 120)  # x0, y0, x1, y1 (exclusive)


def row(y: int) -> bytes:
    room, lamp = bytes((20, 20, 30, 0)), bytes((255, 220, 120, 255))
    x0, y0, x1, y1 = LAMP
    if not y0 <= y < y1:
        return b"\x00" + room * WIDTH
    return b"\x00" + room * x0 + lamp * (x1 - x0) + room * (WIDTH - x1)


def main() -> None:
    header = struct.pack(">IIBBBBB", WIDTH, HEIGHT, 8, 6, 0, 0, 0)  # 8-bit RGBA
    rows = b"".join(row(y) for y in range(HEIGHT))
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
           chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
    out = os.path.join(os.path.dirname(__file__), "..", "listings", "scenes", "lamp.png")
    with open(out, "wb") as f:
        f.write(png)


if __name__ == "__main__":
    main()
