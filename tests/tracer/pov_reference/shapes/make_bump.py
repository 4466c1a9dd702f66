#!/usr/bin/python3
# Writes bump.png for height_field.pov: a 32 x 32 16-bit gray image of a
# smooth bump (a Gaussian hill off centre, a gentle ridge along the image's
# rows so that the top/bottom row order shows), with PIL.
#
# 16-bit, not 8: POV-Ray 3.7 reads 85 of the 256 levels of an 8-bit gray
# PNG one level low (measured with trace(): 3 -> 2, 50 -> 49, 127 -> 126,
# ...), through its image reader's gamma handling; its 16-bit gray levels
# are exact, and hexant reads both exactly.
import math
from PIL import Image

W = H = 32
img = Image.new("I;16", (W, H))
for y in range(H):
    for x in range(W):
        u, v = x / (W - 1), y / (H - 1)
        hill = math.exp(-((u - 0.4) ** 2 + (v - 0.35) ** 2) / 0.04)
        ridge = 0.25 * (1.0 - v)  # higher toward the image's top row
        img.putpixel((x, y), int(round(65535 * min(1.0, 0.05 + 0.7 * hill + ridge))))
img.save("bump.png")
