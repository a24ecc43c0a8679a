#!/usr/bin/env python3
"""Draw the bending stress across the mid-span section of the Ramberg-Osgood
beam (parameters/ramberg-osgood-beam.prm) against beam theory, into a PNG
with gnuplot (pngcairo):

    python3 scripts/plot_bending_section.py output/ramberg-osgood-beam [out.png]

The computed sxx are the point values of solution.vtu on the section x = L/2
(a line of cell edges: each cell's own value, both sides of the edge). The
exact one inverts the uniaxial law eps = s/E + a (s/s0)^(n-1) s/E at eps =
kappa y by Newton's method; the elastic line E kappa y shows what the power
term takes away. The beam's constants below are those of
parameters/ramberg-osgood-beam.prm: change them with the scene.
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_fracture_strain import read_vtu  # noqa: E402

# parameters/ramberg-osgood-beam.prm
L, E, KAPPA, A, S0, N = 1.0, 70e9, 0.1, 3.0 / 7.0, 200e6, 5.0


def uniaxial_stress(eps):
    """s with s/E + a |s/s0|^(n-1) s/E = eps (Newton; monotone, convex)."""
    s = E * eps
    for _ in range(100):
        r = s / E + A * abs(s / S0) ** (N - 1) * s / E - eps
        ds = r / (1 / E + N * A * abs(s / S0) ** (N - 1) / E)
        s -= ds
        if abs(ds) <= 1e-14 * max(abs(s), 1.0):
            break
    return s


def main():
    directory = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(
        directory, "bending-section.png")
    a = read_vtu(os.path.join(directory, "solution.vtu"))
    points, sxx = a["points"], a["sxx"]
    xs = points[0::3]
    h = min(abs(x - L / 2) for x in xs)
    section = sorted((points[3 * i + 1], sxx[i]) for i in range(len(sxx))
                     if abs(xs[i] - L / 2) <= h + 1e-9)
    ys = [y for y, _ in section]
    lo, hi = min(ys), max(ys)
    data = os.path.join(directory, "bending-section.dat")
    exact = os.path.join(directory, "bending-section-exact.dat")
    with open(data, "w") as f:
        for y, s in section:
            f.write("%.9g %.9g\n" % (y, s / 1e6))
    worst = max(abs(s - uniaxial_stress(KAPPA * y)) for y, s in section)
    with open(exact, "w") as f:
        for k in range(201):
            y = lo + (hi - lo) * k / 200
            f.write("%.9g %.9g %.9g\n" % (y, uniaxial_stress(KAPPA * y) / 1e6,
                                          E * KAPPA * y / 1e6))
    script = """
set terminal pngcairo size 800,600 font ",11"
set output '%s'
set xlabel 'sxx at x = L/2 (MPa)'
set ylabel 'y (m)'
set key left top
set grid
set title 'Ramberg-Osgood beam in pure bending: mid-span section'
plot '%s' using 3:1 with lines dt 2 lc rgb '#777777' title 'linear elastic, E kappa y', \\
     '%s' using 2:1 with lines lw 2 lc rgb '#2166ac' title 'beam theory (uniaxial law inverted at kappa y)', \\
     '%s' using 2:1 with points pt 7 ps 0.8 lc rgb '#d7191c' title 'hrcontact, DGQ1 values at the section'
""" % (out, exact, exact, data)
    subprocess.run(["gnuplot"], input=script.encode(), check=True)
    print(out)
    print("largest |sxx - exact| on the section: %.4g MPa (%.3g of the "
          "outer fibre's)" % (worst / 1e6, worst / abs(uniaxial_stress(
              KAPPA * hi))))


if __name__ == "__main__":
    main()
