#!/usr/bin/env python3
"""Write the MoorDyn v2 input file of flexmoor's Example 8 (a single point moor released).

Usage: scripts/moordyn/write_ex8_input.py [CASE.yaml] SEGMENTS DTM > ex8.txt
  CASE default cases/seed/ex8-relaxation-test.yaml (scenario single_point_moor, US units).

Converted to SI from the case: water density and depth, gravity; the rope (length, EA, mass
from its weight in air, diameter, Cd = Cn, Ca, CdAx = Ct / pi, MoorDyn's CdAx acting on pi d
where the case's tangential_drag_area: diameter takes d, CaAx); the anchor (a Fixed point on the
bed below the origin) and the buoy (a Free point where the case holds it: mass from its weight in
air, volume from its buoyancy, CdA = Cd pi D^2 / 4, Ca). No internal damping (the case has
none). MoorDyn's Morison loads and buoyancy are per unstretched length and its EA is on the
engineering strain; the case's are per deformed length on Green's strain unless it says
otherwise (the comparison test runs flexmoor with MoorDyn's conventions).
"""
import math
import sys

import yaml

FT, LBF, SLUG = 0.3048, 4.4482216152605, 14.593902937206364
UNITS = {"in": FT / 12, "ft": FT, "lbf": LBF, "lbf/ft": LBF / FT, "slug/ft^3": SLUG / FT**3,
         "ft/s^2": FT}


def si(value):
    """A quantity of the case ("71.56 in", "4.8 lbf") in SI."""
    number, unit = str(value).split()
    return float(number) * UNITS[unit]


def main():
    args = sys.argv[1:]
    case_path = args.pop(0) if len(args) == 3 else "cases/seed/ex8-relaxation-test.yaml"
    segments, dtm = int(args[0]), float(args[1])
    case = yaml.safe_load(open(case_path))
    if case.get("scenario") != "single_point_moor" or "anchor" in case:
        sys.exit(f"{case_path}: a single_point_moor case with its anchor below the origin expected")
    cable, buoy = case["cable"], case["buoy"]
    rho, depth, g = si(case["water"]["density"]), si(case["water"]["depth"]), si(case["gravity"])
    if cable.get("tangential_drag_area", "perimeter") == "perimeter":
        cdax = float(cable.get("Ct", 0))
    else:  # the dissertation's d: MoorDyn's pi d CdAx = d Ct
        cdax = float(cable.get("Ct", 0)) / math.pi
    mass_per_length = si(cable["weight_in_air"]) / g
    buoy_mass = si(buoy["weight_in_air"]) / g
    buoy_volume = (si(buoy["weight_in_air"]) - si(buoy["weight_in_water"])) / (rho * g)
    diameter = si(buoy["diameter"])
    cda = float(buoy["Cd"]) * math.pi * diameter**2 / 4
    x, z = (si(v) for v in buoy["held_at"])
    out = [
        "--------------------- MoorDyn Input File ------------------------------------",
        f"{case['title']}: written by scripts/moordyn/write_ex8_input.py from {case_path}, SI",
        "----------------------- LINE TYPES ------------------------------------------",
        "TypeName   Diam    Mass/m     EA         BA/-zeta    EI    Cd     Ca     CdAx    CaAx",
        "(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2) (-)  (-)    (-)     (-)",
        f"rope {si(cable['diameter']):.9g} {mass_per_length:.9g} {si(cable['EA']):.9g} 0 0"
        f" {float(cable['Cn']):g} {float(cable['Ca']):g} {cdax:.9g} {float(cable.get('CaAx', 0)):g}",
        "---------------------- POINTS ---------------------------------------",
        "ID    Attachment  X       Y       Z       Mass   Volume  CdA    Ca",
        "(#)   (-)         (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)",
        f"1 Fixed 0 0 {-depth:.9g} 0 0 0 0",
        f"2 Free {x:.9g} 0 {z - depth:.9g} {buoy_mass:.9g} {buoy_volume:.9g} {cda:.9g}"
        f" {float(buoy.get('Ca', 0.5)):g}",
        "---------------------- LINES ----------------------------------------",
        "ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs",
        "(#)  (name)     (#)      (#)      (m)       (-)      (-)",
        f"1 rope 1 2 {si(cable['length']):.9g} {segments} -",
        "---------------------- OPTIONS -----------------------------------------",
        f"{dtm:<14g}dtM", f"{g:<14.9g}g", f"{rho:<14.9g}rho", f"{depth:<14.9g}WtrDpth",
        "1             disableOutput", "1             disableOutTime",
        "------------------------- need this line -------------------------------------"]
    print("\n".join(out))


if __name__ == "__main__":
    main()
