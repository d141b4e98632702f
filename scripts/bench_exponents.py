"""Reads Google Benchmark JSON and prints per-size figures and growth exponents per family."""
import json
import math
import sys
from collections import defaultdict


def per_operation(b):
    """Seconds per operation: per time step when the benchmark counts steps, else per iteration."""
    if "steps" in b:
        return 1.0 / b["steps"]
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
    return b["real_time"] * scale


def main(path):
    with open(path) as f:
        data = json.load(f)
    families = defaultdict(list)
    for b in data["benchmarks"]:
        if b.get("run_type") != "iteration" or "dofs" not in b:
            continue
        families[b["name"].split("/")[0]].append(b)
    for name, runs in families.items():
        runs.sort(key=lambda b: b["dofs"])
        print(f"{name}")
        print(f"  {'dofs':>8} {'time/op':>12} {'exponent':>9}  memory per dof")
        previous = None
        for b in runs:
            t = per_operation(b)
            exponent = ""
            if previous:
                exponent = f"{math.log(t / previous[1]) / math.log(b['dofs'] / previous[0]):9.2f}"
            memory = ", ".join(f"{k} {b[k]:.1f}" for k in ("K_nnz_per_dof", "L_nnz_per_dof") if k in b)
            extra = f", {b['iterations_per_step']:.1f} iterations/step" if "iterations_per_step" in b else ""
            print(f"  {int(b['dofs']):>8} {t * 1e3:>9.4f} ms {exponent:>9}  {memory}{extra}")
            previous = (b["dofs"], t)
        first, last = runs[0], runs[-1]
        overall = math.log(per_operation(last) / per_operation(first)) / math.log(last["dofs"] / first["dofs"])
        print(f"  overall exponent {overall:.2f}\n")


if __name__ == "__main__":
    main(sys.argv[1])
