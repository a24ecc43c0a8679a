#!/usr/bin/env bash
# Speed against accuracy of the contact iterations: every regularisation of
# Augmented Lagrangian/Regularisation (consistent, Macaulay and displacement
# augmented Lagrangian with the classical and the diagonal Iteration scheme;
# pure penalty, classical only, with Initial penalty factors 1e4 and 1e8)
# x Relative tolerance x mesh, on the Hertz scene (parameters/hertz.prm) and
# the lift-off scene (parameters/lift-off.prm). All runs take
# Equilibrium reduction/Path = condensed with the direct sparse solver, so the
# wall times compare; Initial penalty scaling = nodal compliance, factor 1e4
# unless the variant says otherwise.
#
# Per run configuration it records the counts (multiplier updates, Newton
# steps, linear solves), the median wall time of REPEATS runs (the process,
# timed here, and the solver's own wall_time from summary.txt), and:
#   - Hertz: the errors of the peak pressure p0 and the half width a against
#     the analytic Hertz values (summary.txt), and their differences from the
#     reference run. The discretisation error dominates the Hertz comparison;
#     the reference difference isolates the solver's error.
#   - both scenes: the solver error against the reference run (consistent
#     augmented Lagrangian, classical, Relative tolerance 1e-12, same mesh,
#     Initial penalty factor 1e4, or 1e2 or 1 if that run stops; the table
#     says which):
#     max over contact rows |p_n - p_ref| / max |p_ref| (contact.csv);
#     the constraint violation: largest tension max(p_n, 0) / max |p_n| and
#     largest penetration max(w_n - g, 0) / max |u|; the complementarity
#     max |p_n (w_n - g)| / (max |p_n| max |w_n - g|). w_n is the column of
#     contact.csv (g + the opening the solver keeps);
#     penetration and complementarity are also measured with the normal
#     displacement of the computed displacement field, u.n (columns ux, uy,
#     nx, ny of contact.csv).
# Runs that stop (exit code 3) stay in the table as "stopped" with the first
# words of their error message.
#
# Writes doc/speed-accuracy-data.csv, doc/speed-accuracy-table.md and
# doc/figures/speed-accuracy.png (Pareto plots: solver error against wall
# seconds and against linear solves, one row of panels per scene); the run
# directories go to WORK, build/speed-accuracy by default (its run directories
# are wiped at the start); the table's rundir column is relative to WORK.
#
#   bash scripts/speed-accuracy.sh            full study (R = 3 repeats)
#   QUICK=1 bash scripts/speed-accuracy.sh    quick check: one mesh per scene,
#                                             Relative tolerance 1e-8, R = 1
#
# A second part (issue 20), scripts/speed_accuracy_elements.py: the stress
# elements DGQ1 and Pian-Sumihara on the cantilever and Cook's membrane,
# error against wall time and against unknowns on both Newton-step paths:
# doc/speed-accuracy-elements.csv, doc/speed-accuracy-elements-table.md,
# doc/figures/speed-accuracy-elements.png (about 3 minutes).
#   PART=solvers | elements | all (default) selects the parts.
# Optional overrides (environment): REPEATS, TOLERANCES ("1e-4 1e-8"),
# HERTZ_LEVELS ("5 6"), LIFT_OFF_LEVELS ("5 6") (Global refinements),
# RUN_TIMEOUT (seconds per run, default 600), WORK (default build/speed-accuracy).
# Needs python3 and gnuplot (Debian: apt-get install gnuplot-nox).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/hrcontact ] || { echo "build first: bash scripts/quickstart.sh example" >&2; exit 1; }
command -v python3 > /dev/null || { echo "python3 is missing" >&2; exit 1; }
command -v gnuplot > /dev/null || { echo "gnuplot is missing: apt-get install gnuplot-nox" >&2; exit 1; }

# The command line that reproduces this run (printed at the top of the table):
# QUICK plus whichever overrides were given.
reproduce=""
for v in PART QUICK REPEATS TOLERANCES HERTZ_LEVELS LIFT_OFF_LEVELS RUN_TIMEOUT WORK; do
  if [ -n "${!v:-}" ]; then
    case ${!v} in
      *" "*) reproduce+="$v=\"${!v}\" " ;;
      *) reproduce+="$v=${!v} " ;;
    esac
  fi
