#!/usr/bin/env python3
"""Writes a case file with N explicit nodes, to time the reader (docs/performance.md, "Reading
cases"). Every node is given in `nodes:` as a square grid, its ids shuffled so that the reader
cannot rely on their order.
  nodes  (default) the grid is fixed and one line of 10 cables spans it: the time is the
         reading of the node table
  net    the grid is a net of L2 cables along x and y (about 2N elements), its edges pinned

    /usr/bin/python3 scripts/big_case.py 1800000 > /tmp/nodes-1.8M.yaml
    /usr/bin/time -v build/bin/flexmoor check /tmp/nodes-1.8M.yaml
"""
import math
import random
import sys


def main():
    count = int(sys.argv[1])
    net = len(sys.argv) > 2 and sys.argv[2] == "net"
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
    if not net:  # a hanging line from the first grid node up to z = 1, pinned at both ends
        out.write(f"lines:\n  - {{start_node: {ids[0]}, to: [0, 0, 1], elements: 10, order: 2, "
                  "section: wire}\n")
        out.write("supports:\n  - {nodes: {where: {z: 0}}, fix: [x, y, z]}\n"
                  "  - {nodes: {where: {z: 1}}, fix: [x, y, z]}\n")
        out.write("loads:\n  gravity: [0, 0, -9.81]\nsteps:\n  - relax: {}\n")
        return
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
