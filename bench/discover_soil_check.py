#!/usr/bin/env python3
"""Hidden soil effects on the default tyre (issue 45, "Done when", soil part): traction and
sinkage curves made now through `modaltyre traction` on configs/sf350.yaml (the 3D patch) on
LETE sand and sandy loam (configs/soils/), one soil effect hidden per set with its magnitudes
drawn inside the effect's range (`modaltyre effects --json`) by a seeded RNG, several loads and
slips, 2 % relative Gaussian noise on drawbar pull, soil sinkage and torque; noise-only sets the
same way. Each set's traction CSV goes through `modaltyre discover --ground SOIL --json`:

- a set with one effect: that effect named first, the pooled cross-validated gap shrinking (its
  fitted parameters and standard errors are printed beside the drawn ones);
- a noise-only set: nothing named;
- an effect the registry refuses on this tyre and soil (none of the five on the flexible tyre
  today: wong_reece_stress and soil_viscosity are candidates there too): "refused by the
  registry", not a failure, and the set must then name nothing (its data carry no effect the
  model rolls).

soil_viscosity needs a Kelvin-Voigt soil and a speed: its sets run on docs/soil.md section 3.2's
Kelvin-Voigt soil (E2 2 MPa, layer 200 mm, elastic share 0.7, c 1 kPa, phi 30 deg, K 25 mm: the
project's rigid-wheel check soil; seed 000 eq. 23 gives the law, no soil's values), written to
the work directory with eta2 = 0 (the candidate off), at two speeds.

Usage (from the checkout; one table row per set, exit 1 if a check fails):
  python3 bench/discover_soil_check.py build/modaltyre [--seed 45] [--only SET,...]
      [--noise 0.02] [--workdir /tmp/discover_soil_check] [--threads 2] [--unit-length-mm 4]
      [--max-effects 1]
Sets: EFFECT@SOIL (slip_sinkage, soil_unloading, bulldozing, wong_reece_stress on lete_sand and
sandy_loam; soil_viscosity on kv) and noise@SOIL; then EFFECT@SOIL+rigid for the two effects
the registry first took on the rigid wheel only, with noise@lete_sand+rigid and noise@kv+rigid:
the same on the rigid cylinder (--set tyre.rigid=true for traction and discover). discover runs at
4 mm and names one effect by default: a set on the 3D patch is ~8 min of CPU even so
(docs/discover.md, "Hidden soil effects on the default tyre"). Only the standard library is
used; the noise and run helpers are bench/discover_outside_check.py's, the gap
bench/discover_default_check.py's.
"""
import argparse
import csv
import json
import math
import os
import random
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import discover_outside_check as outside  # noqa: E402
from discover_default_check import pooled_gaps  # noqa: E402
from discover_outside_check import noisy, run  # noqa: E402

TRACTION = ["drawbar_pull_N", "soil_sinkage_mm", "torque_Nm"]
outside.OBSERVABLES[:] = TRACTION  # the noise goes on the traction observables only

SLIPS = [0.05, 0.2, 0.5]
# Loads inside each soil's validity range for the SF-350 (sandy loam sinks 57 mm at 5.5 kN).
SOILS = {
    "lete_sand": ("configs/soils/lete_sand.yaml", [2500, 4000, 5500]),
    "sandy_loam": ("configs/soils/sandy_loam.yaml", [1500, 2500, 3500]),
    "kv": (None, [2500, 4000]),
}
SPEEDS = [10]  # km/h: a soil bin's; the flexing loss's speed too
KV_SPEEDS = [2, 10]  # the rate term's regime variable is the speed
KV_SOIL = """# docs/soil.md section 3.2's Kelvin-Voigt soil (seed 000 eq. 23's law), eta2 off.
ground:
  model: kelvin_voigt
  name: docs/soil.md 3.2 Kelvin-Voigt soil
  kelvin_voigt: {E2_MPa: 2, layer_mm: 200, elastic_share: 0.7, eta2_kPa_s: 0,
                 cohesion_kPa: 1, friction_angle_deg: 30, shear_modulus_K_mm: 25}
"""

