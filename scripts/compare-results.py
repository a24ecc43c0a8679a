#!/usr/bin/env python3
"""Compare the result files of two runs of one scene (serial and MPI).

    compare-results.py DIR_A DIR_B

summary.txt: every numeric key must agree to 1e-6 relative, with an
absolute floor of 1e-9. Two kinds of keys are round-off by construction and
only have to stay so in both runs: a total reaction whose load vanishes
(below 1e-6 (1 + the force scale: the largest total or nodal reaction)), and
the residual measures of the contact iteration (final_norm_pbar,
max_complementarity, max_positive_p_n, max_penetration, below the tolerance
key; equilibrium_imbalance, below 1e-9). Tables (*.csv): every column must agree to 1e-6 of the
column's largest magnitude; in history.csv a norm_pbar below the summary's
tolerance on both sides is round-off too (a first update that already holds,
where the column's largest magnitude is that round-off itself). Timings (wall_time, *seconds*), peak_memory_MB and
preconditioner_setups are skipped.
Prints the first differences and exits 1 if there are any.
"""
import csv
import os
import sys


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def compare_summary(a, b, report):
    def read(name):
        entries = {}
        with open(name) as f:
            for line in f:
                key, _, value = line.partition(" = ")
                entries[key.strip()] = value.strip()
        return entries

    ea, eb = read(a), read(b)
    if ea.keys() != eb.keys():
        report(f"summary.txt: keys differ: {sorted(set(ea) ^ set(eb))}")
        return
    totals = [abs(number(v)) for k, v in ea.items()
              if k.startswith("total_") and number(v) is not None]
    force_scale = max(totals + [abs(number(ea.get("max_abs_p_n", "0")))])
    residuals = ("final_norm_pbar", "max_complementarity", "max_positive_p_n",
                 "max_penetration")
    for key, va in ea.items():
        # preconditioner_setups counts the serial direct back end's
        # factorisations but not MUMPS's: a count of work, not a result.
        if key in ("wall_time", "peak_memory_MB", "preconditioner_setups") \
                or "seconds" in key:
            continue
        xa, xb = number(va), number(eb[key])
        if xa is None or xb is None:
            if va != eb[key]:
                report(f"summary.txt: {key}: '{va}' vs '{eb[key]}'")
            continue
        tol = 1e-6 * max(abs(xa), abs(xb)) + 1e-9
        largest = max(abs(xa), abs(xb))
        if key.startswith("total_reaction_") and \
                number(ea.get(key.replace("reaction", "load"), "1")) == 0 and \
                largest < 1e-6 * (1 + force_scale):
            continue
        if key in residuals and "tolerance" in ea and \
                largest <= number(ea["tolerance"]):
            continue
        if key == "equilibrium_imbalance" and largest < 1e-9:
            continue
        if abs(xa - xb) > tol:
            report(f"summary.txt: {key}: {xa} vs {xb}")


def compare_table(name, a, b, report, roundoff=0.0):
    with open(a) as f:
        ra = list(csv.reader(f))
    with open(b) as f:
        rb = list(csv.reader(f))
    if len(ra) != len(rb) or (ra and ra[0] != rb[0]):
        report(f"{name}: different shape or header")
        return
    header = ra[0]
    for c, column in enumerate(header):
        if "seconds" in column:
            continue
        values = [(number(x[c]), number(y[c]), x[c], y[c])
                  for x, y in zip(ra[1:], rb[1:])]
        scale = max((max(abs(u), abs(v)) for u, v, _, _ in values
                     if u is not None and v is not None), default=0.0)
        for row, (u, v, s, t) in enumerate(values, start=2):
            if u is None or v is None:
                if s != t:
                    report(f"{name}: line {row} {column}: '{s}' vs '{t}'")
            elif column == "norm_pbar" and max(abs(u), abs(v)) <= roundoff:
                continue
            elif abs(u - v) > 1e-6 * scale:
                report(f"{name}: line {row} {column}: {u} vs {v}")


def main():
    a, b = sys.argv[1], sys.argv[2]
    problems = []
    # The contact iteration's tolerance, under which ||pbar|| is round-off.
    roundoff = 0.0
    summary = os.path.join(a, "summary.txt")
    if os.path.exists(summary):
        with open(summary) as f:
            for line in f:
                key, _, value = line.partition(" = ")
                if key.strip() == "tolerance" and number(value) is not None:
                    roundoff = number(value)
    for name in sorted(os.listdir(a)):
        if not os.path.isfile(os.path.join(a, name)):
            continue
        if name == "summary.txt":
            compare_summary(os.path.join(a, name), os.path.join(b, name),
                            problems.append)
        elif name.endswith(".csv"):
            if not os.path.exists(os.path.join(b, name)):
                problems.append(f"{name} missing")
                continue
            compare_table(name, os.path.join(a, name), os.path.join(b, name),
                          problems.append,
                          roundoff if name == "history.csv" else 0.0)
    for p in problems[:5]:
        print(p)
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
