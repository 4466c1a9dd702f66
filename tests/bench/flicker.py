#!/usr/bin/env python3
"""flicker.py REGION FRAME.png... : how much a region that does not move
changes from frame to frame (issue 44: the flicker of per-frame radiosity
and photons). REGION is x0,y0,x1,y1 in pixels (x1, y1 excluded). Prints,
in 8-bit sRGB steps over the region's pixels and channels, the mean
temporal standard deviation (each pixel's spread over the frames) and the
root mean square difference between consecutive frames. Reads 8-bit RGB
or RGBA PNGs with the standard library alone (docs/benchmarks.md, "Issue 44:
the caustics example")."""
import math
import struct
import sys
import zlib


def read_png(path):
    data = open(path, 'rb').read()
    pos, width, height, idat, colour_type, depth = 8, 0, 0, b'', 0, 8
    while pos < len(data):
        n, = struct.unpack('>I', data[pos:pos + 4])
        kind, chunk = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b'IHDR':
            width, height, depth, colour_type = struct.unpack('>IIBB', chunk[:10])
        elif kind == b'IDAT':
            idat += chunk
    if depth != 8 or colour_type not in (2, 6):
        sys.exit(f'{path}: only 8-bit RGB or RGBA PNGs')
    channels = 3 if colour_type == 2 else 4
    raw, stride = zlib.decompress(idat), width * channels
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b, c = prev[x], prev[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        prev = line
    return rows


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    x0, y0, x1, y1 = (int(v) for v in sys.argv[1].split(','))
    frames = [read_png(p) for p in sys.argv[2:]]
    values = [[f[y][x][k] for f in frames] for y in range(y0, y1) for x in range(x0, x1)
              for k in range(3)]
    spread = sum(math.sqrt(sum((v - sum(s) / len(s)) ** 2 for v in s) / len(s))
                 for s in values) / len(values)
    steps = [(s[i + 1] - s[i]) ** 2 for s in values for i in range(len(s) - 1)]
    rms = math.sqrt(sum(steps) / len(steps))
    print(f'frames {len(frames)}, region {x1 - x0}x{y1 - y0}: temporal std {spread:.3f} steps, '
          f'frame-to-frame rms {rms:.3f} steps')


if __name__ == '__main__':
    main()
