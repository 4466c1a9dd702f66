#!/usr/bin/env python3
"""Derives POV-Ray 3.7's noise table (runtime/texture/pattern/noise_table.cpp) from
POV-Ray's own output recorded here, and prints it, one entry a line.

POV-Ray's Noise at a lattice point is one table entry, scaled: generator 2
gives (entry / 2 + 1.05242) * 0.48985582. Which entry, the lattice hash
says; the hash is POV-Ray's shuffle of 0..4095 by its generator
r = r * 1812433253 + 12345 (runtime/texture/pattern/noise.cpp builds the same).
lattice_noise.txt gives entries 0 to 510 (every second number of RTable);
lattice_dnoise.txt the vector noise's, 8 and 16 further on (to 526);
dnoise_slopes.txt the last three, from slopes. Each entry has six
significant digits in POV-Ray's source; every measurement here agrees with
its neighbours to that many.

  python3 derive_table.py > table.txt
"""
import collections
import os

HERE = os.path.dirname(os.path.abspath(__file__))
MASK = 0xFFFFFFFF


def hash_table():
    h = list(range(4096))
    r = 0
    for i in range(4095, -1, -1):
        r = (r * 1812433253 + 12345) & MASK
        j = ((r >> 16) & 0x7FFF) % 4096
        h[i], h[j] = h[j], h[i]
    return h + h


H = hash_table()


def entry_index(x, y, z):
    ix, iy, iz = ((int(v) + 10000) & 0xFFF for v in (x, y, z))
    return (H[H[H[ix] ^ iy] ^ iz] & 0xFF) * 2


def six(v):
    return '%.6g' % v


def signed(v):
    # A gradient pattern's value is the noise modulo 1; |noise| < 0.5 here.
    v = float(v)
    return v - 1 if v > 0.5 else v


def main():
    table = {}
    for line in open(os.path.join(HERE, 'lattice_noise.txt')):
        x, y, z, n = line.split()
        table.setdefault(entry_index(float(x), float(y), float(z)), six(2 * (float(n) / 0.48985582 - 1.05242)))
    for line in open(os.path.join(HERE, 'lattice_dnoise.txt')):
        x, y, z, dx, dy, dz = line.split()
        m = entry_index(float(x), float(y), float(z))
        for offset, d in ((0, dx), (8, dy), (16, dz)):
            table.setdefault(m + offset, six(2 * signed(d)))
    rows = collections.defaultdict(dict)
    for line in open(os.path.join(HERE, 'dnoise_slopes.txt')):
        y, z, m, a, b, c, v = line.split()
        rows[(y, z, int(m))][(int(a), int(b), int(c))] = signed(v)
    step = 1e-6
    for (_, _, m), r in rows.items():
        f0 = r[(0, 0, 0)]
        for k, (one, two) in enumerate((((1, 0, 0), (2, 0, 0)), ((0, 1, 0), (0, 2, 0)), ((0, 0, 1), (0, 0, 2)))):
            slope = (4 * r[one] - r[two] - 3 * f0) / (2 * step)
            if k == 2:
                slope -= 1  # moving along z moves the gradient z itself
            table.setdefault(m + 18 + 2 * k, six(slope))
    missing = [m for m in range(0, 534, 2) if m not in table]
    if missing:
        raise SystemExit('entries not measured: %s' % missing)
    for m in range(0, 534, 2):
        print(table[m])


if __name__ == '__main__':
    main()
