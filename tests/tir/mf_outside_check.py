#!/usr/bin/python3
"""An outside check of `modaltyre tir export` (issue 20, "done when"): this script shares no code
with ModalTyre's tir/ module. It reads the exported .tir with its own small parser, evaluates the
Magic Formula's vertical and contact-patch laws (Pacejka 2012, Tire and Vehicle Dynamics, 3rd ed.,
App. 3) with numpy, asks `modaltyre footprint --json` for the model's own footprints, and compares:

  (A3.4)  VERTICAL_STIFFNESS against the model's tangent stiffness at FNOMIN
          (central difference of the model's sinking at 0.98 and 1.02 FNOMIN): within 5 %
  (A3.3)  the law's deflection at each load against the model's sinking: within 3 %
  (A3.7)  2a from Q_RA1, Q_RA2 against the model's contact length: within 3 %
  (A3.8)  2b from Q_RB1, Q_RB2, WIDTH against the model's width: reported (no criterion)
at 11 loads 0.5, 0.6, ..., 1.5 x FNOMIN (none of them one of the export's fitted loads).

  (A3.3)  F_z = F_z0 (q_Fz1 x + q_Fz2 x^2), x = rho / R0    (nominal pressure, standing tyre)
  (A3.4)  q_Fz1 = sqrt((C_z0 R0 / F_z0)^2 - 4 q_Fz2)
  (A3.7)  a = R0 (q_ra2 rho_z / R0 + q_ra1 sqrt(rho_z / R0)),       rho_z = F_z / C_z0
  (A3.8)  b = W (q_rb2 rho_z / R0 + q_rb1 (rho_z / R0)^(1/3))

Usage: /usr/bin/python3 tests/tir/mf_outside_check.py MODALTYRE CONFIG FILE.tir
Prints one JSON object; exit 0 when the three criteria hold, 1 when one fails, 2 on bad input.
No input reaches a shell (subprocess with an argument list).
"""
import json
import re
import subprocess
import sys

import numpy as np

LENGTH = {"meter": 1.0, "m": 1.0, "mm": 1e-3, "millimeter": 1e-3}
FORCE = {"newton": 1.0, "n": 1.0, "kn": 1e3, "kilonewton": 1e3}


def fail(message):
    print(message, file=sys.stderr)
    sys.exit(2)


def read_tir(path):
    """{SECTION: {KEY: text}} of a .tir; '$' and '!' start comments outside quotes."""
    sections, current = {}, None
    with open(path, encoding="utf-8", errors="replace") as fh:
        for no, raw in enumerate(fh, 1):
            line = re.sub(r"""^((?:[^'"$!]|'[^']*'|"[^"]*")*)[$!].*$""", r"\1", raw).strip()
            if not line:
                continue
            if line.startswith("["):
                current = sections.setdefault(line.strip("[]").strip().upper(), {})
            elif "=" in line and current is not None:
                key, value = line.split("=", 1)
                current[key.strip().upper()] = value.strip().strip("'\"")
    return sections


def number(tir, section, key):
    try:
        return float(tir[section][key].replace("D", "e").replace("d", "e"))
    except (KeyError, ValueError):
        fail(f"{sys.argv[3]}: [{section}] {key} missing or not a number")


def footprints(modaltyre, config, loads):
    args = [modaltyre, "footprint", config, "--json"]
    for f in loads:
        args += ["--load", repr(float(f))]
    run = subprocess.run(args, capture_output=True, text=True, check=False)
    if run.returncode != 0:
        fail(f"modaltyre footprint exited {run.returncode}: {run.stderr.strip()}")
    cases = json.loads(run.stdout)["cases"]
    by_load = sorted(cases, key=lambda c: c["load_N"])
    return {k: np.array([c[k] for c in by_load]) * 1e-3
            for k in ("sinking_mm", "contact_length_mm", "width_mm")}


def rel(law, model):
    return (law - model) / model