done
reproduce+="bash scripts/speed-accuracy.sh"

# Mesh levels (Global refinements): one above the scenes' defaults (Hertz 4,
# lift-off 2), whose runs are mostly the ~0.6 s start-up of the process, so
# that the solver dominates the wall time; the largest runs (consistent AL,
# classical, 1e-12) take about 8 s (Hertz 6, 25k displacement dofs) and 14 s
# (lift-off 6, 66k). The full study takes about 25 minutes.
if [ "${QUICK:-0}" = 1 ]; then
  mode=quick
  : "${REPEATS:=1}" "${TOLERANCES:=1e-8}" "${HERTZ_LEVELS:=5}" "${LIFT_OFF_LEVELS:=5}"
else
  mode=full
  : "${REPEATS:=3}" "${TOLERANCES:=1e-4 1e-8 1e-12}" "${HERTZ_LEVELS:=5 6}" "${LIFT_OFF_LEVELS:=5 6}"
fi
: "${RUN_TIMEOUT:=600}" "${WORK:=build/speed-accuracy}"
# The runs change into their own directories: WORK as an absolute path.
mkdir -p "$WORK" && WORK=$(cd "$WORK" && pwd)
# Wipe only what an earlier run of this script put there.
part=${PART:-all}
case "$part" in
  all|solvers|elements) ;;
  *) echo "PART must be all, solvers or elements (got '$part')" >&2; exit 2 ;;
esac
rm -rf "$WORK"/hertz-r* "$WORK"/lift-off-r* "$WORK"/plot "$WORK"/elements
mkdir -p "$WORK" doc/figures
export MODE=$mode REPEATS TOLERANCES HERTZ_LEVELS LIFT_OFF_LEVELS RUN_TIMEOUT WORK
export REPRODUCE=$reproduce ROOT=$PWD

if [ "$part" != elements ]; then
# Run the sweep, write the CSV, the table and the plot script.
python3 - <<'PY'
import csv, datetime, math, os, shutil, statistics, subprocess, sys, time

sys.path.insert(0, os.path.join(os.environ["ROOT"], "scripts"))
from summary_file import num, read_summary  # noqa: E402

ROOT = os.environ["ROOT"]
EXE = os.path.join(ROOT, "build", "hrcontact")
WORK = os.environ["WORK"]
MODE = os.environ["MODE"]
REPEATS = int(os.environ["REPEATS"])
TOLERANCES = os.environ["TOLERANCES"].split()
TIMEOUT = float(os.environ["RUN_TIMEOUT"])
SCENES = [  # (name, parameter file, Global refinements)
    ("hertz", "parameters/hertz.prm", os.environ["HERTZ_LEVELS"].split()),
    ("lift-off", "parameters/lift-off.prm", os.environ["LIFT_OFF_LEVELS"].split()),
]
# (label, Regularisation, Iteration schemes, Initial penalty factor[/Penalty
# update]; the Penalty update is global unless given)
VARIANTS = [
    ("consistent AL", "consistent augmented Lagrangian", ("classical", "diagonal"), "1e4"),
    ("consistent AL, per constraint", "consistent augmented Lagrangian",
     ("classical", "diagonal"), "1e4/per constraint"),
    ("Macaulay AL", "Macaulay augmented Lagrangian", ("classical", "diagonal"), "1e4"),
    ("displacement AL", "displacement augmented Lagrangian", ("classical", "diagonal"), "1e4"),
    ("penalty 1e4", "pure penalty", ("classical",), "1e4"),
    ("penalty 1e8", "pure penalty", ("classical",), "1e8"),
]
# The reference of the solver error, run once per scene and mesh: the
# consistent augmented Lagrangian, classical, Relative tolerance 1e-12, with
# the first of these Initial penalty factors that converges (1e4 as the sweep;
# the smaller ones only if that run stops).
REFERENCE = ("consistent augmented Lagrangian", "classical", ("1e4", "1e2", "1"), "1e-12")
NAN = float("nan")
# Provenance for the table: when the executable was built, which sources.
BUILT = datetime.datetime.fromtimestamp(os.path.getmtime(EXE)).strftime("%Y-%m-%d %H:%M:%S")
try:
    head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                          capture_output=True, text=True, check=True).stdout.strip()
    dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True, check=True).stdout.strip()
    SOURCES = f"git {head}" + (" with uncommitted changes" if dirty else "")
