#!/usr/bin/env python3
"""Draw the cells of an adaptive run's solution.vtu, each outlined and
filled by its refinement_indicator (log scale), the whole body and a zoom
window, into a PNG with gnuplot (pngcairo).

    python3 scripts/plot_adaptive_mesh.py output/hertz-adaptive [out.png] \\
        [x0:x1:y0:y1 of the zoom window]

Reads deal.II's compressed binary VTU with plot_fracture_strain.read_vtu
(no VTK needed). 2D only: each cell is its own patch of 4 points.
"""
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_fracture_strain import read_vtu  # noqa: E402


def main():
    directory = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(
        directory, "adaptive-mesh.png")
    window = (sys.argv[3] if len(sys.argv) > 3 else
              "0:0.02:-0.0502:-0.042").split(":")
    a = read_vtu(os.path.join(directory, "solution.vtu"))
    points, cells = a["points"], a["connectivity"]
    if "refinement_indicator" not in a:
        sys.exit("solution.vtu has no refinement_indicator: not an adaptive "
                 "run")
    eta = a["refinement_indicator"]
    data = os.path.join(directory, "adaptive-mesh.dat")
    with open(data, "w") as f:
        for c in range(len(cells) // 4):
            # VTK's quad order goes round the cell.
            corners = [cells[4 * c + k] for k in (0, 1, 2, 3, 0)]
            value = math.log10(max(eta[corners[0]], 1e-30))
            for p in corners:
                f.write("%.9g %.9g %.6g\n" % (points[3 * p],
                                              points[3 * p + 1], value))
            f.write("\n")
    x0, x1, y0, y1 = window
    script = """
set terminal pngcairo size 1600,800 font ',11'
set output '{out}'
set multiplot layout 1,2
set size ratio -1
unset key
set palette rgbformulae 33,13,10
set cblabel 'log10 refinement indicator'
set title 'the whole body'
plot '{data}' using 1:2:3 with filledcurves closed fillcolor palette, \\
     '{data}' using 1:2 with lines lc rgb 'black' lw 0.15
set title 'zoom: the contact zone'
set xrange [{x0}:{x1}]
set yrange [{y0}:{y1}]
plot '{data}' using 1:2:3 with filledcurves closed fillcolor palette, \\
     '{data}' using 1:2 with lines lc rgb 'black' lw 0.3
unset multiplot
""".format(out=out, data=data, x0=x0, x1=x1, y0=y0, y1=y1)
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    print("wrote", out)


if __name__ == "__main__":
    main()