def main():
    if len(sys.argv) != 4:
        print(__doc__.split("Usage: ")[1].splitlines()[0], file=sys.stderr)
        return 2
    modaltyre, config, path = sys.argv[1:]
    tir = read_tir(path)
    units = tir.get("UNITS", {})
    to_m = LENGTH.get(units.get("LENGTH", "meter").lower())
    to_n = FORCE.get(units.get("FORCE", "newton").lower())
    if to_m is None or to_n is None:
        fail(f"{path}: [UNITS] {units} not handled by this check")
    r0 = number(tir, "DIMENSION", "UNLOADED_RADIUS") * to_m
    width = number(tir, "DIMENSION", "WIDTH") * to_m
    fz0 = number(tir, "VERTICAL", "FNOMIN") * to_n
    cz0 = number(tir, "VERTICAL", "VERTICAL_STIFFNESS") * to_n / to_m
    q_fz2 = number(tir, "VERTICAL", "Q_FZ2")
    q_ra1 = number(tir, "CONTACT_PATCH", "Q_RA1")
    q_ra2 = number(tir, "CONTACT_PATCH", "Q_RA2")
    has_width = "Q_RB1" in tir.get("CONTACT_PATCH", {})
    q_fz1 = np.sqrt((cz0 * r0 / fz0) ** 2 - 4 * q_fz2)  # (A3.4)

    loads = fz0 * np.linspace(0.5, 1.5, 11)
    model = footprints(modaltyre, config, loads)
    near = footprints(modaltyre, config, [0.98 * fz0, 1.02 * fz0])
    tangent = 0.04 * fz0 / (near["sinking_mm"][1] - near["sinking_mm"][0])

    # (A3.3) inverted on its rising branch: q2 x^2 + q1 x - F/F0 = 0.
    f = loads / fz0
    x = f / q_fz1 if q_fz2 == 0 else (-q_fz1 + np.sqrt(q_fz1**2 + 4 * q_fz2 * f)) / (2 * q_fz2)
    rho_z = loads / cz0
    length = 2 * r0 * (q_ra2 * rho_z / r0 + q_ra1 * np.sqrt(rho_z / r0))  # (A3.7)
    out = {
        "tir": path, "config": config, "fnomin_N": fz0, "q_fz1": float(q_fz1),
        "vertical_stiffness_N_per_mm": cz0 * 1e-3,
        "model_tangent_stiffness_N_per_mm": float(tangent * 1e-3),
        "stiffness_rel_diff": float(cz0 / tangent - 1),
        "loads_N": [round(v, 1) for v in loads],
        "sinking_max_abs_rel_diff": float(np.max(np.abs(rel(x * r0, model["sinking_mm"])))),
        "length_max_abs_rel_diff": float(np.max(np.abs(rel(length, model["contact_length_mm"])))),
        "length_rms_rel_diff": float(np.sqrt(np.mean(rel(length, model["contact_length_mm"])**2))),
    }
    if has_width:
        q_rb1 = number(tir, "CONTACT_PATCH", "Q_RB1")
        q_rb2 = number(tir, "CONTACT_PATCH", "Q_RB2")
        w = 2 * width * (q_rb2 * rho_z / r0 + q_rb1 * np.cbrt(rho_z / r0))  # (A3.8)
        out["width_max_abs_rel_diff"] = float(np.max(np.abs(rel(w, model["width_mm"]))))
        out["width_rms_rel_diff"] = float(np.sqrt(np.mean(rel(w, model["width_mm"])**2)))
        out["model_width_mm"] = [round(v * 1e3, 2) for v in model["width_mm"]]
        out["tir_width_mm"] = [round(v * 1e3, 2) for v in w]
    ok = (abs(out["stiffness_rel_diff"]) <= 0.05 and out["sinking_max_abs_rel_diff"] <= 0.03
          and out["length_max_abs_rel_diff"] <= 0.03)
    out["criteria_met"] = bool(ok)
    print(json.dumps(out, indent=1))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
