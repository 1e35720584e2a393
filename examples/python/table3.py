#!/usr/bin/env python3
"""Seed 001 Table 3 from Python: fit the hammer modes, predict the six footprints, validate them
against the measured ones and plot the pressure along the patch (matplotlib, if installed).

    PYTHONPATH=build/python python3 examples/python/table3.py [--plot pressure.png]

Run from the source tree (the paths below are relative to it)."""
import argparse

import modaltyre

HAMMER = "configs/data/sf350_hammer_12pt.csv"
CONFIG = "configs/sf350.yaml"
TABLE3 = "configs/data/sf350_footprint_table3.csv"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plot", default="table3_pressure.png", help="figure file (.png/.svg)")
    args = parser.parse_args()

    modes = modaltyre.fit_modes(HAMMER)
    print("modes:", ", ".join(f"{m['freq_hz']:.0f} Hz (order {m['order']}, {m['kind']})"
                              for m in modes["modes"][:6]), "...")

    tyre = modaltyre.Tyre(CONFIG)  # built once, shared by every load
    footprints = tyre.footprints(tyre.loads_N)
    print(f"\n{'load_N':>7} {'sinking_mm':>10} {'length_mm':>9} {'width_mm':>8} {'peak_kPa':>8}")
    for f in footprints:
        print(f"{f.load_N:7.0f} {f.sinking_mm:10.2f} {f.length_mm:9.1f} {f.width_mm:8.1f} "
              f"{f.pressure_kPa.max():8.0f}")

    report = modaltyre.validate(CONFIG, TABLE3)
    print("\nRMS relative error over the predicted rows (calibration rows",
          report["calibration"]["rows"], "excluded):")
    for observable, rms in report["rms_rel_error"].items():
        print(f"  {observable}: {100 * rms:.1f} %")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("\nmatplotlib is not installed: no plot (Debian: python3-matplotlib)")
        return
    fig, ax = plt.subplots(figsize=(7, 4))
    for f in footprints:
        ax.plot(f.x_mm, f.pressure_kPa, label=f"{f.load_N / 1000:.1f} kN")
    ax.set_xlabel("x along the road from the contact centre [mm]")
    ax.set_ylabel("centre-line contact pressure [kPa]")
    ax.set_title(tyre.name)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.plot)
    print("\npressure plot:", args.plot)


if __name__ == "__main__":
    main()
