# Writes the test images of gif.pov (indexed.gif, heights.pot) with the
# standard library alone: GIF blocks by hand, LZW as literal codes with a
# clear code before the table would widen them, so that the bytes are fixed.
import math, struct

def lzw(indices, m):
    clear, end = 1 << m, (1 << m) + 1
    width, every = m + 1, (1 << m) - 3
    codes = []
    for i, v in enumerate(indices):
        if i % every == 0:
            codes.append(clear)
        codes.append(v)
    codes.append(end)
    bits, n, out = 0, 0, bytearray()
    for c in codes:
        bits |= c << n
        n += width
        while n >= 8:
            out.append(bits & 255)
            bits >>= 8
            n -= 8
    if n:
        out.append(bits & 255)
    blocks = bytearray([m])
    for i in range(0, len(out), 255):
        part = out[i:i + 255]
        blocks += bytes([len(part)]) + part
    return bytes(blocks + b'\x00')

def gif(path, w, h, indices, palette, m, transparent=None):
    n = 1
    while (1 << n) < len(palette):
        n += 1
    palette = palette + [(0, 0, 0)] * ((1 << n) - len(palette))
    data = b'GIF89a' + struct.pack('<HHBBB', w, h, 0x80 | (n - 1), 0, 0)
    data += bytes(c for e in palette for c in e)
    if transparent is not None:
        data += b'!\xf9\x04\x01\x00\x00' + bytes([transparent]) + b'\x00'
    data += b',' + struct.pack('<HHHHB', 0, 0, w, h, 0) + lzw(indices, m) + b';'
    open(path, 'wb').write(data)

# 12x8, 8 colours, index 3 transparent: indexed.gif.
palette = [(30 * i, 255 - 30 * i, (70 * i) % 256) for i in range(8)]
gif('indexed.gif', 12, 8, [(x + 3 * y) % 8 for y in range(8) for x in range(12)], palette, 3, 3)
# A POT file: 16x12 16-bit heights, a ridge; the GIF is 32 wide, each
# value's high byte on the left half, its low byte on the right.
w, h = 16, 12
values = [int(65535 * (0.5 + 0.45 * math.sin(x * 0.5) * math.cos(y * 0.6))) for y in range(h) for x in range(w)]
indices = []
for y in range(h):
    row = values[y * w:(y + 1) * w]
    indices += [v >> 8 for v in row] + [v & 255 for v in row]
gif('heights.pot', 2 * w, h, indices, [(i, i, i) for i in range(256)], 8)
