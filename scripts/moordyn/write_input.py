#!/usr/bin/env python3
"""Write the MoorDyn v2 input file of a flexmoor spread-mooring surge case.

Usage: scripts/moordyn/write_input.py CASE.yaml SEGMENTS DTM [TSCHEME] > lines.txt

CASE is cases/ocean/oc4-semi-surge.yaml or oc3-hywind-surge.yaml (scenario spread_mooring, SI,
one line type, single-segment lines, no waves or current). Everything MoorDyn needs is taken
from the case: water density and depth, gravity, the seabed's stiffness and damping (MoorDyn's
kBot and cBot, no friction), the line type (diameter, mass per length, EA, BA, Cd = Cn, Ca,
CdAx = Ct on pi d, CaAx; MoorDyn's loads are per unstretched length, the case's per_length),
anchors (Fixed points 1-3) and fairleads (Coupled points 4-6: the driver moves them), each
line's unstretched length. SEGMENTS (a line) and DTM (s) are MoorDyn's resolution; TSCHEME its
time integrator (default RK2, MoorDyn-C's). The initial condition is MoorDyn-C's stationary
solver to a relative tension change of 1e-6 (threshIC), at most 300 s (TmaxIC).
"""
import sys

import yaml


def number(value):
    """The number of a flexmoor quantity written in SI ("0.0766 m", "3.052e6 N*s", 200)."""
    if isinstance(value, (int, float)):
        return float(value)
    return float(str(value).split()[0])


def main():
    case_path, segments, dtm = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
    scheme = sys.argv[4] if len(sys.argv) > 4 else "RK2"
    case = yaml.safe_load(open(case_path))
    if case.get("scenario") != "spread_mooring" or case.get("units") != "SI":
        sys.exit(f"{case_path}: not an SI spread_mooring case")
    if "waves" in case or "current" in case or "friction" in case.get("seabed", {}):
        sys.exit(f"{case_path}: waves, current or seabed friction are not written")
    (type_name, line_type), = case["line_types"].items()
    if line_type.get("per_length", "deformed") != "unstretched":
        sys.exit(f"{case_path}: MoorDyn's Morison loads are per unstretched length")
    if line_type.get("tangential_drag_area", "perimeter") != "perimeter":
        sys.exit(f"{case_path}: MoorDyn's CdAx acts on pi d")
    damping = line_type.get("damping", {})
    if set(damping) - {"BA"}:
        sys.exit(f"{case_path}: only damping: {{BA: ...}} is written")
    water, seabed = case["water"], case["seabed"]
    out = []
    out.append("--------------------- MoorDyn Input File ------------------------------------")
    out.append(f"{case['title']}: written by scripts/moordyn/write_input.py from {case_path}")
    out.append("----------------------- LINE TYPES ------------------------------------------")
    out.append("TypeName   Diam    Mass/m     EA         BA/-zeta    EI    Cd     Ca     CdAx    CaAx")
    out.append("(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2) (-)  (-)    (-)     (-)")
    out.append(
        f"{type_name} {number(line_type['diameter']):.6g} {number(line_type['mass_per_length']):.8g}"
        f" {number(line_type['EA']):.8g} {number(damping.get('BA', 0)):.8g} 0"
        f" {number(line_type['Cn']):g} {number(line_type['Ca']):g}"
        f" {number(line_type.get('Ct', 0)):g} {number(line_type.get('CaAx', 0)):g}")
    out.append("---------------------- POINTS ---------------------------------------")
    out.append("ID    Attachment  X       Y       Z       Mass   Volume  CdA    Ca")
    out.append("(#)   (-)         (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)")
    lines = case["mooring_lines"]
    for k, line in enumerate(lines):
        x, y, z = (number(v) for v in line["anchor"])
        out.append(f"{k + 1} Fixed {x:.9g} {y:.9g} {z:.9g} 0 0 0 0")
    for k, line in enumerate(lines):
        x, y, z = (number(v) for v in line["fairlead"])
        out.append(f"{len(lines) + k + 1} Coupled {x:.9g} {y:.9g} {z:.9g} 0 0 0 0")
    out.append("---------------------- LINES ----------------------------------------")
    out.append("ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs")
    out.append("(#)  (name)     (#)      (#)      (m)       (-)      (-)")
    for k, line in enumerate(lines):
        if line.get("type") != type_name or "segments" in line:
            sys.exit(f"{case_path}: line {k + 1} is not a single line of type {type_name}")
        out.append(f"{k + 1} {type_name} {k + 1} {len(lines) + k + 1}"
                   f" {number(line['length']):.9g} {segments} -")
    out.append("---------------------- OPTIONS -----------------------------------------")
    options = [
        (f"{dtm:g}", "dtM"), (scheme, "tScheme"), (f"{number(case['gravity']):.8g}", "g"),
        (f"{number(water['density']):.8g}", "rho"), (f"{number(water['depth']):.8g}", "WtrDpth"),
        (f"{number(seabed['stiffness']):.8g}", "kBot"),
        (f"{number(seabed['damping']):.8g}", "cBot"), ("1.0", "dtIC"), ("300.0", "TmaxIC"),
        ("1e-6", "threshIC"), ("1", "disableOutput"), ("1", "disableOutTime")]
    out += [f"{value:<14}{name}" for value, name in options]
    out.append("------------------------- need this line -------------------------------------")
    print("\n".join(out))


if __name__ == "__main__":
    main()
