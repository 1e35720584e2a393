#!/usr/bin/env python3
"""Outside check of discover's naming and detection limits (issue 23, "Done when").

Held-out weak-effect data sets are made now through the project's own sweep: on the default
config (configs/sf350.yaml, the 3D patch), each testable effect of the current catalogue is
planted alone at a magnitude drawn in 0.25-1.0 x its catalogue default's strength (the strength
parameter from where the effect vanishes: value = m x default; a soil modulus default / m), with
2.5 % relative Gaussian noise on every observable; three noise-only sets are made the same way.
Each set goes through `modaltyre discover --json` and is judged from outside:

- signal: the noise-free relative change of each observable (planted sweep over the effect-free
  sweep), its RMS beyond a constant (the mean removed: the re-fitted baseline absorbs at least
  that); the planted effect's main observable is the one with the largest n (RMS / sigma)^2;
- every planted effect with n (RMS / sigma)^2 >= 40 on one observable must be named first;
- a noise-only set must name nothing;
- a planted effect that is not named must carry a finite detection_limit whose RMS on the main
  observable is at least the planted RMS / 1.5.

Usage (from the checkout; prints one table row per set, exit 1 if a check fails):
  python3 bench/discover_outside_check.py build/modaltyre [--seed 2311] [--sets-per-effect 1]
      [--config configs/sf350.yaml] [--noise 0.025] [--workdir /tmp/doc] [--threads 2]
Only the standard library is used (csv, json, random, subprocess without a shell).
"""
import argparse
import csv
import json
import math
import os
import random
import subprocess
import sys
import time

LOADS6 = [2000, 3300, 4600, 5900, 7200, 8500]
LOADS12 = [2000, 2600, 3200, 3800, 4400, 5000, 5600, 6200, 6800, 7400, 8000, 8600]

# Effect, its strength parameter, its default, whether the effect vanishes as it grows (a
# modulus), and the condition grid (24 rows) that lets it show.
EFFECTS = [
    ("inflation_pressure", "exponent", 1.0, False,
     {"load_N": LOADS6, "pressure_kPa": [170, 210, 250, 290]}),
    ("tread_relaxation", "creep_ratio", 0.5, False,
     {"load_N": LOADS6, "hold_s": [0, 30, 120, 600]}),
    ("dry_friction", "friction_force_N", 200.0, False,
     {"load_N": LOADS12, "branch": ["load", "unload"]}),
    ("load_stiffening", "exponent", 0.25, False,
     {"load_N": LOADS12, "pressure_kPa": [200, 260]}),
    ("soil_compliance", "modulus_MPa", 2.0, True,
     {"load_N": LOADS12, "surface": ["rigid", "soil"]}),
    ("belt_flattening", "stiffness_MPa", 1.0, False,
     {"load_N": LOADS12, "pressure_kPa": [200, 260]}),
]
# Noise-only sets: grids on which several candidates are tested.
NOISE_GRIDS = [
    {"load_N": LOADS6, "pressure_kPa": [200, 260], "hold_s": [0, 120]},
    {"load_N": LOADS12, "branch": ["load", "unload"]},
    {"load_N": LOADS6, "hold_s": [0, 30, 120, 600]},
]
OBSERVABLES = ["sinking_mm", "length_mm", "width_mm"]


def run(cmd):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        sys.exit("failed (%d): %s\n%s" % (r.returncode, " ".join(cmd), r.stderr))
    return r.stdout


def sweep(exe, config, settings, grid, path, threads):
    lines = ["base: " + os.path.abspath(config)]
    if settings:
        lines.append("set:")
        lines += ["  %s: %s" % kv for kv in settings.items()]
    lines.append("grid:")
    lines += ["  %s: [%s]" % (k, ", ".join(str(v) for v in vs)) for k, vs in grid.items()]
    lines.append("output: " + os.path.basename(path))
    yaml = path[:-4] + ".yaml"
    with open(yaml, "w") as f:
        f.write("\n".join(lines) + "\n")
    run([exe, "sweep", yaml, "--threads", str(threads), "--output", path])
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if any(r["status"] != "ok" for r in rows):
        sys.exit("sweep %s: a case failed" % path)
    return rows


def signal(clean, base):
    """Per observable: n and RMS (beyond a constant) of the relative change clean/base - 1."""
    out = {}
    for o in OBSERVABLES:
        if o not in base[0] or float(base[0][o]) == 0:
            continue
        d = [float(c[o]) / float(b[o]) - 1 for c, b in zip(clean, base)]
        mean = sum(d) / len(d)
        out[o] = (len(d), math.sqrt(sum((x - mean) ** 2 for x in d) / len(d)))
    return out


