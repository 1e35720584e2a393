#!/usr/bin/python3
"""Outside check of issue 19 (part 1 of 2): a held-out hammer test of a tyre-like ring.

What it makes: FRFs of a 12-point ring with planted modes, written independently of the
project's code (its own modal model, its own UFF dataset-58 writer after the specification's
fixed columns, its own long-CSV writer):
  - 12 points equally spaced, angle 0 at point 1; radial (UFF direction 3) and tangential
    (UFF direction 1) responses; one radial reference at point 1 = the driving point;
  - in-band ring modes of distinct harmonic orders n (radial A cos n(t-t0), tangential
    -k A/n sin n(t-t0), k in 0.6..1), frequencies >= 8 % apart, damping 1-5 %;
  - out-of-band modes below and above the analysed band;
  - complex Gaussian noise, RMS 1 % of each FRF's RMS; 1600 spectral lines;
  - FRF = sum_k phi_ok phi_ref,k (jw)^p / (w_k^2 - w^2 + 2j zeta_k w_k w), p = 0/1/2 for
    receptance/mobility/accelerance (viscous modal damping; w_k = 2 pi f_k undamped).
Files written to OUTDIR: frf.unv (UFF 58 ASCII), frf.csv (long CSV), nodrive.unv and
nodrive.csv (the same without the driving-point FRF), planted.json (the truth).

Cases (--case): A accelerance, fixed reference (response roves), complex single precision, even
abscissa 0.25-400 Hz, analysed with --band; B mobility, roving hammer (response fixed at point 1
radial, reference roves), complex double, even abscissa from 40 Hz, whole file; C receptance,
fixed reference, complex double, uneven abscissa (1600 lines), some tangential DOFs measured in
direction -1 (values negated as a transducer pointing the other way would measure them).

Run:  /usr/bin/python3 bench/outside_checks/ema_ring_synth.py --case A --seed 11 --outdir /tmp/emaA
Standard library + numpy only.
"""
import argparse
import json
import math
import os

import numpy as np

N_POINTS = 12
FRF_TYPES = {"receptance": (0, 8), "mobility": (1, 11), "accelerance": (2, 12)}  # (p, UFF type)


# ---------------------------------------------------------------- Fortran-style E formatting
def fortran_e(value, width, decimals):
    """Fortran Ew.d edit descriptor: [-]0.ddddE+ee right-aligned in `width` columns."""
    if value == 0.0 or not math.isfinite(value):
        digits, exp = "0" * decimals, 0
    else:
        m, e = f"{abs(value):.{decimals - 1}e}".split("e")  # d.dddd, exact decimal rounding
        digits, exp = m.replace(".", ""), int(e) + 1
    if abs(exp) <= 99:
        e = f"E{'+' if exp >= 0 else '-'}{abs(exp):02d}"
    else:  # Fortran drops the E for 3-digit exponents
        e = f"{'+' if exp >= 0 else '-'}{abs(exp):03d}"
    s = ("-" if value < 0 else "") + "0." + digits + e
    if len(s) > width:
        s = s.replace("0.", ".", 1)
    assert len(s) <= width, s
    return s.rjust(width)


def a_field(text, width):
    return text[:width].ljust(width)


