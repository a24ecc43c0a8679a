#!/usr/bin/env python3
"""Draw the fracture strain of a no-tension (or no-compression) run: each
cell of solution.vtu filled by its largest fracture strain, on the deformed
shape or not, into a PNG with gnuplot (pngcairo), and over it the direction
of the most compressive principal stress at each cell's centre, a stroke
whose length is its magnitude (0.9 of the cell's width at the 95th
percentile and above; none where the cell carries nothing, so cracked cells
stay bare).

    python3 scripts/plot_fracture_strain.py output/masonry-arch [out.png]

Reads deal.II's compressed binary VTU (vtkZLibDataCompressor, UInt32
headers) without VTK: points, connectivity and the point field
`fracture_strain` (each cell is its own patch: 4 points in 2D).
"""
import base64
import math
import os
import re
import struct
import subprocess
import sys
import zlib


def decode(text, kind):
    """One binary DataArray: a base64 header (blocks, block size, last block
    size, compressed sizes) then the base64 of the compressed blocks."""
    text = text.strip()
    head = base64.b64decode(text[:24])
    nblocks = struct.unpack("<I", head[:4])[0]
    header_len = 4 * (3 + nblocks)
    header_chars = ((header_len + 2) // 3) * 4
    header = base64.b64decode(text[:header_chars])
    sizes = struct.unpack("<%dI" % (3 + nblocks), header)
    data = base64.b64decode(text[header_chars:])
    raw, offset = b"", 0
    for size in sizes[3:]:
        raw += zlib.decompress(data[offset:offset + size])
        offset += size
    fmt = {"Float32": "f", "Int32": "i", "UInt8": "B"}[kind]
    n = len(raw) // struct.calcsize(fmt)
    return struct.unpack("<%d%s" % (n, fmt), raw)


def read_vtu(name):
    text = open(name).read()
    arrays = {}
    for m in re.finditer(r'<DataArray type="(\w+)"([^>]*)>(.*?)</DataArray>',
                         text, re.S):
        kind, attributes, body = m.groups()
        key = re.search(r'Name="([^"]+)"', attributes)
        arrays[key.group(1) if key else "points"] = decode(body, kind)
    return arrays


def main():
    directory = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(
        directory, "fracture-strain.png")
    a = read_vtu(os.path.join(directory, "solution.vtu"))
    points, cells = a["points"], a["connectivity"]
    strain = a["fracture_strain"]
    data = os.path.join(directory, "fracture-strain.dat")
    with open(data, "w") as f:
        # VTK quad order: around the cell.
        for c in range(len(cells) // 4):
            ids = [cells[4 * c + k] for k in (0, 1, 2, 3, 0)]
            value = max(strain[i] for i in ids)
            for i in ids:
                f.write("%g %g %g\n" % (points[3 * i], points[3 * i + 1],
                                        value))
            f.write("\n")
    # The compressive principal stress at each cell's centre: the mean of
    # its vertex values is the bilinear field there.
    sxx, syy, sxy = a["sxx"], a["syy"], a["sxy"]
    strokes = []
    for c in range(len(cells) // 4):
        ids = cells[4 * c:4 * c + 4]
        x = sum(points[3 * i] for i in ids) / 4
        y = sum(points[3 * i + 1] for i in ids) / 4
        h = min(math.dist((points[3 * ids[0]], points[3 * ids[0] + 1]),
                          (points[3 * ids[k]], points[3 * ids[k] + 1]))
                for k in (1, 3))
        a_, b_, c_ = (sum(v[i] for i in ids) / 4 for v in (sxx, syy, sxy))
        mean, radius = (a_ + b_) / 2, math.hypot((a_ - b_) / 2, c_)
        smallest = mean - radius
        angle = 0.5 * math.atan2(2 * c_, a_ - b_) + math.pi / 2
        strokes.append((x, y, h, min(smallest, 0.0), angle))
    # Scaled by the 95th percentile, so that one concentrated peak (a
    # springing's corner) does not shrink every other stroke.
    magnitudes = sorted(-s[3] for s in strokes)
    largest = (magnitudes[int(0.95 * (len(magnitudes) - 1))]
               if magnitudes else 0) or 1
    arrows = os.path.join(directory, "compression.dat")
    with open(arrows, "w") as f:
        for x, y, h, s, angle in strokes:
            length = 0.9 * h * min(1.0, -s / largest)
            if length > 0.05 * h:
                dx, dy = length * math.cos(angle), length * math.sin(angle)
                f.write("%g %g %g %g\n" % (x - dx / 2, y - dy / 2, dx, dy))
    xs = points[0::3]
    ys = points[1::3]
    aspect = (max(xs) - min(xs)) / max(max(ys) - min(ys), 1e-300)
    # Width for the shape plus the colour bar; tall bodies get a tall plot.
    width, height = (1000, int(900 / aspect) + 150) if aspect > 1.2 else \
        (int(600 * aspect) + 450, 700)
    script = """
set terminal pngcairo size %d,%d font ",11"
set output '%s'
set size ratio -1
set style fill solid 1.0 noborder
set palette defined (0 '#f7f7f7', 1 '#fdae61', 2 '#d7191c', 3 '#67001f')
set cblabel 'fracture strain'
set xlabel 'x'
set ylabel 'y'
set title '%s: fracture strain, cell by cell; strokes: compression' noenhanced
plot '%s' using 1:2:3 with polygons fillcolor palette notitle, \\
     '%s' using 1:2 with lines lc rgb '#777777' lw 0.3 notitle, \\
     '%s' using 1:2:3:4 with vectors nohead lc rgb '#08306b' lw 1.2 notitle
""" % (width, height, out, os.path.basename(directory.rstrip("/")), data,
       data, arrows)
    subprocess.run(["gnuplot"], input=script.encode(), check=True)
    print(out)


if __name__ == "__main__":
    main()
