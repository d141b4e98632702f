#!/usr/bin/python3
"""Checks of the Python module `flexmoor` (python/flexmoor_python.cpp), each a ctest entry:

  module_checks.py CHECK SOURCE_DIR BUILD_DIR SCRATCH_DIR

PY1 dict_twin      a case given as a dict runs as its YAML file does (summary equal to the bit)
PY2 errors         a case's errors raise CaseError with FILE:LINE; a call out of order CallError;
                   a step that cannot converge ConvergenceError, after which restore goes on
PY3 host_oc4       OC4 stepped from Python with the case's own surge equals `flexmoor run`'s
                   results file in every variable to the last bit (cut to 120 s)
PY4 run_xarray     run() returns the command's summary values to the bit (cpu_seconds aside);
                   the results open in xarray with named lines and a time that selects; states
                   and tensions are NumPy arrays
PY5 example        examples/python/surge_response.py runs and draws its figure
"""
import json
import math
import os
import subprocess
import sys

import numpy as np

CHECK, SOURCE, BUILD, SCRATCH = sys.argv[1:5]
sys.path.insert(0, os.path.join(BUILD, "python"))
import flexmoor  # noqa: E402

FLEXMOOR = os.path.join(BUILD, "bin", "flexmoor")
os.makedirs(SCRATCH, exist_ok=True)


def fail(message):
    print("FAILED:", message)
    sys.exit(1)


def expect(condition, message):
    if not condition:
        fail(message)


def oc4_cut(seconds):
    """oc4-semi-surge with its dynamic step cut to `seconds`, written into SCRATCH."""
    with open(os.path.join(SOURCE, "cases", "ocean", "oc4-semi-surge.yaml")) as f:
        text = f.read()
    expect("steps: 6000" in text, "oc4-semi-surge.yaml no longer says steps: 6000")
    path = os.path.join(SCRATCH, f"oc4-{seconds}s.yaml")
    with open(path, "w") as f:
        f.write(text.replace("steps: 6000", f"steps: {round(seconds / 0.1)}"))
    return path


def run_command(*args):
    r = subprocess.run([FLEXMOOR, *args], capture_output=True, text=True)
    expect(r.returncode == 0, f"flexmoor {' '.join(args)}: exit {r.returncode}\n{r.stderr}")


def ramped_surge(t, amplitude=2.0, period=10.0, ramp=10.0):
    """The case's own surge at t, with its rate and acceleration, in the order of operations of
    its C++ (RampedFunction of SineFunction), so that the values are the same doubles."""
    omega = 2.0 * math.acos(-1.0) / period
    f = 0.0 + amplitude * math.sin(omega * t + 0.0)
    df = amplitude * omega * math.cos(omega * t + 0.0)
    ddf = -amplitude * omega * omega * math.sin(omega * t + 0.0)
    x = (t - 0.0) / ramp
    if x <= 0.0:
        s = ds = dds = 0.0
    elif x >= 1.0:
        s, ds, dds = 1.0, 0.0, 0.0
    else:
        x2 = x * x
        s = x2 * x * (10.0 - 15.0 * x + 6.0 * x2)
        ds = 30.0 * x2 * (1.0 - x) * (1.0 - x) / ramp
        dds = 60.0 * x * (1.0 - x) * (1.0 - 2.0 * x) / (ramp * ramp)
    return s * f, ds * f + s * df, dds * f + 2.0 * ds * df + s * ddf


def dict_twin():
    yaml = __import__("yaml")
    path = os.path.join(SOURCE, "cases", "ocean", "oc4-semi-statics.yaml")
    with open(path) as f:
        case = yaml.safe_load(f)
    from_file = flexmoor.Simulation(path).run()
    from_dict = flexmoor.Simulation(case).run()
    expect(from_file and from_file == from_dict, f"summaries differ:\n{from_file}\n{from_dict}")
    print(f"PY1: {len(from_file)} summary values equal to the bit")


