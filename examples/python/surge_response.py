#!/usr/bin/python3
"""The fairlead tensions of OC4's mooring against the amplitude of a surge motion the host
drives through flexmoor's Python module, with a matplotlib figure.

For each amplitude the platform surges A sin(2 pi t / T), brought in over the first period
(smoothstep ramp), for `--duration` seconds; the figure shows each line's smallest and largest
fairlead tension over the last half of the run.

    surge_response.py [--amplitudes 0.5 1 2 4] [--period 10] [--duration 120] [-o FIGURE.png]
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import flexmoor


def smoothstep(t, ramp):
    """s, s' and s'' of the smoothstep 10 x^3 - 15 x^4 + 6 x^5, x = t / ramp, clamped to [0, 1]."""
    x = min(max(t / ramp, 0.0), 1.0)
    inside = 0.0 < x < 1.0
    return (x**3 * (10 - 15 * x + 6 * x * x),
            30 * x * x * (1 - x) ** 2 / ramp if inside else 0.0,
            60 * x * (1 - x) * (1 - 2 * x) / ramp**2 if inside else 0.0)


def surge(t, amplitude, period):
    """Surge, its rate and its acceleration at t (the other five dofs stay at rest)."""
    w = 2 * np.pi / period
    s, ds, dds = smoothstep(t, period)
    f, df, ddf = amplitude * np.sin(w * t), amplitude * w * np.cos(w * t), -amplitude * w * w * np.sin(w * t)
    x, v, a = np.zeros(6), np.zeros(6), np.zeros(6)
    x[0], v[0], a[0] = s * f, ds * f + s * df, dds * f + 2 * ds * df + s * ddf
    return x, v, a


def tension_range(amplitude, period, duration, dt=0.1):
    sim = flexmoor.Simulation("oc4-semi-surge")
    sim.couple("platform")
    sim.init(np.zeros(6), np.zeros(6))
    lines = sim.lines
    tensions = []
    for n in range(1, round(duration / dt) + 1):
        x, v, a = surge(n * dt, amplitude, period)
        sim.step(x, v, dt, xdd=a)
        if n * dt >= duration / 2:
            tensions.append([sim.end_tension(line, "end") for line in lines])
    sim.finish()
    tensions = np.array(tensions)
    return lines, tensions.min(axis=0), tensions.max(axis=0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--amplitudes", type=float, nargs="+", default=[0.5, 1.0, 2.0, 4.0])
    parser.add_argument("--period", type=float, default=10.0)
    parser.add_argument("--duration", type=float, default=120.0)
    parser.add_argument("-o", "--output", default="surge_response.png")
    args = parser.parse_args()
    low, high = [], []
    for amplitude in args.amplitudes:
        lines, lo, hi = tension_range(amplitude, args.period, args.duration)
        low.append(lo)
        high.append(hi)
        print(f"A = {amplitude:5.2f} m: " + ", ".join(
            f"{name} {l / 1e6:.4f}-{h / 1e6:.4f} MN" for name, l, h in zip(lines, lo, hi)))
    low, high = np.array(low) / 1e6, np.array(high) / 1e6
    fig, ax = plt.subplots(figsize=(7, 4.5), layout="constrained")
    for k, name in enumerate(lines):
        color = f"C{k}"
        ax.plot(args.amplitudes, high[:, k], "o-", color=color, label=f"{name}, fairlead: largest")
        ax.plot(args.amplitudes, low[:, k], "s--", color=color, label=f"{name}, fairlead: smallest")
    ax.set_xlabel("surge amplitude (m)")
    ax.set_ylabel("fairlead tension (MN)")
    ax.set_title(f"OC4 semi-submersible: surge at {args.period:g} s, driven from Python")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.savefig(args.output, dpi=120)
    print(f"figure: {args.output}")


if __name__ == "__main__":
    main()
