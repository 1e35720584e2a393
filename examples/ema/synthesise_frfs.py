#!/usr/bin/env python3
"""Accelerance FRFs of a hammer test synthesised from a hammer CSV (modal parameters), in the
long CSV that `modaltyre ema` reads: a way to try the pipeline ema -> fit-modes -> footprint
without a test rig, and the data of the figure in docs/ema.md.

  python3 examples/ema/synthesise_frfs.py configs/data/sf350_hammer_12pt.csv \
      --noise 0.01 --seed 19 > sf350_frf.csv

Receptance H_ij = sum_k phi_ik phi_jk / (w_k^2 - w^2 + 2 j zeta_k w_k w), times (j w)^2; the
reference is the radial DOF of the first point; lines 0.25 ... 400 Hz in 0.25 Hz steps; noise
is complex Gaussian with an RMS of `--noise` times each FRF's RMS. Standard library only."""
import argparse
import cmath
import csv
import math
import random
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("hammer_csv")
    ap.add_argument("--noise", type=float, default=0.0)
    ap.add_argument("--seed", type=int, default=19)
    ap.add_argument("--df", type=float, default=0.25)
    ap.add_argument("--fmax", type=float, default=400.0)
    a = ap.parse_args()
    modes = {}
    for row in csv.DictReader(open(a.hammer_csv)):
        m = modes.setdefault(row["mode"], {"f": float(row["freq_hz"]),
                                           "z": float(row["damping_ratio"]), "pts": {}})
        m["pts"][int(row["point"])] = (float(row["radial"]), float(row["tangential"]))
    points = sorted(next(iter(modes.values()))["pts"])
    ref = points[0]
    freqs = [a.df * i for i in range(1, int(round(a.fmax / a.df)) + 1)]
    rng = random.Random(a.seed)
    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(["response_point", "response_dir", "reference_point", "reference_dir",
                  "freq_hz", "re", "im"])
    for d, name in ((0, "radial"), (1, "tangential")):
        for p in points:
            h = []
            for f in freqs:
                w = 2 * math.pi * f
                s = 0j
                for m in modes.values():
                    wk = 2 * math.pi * m["f"]
                    s += m["pts"][p][d] * m["pts"][ref][0] / complex(wk * wk - w * w,
                                                                      2 * m["z"] * wk * w)
                h.append(-w * w * s)
            sigma = a.noise * math.sqrt(sum(abs(v) ** 2 for v in h) / len(h) / 2)
            for f, v in zip(freqs, h):
                v += complex(rng.gauss(0, sigma), rng.gauss(0, sigma))
                out.writerow([p, name, ref, "radial", f"{f:.6g}", f"{v.real:.9e}",
                              f"{v.imag:.9e}"])


if __name__ == "__main__":
    main()
