#!/usr/bin/python3
"""Outside check of issue 22: the Python module `modaltyre` against the CLI.

Checks (issue 22 "Done when"), each in a fresh interpreter started from this script:
  1. `python3 -c "import modaltyre"` with the README's path (PYTHONPATH=BUILD/python), for every
     interpreter given (default: /usr/bin/python3 and the first python3 on the PATH);
  2. Tyre(CONFIG).footprint(4000) equals `modaltyre footprint CONFIG --load 4000 --json` to 1e-9
     relative in sinking, length and every pressure (the centre-line units' pressure_kPa and, for a
     3D patch, every cell of the map);
  3. fit_modes(HAMMER) gives the orders (and kinds, aliasing) of `modaltyre fit-modes HAMMER --json`;
  4. a copy of CONFIG with one key misspelt raises modaltyre.InputError (a ValueError) whose
     message names the misspelt key;
  5. with --prefix PREFIX (after `cmake --install BUILD --prefix PREFIX`): the module imports from
     PREFIX/lib/python3.X/dist-packages on Debian (the path is printed) and gives the same footprint.
Exit status 1 if a check fails.

Run:  /usr/bin/python3 bench/outside_checks/py_check.py --build build --config configs/sf350.yaml \
          [--prefix /tmp/inst] [--python /usr/bin/python3 python3]
Standard library + numpy only.
"""
import argparse
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

from outside_report import Report

PROBE = r'''
import json, sys
import modaltyre  # first: with a python3 that lacks NumPy the package supplies the build's NumPy
cfg, load = sys.argv[1], float(sys.argv[2])
fp = modaltyre.Tyre(cfg).footprint(load)
out = dict(file=modaltyre.__file__, sinking_mm=float(fp.sinking_mm), length_mm=float(fp.length_mm),
           x_mm=[float(v) for v in fp.x_mm], pressure_kPa=[float(v) for v in fp.pressure_kPa])
m = getattr(fp, "map", None)
if m is not None:
    out["map_pressure_kPa"] = [[float(v) for v in row] for row in m["pressure_kPa"]]
print(json.dumps(out))
'''

FIT = r'''
import json, sys, modaltyre
print(json.dumps(modaltyre.fit_modes(sys.argv[1]), default=lambda o: o.tolist()))
'''

BADKEY = r'''
import sys, modaltyre
try:
    modaltyre.Tyre(sys.argv[1])
except modaltyre.InputError as e:
    print("InputError|%s|%s" % (isinstance(e, ValueError), str(e).replace("\n", " ")))
except Exception as e:
    print("other|%s|%s" % (type(e).__name__, e))
else:
    print("no error")
'''


def py(interp, code, args, pythonpath):
    env = dict(os.environ, PYTHONPATH=pythonpath)
    return subprocess.run([interp, "-c", code] + args, capture_output=True, text=True, env=env)


