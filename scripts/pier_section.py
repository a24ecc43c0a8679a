#!/usr/bin/env python3
"""The mid-height section of a no-tension pier run (parameters/
no-tension-pier.prm and its variants) from its solution.vtu, against the
closed form of a no-tension rectangle (compressed width c = 3 (b/2 - e),
triangular block of peak 2N/c):

    python3 scripts/pier_section.py output/no-tension-pier [N e b]

Defaults N = 1e5, e = 0.25, b = 1 (the scene's constants). The section is
the middle of the cell row just above mid-height (as tests/no_tension_pier
takes it); sigma_yy along it is each cell's bilinear field (solution.vtu
holds each cell's own vertex values). Prints one Markdown row: resultant /
N, moment / (N e) about the section's centre, compressed width / c (where
sigma_yy < -1e-3 of 2N/c), peak / (2N/c), the peak's x / b, and the share of
N carried by the outer sixteenth (x > 15/16 b; the closed form: 16 %).
Axis-parallel rectangular cells only.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_fracture_strain import read_vtu  # noqa: E402


def main():
    directory = sys.argv[1]
    N, e, b = (float(v) for v in (sys.argv[2:5] if len(sys.argv) >= 5
                                  else (1e5, 0.25, 1)))
    c = 3 * (b / 2 - e)
    peak = 2 * N / c
    vtu = os.path.join(directory, "solution.vtu")
    if not os.path.isfile(vtu):
        sys.exit("pier_section.py: no %s (run the scene with Output/Write "
                 "solution = true)" % vtu)
    a = read_vtu(vtu)
    points, cells, syy = a["points"], a["connectivity"], a["syy"]
    ys = points[1::3]
    half = (min(ys) + max(ys)) / 2
    # Each cell: its x and y ranges and sigma_yy at its four vertices.
    boxes = []
    for k in range(len(cells) // 4):
        ids = cells[4 * k:4 * k + 4]
        xy = [(points[3 * i], points[3 * i + 1], syy[i]) for i in ids]
        x0, x1 = min(p[0] for p in xy), max(p[0] for p in xy)
        y0, y1 = min(p[1] for p in xy), max(p[1] for p in xy)
        boxes.append((x0, x1, y0, y1, xy))
    row = [bx for bx in boxes if abs(bx[2] - half) < 1e-9 * (1 + abs(half))]
    if not row:
        sys.exit("pier_section.py: no cell row starts at mid-height y = %g"
                 % half)
    y = (row[0][2] + row[0][3]) / 2

    def value(bx, x):
        x0, x1, y0, y1, xy = bx
        s, t = (x - x0) / (x1 - x0), (y - y0) / (y1 - y0)
        total = 0
        for px, py, v in xy:
            wx = s if abs(px - x1) < 1e-12 * (1 + abs(x1)) else 1 - s
            wy = t if abs(py - y1) < 1e-12 * (1 + abs(y1)) else 1 - t
            total += wx * wy * v
        return total

    n = 4000
    resultant = moment = width = outer = 0
    s_peak, x_peak = 0, 0
    for i in range(n):
        x = (i + 0.5) * b / n
        bx = next(bx for bx in row if bx[0] <= x <= bx[1])
        s = value(bx, x)
        resultant += s * b / n
        moment += s * (x - b / 2) * b / n
        if s < s_peak:
            s_peak, x_peak = s, x
        if s < -1e-3 * peak:
            width += b / n
        if x > 15 / 16 * b:
            outer -= s * b / n
    print("| %.4f | %.4f | %.3f | %.3f | %.3f | %.1f %% |" %
          (-resultant / N, -moment / (N * e), width / c, -s_peak / peak,
           x_peak / b, 100 * outer / N))


if __name__ == "__main__":
    main()
