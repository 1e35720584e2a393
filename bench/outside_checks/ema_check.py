#!/usr/bin/python3
"""Outside check of issue 19 (part 2 of 2): `modaltyre ema` on held-out ring hammer tests.

For each (case, seed) it synthesises the FRFs with ema_ring_synth.py (UFF 58 ASCII in the
specification's fixed columns, and the long CSV), runs
    modaltyre ema FILE [--band LO:HI] [--format csv --frf-type T] --json --output hammer.csv
and checks against the planted modes (issue 19 "Done when"):
  - every planted in-band mode found (matched to the nearest identified mode within 3 %),
  - frequency within 0.5 %, damping within 15 % (relative), MAC >= 0.95 over the 24 DOFs,
  - mass-normalised radial value at the driving point within 10 %,
  - no spurious mode (every identified mode matches a planted in-band mode),
  - `modaltyre fit-modes hammer.csv --json` gives the planted harmonic orders,
  - the file without the driving-point FRF exits 2 with a message on stderr,
  - wall time of the whole `ema` command on the UFF file (median of --repeats runs) < 2 s
    (CPU time and the load average printed too: the machine may be shared).
Prints one line per criterion and a summary; exit status 1 if any check fails.

Run:  /usr/bin/python3 bench/outside_checks/ema_check.py --binary build/modaltyre \
          [--cases A:11,B:23,C:37] [--workdir /tmp/ema_outside]
Standard library + numpy only.
"""
import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import time

import numpy as np

from outside_report import Report

HERE = os.path.dirname(os.path.abspath(__file__))


def run(cmd):
    """(result, wall seconds, CPU seconds of the child)"""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return p, wall, (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)


def planted_vector(m):
    return np.array(m["radial"] + m["tangential"])


def identified_vector(mode):
    shape = sorted(mode["shape"], key=lambda s: s["point"])
    return np.array([s["radial"] for s in shape] + [s["tangential"] for s in shape])


def mac(a, b):
    return abs(a @ b) ** 2 / ((a @ a) * (b @ b))


