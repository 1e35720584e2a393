#!/usr/bin/env python3
"""Hidden-effect sets on the default tyre (issue 45, "Done when"): every road effect the 3D patch
takes, hidden alone, pairs hidden together and noise-only sets, made now through `modaltyre
sweep` on configs/sf350.yaml with magnitudes drawn inside each effect's range, 1.5 % relative
Gaussian noise on every observable. Each set goes through `modaltyre discover --json`:

- a set with one effect: that effect named first; for an option effect (lateral_belt,
  pneumatic_share, crown_shape, sidewall_softening) its drawn value within its reported band as
  well (two standard errors either side, from the profile likelihood; a report without bands:
  the fitted value +- two Gauss-Newton standard errors);
- a pair: both named;
- a noise-only set: nothing named;
- every set with an effect: the pooled cross-validated gap shrinks.

Usage (from the checkout; one table row per set, exit 1 if a check fails):
  python3 bench/discover_default_check.py build/modaltyre [--seed 45] [--only NAME,...]
      [--noise 0.015] [--workdir /tmp/discover_default_check] [--threads 2]
Only the standard library is used; the sweep, noise and signal helpers are
bench/discover_outside_check.py's.
"""
import argparse
import json
import os
import random
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import discover_outside_check as outside  # noqa: E402
from discover_outside_check import discover, noisy, sweep  # noqa: E402

# Rolling rows measure the rolling resistance too: noise on it as on the footprint.
outside.OBSERVABLES.append("rolling_resistance_N")

LOADS6 = [2000, 3300, 4600, 5900, 7200, 8500]
LOADS12 = [2000, 2600, 3200, 3800, 4400, 5000, 5600, 6200, 6800, 7400, 8000, 8600]
BELT = {"footprint_3d.lateral_belt.supports": "free",
        "footprint_3d.lateral_belt.bending_stiffness_Nm": "0.27"}

# name: (key, drawn range, stated keys switched with it, grid). An effect of section effects:
# is switched by effects.NAME.enabled; an option effect by its own keys (modaltyre effects).
EFFECTS = {
    "inflation_pressure": ("effects.inflation_pressure.exponent", (0.6, 1.2), {},
                           {"load_N": LOADS6, "pressure_kPa": [180, 280]}),
    "tread_relaxation": ("effects.tread_relaxation.creep_ratio", (0.4, 0.8), {},
                         {"load_N": LOADS6, "hold_s": [0, 300]}),
    "dry_friction": ("effects.dry_friction.friction_force_N", (200, 400), {},
                     {"load_N": LOADS6, "branch": ["load", "unload"]}),
    "load_stiffening": ("effects.load_stiffening.exponent", (0.15, 0.3), {}, {"load_N": LOADS6}),
    "tread_coupling": ("effects.tread_coupling.coupling_length_mm", (8, 20), {},
                       {"load_N": LOADS6}),
    "soil_compliance": ("effects.soil_compliance.modulus_MPa", (2, 8), {},
                        {"load_N": LOADS6, "surface": ["rigid", "soil"]}),
    "rolling_speed": ("effects.rolling_speed.damping_scale", (2, 4), {},
                      {"load_N": LOADS6, "speed_kmh": [30, 90]}),
    "belt_flattening": ("effects.belt_flattening.stiffness_MPa", (15, 30), {},
                        {"load_N": LOADS6}),
    "lateral_belt": ("footprint_3d.lateral_belt.foundation_MPa_per_m", (300, 1000), BELT,
                     {"load_N": LOADS12}),
    "pneumatic_share": ("modal.pneumatic_share", (0.25, 0.5), {}, {"load_N": LOADS12}),
    "crown_shape": ("footprint_3d.crown.exponent", (1.3, 4.0),
                    {"footprint_3d.crown.shape": "power",
                     "footprint_3d.crown.reference_half_width_mm": "60"}, {"load_N": LOADS12}),
    "sidewall_softening": ("footprint_3d.sidewall.chord_over_length", (0.8, 0.86),
                           {"footprint_3d.sidewall.meridian_chord_mm": "117"},
                           {"load_N": LOADS12}),
}
OPTIONS = {"lateral_belt", "pneumatic_share", "crown_shape", "sidewall_softening"}
PAIRS = [
    ("inflation_pressure", "tread_relaxation",
     {"load_N": LOADS6, "pressure_kPa": [180, 280], "hold_s": [0, 300]}),
    ("dry_friction", "belt_flattening", {"load_N": LOADS6, "branch": ["load", "unload"]}),
    ("soil_compliance", "sidewall_softening",
     {"load_N": LOADS6, "surface": ["rigid", "soil"]}),
]
NOISE_GRIDS = [
    {"load_N": LOADS6, "pressure_kPa": [180, 280], "hold_s": [0, 300]},
    {"load_N": LOADS6, "branch": ["load", "unload"]},
    {"load_N": LOADS12},
]


def settings_of(name, value):
    key, _, stated, _ = EFFECTS[name]
    s = dict(stated)
    if name not in OPTIONS:
        s["effects.%s.enabled" % name] = "true"
    s[key] = "%.6g" % value
    return s


