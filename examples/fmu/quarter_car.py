#!/usr/bin/env python3
"""A quarter-car coupled to the ModalTyre FMU over a road with a cleat (issue 34's example).

    modaltyre fmu configs/sf350_2d_table3.yaml --output sf350.fmu
    python3 examples/fmu/quarter_car.py sf350.fmu --csv quarter_car.csv --plot quarter_car.png

The host (fmi2_host.py) loads the FMU as any FMI 2.0 host would. The car: a quarter of a
1200 kg passenger car on a linear suspension (sprung 300 kg, unsprung 35 kg, 25 kN/m, 2.0 kN s/m:
body bounce 1.4 Hz), driven at a constant forward speed; the wheel spins freely about its axle
(inertia 0.9 kg m^2) under the tyre's moment. Co-simulation at a fixed communication step
(1 ms): the host sets the wheel state at t, the FMU steps to t + h and returns the wheel load,
and the host integrates its own states over the step with that load (semi-implicit Euler).
The road: flat, with a cleat (height, length, raised-cosine edges of a quarter of its length)
given to the FMU as its road_profile parameter. The run starts at static equilibrium (found in
the FMU's initialization mode, where it returns the standing tyre's load at the wheel height set).
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fmi2_host import Fmu, Instance  # noqa: E402

G = 9.81


def write_cleat(path, x_centre, height, length, step=0.5e-3):
    """Raised-cosine cleat as x_m,height_m points (flat far beyond)."""
    edge = length / 4
    xs = [-1000.0, x_centre - length / 2 - 1.0]
    x = x_centre - length / 2
    while x <= x_centre + length / 2 + 1e-12:
        xs.append(x)
        x += step
    xs += [x_centre + length / 2 + 1.0, 1000.0]

    def h(x):
        d = abs(x - x_centre)
        if d >= length / 2:
            return 0.0
        if d <= length / 2 - edge:
            return height
        s = (length / 2 - d) / edge  # 0 at the foot, 1 at the top
        return height * 0.5 * (1 - math.cos(math.pi * s))

    with open(path, "w") as f:
        f.write("x_m,height_m\n")
        for x in xs:
            f.write(f"{x:.6f},{h(x):.9f}\n")


def quaternion_about_y(angle):
    return (math.cos(angle / 2), 0.0, math.sin(angle / 2), 0.0)


def run(fmu, speed, duration, h, profile, quiet=True, name="car"):
    ms, mu_, ks, cs, Iw = 300.0, 35.0, 25e3, 2.0e3, 0.9
    weight = (ms + mu_) * G
    inst = Instance(fmu, name, quiet=quiet)
    inst.set({"step_size": h})
    if profile:
        inst.set_string("road_profile", profile)
    R0 = fmu_start_radius(fmu)
    # Static equilibrium before the run: in initialization mode the FMU returns the standing
    # tyre's load at the wheel height set, so a secant search finds the height that carries
    # the car's weight; the body sits on its suspension's static compression.
    inst.enter_initialization()
    z0, z1 = R0 - 0.005, R0 - 0.015
    f0 = f1 = None
    for _ in range(30):
        if f0 is None:
            inst.set(state(0.0, z0, speed, 0.0, 0.0, speed / R0))
            f0 = inst.get(["wheel_load.force.z"])["wheel_load.force.z"] - weight
        inst.set(state(0.0, z1, speed, 0.0, 0.0, speed / R0))
        f1 = inst.get(["wheel_load.force.z"])["wheel_load.force.z"] - weight
        if abs(f1) < 1e-6 * weight or f1 == f0:
            break
        z0, z1, f0 = z1, z1 - f1 * (z1 - z0) / (f1 - f0), f1
    zu, wu = z1, 0.0
    zs, ws = zu + 0.35 - ms * G / ks, 0.0
    x, angle, spin = 0.0, 0.0, speed / R0
    inst.set(state(x, zu, speed, wu, angle, spin))
    inst.exit_initialization()
    zu0, zs0 = zu, zs
    rows = []
    t = 0.0
    wall = time.perf_counter()
    steps = int(round(duration / h))
    for k in range(steps):
        inst.set(state(x, zu, speed, wu, angle, spin))
        inst.step(h)
        out = inst.get(["wheel_load.force.x", "wheel_load.force.z", "wheel_load.moment.y",
                        "tyre.deflection", "tyre.slip_ratio"])
        fz, fx, my = out["wheel_load.force.z"], out["wheel_load.force.x"], out["wheel_load.moment.y"]
        # The car over [t, t + h] under the tyre's load at t + h (semi-implicit Euler).
        fsusp = ks * (zs - zu - 0.35) + cs * (ws - wu)
        ws += h * (-fsusp / ms - G)
        wu += h * ((fsusp + fz) / mu_ - G)
        zs += h * ws
        zu += h * wu
        spin += h * my / Iw
        angle += h * spin
        x += h * speed
        t += h
        rows.append((t, x, zs - zs0, zu - zu0, fz, fx, my, out["tyre.deflection"],
                     out["tyre.slip_ratio"], spin))
    wall = time.perf_counter() - wall
    inst.free()
    return rows, wall


def fmu_start_radius(fmu):
    import xml.etree.ElementTree as ET
    root = ET.parse(os.path.join(fmu.folder, "modelDescription.xml")).getroot()
    for sv in root.find("ModelVariables"):
        if sv.get("name") == "wheel_state.pos.z":
            return float(sv[0].get("start"))
    raise RuntimeError("no wheel_state.pos.z")


def state(x, z, vx, vz, angle, spin):
    q = quaternion_about_y(angle)
    return {"wheel_state.pos.x": x, "wheel_state.pos.y": 0.0, "wheel_state.pos.z": z,
            "wheel_state.rot.e0": q[0], "wheel_state.rot.e1": q[1],
            "wheel_state.rot.e2": q[2], "wheel_state.rot.e3": q[3],
            "wheel_state.lin_vel.x": vx, "wheel_state.lin_vel.y": 0.0,
            "wheel_state.lin_vel.z": vz, "wheel_state.ang_vel.x": 0.0,
            "wheel_state.ang_vel.y": spin, "wheel_state.ang_vel.z": 0.0,
            "terrain_height": 0.0, "terrain_normal.x": 0.0, "terrain_normal.y": 0.0,
            "terrain_normal.z": 1.0, "terrain_mu": 0.8}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("fmu")
    ap.add_argument("--speed-kmh", type=float, default=30.0)
    ap.add_argument("--duration-s", type=float, default=2.0)
    ap.add_argument("--step-ms", type=float, default=1.0)
    ap.add_argument("--cleat-mm", default="10,20", help="height,length of the cleat [mm]")
    ap.add_argument("--cleat-at-s", type=float, default=0.8, help="when the wheel reaches it")
    ap.add_argument("--csv", default="quarter_car.csv")
    ap.add_argument("--plot", default="")
    a = ap.parse_args()
    fmu = Fmu(a.fmu)
    speed = a.speed_kmh / 3.6
    height, length = (float(v) * 1e-3 for v in a.cleat_mm.split(","))
    cleat_x = speed * a.cleat_at_s
    profile = os.path.join(fmu.folder, "cleat.csv")
    write_cleat(profile, cleat_x, height, length)
    rows, wall = run(fmu, speed, a.duration_s, a.step_ms * 1e-3, profile)
    with open(a.csv, "w") as f:
        f.write("t_s,x_m,body_dz_m,wheel_dz_m,force_z_N,force_x_N,moment_y_Nm,deflection_m,"
                "slip_ratio,spin_rad_s\n")
        for r in rows:
            f.write(",".join(f"{v:.9g}" for v in r) + "\n")
    weight = (300.0 + 35.0) * G
    before = [r for r in rows if a.cleat_at_s - 0.1 <= r[0] < a.cleat_at_s - 0.02]
    last = rows[-1]
    print(f"{len(rows)} steps of {a.step_ms} ms, {a.duration_s} s simulated in {wall:.2f} s "
          f"(real-time factor {a.duration_s / wall:.1f})")
    print(f"static load {weight:.0f} N; before the cleat Fz {sum(r[4] for r in before) / len(before):.0f} N, "
          f"peak {max(r[4] for r in rows if r[0] > a.cleat_at_s - 0.05):.0f} N, "
          f"at the end {last[4]:.0f} N; wheel centre from its static height: before "
          f"{before[-1][3] * 1e3:+.3f} mm, at the end {last[3] * 1e3:+.3f} mm")
    if a.plot and shutil.which("gnuplot"):
        term = "pngcairo size 1000,700" if a.plot.endswith(".png") else "svg size 1000,700"
        script = f"""set terminal {term}
set output '{a.plot}'
set datafile separator ','
set multiplot layout 2,1 title 'Quarter-car over a {height * 1e3:.0f} mm cleat at {a.speed_kmh:.0f} km/h (ModalTyre FMU, {a.step_ms} ms steps)'
set ylabel 'tyre load [N]'
set grid
plot '{a.csv}' every ::1 using 1:5 with lines title 'Fz', '' every ::1 using 1:6 with lines title 'Fx'
set xlabel 't [s]'
set ylabel 'from static equilibrium [mm]'
plot '{a.csv}' every ::1 using 1:($3*1e3) with lines title 'body', '' every ::1 using 1:($4*1e3) with lines title 'wheel centre'
unset multiplot
"""
        subprocess.run(["gnuplot"], input=script.encode(), check=True)
        print(f"wrote {a.plot}")


if __name__ == "__main__":
    main()
