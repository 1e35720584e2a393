#!/usr/bin/python3
"""Outside check of issue 20: the `.tir` bridge against an independent Magic Formula evaluation.

1. `modaltyre tir export CONFIG --output OUT.tir`, read back with this script's own parser
   (sections, KEY = value, `$`/`!` comments, [UNITS] for length/force/pressure).
2. The model's own footprints: `modaltyre footprint CONFIG --load L --json` at 11 loads over
   0.5-1.5 x FNOMIN and at (1 -+ 0.02) x FNOMIN for the tangent stiffness (central difference of
   the sinking).
3. Pacejka 2012 App. 3 evaluated here:
     A3.3/A3.4  F = Fz0 (q1 x + q2 x^2), x = rho/R0, q1 = sqrt((Cz0 R0/Fz0)^2 - 4 q2)
     A3.7       a = R0 (Q_RA2 rho/R0 + Q_RA1 sqrt(rho/R0))            (2a = contact length)
     A3.8       b = W (Q_RB2 rho/R0 + Q_RB1 (rho/R0)^(1/3))           (2b = contact width)
   with rho for A3.7/A3.8 taken three ways: (i) Fz/Cz (as MF evaluators such as TyreDyn and
   mfeval do), (ii) the A3.3 deflection at that load, (iii) the model's own sinking.
   Criteria (issue 20): VERTICAL_STIFFNESS within 5 % of the model's tangent stiffness at
   FNOMIN; lengths within 3 % over 0.5-1.5 x FNOMIN (judged on (i), the simulators' reading;
   (ii) and (iii) printed); also sinking from A3.3 within 3 % (printed, judged).
4. `tir compare CONFIG FILE --json` on every .tir given with --public (reports dimensionless
   rows for other tyre sizes: checked), an FTire-like file made here (exit 2 and a sentence
   naming FTire), and malformed files made here (exit 2, the message naming the line).

Run:  /usr/bin/python3 bench/outside_checks/tir_check.py --binary build/modaltyre \
          --config configs/sf350.yaml [--public tests/data/tir/*.tir other.tir ...]
Standard library + numpy only. Exit status 1 if a check fails.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

from outside_report import Report

LENGTH = {"meter": 1.0, "m": 1.0, "mm": 1e-3, "millimeter": 1e-3, "cm": 1e-2, "inch": 0.0254, "in": 0.0254}
FORCE = {"newton": 1.0, "n": 1.0, "kn": 1e3, "kilonewton": 1e3, "lbf": 4.4482216152605}


def parse_tir(path):
    """Own minimal .tir parser: {SECTION: {KEY: float|str}}; SI for the keys used here."""
    sections, cur = {}, None
    with open(path, encoding="latin-1") as fh:
        for raw in fh:
            line = raw.rstrip("\r\n")
            s = line.strip()
            if not s or s[0] in "$!":
                continue
            m = re.match(r"^\[([A-Za-z0-9_]+)\]", s)
            if m:
                cur = m.group(1).upper()
                sections.setdefault(cur, {})
                continue
            if "=" not in s or cur is None:
                continue
            key, val = s.split("=", 1)
            val = re.split(r"\$|!", val, maxsplit=1)[0].strip() if "'" not in val else val.strip()
            if val.startswith("'"):
                val = val[1:].split("'", 1)[0]
            else:
                try:
                    val = float(val.replace("D", "E").replace("d", "e")) if val else None
                except ValueError:
                    pass
            sections[cur].setdefault(key.strip().upper(), val)
    units = sections.get("UNITS", {})
    lf = LENGTH.get(str(units.get("LENGTH", "meter")).lower(), 1.0)
    ff = FORCE.get(str(units.get("FORCE", "newton")).lower(), 1.0)
    return sections, lf, ff


def footprint(binary, config, loads):
    cmd = [binary, "footprint", config, "--json"]
    for L in loads:
        cmd += ["--load", f"{L:.6f}"]
    p = subprocess.run(cmd, capture_output=True, text=True, check=True)
    return json.loads(p.stdout)


def case_values(doc):
    out = []
    for c in doc["cases"]:
        out.append(dict(load_N=c["load_N"], sinking_mm=c["sinking_mm"],
                        length_mm=c["contact_length_mm"], width_mm=c.get("width_mm")))
    return out


def mf_law(sec, lf, ff):
    v, d, c = sec["VERTICAL"], sec["DIMENSION"], sec.get("CONTACT_PATCH", {})
    R0 = d["UNLOADED_RADIUS"] * lf
    W = d.get("WIDTH") * lf if isinstance(d.get("WIDTH"), float) else None
    Fz0 = v["FNOMIN"] * ff
    Cz = v["VERTICAL_STIFFNESS"] * ff / lf
    q2 = v.get("Q_FZ2") or 0.0
    q1 = math.sqrt((Cz * R0 / Fz0) ** 2 - 4 * q2)  # A3.4
    return dict(R0=R0, W=W, Fz0=Fz0, Cz=Cz, q1=q1, q2=q2, ra1=c.get("Q_RA1"), ra2=c.get("Q_RA2"),
                rb1=c.get("Q_RB1"), rb2=c.get("Q_RB2"))


def rho_of_load(law, F):
    """Invert A3.3: q2 x^2 + q1 x - F/Fz0 = 0."""
    q1, q2, f = law["q1"], law["q2"], F / law["Fz0"]
    x = f / q1 if abs(q2) < 1e-15 else (-q1 + math.sqrt(q1 * q1 + 4 * q2 * f)) / (2 * q2)
    return x * law["R0"]


def half_length(law, rho):
    x = rho / law["R0"]
    return law["R0"] * (law["ra2"] * x + law["ra1"] * math.sqrt(x))  # A3.7


def half_width(law, rho):
    x = rho / law["R0"]
    return law["W"] * (law["rb2"] * x + law["rb1"] * x ** (1.0 / 3.0))  # A3.8


def export_check(binary, config, rep, workdir):
    tir = os.path.join(workdir, "export.tir")
    cmd = [binary, "tir", "export", config, "--output", tir]
    print("$ " + " ".join(cmd))
    p = subprocess.run(cmd, capture_output=True, text=True)
    rep.check("tir export exits 0", p.returncode == 0, f"exit {p.returncode} {p.stderr.strip()[:200]}")
    sec, lf, ff = parse_tir(tir)
    law = mf_law(sec, lf, ff)
    print(f"  file: R0 {law['R0'] * 1e3:.2f} mm, W {law['W'] and law['W'] * 1e3} mm, FNOMIN {law['Fz0']:.1f} N, "
          f"Cz {law['Cz'] / 1e3:.3f} N/mm, Q_FZ2 {law['q2']:.4g} (q1 {law['q1']:.4g}), Q_RA1 {law['ra1']}, "
          f"Q_RA2 {law['ra2']}, Q_RB1 {law['rb1']}, Q_RB2 {law['rb2']}")
    Fz0 = law["Fz0"]
    # tangent stiffness of the model at FNOMIN by central difference of its sinking
    h = 0.02
    fd = case_values(footprint(binary, config, [(1 - h) * Fz0, (1 + h) * Fz0]))
    kt = (fd[1]["load_N"] - fd[0]["load_N"]) / (fd[1]["sinking_mm"] - fd[0]["sinking_mm"])  # N/mm
    rel = law["Cz"] / 1e3 / kt - 1
    rep.check("VERTICAL_STIFFNESS within 5 % of the model's tangent stiffness at FNOMIN", abs(rel) <= 0.05,
              f"{law['Cz'] / 1e3:.2f} N/mm vs {kt:.2f} N/mm (central difference +-2 %): {100 * rel:+.2f} %")
    loads = [Fz0 * (0.5 + 0.1 * i) for i in range(11)]
    rows = case_values(footprint(binary, config, loads))
    worst = dict(sink=0.0, len_i=0.0, len_ii=0.0, len_iii=0.0, wid_i=0.0)
    print("   load/F0  sink_model  sink_A3.3   len_model  len(i)F/Cz len(ii)A3.3 len(iii)own  width_model width(i)")
    for r in rows:
        F = r["load_N"]
        rho_mf = rho_of_load(law, F)
        rho_lin = F / law["Cz"]
        rho_own = r["sinking_mm"] * 1e-3
        L = [2e3 * half_length(law, rho) for rho in (rho_lin, rho_mf, rho_own)]
        e_s = rho_mf * 1e3 / r["sinking_mm"] - 1
        e_l = [x / r["length_mm"] - 1 for x in L]
        worst["sink"] = max(worst["sink"], abs(e_s))
        for k, e in zip(("len_i", "len_ii", "len_iii"), e_l):
            worst[k] = max(worst[k], abs(e))
        wtxt = ""
        if law["rb1"] is not None and law["W"] and r["width_mm"]:
            Wd = 2e3 * half_width(law, rho_lin)
            worst["wid_i"] = max(worst["wid_i"], abs(Wd / r["width_mm"] - 1))
            wtxt = f"{r['width_mm']:9.2f} {Wd:9.2f}"
        print(f"   {F / Fz0:5.2f} {r['sinking_mm']:10.3f} {rho_mf * 1e3:10.3f} {r['length_mm']:11.2f} "
              f"{L[0]:10.2f} {L[1]:10.2f} {L[2]:10.2f}   {wtxt}")
    rep.check("sinking from A3.3 within 3 % over 0.5-1.5 x FNOMIN", worst["sink"] <= 0.03,
              f"worst {100 * worst['sink']:.2f} %")
    rep.check("length 2a (A3.7, rho = Fz/Cz) within 3 % over 0.5-1.5 x FNOMIN", worst["len_i"] <= 0.03,
              f"worst {100 * worst['len_i']:.2f} % (rho from A3.3: {100 * worst['len_ii']:.2f} %, "
              f"model's own sinking: {100 * worst['len_iii']:.2f} %)")
    if worst["wid_i"]:
        print(f"  info  width 2b (A3.8, rho = Fz/Cz) worst {100 * worst['wid_i']:.2f} % over 0.5-1.5 x FNOMIN")
    return tir


def compare_check(binary, config, path, rep):
    p = subprocess.run([binary, "tir", "compare", config, path, "--json"], capture_output=True, text=True)
    name = os.path.basename(path)
    if p.returncode != 0:
        msg = p.stderr.strip().replace("\n", " | ")
        print(f"  info  {name}: exit {p.returncode}: {msg[:300]}")
        return p.returncode, None
    doc = json.loads(p.stdout)
    t = doc["tir"]
    rms = doc["rms_rel_diff"]
    fmt = lambda v: "null" if v is None else f"{100 * v:.1f} %"
    print(f"  info  {name}: fittyp {t.get('fittyp')}, R0 {t.get('unloaded_radius_mm')} mm, W {t.get('width_mm')} mm, "
          f"FNOMIN {t.get('fnomin_N')} N, dimensionless {doc['dimensionless']}, {len(doc['rows'])} rows, "
          f"RMS load {fmt(rms['load'])} length {fmt(rms['length'])} width {fmt(rms['width'])}")
    return 0, doc


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default="build/modaltyre")
    ap.add_argument("--config", default="configs/sf350.yaml")
    ap.add_argument("--public", nargs="*", default=[], help="public MF .tir files of other tyres")
    a = ap.parse_args()
    rep = Report()
    work = tempfile.mkdtemp(prefix="tir_outside_")
    exported = export_check(a.binary, a.config, rep, work)
    code, doc = compare_check(a.binary, a.config, exported, rep)
    rep.check("tir compare of the export against its own config: absolute units", code == 0 and doc
              and not doc["dimensionless"], f"dimensionless = {doc and doc['dimensionless']}")
    # public files of other tyres: dimensionless rows
    for path in a.public:
        code, doc = compare_check(a.binary, a.config, path, rep)
        if doc is not None:
            finite = all(r["tir_load_N"] is None or math.isfinite(r["tir_load_N"]) for r in doc["rows"])
            rep.check(f"{os.path.basename(path)}: dimensionless rows", doc["dimensionless"] and len(doc["rows"]) > 0
                      and finite, f"{len(doc['rows'])} rows, dimensionless {doc['dimensionless']}")
        else:
            rep.check(f"{os.path.basename(path)}: refused with exit 2 and a reason (no usable law)", code == 2,
                      f"exit {code}")
    # an FTire-like file (own imitation of cosin's layout) -> exit 2 naming FTire
    ftire = os.path.join(work, "ftire_like.tir")
    with open(ftire, "w") as fh:
        fh.write("$ FTire tyre data file (made by the outside check)\n[MODEL]\n"
                 "FUNCTION_NAME = 'FTire::ftr_adm'\nPROPERTY_FILE_FORMAT = 'FTIRE'\n"
                 "[TIRE_DATA]\nrim_radius = 0.2032\ntire_radius = 0.3165\nbelt_width = 0.185\n"
                 "inflation_pressure = 2.2e5\nnumber_of_belt_segments = 100\n")
    p = subprocess.run([a.binary, "tir", "compare", a.config, ftire], capture_output=True, text=True)
    rep.check("FTire file exits 2 with a clear sentence", p.returncode == 2 and "ftire" in p.stderr.lower(),
              f"exit {p.returncode}: {p.stderr.strip()[:250]}")
    # malformed files made from the export: the line must be named
    with open(exported) as fh:
        lines = fh.read().split("\n")
    idx = next(i for i, s in enumerate(lines) if s.strip().upper().startswith("VERTICAL_STIFFNESS"))
    cases = {
        "number_typo": (idx, re.sub(r"=\s*([-0-9.eE+]+)", "= 3.5.1e5", lines[idx])),
        "unterminated_quote": (next(i for i, s in enumerate(lines) if s.strip().upper().startswith("FILE_TYPE")),
                               "FILE_TYPE = 'tir"),
        "duplicate_key": (idx, lines[idx] + "\n" + lines[idx]),
    }
    for name, (i, repl) in cases.items():
        bad = list(lines)
        bad[i] = repl
        path = os.path.join(work, f"bad_{name}.tir")
        with open(path, "w") as fh:
            fh.write("\n".join(bad))
        want_line = i + 1 + (1 if name == "duplicate_key" else 0)
        p = subprocess.run([a.binary, "tir", "compare", a.config, path], capture_output=True, text=True)
        named = re.search(rf":{want_line}\b", p.stderr) is not None
        rep.check(f"malformed .tir ({name}) exits 2 naming line {want_line}", p.returncode == 2 and named,
                  f"exit {p.returncode}: {p.stderr.strip()[:250]}")
    print(f"\n{rep.failures} check(s) failed")
    return 1 if rep.failures else 0


if __name__ == "__main__":
    sys.exit(main())