# ---------------------------------------------------------------- planted ring model
def make_model(case, seed):
    rng = np.random.default_rng(seed)
    if case == "A":
        lines = 0.25 * np.arange(1, 1601)
        band = (50.0, 380.0)
    elif case == "B":
        lines = 40.0 + 0.2 * np.arange(1600)
        band = (float(lines[0]), float(lines[-1]))
    else:  # uneven: denser around the middle, 1600 lines over 45-390 Hz
        u = np.linspace(0.0, 1.0, 1600)
        lines = 45.0 + 345.0 * (u + 0.08 * np.sin(2 * np.pi * u) / (2 * np.pi))
        # the uneven abscissa is E13.5 (5 significant digits): synthesise on representable lines
        lines = np.array([float(f"{x:.4e}") for x in lines])
        lines = np.unique(lines)
        assert len(lines) == 1600
        band = (float(lines[0]), float(lines[-1]))
    lo, hi = band
    n_modes = int(rng.integers(5, 7))  # 5 or 6 in band
    # a tyre's radial family: frequency rises with the order; breathing (0) may lie above
    # order 1 (seed 001 Fig. 8: 1, 0, 2, 3, ...)
    orders = sorted(rng.permutation([0, 1, 2, 3, 4, 5])[:n_modes].tolist())
    if orders[:2] == [0, 1] and rng.uniform() < 0.5:
        orders[:2] = [1, 0]
    # frequencies: log-uniform inside the band with 10 % margins, >= 8 % apart (issue 19)
    while True:
        freqs = np.sort(np.exp(rng.uniform(np.log(lo * 1.10), np.log(hi / 1.10), n_modes)))
        if np.all(freqs[1:] / freqs[:-1] >= 1.08):
            break
    zetas = rng.uniform(0.01, 0.05, n_modes)
    modes = []
    theta = 2 * np.pi * np.arange(N_POINTS) / N_POINTS
    for f, z, n in zip(freqs, zetas, orders):
        amp = rng.uniform(0.35, 0.8)  # kg^-1/2
        if n == 0:
            t0 = 0.0
            radial = amp * np.ones(N_POINTS)
            tangential = 0.02 * amp * rng.standard_normal(N_POINTS)  # small tangential content
        else:
            # orientation: the driving point (theta=0) must see the mode (|cos| >= 0.5)
            t0 = rng.uniform(-1, 1) * math.acos(0.5) / n
            kappa = rng.uniform(0.6, 1.0)
            radial = amp * np.cos(n * (theta - t0))
            tangential = -kappa * amp / n * np.sin(n * (theta - t0))
        modes.append(dict(freq_hz=float(f), damping_ratio=float(z), order=int(n), t0=float(t0),
                          radial=radial.tolist(), tangential=tangential.tolist(), in_band=True))
    # out-of-band modes: one or two below, two above
    below = [lo / rng.uniform(1.3, 2.0)]
    above = [hi * rng.uniform(1.12, 1.3), hi * rng.uniform(1.5, 2.0)]
    for f in below + above:
        n = 6 if f > hi else 1
        t0 = rng.uniform(0, 2 * np.pi)
        amp = rng.uniform(0.5, 1.0)
        modes.append(dict(freq_hz=float(f), damping_ratio=float(rng.uniform(0.01, 0.05)),
                          order=n, t0=float(t0),
                          radial=(amp * np.cos(n * (theta - t0))).tolist(),
                          tangential=(-0.8 * amp / n * np.sin(n * (theta - t0))).tolist(),
                          in_band=False))
    return lines, band, modes


def synthesise(lines, modes, frf_type, rng, noise=0.01):
    """Rows: (point, 'radial'|'tangential') for each response; reference = point 1 radial."""
    p = FRF_TYPES[frf_type][0]
    w = 2 * np.pi * lines
    jw = 1j * w
    frfs = {}
    for pt in range(N_POINTS):
        for d in ("radial", "tangential"):
            h = np.zeros_like(jw)
            for m in modes:
                wk = 2 * np.pi * m["freq_hz"]
                phi_o = m[d][pt]
                phi_ref = m["radial"][0]
                h += phi_o * phi_ref / (wk**2 - w**2 + 2j * m["damping_ratio"] * wk * w)
            h *= jw**p
            rms = np.sqrt(np.mean(np.abs(h) ** 2))
            h = h + noise * rms * (rng.standard_normal(len(w)) + 1j * rng.standard_normal(len(w))) / np.sqrt(2)
            frfs[(pt + 1, d)] = h
    return frfs


# ---------------------------------------------------------------- writers
def uff58(resp_node, resp_dir, ref_node, ref_dir, lines, h, frf_type, double, even, fid):
    """One dataset 58 laid out in the specification's fixed columns."""
    out = []
    out.append(f"{-1:6d}")
    out.append(f"{58:6d}")
    out.append(a_field(f"FRF {resp_node}:{resp_dir:+d} / {ref_node}:{ref_dir:+d}", 80))
    out.append("NONE")
    out.append("26-NOV-26 12:00:00")
    out.append("NONE")
    out.append("outside check issue 19")
    # Record 6: Format(2(I5,I10),2(1X,10A1,I10,I4))
    out.append(f"{4:5d}{fid:10d}{1:5d}{0:10d}" + " " + a_field("TYRE", 10) + f"{resp_node:10d}{resp_dir:4d}"
               + " " + a_field("TYRE", 10) + f"{ref_node:10d}{ref_dir:4d}")
    # Record 7: Format(3I10,3E13.5)
    n = len(lines)
    ord_type = 6 if double else 5
    if even:
        dx = (lines[-1] - lines[0]) / (n - 1)
        out.append(f"{ord_type:10d}{n:10d}{1:10d}" + fortran_e(lines[0], 13, 5) + fortran_e(dx, 13, 5)
                   + fortran_e(0.0, 13, 5))
    else:
        out.append(f"{ord_type:10d}{n:10d}{0:10d}" + fortran_e(0.0, 13, 5) * 3)
    # Records 8-11: Format(I10,3I5,2(1X,20A1))
    num_type = FRF_TYPES[frf_type][1]
    unit = {8: "m/N", 11: "m/s/N", 12: "m/s^2/N"}[num_type]
    out.append(f"{18:10d}{0:5d}{0:5d}{0:5d}" + " " + a_field("Frequency", 20) + " " + a_field("Hz", 20))
    out.append(f"{num_type:10d}{1:5d}{0:5d}{0:5d}" + " " + a_field(frf_type.capitalize(), 20) + " "
               + a_field(unit, 20))
    out.append(f"{13:10d}{0:5d}{1:5d}{0:5d}" + " " + a_field("Force", 20) + " " + a_field("N", 20))
    out.append(f"{0:10d}{0:5d}{0:5d}{0:5d}" + " " + a_field("NONE", 20) + " " + a_field("NONE", 20))
    # Record 12
    if not double and even:  # case 3: RY IY pairs, 6E13.5
        vals = np.column_stack([h.real, h.imag]).ravel()
        for i in range(0, len(vals), 6):
            out.append("".join(fortran_e(v, 13, 5) for v in vals[i:i + 6]))
    elif double and even:  # case 7: 4E20.12
        vals = np.column_stack([h.real, h.imag]).ravel()
        for i in range(0, len(vals), 4):
            out.append("".join(fortran_e(v, 20, 12) for v in vals[i:i + 4]))
    elif double and not even:  # case 8: E13.5,2E20.12 per line
        for x, y in zip(lines, h):
            out.append(fortran_e(x, 13, 5) + fortran_e(y.real, 20, 12) + fortran_e(y.imag, 20, 12))
    else:  # case 4: X RY IY X RY IY, 6E13.5
        vals = np.column_stack([lines, h.real, h.imag]).ravel()
        for i in range(0, len(vals), 6):
            out.append("".join(fortran_e(v, 13, 5) for v in vals[i:i + 6]))
    out.append(f"{-1:6d}")
    return out