# name: (drawn keys {key: (lo, hi, log-uniform)}, stated keys, soils). The drawn ranges lie
# inside the registry's (checked against `effects --json` at run time) where measured soils do.
EFFECTS = {
    # f(0.5) = 1.4-2.5: around the 30-100 % slip sinkage of soil-bin tyre tests (docs/soil.md 5.3).
    "slip_sinkage": ({"ground.bekker.slip_sinkage.k1": (0.5, 1.5, False),
                      "ground.bekker.slip_sinkage.k2": (0.25, 0.6, False)},
                     {"ground.bekker.slip_sinkage.enabled": "true"}, ["lete_sand", "sandy_loam"]),
    # A rebound of 1-4 mm of the 10-30 mm sinkage (Au 5e5 takes the whole rut back).
    "soil_unloading": ({"ground.bekker.unloading.Au": (1e6, 1e7, True)},
                       {"ground.bekker.unloading.enabled": "true",
                        "ground.bekker.unloading.k0": "0"}, ["lete_sand", "sandy_loam"]),
    "bulldozing": ({"ground.bekker.bulldozing.unit_weight_kN_m3": (14, 20, False)},
                   {"ground.bekker.bulldozing.enabled": "true"}, ["lete_sand", "sandy_loam"]),
    # Wong & Reece's loose (0.18) to compact (0.43) sand, c2 around their 0.32.
    "wong_reece_stress": ({"ground.bekker.wong_reece.c1": (0.18, 0.43, False),
                           "ground.bekker.wong_reece.c2": (0.2, 0.4, False)},
                          {"ground.bekker.wong_reece.enabled": "true"},
                          ["lete_sand", "sandy_loam"]),
    # tau = eta2 / E2 from 10 to 100 ms at E2 2 MPa.
    "soil_viscosity": ({"ground.kelvin_voigt.eta2_kPa_s": (20, 200, True)}, {}, ["kv"]),
}
# Effects the registry first took on the rigid wheel only (candidates on the flexible tyre too
# now): their sets again on the rigid cylinder of the outer radius (tyre.rigid=true).
RIGID = {"wong_reece_stress", "soil_viscosity"}


def draw(lo, hi, log, rng):
    return math.exp(rng.uniform(math.log(lo), math.log(hi))) if log else rng.uniform(lo, hi)


def check_ranges(exe):
    """Every drawn range inside its registry range (a registry change shows here first)."""
    reg = {p["key"]: (p["min"], p["max"])
           for e in json.loads(run([exe, "effects", "--json"]))["effects"]
           for p in e.get("parameters", [])}
    for drawn, _, _ in EFFECTS.values():
        for key, (lo, hi, _) in drawn.items():
            if key not in reg or not (reg[key][0] <= lo < hi <= reg[key][1]):
                sys.exit("%s: drawn range [%g, %g] outside the registry's %s" % (
                    key, lo, hi, reg.get(key)))


def traction_rows(exe, config, soil, loads, speeds, settings, path):
    """The model's curves as a traction CSV (load_N, slip, speed_kmh and the observables)."""
    rows = []
    for v in speeds:
        cmd = [exe, "traction", config, "--ground", soil, "--json", "--speed-km-h", str(v)]
        for load in loads:
            cmd += ["--load", str(load)]
        cmd += ["--slip"] + [str(s) for s in SLIPS]
        for kv in settings.items():
            cmd += ["--set", "%s=%s" % kv]
        for c in json.loads(run(cmd))["cases"]:
            if not c.get("converged"):
                sys.exit("%s: traction at %g N, slip %g did not converge" % (path, c["load_N"],
                                                                            c["slip"]))
            row = {"load_N": "%g" % c["load_N"], "slip": "%g" % c["slip"], "speed_kmh": "%g" % v}
            row.update({o: "%.9g" % c[o] for o in TRACTION})
            rows.append(row)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    return rows


def candidate(j, name):
    return next((c for c in j["rounds"][0] if c["name"] == name), None)


