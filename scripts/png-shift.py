#!/usr/bin/env python3
"""png-shift.py FULL.png QUANT.png [PALETTE] - how far a compressed chart's
pixels moved from its full-colour drawing (docs/chart-grading.md: why the
line charts are not quantized).  Both PNGs are read through `convert FILE
ppm:-` (white behind transparency), the colour distance is the CIE76
delta-E in CIELAB (D65), as scripts/lab.awk's.  Prints: the pixels of
FULL that are not white, how many moved by a delta-E above 5 and above 10,
the largest move; with PALETTE (scripts/palette.txt), per method the
pixels drawn exactly in its colour in FULL and their largest move.
Redraw a chart without pngquant (PATH without it, or pngquant absent) for
FULL, and run `pngquant --force --speed 1 --output QUANT.png 256 FULL.png`
for QUANT."""
import math
import subprocess
import sys


def ppm(path):
    data = subprocess.run(['convert', path, 'ppm:-'], capture_output=True, check=True).stdout
    parts = data.split(b'\n', 3)
    w, h = map(int, parts[1].split())
    return w, h, parts[3]


def lab(c):
    def lin(v):
        v /= 255
        return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4
    r, g, b = map(lin, c)
    x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047
    y = 0.2126 * r + 0.7152 * g + 0.0722 * b
    z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883
    f = lambda t: t ** (1 / 3) if t > 0.008856 else 7.787 * t + 16 / 116
    return 116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))


def main():
    if len(sys.argv) not in (3, 4):
        print(__doc__.split('\n')[0], file=sys.stderr)
        sys.exit(2)
    wa, ha, a = ppm(sys.argv[1])
    wb, hb, b = ppm(sys.argv[2])
    if (wa, ha) != (wb, hb):
        print('png-shift: the two PNGs differ in size', file=sys.stderr)
        sys.exit(2)
    pal = {}
    if len(sys.argv) == 4:
        for line in open(sys.argv[3]):
            f = line.split()
            if line.startswith('#') or len(f) < 2:
                continue
            c = f[1].lstrip('#')
            pal[bytes(int(c[k:k + 2], 16) for k in (0, 2, 4))] = f[0]
    cache = {}
    n = n5 = n10 = 0
    worst = 0.0
    per = {}
    for i in range(0, len(a), 3):
        pa = a[i:i + 3]
        if pa == b'\xff\xff\xff':
            continue
        pb = b[i:i + 3]
        n += 1
        d = 0.0
        if pa != pb:
            k = pa + pb
            if k not in cache:
                cache[k] = math.dist(lab(pa), lab(pb))
            d = cache[k]
        worst = max(worst, d)
        n5 += d > 5
        n10 += d > 10
        if pa in pal:
            m = per.setdefault(pal[pa], [0, 0.0])
            m[0] += 1
            m[1] = max(m[1], d)
    print(f'{sys.argv[2]}: {n} non-white pixels, {n5} moved by a delta-E above 5 '
          f'({100 * n5 / max(n, 1):.2f}%), {n10} above 10, largest {worst:.1f}')
    for m in sorted(per):
        print(f'  {m}: {per[m][0]} pixels in its exact colour, largest move {per[m][1]:.1f}')


main()
