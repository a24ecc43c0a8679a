"""Reading an hrcontact summary.txt (shared by the speed-accuracy scripts)."""
import os

NAN = float("nan")


def read_summary(path):
    """summary.txt as a dict of strings ('key = value' lines); empty if the
    file is missing."""
    s = {}
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                if " = " in line:
                    k, v = line.rstrip("\n").split(" = ", 1)
                    s[k.strip()] = v.strip()
    return s


def num(s, key):
    """The value of key as a float, NaN if missing or not a number."""
    try:
        return float(s[key])
    except (KeyError, ValueError):
        return NAN
