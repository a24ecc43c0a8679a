"""Speed against accuracy of the stress elements (issue 20), the second part
of scripts/speed-accuracy.sh (PART=elements runs only this part).

DGQ1 and Pian-Sumihara stresses on the cantilever (parameters/cantilever.prm,
beam with the elasticity solution; error of the tip deflection and the L2
stress error) and Cook's membrane (parameters/cooks-membrane.prm; error of
the deflection at (48, 52) against the published 23.96), over a sequence of
meshes, on both Newton-step paths: condensed (UMFPACK, all meshes) and
null-space (the paper's dense reduction, while the stress unknowns are at
most NULL_SPACE_MAX). Per run: unknowns (displacement dofs + stress
unknowns: 12 per cell for DGQ1, 5 for Pian-Sumihara), the median process
wall time of REPEATS runs and the median of the solver's own wall_time (summary.txt),
which the plot and the table use: the start-up of the process (about
0.6 s, the same for every run) would otherwise hide the small meshes.

Writes doc/speed-accuracy-elements.csv, doc/speed-accuracy-elements-table.md
and doc/figures/speed-accuracy-elements.png (error against wall time and
against unknowns, one row of panels per scene). Environment: ROOT, WORK,
REPEATS, RUN_TIMEOUT, MODE (quick: fewer meshes), REPRODUCE, NULL_SPACE_MAX.
"""
import csv
import datetime
import math
import os
import shutil
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from summary_file import NAN, num, read_summary  # noqa: E402

ROOT = os.environ["ROOT"]
EXE = os.path.join(ROOT, "build", "hrcontact")
WORK = os.path.join(os.environ["WORK"], "elements")
MODE = os.environ.get("MODE", "full")
REPEATS = int(os.environ.get("REPEATS", "3"))
TIMEOUT = float(os.environ.get("RUN_TIMEOUT", "600"))
NULL_SPACE_MAX = int(os.environ.get("NULL_SPACE_MAX", "6000"))
ELEMENTS = ("DGQ1", "Pian-Sumihara")
PATHS = ("condensed", "null-space")
# (scene, parameter file, mesh lines per level, levels, error key, label)
SCENES = [
    ("cantilever", "parameters/cantilever.prm",
     lambda n: f"subsection Geometry\n  set Global refinements = {n}\nend\n",
     (0, 1, 2, 3) if MODE == "quick" else (0, 1, 2, 3, 4, 5),
     "relative_error.tip_deflection", "tip deflection"),
    ("cook", "parameters/cooks-membrane.prm",
     lambda n: (f"subsection Geometry\n  set Grid arguments = {n}\n"
                "  set Global refinements = 0\nend\n"),
     (2, 4, 8, 16) if MODE == "quick" else (2, 4, 8, 16, 32, 64),
     "relative_error.tip_deflection", "deflection at (48, 52)"),
]


def log(msg):
    print(msg, flush=True)


def run(name, scene_prm, mesh, element, path):
    rundir = os.path.join(WORK, name)
    out = os.path.join(rundir, "out")
    os.makedirs(rundir, exist_ok=True)
    prm = os.path.join(rundir, "run.prm")
    with open(prm, "w") as f:
        f.write(f"include {ROOT}/{scene_prm}\n{mesh}"
                f"subsection Finite elements\n  set Stress element = {element}\nend\n"
                f"subsection Equilibrium reduction\n  set Path = {path}\nend\n"
                "subsection Linear solver\n  set Solver = direct\nend\n"
                f"subsection Output\n  set Output directory = {out}\n"
                "  set Print timing = false\n  set Write solution = false\nend\n")
    walls, solver_walls, rc = [], [], None
    for _ in range(REPEATS):
        shutil.rmtree(out, ignore_errors=True)
        t0 = time.perf_counter()
        try:
            with open(os.path.join(rundir, "log"), "w") as fo:
                rc = subprocess.run([EXE, prm], stdout=fo, stderr=subprocess.STDOUT,
                                    cwd=rundir, timeout=TIMEOUT).returncode
        except subprocess.TimeoutExpired:
            rc = None
        walls.append(time.perf_counter() - t0)
        solver_walls.append(num(read_summary(os.path.join(out, "summary.txt")), "wall_time"))
        if rc != 0:
            break
    return rc, walls, solver_walls, read_summary(os.path.join(out, "summary.txt"))


records = []
for scene, scene_prm, mesh_of, levels, key, label in SCENES:
    for element in ELEMENTS:
        for level in levels:
            for path in PATHS:
                name = f"{scene}-{element}-{level}-{path}"
                if path == "null-space":
                    # Only where the dense reduction stays small: the stress
                    # unknowns of the condensed run of the same mesh.
                    same = [r for r in records if r["scene"] == scene and
                            r["element"] == element and r["level"] == level]
                    if not same or not same[0]["stress_unknowns"] or \
                            int(same[0]["stress_unknowns"]) > NULL_SPACE_MAX:
                        continue
                rc, walls, solver_walls, s = run(name, scene_prm, mesh_of(level), element, path)
                u = s.get("displacement_dofs", "")
                sd = s.get("stress_dofs", "")
                rec = dict(scene=scene, element=element, level=level, path=path,
                           status="ok" if rc == 0 else f"failed (exit {rc})",
                           cells=s.get("cells", ""), displacement_dofs=u,
                           stress_unknowns=sd,
                           unknowns=(int(u) + int(sd)) if u and sd else "",
                           wall_median_s=statistics.median(walls),
                           wall_runs_s=";".join(f"{w:.4f}" for w in walls),
                           solver_wall_s=statistics.median(solver_walls),
                           value=num(s, key.replace("relative_error", "probe")),
                           reference=num(s, key.replace("relative_error", "reference")),
                           error=abs(num(s, key)),
                           stress_error_l2=num(s, "stress_error_l2"))
                records.append(rec)
                log(f"{name}: {rec['status']}, {rec['unknowns']} unknowns,"
                    f" {rec['solver_wall_s']:.3f} s, error {rec['error']:.3e}")