def errors():
    try:
        flexmoor.Simulation({"name": "broken", "materials": {"steel": {"type": "linear_elastic",
                                                                        "E": -3}}})
        fail("a case with errors was accepted")
    except flexmoor.CaseError as e:
        expect("broken.yaml:" in str(e), f"no FILE:LINE in: {e}")
        expect(isinstance(e, flexmoor.Error), "CaseError is not a flexmoor.Error")
    try:
        flexmoor.Simulation("no-such-case-anywhere")
        fail("a missing case was accepted")
    except flexmoor.CaseError as e:
        expect("no-such-case-anywhere" in str(e), f"the message does not name the case: {e}")
    sim = flexmoor.Simulation("oc4-semi-surge")
    try:
        sim.step(np.zeros(0), np.zeros(0), 0.1)
        fail("a step before init was accepted")
    except flexmoor.CallError as e:
        expect("before flexmoor_init" in str(e), str(e))
    sim.couple("platform")
    try:
        sim.init(np.zeros(5), np.zeros(5))
        fail("five values for six dofs were accepted")
    except ValueError as e:
        expect("expected 6" in str(e), str(e))
    sim.init(np.zeros(6), np.zeros(6))
    sim.step(np.zeros(6), np.zeros(6), 0.1)
    saved = sim.save()
    before = sim.line_positions("line_1")
    try:
        sim.step(np.array([1e6, 0, 0, 0, 0, 0]), np.zeros(6), 0.1)
        fail("a 1,000 km jump in 0.1 s converged")
    except flexmoor.Error as e:
        expect(str(e), "no message")
    sim.restore(saved)
    expect(np.array_equal(sim.line_positions("line_1"), before), "restore did not go back")
    loads = sim.step(np.zeros(6), np.zeros(6), 0.1)
    expect(loads.shape == (6,) and np.all(np.isfinite(loads)), f"loads {loads}")
    print("PY2: CaseError, CallError, ValueError and a failed step, each with its message")


def host_oc4():
    path = oc4_cut(120)
    run_command("run", path, "-o", os.path.join(SCRATCH, "command"), "--no-figure")
    sim = flexmoor.Simulation(path)
    sim.couple("platform")
    sim.output(os.path.join(SCRATCH, "python"))
    sim.init(np.zeros(6), np.zeros(6))
    t0 = sim.time
    for n in range(1200):
        t = t0 + (n + 1) * 0.1
        x, v, a = ramped_surge(t)
        sim.step(np.array([x, 0, 0, 0, 0, 0]), np.array([v, 0, 0, 0, 0, 0]), 0.1,
                 xdd=np.array([a, 0, 0, 0, 0, 0]))
    sim.finish()
    r = subprocess.run(["/usr/bin/python3", os.path.join(SOURCE, "tests", "capi", "same_netcdf.py"),
                        os.path.join(SCRATCH, "command", "oc4-120s.nc"),
                        os.path.join(SCRATCH, "python", "oc4-120s.nc")],
                       capture_output=True, text=True)
    print(r.stdout)
    expect(r.returncode == 0, "the Python host's results differ from the command's")
    print("PY3: every variable equal to the bit")


def run_xarray():
    import xarray as xr
    path = oc4_cut(120)
    run_command("run", path, "-o", os.path.join(SCRATCH, "command"), "--no-figure")
    with open(os.path.join(SCRATCH, "command", "oc4-120s.summary.json")) as f:
        command = json.load(f)
    sim = flexmoor.Simulation(path)
    sim.output(os.path.join(SCRATCH, "library"))
    summary = sim.run()
    results = command["results"]
    expect(list(summary) == list(results), f"names {list(summary)} against {list(results)}")
    for name, value in summary.items():
        if name != "cpu_seconds":
            expect(value == results[name], f"{name}: {value} against the command's {results[name]}")
    ds = xr.open_dataset(os.path.join(SCRATCH, "library", "oc4-120s.nc"))
    names = [n.decode() if isinstance(n, bytes) else str(n) for n in ds.line_name.values]
    expect(names == ["line_1", "line_2", "line_3"], f"line names {names}")
    expect(abs(float(ds.time.sel(time=2.5))) == 2.5, "time does not select")
    stepper = flexmoor.Simulation(path)
    stepper.init()
    positions = stepper.line_positions("line_2")
    expect(isinstance(positions, np.ndarray) and positions.shape[1] == 3, f"{positions.shape}")
    expect(stepper.node_positions().shape[1] == 3, "node positions")
    tension = stepper.end_tension("line_2", "end")
    expect(tension > 1e6, f"line_2's fairlead tension {tension} N")
    print(f"PY4: {len(summary)} summary values; line_2 fairlead tension at rest {tension:.6g} N")


def example():
    png = os.path.join(SCRATCH, "surge_response.png")
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, "python"))
    r = subprocess.run(["/usr/bin/python3", os.path.join(SOURCE, "examples", "python",
                                                         "surge_response.py"),
                        "--amplitudes", "0.5", "2", "--duration", "30", "-o", png],
                       capture_output=True, text=True, env=env)
    print(r.stdout, r.stderr)
    expect(r.returncode == 0, "the example failed")
    with open(png, "rb") as f:
        expect(f.read(8) == b"\x89PNG\r\n\x1a\n", "no PNG")
    print("PY5: the example ran and drew its figure")


{"dict_twin": dict_twin, "errors": errors, "host_oc4": host_oc4, "run_xarray": run_xarray,
 "example": example}[CHECK]()
