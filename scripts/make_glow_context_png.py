#!/usr/bin/env python3
"""Writes listings/scenes/sign-glow.png, the glow render of listings/scenes/glow-context.json.

A rendering context (Tron 2.0): the sign of sign.png drawn a second time, the way it should
glow, each object with its own glow colour (rgb) and strength (alpha). 160x96 RGBA, the size
of sign.png. The pink frame glows violet at full strength, the cyan bar not at all (it is lit
but does not glow), the three lamps warm orange at full strength, the amber panel green at a
quarter strength; the wall is black with alpha 0. The scene image's own alpha is not used.
Re-make it with: python3 scripts/make_glow_context_png.py
"""
import os

from make_scene_png import HEIGHT, WIDTH, png_bytes


def make_pixels():
    px = [[(0, 0, 0, 0) for _ in range(WIDTH)] for _ in range(HEIGHT)]

    def fill(x0, y0, x1, y1, colour):
        for y in range(max(0, y0), min(HEIGHT, y1)):
            for x in range(max(0, x0), min(WIDTH, x1)):
                px[y][x] = colour

    fill(36, 50, 124, 80, (60, 255, 90, 64))  # the panel: green, a quarter strength
    violet = (150, 60, 255, 255)
    fill(20, 12, 140, 14, violet)  # the frame, as in sign.png
    fill(20, 40, 140, 42, violet)
    fill(20, 12, 22, 42, violet)
    fill(138, 12, 140, 42, violet)
    for cx, cy in ((12, 86), (80, 88), (150, 86)):  # lamps, radius 3
        for y in range(cy - 3, cy + 4):
            for x in range(cx - 3, cx + 4):
                if (x - cx) ** 2 + (y - cy) ** 2 <= 9:
                    fill(x, y, x + 1, y + 1, (255, 140, 30, 255))
    return px


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = os.path.join(root, "listings", "scenes", "sign-glow.png")
    with open(out, "wb") as f:
        f.write(png_bytes(make_pixels()))
    print(out)


if __name__ == "__main__":
    main()