def judge(j, planted):
    """(ok, refused, recovered text) of one discover report."""
    named = [e["name"] for e in j["effects"]]
    if not planted:
        return not named, False, "-"
    name, values = planted
    cand = candidate(j, name)
    if cand is not None and not cand.get("testable"):
        # Refused by the registry on this tyre and soil: its data carry no effect the model
        # rolls, so the set is a noise-only one.
        return not named, True, "refused: " + cand.get("reason", "")[:90]
    if not named or named[0] != name:
        lim = (cand or {}).get("detection_limit")
        text = ("%s unnamed (dBIC %.1f)" % (name, cand["delta_bic"]) if cand and "delta_bic" in
                cand else "%s unnamed" % name)
        if lim:
            text += ": limit %s %.4g" % (lim["bound"], lim["value"])
        return False, False, text
    fit, se = j["effects"][0]["parameters"], j["effects"][0]["standard_errors"]
    parts = []
    for key, value in values.items():
        short = key.split(".")[-1]
        if key in fit:
            # null: infinite (the rigid wheel reads none of the re-fitted tyre scalars)
            err = "%.2g" % se[key] if se.get(key) is not None else "inf"
            text = "%s %.4g +- %s (drawn %.4g)" % (short, fit[key], err, value)
            # The band with the evaluation mesh's share (discover/mesh_bias.h), where made.
            band = j["effects"][0].get("bands_with_mesh", {}).get(key)
            if band:
                inside = band["lower"] <= value <= band["upper"]
                text += ", mesh band %.4g-%.4g %s" % (band["lower"], band["upper"],
                                                      "holds it" if inside else "misses it")
            parts.append(text)
    before, after = pooled_gaps(j)
    return after < before, False, "; ".join(parts)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("modaltyre")
    ap.add_argument("--config", default="configs/sf350.yaml")
    ap.add_argument("--seed", type=int, default=45)
    ap.add_argument("--noise", type=float, default=0.02)
    ap.add_argument("--workdir", default="/tmp/discover_soil_check")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--max-effects", default="1",
                    help="discover's --max-effects (the check reads the first name)")
    ap.add_argument("--unit-length-mm", default="4",
                    help="discover's evaluation mesh (the data are made at the config's own)")
    ap.add_argument("--only", default="", help="comma-separated sets (EFFECT@SOIL, noise@SOIL)")
    a = ap.parse_args()
    os.makedirs(a.workdir, exist_ok=True)
    check_ranges(a.modaltyre)
    kv_path = os.path.join(a.workdir, "kv_soil.yaml")
    with open(kv_path, "w") as f:
        f.write(KV_SOIL)
    rng = random.Random(a.seed)
    sets = []  # (tag, soil, planted (name, {key: value}) or None, noise seed, rigid)
    for rigid in (False, True):
        for soil in SOILS:
            for name, (drawn, _, soils) in EFFECTS.items():
                if soil in soils and (not rigid or name in RIGID):
                    values = {k: draw(lo, hi, log, rng) for k, (lo, hi, log) in drawn.items()}
                    sets.append(("%s@%s%s" % (name, soil, "+rigid" if rigid else ""), soil,
                                 (name, values), rng.randrange(1 << 30), rigid))
            if not rigid or soil != "sandy_loam":
                sets.append(("noise@%s%s" % (soil, "+rigid" if rigid else ""), soil, None,
                             rng.randrange(1 << 30), rigid))
    only = set(a.only.split(",")) if a.only else None
    print("seed %d, noise %.3g, config %s, slips %s, discover at %s mm" % (
        a.seed, a.noise, a.config, SLIPS, a.unit_length_mm))
    print("set | planted | named | cv gap before -> after | recovered (+- se) | verdict | s")
    failures = 0
    for tag, soil, planted, seed, rigid in sets:
        if only and tag not in only:
            continue
        path, loads = SOILS[soil]
        path = path or kv_path
        speeds = KV_SPEEDS if soil == "kv" else SPEEDS
        settings = {"tyre.rigid": "true"} if rigid else {}
        if planted:
            settings.update(EFFECTS[planted[0]][1])
            settings.update({k: "%.6g" % v for k, v in planted[1].items()})
        clean = traction_rows(a.modaltyre, a.config, path, loads, speeds, settings,
                              os.path.join(a.workdir, tag + "_clean.csv"))
        measured = os.path.join(a.workdir, tag + "_measured.csv")
        noisy(clean, measured, a.noise, random.Random(seed))
        t = time.time()
        j = json.loads(run([a.modaltyre, "discover", a.config, measured, "--ground", path] +
                           (["--set", "tyre.rigid=true"] if rigid else []) +
                           ["--json", "--threads", str(a.threads),
                            "--unit-length-mm", a.unit_length_mm,
                            "--max-effects", a.max_effects]))
        seconds = time.time() - t
        with open(os.path.join(a.workdir, tag + ".json"), "w") as f:
            json.dump(j, f, indent=1)
        ok, refused, recovered = judge(j, planted)
        before, after = pooled_gaps(j)
        failures += not ok
        gap = ("%.2f -> %.2f %%" % (100 * before, 100 * after) if before is not None else
               "- (no candidate testable)")
        print("%s | %s | %s | %s | %s | %s | %.0f" % (
            tag, ", ".join("%s %.4g" % (k.split(".")[-1], v) for k, v in planted[1].items())
            if planted else "none", ",".join(e["name"] for e in j["effects"]) or "nothing",
            gap, recovered,
            ("refused by the registry" if ok else "FAIL (named on refused)") if refused else
            ("ok" if ok else "FAIL"), seconds))
        sys.stdout.flush()
    print("%d failed" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
