#!/usr/bin/env bash
# A 2D solution.vtu's mesh, each cell filled by the colour of one cell field
# (a log scale), as a PNG: e.g. the bound-refined L-shape coloured by its
# error_bound_indicator (doc/error-bounds.md).
#   bash scripts/plot-cell-field.sh output/l-shape-error-bound/solution.vtu \
#        error_bound_indicator doc/l-shape-error-bound.png
# An optional fourth argument XMIN:XMAX:YMIN:YMAX shows only that window
# (e.g. the contact zone of a Hertz mesh); MESH_LINES=0 leaves out the cell
# edges (a mesh of 10^5 cells is black with them).
# Reads deal.II's compressed binary VTU with Python's standard library;
# needs gnuplot (Debian: apt-get install gnuplot-nox).
set -euo pipefail
[ $# -eq 3 ] || [ $# -eq 4 ] || { echo "usage: $0 SOLUTION.vtu FIELD OUT.png [XMIN:XMAX:YMIN:YMAX]" >&2; exit 2; }
command -v gnuplot > /dev/null || { echo "gnuplot is missing: apt-get install gnuplot-nox" >&2; exit 1; }
vtu=$1 field=$2 png=$3 window=${4:-}
ranges=""
if [ -n "$window" ]; then
  IFS=: read -r x0 x1 y0 y1 <<< "$window"
  ranges="set xrange [$x0:$x1]
set yrange [$y0:$y1]"
fi
data=$(mktemp)
lines=', "'"$data"'" using 1:2 with lines lc rgb "#404040" lw 0.3'
[ "${MESH_LINES:-1}" = 0 ] && lines=""
trap 'rm -f "$data"' EXIT
python3 - "$vtu" "$field" > "$data" <<'PY'
import base64, re, struct, sys, zlib
text = open(sys.argv[1]).read()
def array(name):
    # deal.II: a base64 header (blocks, block size, last size, compressed
    # sizes), then the base64 of the zlib blocks.
    m = re.search(r'<DataArray type="(\w+)"[^>]*' + name + r'[^>]*>\s*(\S+)\s*</DataArray>', text)
    if not m:
        sys.exit("no DataArray " + name + " in " + sys.argv[1])
    kind, blob = m.group(1), m.group(2)
    head = base64.b64decode(blob[:24])
    n = struct.unpack('<I', head[:4])[0]
    hlen = 4 * (3 + n)
    hlen64 = 4 * ((hlen + 2) // 3)
    header = struct.unpack('<%dI' % (3 + n), base64.b64decode(blob[:hlen64])[:hlen])
    raw = base64.b64decode(blob[hlen64:])
    out, pos = b'', 0
    for size in header[3:]:
        out += zlib.decompress(raw[pos:pos + size]); pos += size
    code = {'Float32': 'f', 'Float64': 'd', 'Int32': 'i', 'UInt8': 'B'}[kind]
    return struct.unpack('<%d%s' % (len(out) // struct.calcsize(code), code), out)
points = array('NumberOfComponents="3" format')
conn, offsets = array('Name="connectivity"'), array('Name="offsets"')
values = array('Name="' + sys.argv[2] + '"')
start = 0
for end in offsets:
    cell = conn[start:end]
    # VTK's quadrilaterals go round already.
    ring = list(cell) + [cell[0]]
    v = max(values[cell[0]], 1e-30)
    for p in ring:
        print(points[3 * p], points[3 * p + 1], v)
    print()
    start = end
PY
gnuplot <<GP
set terminal pngcairo size 900,800
set output "$png"
set size ratio -1
$ranges
set logscale cb
set format cb "%.0e"
set palette rgb 33,13,10
set cblabel "$field" noenhanced
unset key
plot "$data" using 1:2:3 with filledcurves fc palette$lines
GP
echo "plot-cell-field: $png"