def write_files(outdir, lines, frfs, frf_type, case, drop_driving):
    roving_hammer = case == "B"
    double = case != "A"
    even = case != "C"
    uff, csv = [], ["response_point,response_dir,reference_point,reference_dir,freq_hz,re,im"]
    # a units dataset 164 first (SI), which readers skip or honour
    uff += [f"{-1:6d}", f"{164:6d}",
            f"{1:10d}" + a_field("SI - mks (Newton)", 20) + f"{2:10d}",
            "".join(fortran_e(1.0, 25, 17).replace("E", "D") for _ in range(3)),
            fortran_e(273.15, 25, 17).replace("E", "D"), f"{-1:6d}"]
    fid = 0
    for (pt, d), h in frfs.items():
        if drop_driving and pt == 1 and d == "radial":
            continue
        fid += 1
        udir = 3 if d == "radial" else 1
        hh = h
        if case == "C" and d == "tangential" and pt % 3 == 0:
            udir, hh = -1, -h  # transducer pointing the other way measures -H
        if roving_hammer:  # accelerometer fixed at 1 radial, hammer roves (reciprocity H_ij = H_ji)
            uff += uff58(1, 3, pt, udir, lines, hh, frf_type, double, even, fid)
            rows = [(1, "radial", pt, d)]
        else:
            uff += uff58(pt, udir, 1, 3, lines, hh, frf_type, double, even, fid)
            rows = [(pt, d, 1, "radial")]
        for (rp, rd, fp, fd) in rows:
            for f, y in zip(lines, h):
                csv.append(f"{rp},{rd},{fp},{fd},{f:.6f},{y.real:.9e},{y.imag:.9e}")
    stem = "nodrive" if drop_driving else "frf"
    with open(os.path.join(outdir, stem + ".unv"), "w") as fh:
        fh.write("\n".join(uff) + "\n")
    with open(os.path.join(outdir, stem + ".csv"), "w") as fh:
        fh.write("\n".join(csv) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--case", choices="ABC", default="A")
    ap.add_argument("--seed", type=int, default=11)
    ap.add_argument("--noise", type=float, default=0.01)
    ap.add_argument("--outdir", required=True)
    a = ap.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    frf_type = {"A": "accelerance", "B": "mobility", "C": "receptance"}[a.case]
    lines, band, modes = make_model(a.case, a.seed)
    frfs = synthesise(lines, modes, frf_type, np.random.default_rng(a.seed + 1000), a.noise)
    write_files(a.outdir, lines, frfs, frf_type, a.case, drop_driving=False)
    write_files(a.outdir, lines, frfs, frf_type, a.case, drop_driving=True)
    truth = dict(case=a.case, seed=a.seed, frf_type=frf_type, band_hz=list(band), n_lines=len(lines),
                 band_option=(f"{band[0]:g}:{band[1]:g}" if a.case == "A" else None),
                 noise=a.noise, modes=modes)
    with open(os.path.join(a.outdir, "planted.json"), "w") as fh:
        json.dump(truth, fh, indent=1)
    print(json.dumps({k: truth[k] for k in ("case", "seed", "frf_type", "band_hz")}))
    for m in modes:
        print(f"  {'in ' if m['in_band'] else 'out'} f={m['freq_hz']:8.3f} z={m['damping_ratio']:.4f} "
              f"n={m['order']} phi_r(0)={m['radial'][0]:+.4f}")


if __name__ == "__main__":
    main()
