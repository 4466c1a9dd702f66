# Writes the test images of image_map.pov (tiles.png, gamma18.png) with zlib
# alone: PNG chunks by hand, so that the bytes are fixed.
import zlib, struct
def chunk(t, d): 
    c = struct.pack('>I', len(d)) + t + d
    return c + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
def png(path, w, h, rows, colour_type, extra=b''):
    raw = b''.join(b'\x00' + bytes(r) for r in rows)
    data = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, colour_type, 0, 0, 0)) + extra
    data += chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b'')
    open(path, 'wb').write(data)
# 8x6 RGBA: hues across, brightness down; a transparent band in the bottom row.
w, h = 8, 6
rows = []
for y in range(h):
    r = []
    for x in range(w):
        R = (x * 37 + y * 11) % 256
        G = (255 - x * 29) % 256
        B = (y * 50 + 20) % 256
        A = 255 if y < 4 else (80 if x % 2 else 200)
        r += [R, G, B, A]
    rows.append(r)
png('tiles.png', w, h, rows, 6)
# 5x4 RGB with a gAMA chunk (encoding gamma 1/1.8).
rows = []
for y in range(4):
    r = []
    for x in range(5):
        r += [x * 60, y * 80, 255 - x * 50]
    rows.append(r)
png('gamma18.png', 5, 4, rows, 2, chunk(b'gAMA', struct.pack('>I', int(round(100000 / 1.8)))))
# 8x6, 4 bits an index into 12 entries (a colour-mapped image as POV-Ray's
# test.png), entry 0 half clear by a tRNS chunk: palette.png.
def png4(path, w, h, indices, palette, alpha):
    rows = []
    for y in range(h):
        r = indices[y * w:(y + 1) * w]
        rows.append([r[i] << 4 | r[i + 1] for i in range(0, w, 2)])
    raw = b''.join(b'\x00' + bytes(r) for r in rows)
    data = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 4, 3, 0, 0, 0))
    data += chunk(b'PLTE', bytes(c for e in palette for c in e)) + chunk(b'tRNS', bytes(alpha))
    data += chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b'')
    open(path, 'wb').write(data)
palette = [(20 * i, 250 - 20 * i, (90 * i) % 256) for i in range(12)]
png4('palette.png', 8, 6, [(x + 2 * y) % 12 for y in range(6) for x in range(8)], palette, [128])
