"""modaltyre.init against `modaltyre init --json`: the same decisions for the SF-350's Table 2
frequencies, a written config that the footprint runs as the CLI's does, refusals by name."""
import pytest

from conftest import assert_same, cli_json, src

# Seed 001's Table 2 (orders: fit-modes' on the bundled shapes, r the rotation mode), as
# docs/validation.md, "A tyre that was never calibrated".
FREQ = [112.839, 113.661, 125.58, 133.58, 135.528, 155.739, 156.657, 180.092, 182.454, 207.977,
        210.787, 238.917, 241.519, 250.064, 274.594, 312.03]
ORDERS = [1, 1, 0, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, "r", 7, 8]


def cli_args(extra=()):
    return ["init", "--size", "195/60R14", "--test-pressure-kPa", "230",
            "--frequencies", ",".join(str(f) for f in FREQ),
            "--orders", ",".join(str(k) for k in ORDERS), "--wheel-mass-kg", "7", *extra]


def test_init_equals_the_cli(modaltyre):
    got = modaltyre.init("195/60R14", test_pressure_kPa=230, frequencies_hz=FREQ,
                         orders=ORDERS, wheel_mass_kg=7)
    assert_same(got, cli_json(*cli_args()))
    assert got["orders"][13] == -1 and got["mass_source"] == "tension"
    # The mass comes from the tension, so the implied tension is the membrane's p b R.
    assert got["implied_tension_N"] == pytest.approx(got["membrane_tension_N"], rel=1e-6)
    assert "tyre:" in got["config"] and got["decisions"]


def test_written_config_runs_the_footprint_as_the_cli(modaltyre, tmp_path):
    out = tmp_path / "tyre.yaml"
    got = modaltyre.init("195/60R14", test_pressure_kPa=230, pressure_kPa=200,
                         frequencies_hz=FREQ, orders=ORDERS, wheel_mass_kg=7, output=out)
    assert got["output"] == str(out) and "config" not in got
    report = modaltyre.Tyre(out).report([4000])
    assert_same(report, cli_json("footprint", str(out), "--load", "4000"))
    # The footprint says where its modal masses came from: init's tension, at both pressures.
    carcass = report["model"]["carcass"]
    assert carcass["normalisation"] == "ring" and carcass["mass_source"] == "tension"
    assert carcass["mass_per_length_kg_m"] == pytest.approx(got["mass_per_length_kg_m"])
    assert (carcass["test_pressure_kPa"], carcass["operating_pressure_kPa"]) == (230, 200)
    # The operating pressure acts: at 200 kPa the tyre sinks more than at the test's 230 kPa.
    at230 = tmp_path / "tyre230.yaml"
    modaltyre.init("195/60R14", test_pressure_kPa=230, frequencies_hz=FREQ, orders=ORDERS,
                   wheel_mass_kg=7, output=at230)
    assert (modaltyre.Tyre(out).footprint(4000).sinking_mm
            > modaltyre.Tyre(at230).footprint(4000).sinking_mm)


def test_init_refuses_bad_input(modaltyre, tmp_path):
    with pytest.raises(modaltyre.InputError, match="orders"):
        modaltyre.init("195/60R14", test_pressure_kPa=230, frequencies_hz=FREQ, orders="1,2")
    with pytest.raises(modaltyre.InputError, match="not an order"):
        modaltyre.init("195/60R14", test_pressure_kPa=230, frequencies_hz=[100, 120],
                       orders=[1, "x"])
    with pytest.raises(modaltyre.InputError, match="boundary"):
        modaltyre.init("195/60R14", test_pressure_kPa=230, frequencies_hz=FREQ, boundary="held")
    hammer = tmp_path / "h.csv"
    hammer.write_bytes(open(src("configs", "data", "sf350_hammer_12pt.csv"), "rb").read())
    before = hammer.read_bytes()
    with pytest.raises(modaltyre.InputError, match="over an input"):
        modaltyre.init("195/60R14", test_pressure_kPa=230, hammer_csv=hammer, output=hammer)
    assert hammer.read_bytes() == before