def pooled_gaps(j):
    # The pooled cross-validated RMS before the first round and after the last named effect.
    first = j["rounds"][0]
    before = next((c["cv_rms_before"] for c in first if c.get("testable")), None)
    after = j["effects"][-1]["cv_rms_after"] if j["effects"] else before
    return before, after


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("modaltyre")
    ap.add_argument("--config", default="configs/sf350.yaml")
    ap.add_argument("--seed", type=int, default=45)
    ap.add_argument("--noise", type=float, default=0.015)
    ap.add_argument("--workdir", default="/tmp/discover_default_check")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--only", default="", help="comma-separated set names (effect, pair a+b, "
                                               "noise_K) to run")
    ap.add_argument("--value", default="", help="comma-separated NAME=VALUE: plant NAME at VALUE "
                                                "instead of the drawn value (a magnitude study)")
    a = ap.parse_args()
    fixed = {k: float(v) for k, v in (kv.split("=") for kv in a.value.split(",") if kv)}
    os.makedirs(a.workdir, exist_ok=True)
    rng = random.Random(a.seed)
    only = set(a.only.split(",")) if a.only else None
    sets = []  # (tag, [(effect, value)], grid, noise seed)
    for name, (_, (lo, hi), _, grid) in EFFECTS.items():
        sets.append((name, [(name, rng.uniform(lo, hi))], grid, rng.randrange(1 << 30)))
    for p, q, grid in PAIRS:
        planted = [(e, rng.uniform(*EFFECTS[e][1])) for e in (p, q)]
        sets.append((p + "+" + q, planted, grid, rng.randrange(1 << 30)))
    for k, grid in enumerate(NOISE_GRIDS):
        sets.append(("noise_%d" % k, [], grid, rng.randrange(1 << 30)))
    print("seed %d, noise %.3g, config %s" % (a.seed, a.noise, a.config))
    print("set | planted | named | cv gap before -> after | recovered (band) | verdict | s")
    failures = 0
    for tag, planted, grid, seed in sets:
        if only and tag not in only:
            continue
        settings = {}
        planted = [(name, fixed.get(name, value)) for name, value in planted]
        for name, value in planted:
            settings.update(settings_of(name, value))
        clean = sweep(a.modaltyre, a.config, settings, grid,
                      os.path.join(a.workdir, tag + "_clean.csv"), a.threads)
        measured = os.path.join(a.workdir, tag + "_measured.csv")
        noisy(clean, measured, a.noise, random.Random(seed))
        t = time.time()
        j, _ = discover(a.modaltyre, a.config, measured, a.threads)
        seconds = time.time() - t
        with open(os.path.join(a.workdir, tag + ".json"), "w") as f:
            json.dump(j, f, indent=1)
        named = [e["name"] for e in j["effects"]]
        before, after = pooled_gaps(j)
        recovered = []
        ok = True
        if not planted:
            ok = not named
        elif len(planted) == 1:
            name, value = planted[0]
            ok = bool(named) and named[0] == name
            if ok and name in OPTIONS:
                key = EFFECTS[name][0]
                fit = j["effects"][0]["parameters"].get(key)
                se = j["effects"][0]["standard_errors"].get(key)
                band = j["effects"][0].get("bands_two_standard_errors", {}).get(key)
                if band:  # the reported band (profile likelihood, two standard errors)
                    good = fit is not None and band["lower"] <= value <= band["upper"]
                    text = "%s %.4g (%.4g to %.4g; planted %.4g)" % (
                        key, fit or 0, band["lower"], band["upper"], value)
                    # The band with the evaluation mesh's share (discover/mesh_bias.h): the data
                    # come from a finer mesh than discover's.
                    mesh = j["effects"][0].get("bands_with_mesh", {}).get(key)
                    if mesh and not good and fit is not None:
                        good = mesh["lower"] <= value <= mesh["upper"]
                        text += "; with the mesh %.4g to %.4g %s" % (
                            mesh["lower"], mesh["upper"], "holds it" if good else "misses it")
                    recovered.append(text)
                else:
                    good = fit is not None and se is not None and abs(fit - value) <= 2 * se
                    recovered.append("%s %.4g (+- %.3g; planted %.4g)" % (key, fit or 0, se or 0,
                                                                         value))
                ok = good
        else:
            ok = set(named) >= {p[0] for p in planted}
        for name, _ in planted:  # a planted effect left unnamed: its limit and Delta BIC
            if name in named:
                continue
            cand = next((c for c in j["rounds"][-1] if c["name"] == name), None)
            lim = cand.get("detection_limit") if cand else None
            if lim:
                below = lim.get("below_neutral")
                recovered.append("%s unnamed (dBIC %.1f): limit %s %.4g%s" % (
                    name, cand["delta_bic"], lim["bound"], lim["value"],
                    " or at most %.4g" % below["value"] if below and below.get("value")
                    else ""))
            else:
                recovered.append("%s unnamed: %s" % (name, cand.get("detection_limit_reason", "")
                                                     if cand else "not a candidate"))
        if planted:
            ok = ok and after < before
        failures += not ok
        print("%s | %s | %s | %.2f -> %.2f %% | %s | %s | %.0f" % (
            tag, ", ".join("%s %.4g" % p for p in planted) or "none",
            ",".join(named) or "nothing", 100 * (before or 0), 100 * (after or 0),
            "; ".join(recovered) or "-", "ok" if ok else "FAIL", seconds))
        sys.stdout.flush()
    print("%d failed" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
