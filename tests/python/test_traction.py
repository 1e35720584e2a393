"""modaltyre.traction equals `modaltyre traction --json` (the same library call and JSON
builder, report/traction_json.h), its columns the cases' numbers; the soil's physics as the
command's (drawbar pull rises with slip); bad arguments are InputErrors naming them; the
transient onto a soil through overrides carries the soil's series."""
import numpy as np
import pytest

from conftest import assert_same, cli_json, src

SF350_2D = src("configs", "sf350_2d_table3.yaml")
LETE = src("configs", "soils", "lete_sand.yaml")
COARSE = {"contact.unit_length_mm": 2}


def cli_args(loads, slips, extra=()):
    args = ["traction", SF350_2D, "--ground", LETE, "--set", "contact.unit_length_mm=2"]
    args += ["--load", *[str(x) for x in loads], "--slip", *[str(s) for s in slips], *extra]
    return args


def test_traction_equals_the_cli(modaltyre):
    slips = [0.05, 0.2, 0.4]
    got = modaltyre.traction(SF350_2D, [3000], slips, ground=LETE, overrides=COARSE)
    cols = got.pop("columns")
    assert_same(got, cli_json(*cli_args([3000], slips)))
    assert list(cols["slip"]) == slips
    dp = cols["drawbar_pull_N"]
    assert isinstance(dp, np.ndarray) and dp.shape == (3,)
    assert np.all(np.diff(dp) > 0)  # drawbar pull rises with slip (issue 37)
    assert np.all(cols["rut_depth_mm"] <= cols["soil_sinkage_mm"] + 1e-9)


def test_traction_returns_the_terramechanics_fields_as_the_cli(modaltyre):
    # Issue 48: the rolling radius, the resistance's parts, the efficiency, validity and the
    # curve's towed and self-propelled points, for both slip references and a stated speed.
    slips = [-0.1, 0.0, 0.1]
    sets = {**COARSE, "ground.bekker.bulldozing.enabled": True}
    for ref in ("rolling", "unloaded"):
        got = modaltyre.traction(SF350_2D, [3000], slips, ground=LETE, overrides=sets,
                                 slip_reference=ref, speed_km_h=10)
        cols = got.pop("columns")
        extra = ["--set", "ground.bekker.bulldozing.enabled=true", "--slip-reference", ref,
                 "--speed-km-h", "10"]
        assert_same(got, cli_json(*cli_args([3000], slips, extra)))
        assert got["slip_reference"] == ref and got["speed_km_h"] == 10
        for key in ("rolling_radius_mm", "tractive_efficiency", "compaction_resistance_N",
                    "flexing_resistance_N", "bulldozing_resistance_N"):
            assert cols[key].shape == (3,), key
        parts = (cols["compaction_resistance_N"] + cols["flexing_resistance_N"]
                 + cols["bulldozing_resistance_N"])
        assert np.allclose(cols["motion_resistance_N"], parts, rtol=1e-6)
        assert all("valid" in c for c in got["cases"])
        assert got["towed_point"]["slip"] < 0 and got["towed_point"]["drawbar_pull_N"] < 0
    with pytest.raises(modaltyre.InputError, match="slip_reference"):
        modaltyre.traction(SF350_2D, [3000], [0.1], ground=LETE, slip_reference="R0")
    with pytest.raises(modaltyre.InputError, match="speed_km_h"):
        modaltyre.traction(SF350_2D, [3000], [0.1], ground=LETE, speed_km_h=500)


def test_traction_passes_and_rigid_wheel_equal_the_cli(modaltyre):
    sets = dict(COARSE)
    sets["ground.bekker.unloading.k0"] = 0
    sets["ground.bekker.unloading.Au"] = 5e5
    got = modaltyre.traction(SF350_2D, [3000], [0.2], ground=LETE, overrides=sets, passes=2)
    got.pop("columns")
    extra = ["--passes", "2", "--set", "ground.bekker.unloading.k0=0", "--set",
             "ground.bekker.unloading.Au=5e5"]
    assert_same(got, cli_json(*cli_args([3000], [0.2], extra)))
    rigid = modaltyre.traction(SF350_2D, [3000], [0.2], ground=LETE,
                               overrides={**COARSE, "tyre.rigid": True})
    rigid.pop("columns")
    assert_same(rigid, cli_json(*cli_args([3000], [0.2], ["--set", "tyre.rigid=true"])))


def test_traction_refuses_bad_arguments_naming_them(modaltyre):
    with pytest.raises(modaltyre.InputError, match="slips"):
        modaltyre.traction(SF350_2D, [3000], [1.5], ground=LETE)
    with pytest.raises(modaltyre.InputError, match="passes"):
        modaltyre.traction(SF350_2D, [3000], [0.1], ground=LETE, passes=0)
    with pytest.raises(modaltyre.InputError, match="ground.model"):
        modaltyre.traction(SF350_2D, [3000], [0.1])  # the config's ground is the road


def test_transient_onto_a_soil_carries_its_series(modaltyre):
    sets = {"contact.unit_length_mm": 5, "contact.window_mm": 300,
            "transient.load_hold.hold_s": 0.2, "transient.load_hold.ramp_rate_N_s": 20000,
            "ground.model": "bekker", "ground.bekker.n": 0.79, "ground.bekker.k_c": 102,
            "ground.bekker.k_phi": 5301}
    got = modaltyre.transient(SF350_2D, "load-hold", sets)
    assert got["ground"] == "bekker"
    soil = got["series"]["soil_sinkage_mm"]
    assert soil[-1] == pytest.approx(got["final"]["soil_sinkage_mm"], rel=1e-6)
    assert soil[-1] > 1.0