except (OSError, subprocess.CalledProcessError):
    SOURCES = "not a git checkout"


def log(msg):
    print(msg, flush=True)


def prm_text(scene_prm, level, regularisation, scheme, penalty, tol, out):
    """A parameter file: the scene plus this run's overrides."""
    penalty, _, update = penalty.partition("/")
    update = update or "global"
    return f"""include {ROOT}/{scene_prm}
subsection Geometry
  set Global refinements = {level}
end
subsection Augmented Lagrangian
  set Regularisation          = {regularisation}
  set Iteration scheme        = {scheme}
  set Initial penalty scaling = nodal compliance
  set Initial penalty         = {penalty}
  set Penalty update          = {update}
  set Relative tolerance      = {tol}
end
subsection Equilibrium reduction
  set Path = condensed
end
subsection Linear solver
  set Solver = direct
end
subsection Output
  set Output directory = {out}
  set Print timing     = false
  set Write solution   = false
end
"""


def read_contact(path):
    """contact.csv rows as dicts of floats (status kept as a string)."""
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [{k: (v if k == "status" else float(v)) for k, v in row.items()}
                for row in csv.DictReader(f)]


def ratio(a, b):
    return a / b if b and math.isfinite(a) and math.isfinite(b) else NAN


def run(name, scene_prm, level, regularisation, scheme, penalty, tol, repeats):
    """Run one configuration `repeats` times (one process at a time); return
    the run directory, status, reason, wall times and the last run's results."""
    rundir = os.path.join(WORK, name)
    out = os.path.join(rundir, "out")
    os.makedirs(rundir, exist_ok=True)
    prm = os.path.join(rundir, "run.prm")
    with open(prm, "w") as f:
        f.write(prm_text(scene_prm, level, regularisation, scheme, penalty, tol, out))
    walls, counts = [], set()
    for _ in range(repeats):
        # No stale results: a run that fails early must not find old files.
        shutil.rmtree(out, ignore_errors=True)
        with open(os.path.join(rundir, "stdout.log"), "w") as fo, \
             open(os.path.join(rundir, "stderr.log"), "w") as fe:
            t0 = time.perf_counter()
            try:
                rc = subprocess.run([EXE, prm], stdout=fo, stderr=fe, cwd=rundir,
                                    timeout=TIMEOUT).returncode
            except subprocess.TimeoutExpired:  # the child has been killed
                rc = None
            walls.append(time.perf_counter() - t0)
        summary = read_summary(os.path.join(out, "summary.txt"))
        counts.add(summary.get("linear_solves"))
        if rc not in (0, 3):
            break  # input errors and timeouts: no point repeating
    if len(counts) > 1:
        log(f"  warning: {name}: linear_solves differ between repeats: {counts}")
    with open(os.path.join(rundir, "stderr.log")) as f:
        err = " ".join(f.read().split())
    # The first words of the message, safe in a Markdown table cell.
    reason = " ".join(err.replace("hrcontact: error:", "").replace("|", "/").split()[:12])
    if rc == 0 and summary.get("converged") == "true":
        status, reason = "converged", ""
    elif rc == 3:
        status = "stopped"
    elif rc is None:
        status, reason = "timeout", f"killed after {TIMEOUT:g} s"
    else:
        status = f"error (exit {rc})" if rc else "error (converged != true)"
    return dict(rundir=rundir, status=status, reason=reason, walls=walls,
                summary=summary, contact=read_contact(os.path.join(out, "contact.csv")))