os.makedirs(os.path.join(ROOT, "doc", "figures"), exist_ok=True)
fields = list(records[0].keys())
tmp = os.path.join(ROOT, "doc", "speed-accuracy-elements.csv.tmp")
with open(tmp, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=fields)
    w.writeheader()
    for r in records:
        w.writerow({k: (f"{v:.10g}" if isinstance(v, float) else v) for k, v in r.items()})
os.replace(tmp, tmp[:-4])

# The table: one row per scene, element and mesh; both paths' times.
lines = [
    "<!-- Generated by scripts/speed-accuracy.sh (PART=elements); do not edit. -->",
    f"Reproduce: `{os.environ.get('REPRODUCE', 'PART=elements bash scripts/speed-accuracy.sh')}`"
    f" ({MODE} mode, {REPEATS} repeat(s) per run, generated {datetime.date.today().isoformat()}).",
    "",
    "Solver s: median of the solver's own wall_time (summary.txt: mesh, assembly, solve,"
    " postprocessing; without the process start-up, which is about 0.6 s on an idle"
    " machine and the same for both elements); null-space only"
    f" up to {NULL_SPACE_MAX} stress unknowns. Error: |computed / reference - 1| of the"
    " probe (cantilever: tip deflection against the elasticity solution; Cook: deflection"
    " at (48, 52) against 23.96); stress L2: relative L2 error of the stresses"
    " (cantilever only).",
    "",
    "| scene | element | mesh | cells | u dofs | stress unknowns | unknowns | value | error"
    " | stress L2 | condensed solver s | null-space solver s |",
    "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
]
for scene, _, _, levels, _, _ in SCENES:
    for element in ELEMENTS:
        for level in levels:
            rs = {r["path"]: r for r in records
                  if (r["scene"], r["element"], r["level"]) == (scene, element, level)}
            c = rs.get("condensed")
            if c is None:
                continue
            n = rs.get("null-space")
            lines.append(
                f"| {scene} | {element} | {level} | {c['cells']} | {c['displacement_dofs']}"
                f" | {c['stress_unknowns']} | {c['unknowns']} | {c['value']:.6g}"
                f" | {c['error']:.3e} | "
                + ("–" if math.isnan(c["stress_error_l2"]) else f"{c['stress_error_l2']:.3e}")
                + f" | {c['solver_wall_s']:.3f} | "
                + (f"{n['solver_wall_s']:.3f}" if n else "–") + " |")
with open(os.path.join(ROOT, "doc", "speed-accuracy-elements-table.md"), "w") as f:
    f.write("\n".join(lines) + "\n")

# The plot: per scene, error against wall time (both paths) and against
# unknowns.
plotdir = os.path.join(WORK, "plot")
os.makedirs(plotdir, exist_ok=True)
colour = {"DGQ1": "#d62728", "Pian-Sumihara": "#1f77b4"}
point = {"condensed": 7, "null-space": 6}
gp = ["set terminal pngcairo size 1300,900 font ',10'",
      f"set output '{ROOT}/doc/figures/speed-accuracy-elements.png.tmp'",
      "set multiplot layout 2,2 title \"Stress elements: error against wall time and"
      f" against unknowns ({MODE} mode)\"",
      "set logscale xy; set grid; set format y '10^{%L}'; set key bottom left"]
for scene, _, _, _, _, label in SCENES:
    for xkey, xlabel in (("solver_wall_s", "solver wall time (s), median"),
                         ("unknowns", "unknowns (displacement dofs + stress unknowns)")):
        items = []
        for element in ELEMENTS:
            for path in (PATHS if xkey == "solver_wall_s" else ("condensed",)):
                sel = [r for r in records if r["scene"] == scene and r["element"] == element
                       and r["path"] == path and r["status"] == "ok"]
                if not sel:
                    continue
                fn = os.path.join(plotdir, f"{scene}-{element}-{path}-{xkey}.dat")
                with open(fn, "w") as f:
                    f.writelines(f"{r[xkey]} {max(r['error'], 1e-16)}\n" for r in sel)
                title = element + (f", {path}" if xkey == "solver_wall_s" else "")
                items.append(f"'{fn}' using 1:2 with linespoints pt {point[path]} ps 1.4"
                             f" dt {1 if path == 'condensed' else 2}"
                             f" lc rgb '{colour[element]}' title '{title}'")
        gp.append(f"set title '{scene}: {label}'; set xlabel '{xlabel}';"
                  " set ylabel '|computed / reference - 1|'")
        gp.append("plot " + ", \\\n     ".join(items))
gp.append("unset multiplot")
with open(os.path.join(plotdir, "elements.gp"), "w") as f:
    f.write("\n".join(gp) + "\n")
subprocess.run(["gnuplot", os.path.join(plotdir, "elements.gp")], check=True)
os.replace(f"{ROOT}/doc/figures/speed-accuracy-elements.png.tmp",
           f"{ROOT}/doc/figures/speed-accuracy-elements.png")
log("wrote doc/speed-accuracy-elements.csv, doc/speed-accuracy-elements-table.md,"
    " doc/figures/speed-accuracy-elements.png")