def rel(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def compare_footprint(doc, cli_case, rep, tag):
    worst = max(rel(doc["sinking_mm"], cli_case["sinking_mm"]), rel(doc["length_mm"], cli_case["contact_length_mm"]))
    units = cli_case["units"]
    n_ok = len(units) == len(doc["pressure_kPa"])
    wp = 0.0
    if n_ok:
        for u, x, p in zip(units, doc["x_mm"], doc["pressure_kPa"]):
            wp = max(wp, rel(x, u["x_mm"]) if u["x_mm"] else abs(x), abs(p - u["pressure_kPa"]) /
                     max(abs(u["pressure_kPa"]), 1e-300) if u["pressure_kPa"] else abs(p))
    rep.check(f"{tag}: sinking and length equal the CLI to 1e-9", worst <= 1e-9, f"largest rel. diff {worst:.2e}")
    rep.check(f"{tag}: every unit pressure (and x) equals the CLI to 1e-9", n_ok and wp <= 1e-9,
              f"{len(doc['pressure_kPa'])} vs {len(units)} units, largest rel. diff {wp:.2e}")
    if "map" in cli_case and "map_pressure_kPa" in doc:
        cm = cli_case["map"]["pressure_kPa"]
        pm = doc["map_pressure_kPa"]
        same_shape = len(cm) == len(pm) and all(len(a) == len(b) for a, b in zip(cm, pm))
        peak = max(max(r) for r in cm)
        wm = max((abs(a - b) / max(abs(b), 1e-300) for ra, rb in zip(pm, cm) for a, b in zip(ra, rb) if b), default=0)
        wabs = max((abs(a - b) for ra, rb in zip(pm, cm) for a, b in zip(ra, rb)), default=0)
        rep.check(f"{tag}: every map pressure equals the CLI to 1e-9", same_shape and wm <= 1e-9,
                  f"{len(pm)}x{len(pm[0]) if pm else 0} cells, largest rel. diff {wm:.2e} "
                  f"(abs {wabs:.2e} kPa of peak {peak:.1f}; the CLI writes the map with 6 significant digits)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--config", default="configs/sf350.yaml")
    ap.add_argument("--hammer", default="configs/data/sf350_hammer_12pt.csv")
    ap.add_argument("--load", type=float, default=4000.0)
    ap.add_argument("--prefix", default=None)
    ap.add_argument("--python", nargs="*", default=["/usr/bin/python3", shutil.which("python3")])
    a = ap.parse_args()
    rep = Report()
    binary = os.path.join(a.build, "modaltyre")
    pp = os.path.abspath(os.path.join(a.build, "python"))
    cli = json.loads(subprocess.run([binary, "footprint", a.config, "--load", str(a.load), "--json"],
                                    capture_output=True, text=True, check=True).stdout)
    cli_case = cli["cases"][0]
    cli_fm = json.loads(subprocess.run([binary, "fit-modes", a.hammer, "--json"], capture_output=True, text=True,
                                       check=True).stdout)
    want = [(m["mode"], m["order"], m["kind"], m["aliased"]) for m in cli_fm["modes"]]

    # the misspelt key: a copy of the config's folder (relative paths keep working)
    tmp = tempfile.mkdtemp(prefix="py_outside_")
    cfg_dir = os.path.dirname(os.path.abspath(a.config))
    shutil.copytree(cfg_dir, os.path.join(tmp, "configs"))
    bad_cfg = os.path.join(tmp, "configs", os.path.basename(a.config))
    with open(bad_cfg) as fh:
        text = fh.read()
    m = re.search(r"^(\s*)(modulus_MPa)(\s*:)", text, re.M)
    misspelt = "modulos_MPa"
    text = text[:m.start(2)] + misspelt + text[m.end(2):]
    with open(bad_cfg, "w") as fh:
        fh.write(text)

    interps = [i for i in dict.fromkeys(a.python) if i]
    places = [("build tree (PYTHONPATH=%s)" % pp, pp)]
    if a.prefix:
        site = glob.glob(os.path.join(a.prefix, "lib", "python3*", "*-packages"))
        # The folder CMake chose (Debian: lib/python3.X/dist-packages): the one holding modaltyre.
        held = [d for d in site if os.path.isdir(os.path.join(d, "modaltyre"))]
        sp = os.path.abspath(held[0] if held else os.path.join(a.prefix, "lib", "python3",
                                                               "dist-packages"))
        print(f"install prefix {a.prefix}: package folders found {site}")
        places.append(("install prefix (PYTHONPATH=%s)" % sp, sp))
    for where, path in places:
        for interp in interps:
            ver = subprocess.run([interp, "--version"], capture_output=True, text=True).stdout.strip()
            tag = f"{interp} ({ver}), {where}"
            print(f"[{tag}]")
            p = py(interp, "import modaltyre; print(modaltyre.__file__)", [], path)
            rep.check("import modaltyre", p.returncode == 0,
                      p.stdout.strip() if p.returncode == 0 else p.stderr.strip()[-300:])
            if p.returncode != 0:
                continue
            p = py(interp, PROBE, [a.config, str(a.load)], path)
            if p.returncode != 0:
                rep.check("Tyre(...).footprint runs", False, p.stderr.strip()[-300:])
                continue
            compare_footprint(json.loads(p.stdout), cli_case, rep, f"footprint({a.load:g})")
            p = py(interp, FIT, [a.hammer], path)
            if p.returncode == 0:
                got = [(m["mode"], m["order"], m["kind"], m["aliased"]) for m in json.loads(p.stdout)["modes"]]
                rep.check("fit_modes gives the CLI's orders", got == want,
                          f"orders {[g[1] for g in got]} (CLI {[w[1] for w in want]})")
            else:
                rep.check("fit_modes runs", False, p.stderr.strip()[-300:])
            p = py(interp, BADKEY, [bad_cfg], path)
            out = p.stdout.strip()
            ok = out.startswith("InputError|True|") and misspelt in out
            rep.check(f"misspelt key '{misspelt}' raises modaltyre.InputError (a ValueError) naming it", ok, out[:250])
    print(f"\n{rep.failures} check(s) failed")
    return 1 if rep.failures else 0


if __name__ == "__main__":
    sys.exit(main())