def measures(r, ref):
    """All accuracy measures of run r (a dict from run()) against ref."""
    s, rows = r["summary"], r["contact"]
    p = [row["p_n"] for row in rows]
    opening = [row["w_n"] - row["gap"] for row in rows]
    # The same from the displacement field: u.n - g.
    dim = 3 if "uz" in (rows[0] if rows else {}) else 2
    opening_u = [sum(row["u" + c] * row["n" + c] for c in "xyz"[:dim]) - row["gap"]
                 for row in rows]
    max_u = num(s, "max_abs_displacement_component")
    max_p = num(s, "max_abs_p_n")
    if not math.isfinite(max_p) and p:
        max_p = max(abs(x) for x in p)
    # Prefer the full-precision values of summary.txt; contact.csv otherwise.
    tension = num(s, "max_positive_p_n")
    if not math.isfinite(tension) and p:
        tension = max(max(p), 0.0)
    penetration = num(s, "max_penetration")
    if not math.isfinite(penetration) and p:
        penetration = max(max(opening), 0.0)
    compl = num(s, "max_complementarity")
    if not math.isfinite(compl) and p:
        compl = max(abs(a * b) for a, b in zip(p, opening))
    max_opening = max((abs(x) for x in opening), default=NAN)
    penetration_u = max((max(x, 0.0) for x in opening_u), default=NAN)
    compl_u = max((abs(a * b) for a, b in zip(p, opening_u)), default=NAN)
    max_opening_u = max((abs(x) for x in opening_u), default=NAN)
    m = dict(
        tension=tension, penetration=penetration, complementarity=compl,
        tension_rel=ratio(tension, max_p),
        penetration_rel=ratio(penetration, max_u),
        complementarity_rel=ratio(compl, max_p * max_opening),
        penetration_u_rel=ratio(penetration_u, max_u),
        complementarity_u_rel=ratio(compl_u, max_p * max_opening_u),
        err_p0_hertz=num(s, "relative_error_peak_pressure"),
        err_a_hertz=num(s, "relative_error_half_width"),
        err_p0_ref=NAN, err_a_ref=NAN, err_ref=NAN)
    if ref is not None and ref["status"] == "converged" and rows:
        rs, rrows = ref["summary"], ref["contact"]
        if len(rrows) != len(rows) or any(
                abs(a["x"] - b["x"]) + abs(a["y"] - b["y"]) > 1e-12 * (1 + abs(b["x"]) + abs(b["y"]))
                for a, b in zip(rows, rrows)):
            log(f"  warning: {r['rundir']}: contact rows differ from the reference")
        else:
            max_ref = max(abs(b["p_n"]) for b in rrows)
            m["err_ref"] = ratio(max(abs(a["p_n"] - b["p_n"]) for a, b in zip(rows, rrows)), max_ref)
            m["err_p0_ref"] = ratio(num(s, "peak_pressure") - num(rs, "peak_pressure"),
                                    num(rs, "peak_pressure"))
            m["err_a_ref"] = ratio(num(s, "contact_half_width") - num(rs, "contact_half_width"),
                                   num(rs, "contact_half_width"))
    return m


# ---------------------------------------------------------------- the sweep
configs = []
for scene, scene_prm, levels in SCENES:
    for level in levels:
        for label, regularisation, schemes, penalty in VARIANTS:
            for scheme in schemes:
                for tol in TOLERANCES:
                    configs.append((scene, scene_prm, level, label, regularisation,
                                    scheme, penalty, tol))
log(f"speed-accuracy ({MODE}): {len(configs)} configurations x {REPEATS} repeats"
    f" + references, run directories in {WORK}")

