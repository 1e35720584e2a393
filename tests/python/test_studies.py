"""validate, sweep, transient, effects and discover equal their commands' output: --json to
1e-12 (the same JSON-building code), the sweep's columns and the transient series cell for
cell against the CSV the command writes."""
import csv
import math

import numpy as np

from conftest import assert_same, cli_json, run_cli, src

SF350_2D = src("configs", "sf350_2d_table3.yaml")
TABLE3 = src("configs", "data", "sf350_footprint_table3.csv")


def cell(v):
    """A number as the CSVs write it (%.10g)."""
    return "%.10g" % v


def test_validate_equals_the_cli(modaltyre):
    for config in (SF350_2D, src("configs", "sf350.yaml")):
        got = modaltyre.validate(config, TABLE3)
        cli = cli_json("validate", config, TABLE3)
        assert cli["conditions"] == {}  # conditions stated with --set: none here
        assert_same(got, cli)
        assert got["calibration"]["rows"] == [1, 6]


def test_validate_with_conditions_equals_the_cli_set(modaltyre):
    sets = {"contact.unit_length_mm": 2, "validation.calibrate": [],
            "effects.tread_relaxation.enabled": True}
    args = ["validate", SF350_2D, TABLE3, "--set", "contact.unit_length_mm=2", "--set",
            "validation.calibrate=[]", "--set", "effects.tread_relaxation.enabled=true"]
    got = modaltyre.validate(SF350_2D, TABLE3, sets, conditions={"hold_s": 60})
    cli = cli_json(*args, "--set", "hold_s=60")
    assert got["conditions"] == {"hold_s": 60.0}
    assert_same(got, cli)
    base = modaltyre.validate(SF350_2D, TABLE3, sets)
    # Held 60 s, every row's predicted sinking is deeper.
    for h, b in zip(got["rows"], base["rows"]):
        assert h["predicted"]["sinking_mm"] > b["predicted"]["sinking_mm"]


def test_transient_with_conditions_equals_the_cli_set(modaltyre):
    sets = {"contact.unit_length_mm": 4}
    cli = cli_json("transient", SF350_2D, "--scenario", "load-hold", "--set",
                   "contact.unit_length_mm=4", "--set", "load_N=3000", "--set", "hold_s=0.5")
    got = modaltyre.transient(SF350_2D, "load-hold", sets,
                              conditions={"load_N": 3000, "hold_s": 0.5})
    got.pop("series")
    for timing in ("wall_s", "real_time_factor"):
        got.pop(timing), cli.pop(timing)
    assert got["conditions"] == {"load_N": 3000.0, "hold_s": 0.5}
    assert_same(got, cli)


def test_effects_equal_the_cli(modaltyre):
    got = modaltyre.effects()
    assert_same(got, cli_json("effects")["effects"])
    assert "belt_flattening" in [e["name"] for e in got]


def test_sweep_columns_equal_the_cli_csv(modaltyre, tmp_path):
    sweep = src("configs", "sweeps", "modulus_load_grid.yaml")
    out = tmp_path / "grid.csv"
    run_cli("sweep", sweep, "--set", "contact.unit_length_mm=1", "--output", str(out))
    rows = list(csv.DictReader(open(out)))
    got = modaltyre.sweep(sweep, threads=2, overrides={"contact.unit_length_mm": 1})
    assert list(got) == list(rows[0])
    for name, column in got.items():
        assert len(column) == len(rows)
        if column.dtype == np.float64:
            assert [cell(v) for v in column] == [r[name] for r in rows], name
        else:
            assert list(column) == [r[name] for r in rows], name
    serial = modaltyre.sweep(sweep, threads=1, overrides={"contact.unit_length_mm": 1})
    np.testing.assert_array_equal(serial["sinking_mm"], got["sinking_mm"])
    assert (got["status"] == "ok").all()


def test_transient_equals_the_cli(modaltyre, tmp_path):
    sets = {"contact.unit_length_mm": 4, "transient.load_hold.hold_s": 0.5}
    args = ["transient", SF350_2D, "--scenario", "load-hold"]
    for k, v in sets.items():
        args += ["--set", f"{k}={v}"]
    series_csv = tmp_path / "hold.csv"
    cli = cli_json(*args, "--csv", str(series_csv))
    got = modaltyre.transient(SF350_2D, "load-hold", sets)
    series = got.pop("series")
    for timing in ("wall_s", "real_time_factor"):  # the machine's, not the model's
        assert got.pop(timing) > 0 and cli.pop(timing) > 0
    assert cli["conditions"] == {}  # conditions stated with --set: none here
    assert_same(got, cli)
    rows = list(csv.DictReader(open(series_csv)))
    assert list(series) == list(rows[0])
    for name, column in series.items():
        assert column.flags["OWNDATA"] and len(column) == got["samples"]
        assert [cell(v) for v in column] == [r[name] for r in rows], name
    # After the ramp the contact carries the load, up to the hub's lightly damped bounce
    # (0.1 % after half a second of hold).
    assert math.isclose(series["load_N"][-1], 4000, rel_tol=1e-2)


def test_transient_runs_the_3d_patch_like_the_cli(modaltyre, tmp_path):
    # The default config's footprint_3d: the 3D patch, as `modaltyre transient` (coarse mesh).
    config = src("configs", "sf350.yaml")
    sets = {"contact.unit_length_mm": 2, "footprint_3d.lateral_cell_mm": 7.5,
            "transient.load_hold.hold_s": 0.2}
    args = ["transient", config, "--scenario", "load-hold"]
    for k, v in sets.items():
        args += ["--set", f"{k}={v}"]
    series_csv = tmp_path / "hold3d.csv"
    cli = cli_json(*args, "--csv", str(series_csv))
    got = modaltyre.transient(config, "load-hold", sets)
    series = got.pop("series")
    for timing in ("wall_s", "real_time_factor"):
        assert got.pop(timing) > 0 and cli.pop(timing) > 0
    assert got["patch"] == "3d"
    assert_same(got, cli)
    rows = list(csv.DictReader(open(series_csv)))
    assert list(series) == list(rows[0])
    assert "width_mm" in series and "contact_area_mm2" in series
    for name, column in series.items():
        assert [cell(v) for v in column] == [r[name] for r in rows], name


def test_discover_equals_the_cli(modaltyre):
    got = modaltyre.discover(SF350_2D, TABLE3, threads=1)
    assert_same(got, cli_json("discover", SF350_2D, TABLE3, "--threads", "1"))
    assert got["rows"] == 6