def check_file(binary, path, truth, fmt, workdir, rep):
    tag = os.path.basename(path)
    out_csv = os.path.join(workdir, f"hammer_{tag}.csv")
    cmd = [binary, "ema", path, "--json", "--output", out_csv]
    if truth["band_option"]:
        cmd += ["--band", truth["band_option"]]
    if fmt == "csv":
        cmd += ["--format", "csv", "--frf-type", truth["frf_type"]]
    print(f"[{truth['case']} seed {truth['seed']}] {' '.join(cmd)}")
    p, _, _ = run(cmd)
    if p.returncode != 0:
        rep.check("ema runs", False, f"exit {p.returncode}: {p.stderr.strip()[:300]}")
        return
    res = json.loads(p.stdout)
    ident = res["modes"]
    planted = [m for m in truth["modes"] if m["in_band"]]
    used = set()
    worst = dict(df=0.0, dz=0.0, mac=1.0, drive=0.0)
    found = 0
    for m in planted:
        j = min(range(len(ident)), key=lambda i: abs(ident[i]["freq_hz"] / m["freq_hz"] - 1)) if ident else None
        if j is None or abs(ident[j]["freq_hz"] / m["freq_hz"] - 1) > 0.03 or j in used:
            print(f"      planted {m['freq_hz']:.3f} Hz (order {m['order']}) NOT FOUND")
            continue
        used.add(j)
        found += 1
        e = ident[j]
        df = abs(e["freq_hz"] / m["freq_hz"] - 1)
        dz = abs(e["damping_ratio"] / m["damping_ratio"] - 1)
        mc = mac(planted_vector(m), identified_vector(e))
        drive_id = next(s["radial"] for s in e["shape"] if s["point"] == 1)
        dd = abs(drive_id / m["radial"][0] - 1)
        worst = dict(df=max(worst["df"], df), dz=max(worst["dz"], dz), mac=min(worst["mac"], mc),
                     drive=max(worst["drive"], dd))
        print(f"      {m['freq_hz']:8.3f} Hz z={m['damping_ratio']:.4f} phi={m['radial'][0]:+.4f} -> "
              f"{e['freq_hz']:8.3f} z={e['damping_ratio']:.4f} phi={drive_id:+.4f}  "
              f"df={100 * df:.3f}% dz={100 * dz:.2f}% MAC={mc:.5f} drive={100 * dd:.2f}%")
    spurious = [ident[i]["freq_hz"] for i in range(len(ident)) if i not in used]
    rep.check("every planted in-band mode found", found == len(planted), f"{found} of {len(planted)}")
    rep.check("frequency within 0.5 %", worst["df"] <= 0.005, f"worst {100 * worst['df']:.3f} %")
    rep.check("damping within 15 %", worst["dz"] <= 0.15, f"worst {100 * worst['dz']:.2f} %")
    rep.check("MAC >= 0.95", worst["mac"] >= 0.95, f"lowest {worst['mac']:.5f}")
    rep.check("driving-point mass-normalised radial within 10 %", worst["drive"] <= 0.10,
              f"worst {100 * worst['drive']:.2f} %")
    rep.check("no spurious mode", not spurious, f"spurious at {spurious} Hz" if spurious else "none")
    # the chain: fit-modes reads --output and gives the planted orders
    p2, _, _ = run([binary, "fit-modes", out_csv, "--json"])
    if p2.returncode != 0:
        rep.check("fit-modes reads --output", False, f"exit {p2.returncode}: {p2.stderr.strip()[:300]}")
        return
    fm = json.loads(p2.stdout)["modes"]
    got = [(round(x["freq_hz"], 2), x["order"], x["kind"], x["aliased"]) for x in fm]
    want = [m["order"] for m in sorted(planted, key=lambda m: m["freq_hz"])]
    orders = [x["order"] for x in sorted(fm, key=lambda x: x["freq_hz"])]
    ok = orders == want and not any(x["aliased"] for x in fm)
    rep.check("fit-modes gives the planted orders", ok, f"planted {want}, fit-modes {got}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default="build/modaltyre")
    ap.add_argument("--cases", default="A:11,B:23,C:37", help="CASE:SEED,... (cases A, B, C)")
    ap.add_argument("--workdir", default="/tmp/ema_outside")
    ap.add_argument("--repeats", type=int, default=5, help="runs of the timed command")
    a = ap.parse_args()
    rep = Report()
    timings = []
    for item in a.cases.split(","):
        case, seed = item.split(":")
        wd = os.path.join(a.workdir, f"{case}{seed}")
        subprocess.run([sys.executable, os.path.join(HERE, "ema_ring_synth.py"), "--case", case, "--seed",
                        seed, "--outdir", wd], check=True, capture_output=True)
        with open(os.path.join(wd, "planted.json")) as fh:
            truth = json.load(fh)
        for fmt, name in (("uff", "frf.unv"), ("csv", "frf.csv")):
            check_file(a.binary, os.path.join(wd, name), truth, fmt, wd, rep)
        # no driving point: exit 2 with a message
        for fmt, name in (("uff", "nodrive.unv"), ("csv", "nodrive.csv")):
            cmd = [a.binary, "ema", os.path.join(wd, name)]
            if fmt == "csv":
                cmd += ["--format", "csv", "--frf-type", truth["frf_type"]]
            if truth["band_option"]:
                cmd += ["--band", truth["band_option"]]
            p, _, _ = run(cmd)
            msg = p.stderr.strip().replace("\n", " | ")
            rep.check(f"{name} without driving point exits 2 with a message", p.returncode == 2 and msg != "",
                      f"exit {p.returncode}: {msg[:200]}")
        # whole-command wall time on the 24-FRF, 1600-line UFF file
        cmd = [a.binary, "ema", os.path.join(wd, "frf.unv")] + (
            ["--band", truth["band_option"]] if truth["band_option"] else [])
        ts = [run(cmd)[1:] for _ in range(a.repeats)]
        wall = statistics.median(t[0] for t in ts)
        cpu = statistics.median(t[1] for t in ts)
        load = os.getloadavg()[0]
        timings.append(wall)
        rep.check(f"ema wall time < 2 s (24 FRFs, 1600 lines, median of {a.repeats})", wall < 2.0,
                  f"{wall:.2f} s wall, {cpu:.2f} s CPU (walls {', '.join(f'{t[0]:.2f}' for t in ts)}; "
                  f"load average {load:.1f} on {os.cpu_count()} CPUs)")
    print(f"\n{rep.failures} check(s) failed")
    return 1 if rep.failures else 0


if __name__ == "__main__":
    sys.exit(main())