# The start-up of the process (loading the libraries): `hrcontact --help`.
startup = []
for _ in range(max(REPEATS, 1)):
    t0 = time.perf_counter()
    subprocess.run([EXE, "--help"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    startup.append(time.perf_counter() - t0)
STARTUP = statistics.median(startup)
log(f"start-up of the process: {STARTUP:.2f} s")

references, records = {}, []
for i, (scene, scene_prm, level, label, regularisation, scheme, penalty, tol) in \
        enumerate(configs, 1):
    key = (scene, level)
    if key not in references:
        reg, sch, factors, rtol = REFERENCE
        for pen in factors:
            ref = run(f"{scene}-r{level}/reference-{pen}", scene_prm, level, reg, sch,
                      pen, rtol, 1)
            ref["penalty"] = pen
            log(f"reference {scene} r{level} (Initial penalty {pen}): {ref['status']}"
                f" {ref['reason']} ({ref['walls'][0]:.2f} s,"
                f" {ref['summary'].get('linear_solves', '?')} solves)")
            if ref["status"] == "converged":
                break
        else:
            log("  warning: no reference, the errors against it stay empty")
        references[key] = ref
    name = f"{scene}-r{level}/{label.replace(',', '').replace(' ', '-')}-{scheme}-tol{tol}"
    r = run(name, scene_prm, level, regularisation, scheme, penalty, tol, REPEATS)
    s = r["summary"]
    rec = dict(
        scene=scene, refinements=level, cells=s.get("cells", ""),
        displacement_dofs=s.get("displacement_dofs", ""),
        stress_dofs=s.get("stress_dofs", ""),
        contact_constraints=s.get("contact_constraints", ""),
        variant=label, regularisation=regularisation, scheme=scheme,
        initial_penalty=penalty, tolerance=tol, status=r["status"], reason=r["reason"],
        updates=s.get("iterations", ""), newton_steps=s.get("newton_steps", ""),
        linear_solves=s.get("linear_solves", ""),
        wall_median_s=statistics.median(r["walls"]),
        wall_runs_s=";".join(f"{w:.4f}" for w in r["walls"]),
        solver_wall_s=num(s, "wall_time"),
        final_norm_pbar=num(s, "final_norm_pbar"),
        max_abs_p_n=num(s, "max_abs_p_n"),
        peak_pressure=num(s, "peak_pressure"),
        contact_half_width=num(s, "contact_half_width"),
        **measures(r, references[key]),
        reference_penalty=(references[key]["penalty"]
                           if references[key]["status"] == "converged" else ""),
        rundir=os.path.relpath(r["rundir"], WORK))
    records.append(rec)
    log(f"[{i}/{len(configs)}] {scene} r{level} {label} {scheme} tol {tol}: {r['status']}"
        f"{' (' + r['reason'] + ')' if r['reason'] else ''}, {rec['wall_median_s']:.2f} s,"
        f" {rec['linear_solves'] or '?'} solves, error vs reference {rec['err_ref']:.3g}")

# A rebuild during the sweep mixes two executables in one table: say so.
if datetime.datetime.fromtimestamp(os.path.getmtime(EXE)).strftime("%Y-%m-%d %H:%M:%S") != BUILT:
    BUILT += " (WARNING: rebuilt during the sweep, the runs mix two builds)"
    log(f"warning: {EXE} was rebuilt during the sweep")

# ---------------------------------------------------------------- CSV
fields = list(records[0].keys())


def csv_value(v):
    if isinstance(v, float):
        return "" if math.isnan(v) else f"{v:.10g}"
    return v


os.makedirs("doc", exist_ok=True)
tmp = "doc/speed-accuracy-data.csv.tmp"
with open(tmp, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=fields)
    w.writeheader()
    for rec in records:
        w.writerow({k: csv_value(v) for k, v in rec.items()})
os.replace(tmp, "doc/speed-accuracy-data.csv")
log("wrote doc/speed-accuracy-data.csv")

# ---------------------------------------------------------------- table


def sci(v):
    return "–" if not math.isfinite(v) else ("0" if v == 0 else f"{v:.2e}")


def pct(v):
    return "–" if not math.isfinite(v) else f"{100 * v:+.2f} %"


lines = [
    "<!-- Generated by scripts/speed-accuracy.sh; do not edit. -->",
    f"Reproduce: `{os.environ['REPRODUCE']}` ({MODE} mode, {REPEATS} repeat(s) per run,"
    f" generated {datetime.date.today().isoformat()}).",
    "",
    f"Executable: {os.path.relpath(EXE, ROOT)} built {BUILT}; sources {SOURCES}.",
    "",
    "Reference: consistent augmented Lagrangian, classical, Relative tolerance 1e-12,"
    " same mesh, Initial penalty factor " + "; ".join(
        f"{sc} r{lv}: " + (ref["penalty"] if ref["status"] == "converged" else
                           f"none converged ({ref['status']}: {ref['reason']})")
        for (sc, lv), ref in references.items()) + ". All runs: Path = condensed, direct solver, Initial penalty scaling ="
    " nodal compliance (factor 1e4 unless named). Wall s: median process wall time"
    f" (includes the start-up of the process, {STARTUP:.2f} s for `hrcontact --help`);"
    " solver s: summary.txt wall_time. Error p0 / a:"
    " against Hertz; Δ ref: against the reference run; error vs ref:"
    " max |p_n - p_ref| / max |p_ref|. Tension: max(p_n, 0) / max |p_n|; penetration:"
    " max(w_n - g, 0) / max |u|; complementarity: max |p_n (w_n - g)| /"
    " (max |p_n| max |w_n - g|), with w_n the column of contact.csv (g + mu: g for"
    " the pure penalty); (u·n): the same with the normal displacement of the"
    " displacement field. contact.csv holds 12 digits: differences below ~1e-12 are"
    " rounding. Runs that did not converge: accuracy in the CSV only.",
    "",
    "| scene | u dofs | variant | scheme | tol | status | updates | Newton steps"
    " | linear solves | wall s | solver s | error p0 | error a | Δp0 ref | Δa ref"
    " | error vs ref | max tension | max penetration | complementarity"
    " | max penetration (u·n) | complementarity (u·n) |",
    "|---|---:|---|---|---:|---|" + "---:|" * 15,
]
for r in records:
    hertz = r["scene"] == "hertz"
    if r["status"] != "converged":  # accuracy of an unfinished run: CSV only
        r = dict(r, **{k: NAN for k in r if k.startswith(("err_", "tension", "penetration",
                                                           "complementarity"))})
    status = r["status"] + (f": {r['reason']}" if r["reason"] else "")
    lines.append(
        f"| {r['scene']} | {r['displacement_dofs'] or '–'} | {r['variant']} | {r['scheme']}"
        f" | {r['tolerance']} | {status} | {r['updates'] or '–'} | {r['newton_steps'] or '–'}"
        f" | {r['linear_solves'] or '–'} | {r['wall_median_s']:.2f}"
        f" | {'–' if math.isnan(r['solver_wall_s']) else format(r['solver_wall_s'], '.2f')}"
        f" | {pct(r['err_p0_hertz']) if hertz else '–'} | {pct(r['err_a_hertz']) if hertz else '–'}"
        f" | {sci(r['err_p0_ref']) if hertz else '–'} | {sci(r['err_a_ref']) if hertz else '–'}"
        f" | {sci(r['err_ref'])} | {sci(r['tension_rel'])} | {sci(r['penetration_rel'])}"
        f" | {sci(r['complementarity_rel'])} | {sci(r['penetration_u_rel'])}"
        f" | {sci(r['complementarity_u_rel'])} |")
tmp = "doc/speed-accuracy-table.md.tmp"
with open(tmp, "w") as f:
    f.write("\n".join(lines) + "\n")
os.replace(tmp, "doc/speed-accuracy-table.md")
log("wrote doc/speed-accuracy-table.md")

# ---------------------------------------------------------------- plot data
# Per scene and axis (wall s, linear solves): one data file per variant and
# scheme (x, error, point size by mesh), the Pareto front per mesh (no other
# converged run of that mesh is cheaper and more accurate; an error within a
# factor PARETO_SLACK of a cheaper run's counts as no better, so that
# rounding-level differences do not make fronts), and a gnuplot
# script. Errors below FLOOR (0 for a run identical to the reference; the
# 12 digits of contact.csv resolve little below) are drawn at FLOOR.
FLOOR = 1e-13
PARETO_SLACK = 2.0
plotdir = os.path.join(WORK, "plot")
os.makedirs(plotdir, exist_ok=True)
colours = ["#1f77b4", "#17becf", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd"]
filled = {"classical": [7, 15, 5, 9, 11, 13], "diagonal": [6, 14, 4, 8, 10, 12]}
axes = [("wall_median_s", "median wall time (s)"), ("linear_solves", "linear solves")]
ok = [r for r in records if r["status"] == "converged" and math.isfinite(r["err_ref"])]
levels_of = {scene: levels for scene, _, levels in SCENES}
gp = [
    "set terminal pngcairo size 1400,1000 font ',10'",
    "set output 'doc/figures/speed-accuracy.png.tmp'",
    "set multiplot layout 2,2 title \"Speed against accuracy: solver error against the"
    f" reference run ({MODE} mode). Filled: classical, open: diagonal; larger points:"
    " finer mesh.\\nBlack: Pareto front per mesh (errors within a factor"
    f" {PARETO_SLACK:g} count as equal); errors below {FLOOR:g} drawn at {FLOOR:g}.\"",
    "set logscale xy; set grid; set format y '10^{%L}'",
    "set ylabel 'max |p_n - p_{ref}| / max |p_{ref}|'",
]
for scene, _, _ in SCENES:
    for ax, (xkey, xlabel) in enumerate(axes):
        pts = [r for r in ok if r["scene"] == scene]
        items = []
        for vi, (label, _, schemes, _) in enumerate(VARIANTS):
            for scheme in schemes:
                sel = [r for r in pts if r["variant"] == label and r["scheme"] == scheme]
                if not sel:
                    continue
                fn = os.path.join(plotdir, f"{scene}-{ax}-{vi}-{scheme}.dat")
                with open(fn, "w") as f:
                    for r in sel:
                        size = 1.0 + 0.6 * levels_of[scene].index(r["refinements"])
                        f.write(f"{float(r[xkey])} {max(r['err_ref'], FLOOR)} {size}\n")
                items.append(f"'{fn}' using 1:2:3 with points pt {filled[scheme][vi]}"
                             f" ps variable lc rgb '{colours[vi]}' title '{label}, {scheme}'")
        for li, level in enumerate(levels_of[scene]):
            mesh = sorted(((float(r[xkey]), max(r["err_ref"], FLOOR)) for r in pts
                           if r["refinements"] == level))
            front, best = [], math.inf
            for x, e in mesh:  # sorted by cost: keep each clearly better error
                if e * PARETO_SLACK < best:
                    front.append((x, e))
                    best = e
            if not front:
                continue
            fn = os.path.join(plotdir, f"{scene}-{ax}-front-r{level}.dat")
            with open(fn, "w") as f:
                f.writelines(f"{x} {e}\n" for x, e in front)
            items.append(f"'{fn}' using 1:2 with steps lc rgb 'black' dt {li + 1}"
                         f" title 'Pareto front, refinements {level}'")
            items.append(f"'{fn}' using 1:2 with points pt 6 ps 2.6 lc rgb 'black' notitle")
        gp.append(f"set title '{scene}'; set xlabel '{xlabel}'")
        if pts:  # ranges with a margin, so no point sits on the border
            xs = [float(r[xkey]) for r in pts]
            es = [max(r["err_ref"], FLOOR) for r in pts]
            x0, x1 = min(xs) / 1.5, max(xs) * 1.5
            # Tics at 1, 2, 3, 5 (and 1.5, 7 in narrow ranges) per decade.
            mant = (1, 2, 3, 5) if x1 / x0 > 30 else (1, 1.5, 2, 3, 5, 7)
            tics = [m * 10.0 ** d for d in range(math.floor(math.log10(x0)),
                                                 math.ceil(math.log10(x1)) + 1)
                    for m in mant if x0 <= m * 10.0 ** d <= x1]
            gp.append(f"set xrange [{x0:g}:{x1:g}]; set yrange [{min(es) / 10:g}:{max(es) * 10:g}]")
            gp.append("set xtics (" + ", ".join(f"'{t:g}' {t:g}" for t in tics) + ")")
        gp.append("set key outside right top" if ax == 1 else "unset key")
        if items:
            gp.append("plot " + ", \\\n     ".join(items))
        else:  # nothing converged: an empty panel that says so
            gp.append("unset logscale; set label 1 'no converged runs' at graph 0.4, 0.5;"
                      " plot [0:1] [0:1] 1/0 notitle; unset label 1; set logscale xy")
gp.append("unset multiplot")
with open(os.path.join(plotdir, "speed-accuracy.gp"), "w") as f:
    f.write("\n".join(gp) + "\n")
stopped = [r for r in records if r["status"] != "converged"]
log(f"{len(records) - len(stopped)} converged, {len(stopped)} not:"
    + "".join(f"\n  {r['scene']} r{r['refinements']} {r['variant']} {r['scheme']}"
              f" tol {r['tolerance']}: {r['status']} {r['reason']}" for r in stopped))
PY

gnuplot "$WORK/plot/speed-accuracy.gp"
mv doc/figures/speed-accuracy.png.tmp doc/figures/speed-accuracy.png
echo "wrote doc/figures/speed-accuracy.png"
fi

if [ "$part" != solvers ]; then
  python3 scripts/speed_accuracy_elements.py
fi