def noisy(rows, path, sigma, rng):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        for r in rows:
            r = dict(r)
            for o in OBSERVABLES:
                if o in r and float(r[o]) != 0:
                    r[o] = "%.9g" % (float(r[o]) * (1 + sigma * rng.gauss(0, 1)))
            w.writerow(r)


def discover(exe, config, csv_path, threads):
    t = time.time()
    j = json.loads(run([exe, "discover", config, csv_path, "--json", "--threads", str(threads)]))
    return j, time.time() - t


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("modaltyre")
    ap.add_argument("--config", default="configs/sf350.yaml")
    ap.add_argument("--seed", type=int, default=2311)
    ap.add_argument("--sets-per-effect", type=int, default=1)
    ap.add_argument("--noise", type=float, default=0.025)
    ap.add_argument("--workdir", default="/tmp/discover_outside_check")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--only", default="", help="comma-separated effects (and 'noise') to run")
    a = ap.parse_args()
    os.makedirs(a.workdir, exist_ok=True)
    rng = random.Random(a.seed)
    only = set(a.only.split(",")) if a.only else None
    failures = 0
    print("seed %d, noise %.3g, config %s" % (a.seed, a.noise, a.config))
    print("set | planted | n(RMS/sigma)^2 on main observable (RMS) | named first | "
          "limit RMS on main / planted RMS | verdict | s")
    sets = []
    for k in range(a.sets_per_effect):
        for e in EFFECTS:
            sets.append((e, rng.uniform(0.25, 1.0), rng.randrange(1 << 30), k))
    for i, grid in enumerate(NOISE_GRIDS):
        sets.append((None, 0, rng.randrange(1 << 30), i))
    for e, m, seed, k in sets:
        name = e[0] if e else "noise"
        if only and name not in only:
            continue
        tag = "%s_%d" % (name, k)
        grid = e[4] if e else NOISE_GRIDS[k]
        base = sweep(a.modaltyre, a.config, {}, grid, os.path.join(a.workdir, tag + "_off.csv"),
                     a.threads)
        if e:
            value = e[2] / m if e[3] else e[2] * m
            settings = {"effects.%s.enabled" % name: "true",
                        "effects.%s.%s" % (name, e[1]): "%.6g" % value}
            clean = sweep(a.modaltyre, a.config, settings, grid,
                          os.path.join(a.workdir, tag + "_on.csv"), a.threads)
        else:
            clean, value = base, 0
        measured = os.path.join(a.workdir, tag + "_measured.csv")
        noisy(clean, measured, a.noise, random.Random(seed))
        j, seconds = discover(a.modaltyre, a.config, measured, a.threads)
        named = [x["name"] for x in j["effects"]]
        if not e:
            ok = not named
            print("%s | none | - | %s | - | %s | %.0f" % (
                tag, ",".join(named) or "nothing", "ok" if ok else "FAIL", seconds))
            failures += not ok
            continue
        sig = signal(clean, base)
        main_obs = max(sig, key=lambda o: sig[o][0] * (sig[o][1] / a.noise) ** 2)
        n, rms = sig[main_obs]
        strength = n * (rms / a.noise) ** 2
        first = named[0] if named else "nothing"
        limit_text = "-"
        if first == name:
            ok = True
        else:
            cand = next((c for c in j["rounds"][-1] if c["name"] == name), None)
            lim = cand.get("detection_limit") if cand else None
            if lim:
                lim_rms = lim["observable_rms_rel"].get(main_obs, 0)
                limit_text = "%s %s %.3g: %.2f %% / %.2f %% = %.2f" % (
                    e[1], "<=" if lim["bound"] == "at most" else ">=", lim["value"],
                    100 * lim_rms, 100 * rms, lim_rms / rms)
                honest = lim_rms >= rms / 1.5
            else:
                reason = cand.get("detection_limit_reason", "no candidate") if cand else "absent"
                limit_text = "no limit: " + reason
                honest = False
            ok = strength < 40 and honest
        failures += not ok
        print("%s | %s=%.4g (%.2fx) | %.0f on %s (%.2f %%) | %s | %s | %s | %.0f" % (
            tag, e[1], value, m, strength, main_obs, 100 * rms, ",".join(named) or "nothing",
            limit_text, "ok" if ok else "FAIL", seconds))
        sys.stdout.flush()
    print("%d failed" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
