#!/usr/bin/env python3
"""Writes a case file with N explicit nodes, to time the reader (docs/performance.md, "Reading
cases"): a square net of ceil(sqrt(N)) chains of L2 cables along x, tied by cables along y, every
node given in `nodes:` (ids shuffled, so that the reader cannot rely on their order), the four
edges pinned, one static step.

    /usr/bin/python3 scripts/big_case.py 1800000 > /tmp/net-1.8M.yaml
    /usr/bin/time -v build/bin/flexmoor check /tmp/net-1.8M.yaml
"""
import math
import random
import sys


def main():
    count = int(sys.argv[1])
    side = max(2, math.isqrt(count - 1) + 1)
    rows = max(2, -(-count // side))
    nodes = side * rows
    ids = list(range(1, nodes + 1))
    random.Random(1).shuffle(ids)  # file id of node (i, j) = ids[j * side + i]
    out = sys.stdout
    out.write("name: net\nunits: SI\n")
    out.write("materials:\n  steel: {type: linear_elastic, E: 2.0e11}\n")
    out.write("sections:\n  wire: {material: steel, area: 1.0e-4, density: 7850}\n")
    out.write("nodes:\n")
    for j in range(rows):
        for i in range(side):
            out.write(f"  {ids[j * side + i]}: [{i}, {j}, 0]\n")
    out.write("elements:\n")
    for j in range(rows):
        for i in range(side):
            a = ids[j * side + i]
            if i + 1 < side:
                out.write(f"  - {{type: cable, nodes: [{a}, {ids[j * side + i + 1]}], section: wire}}\n")
            if j + 1 < rows:
                out.write(f"  - {{type: cable, nodes: [{a}, {ids[(j + 1) * side + i]}], section: wire}}\n")
    edge = [ids[j * side + i] for j in range(rows) for i in range(side)
            if i in (0, side - 1) or j in (0, rows - 1)]
    out.write("node_sets:\n  edge: [" + ", ".join(map(str, edge)) + "]\n")
    out.write("supports:\n  - {nodes: edge, fix: [x, y, z]}\n")
    out.write("loads:\n  gravity: [0, 0, -9.81]\n")
    out.write("steps:\n  - static: {}\n")


if __name__ == "__main__":
    main()
