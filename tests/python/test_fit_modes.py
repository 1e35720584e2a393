"""modaltyre.fit_modes equals `modaltyre fit-modes --json` on the bundled hammer data."""
from conftest import assert_same, cli_json, src

HAMMER = src("configs", "data", "sf350_hammer_12pt.csv")


def test_fit_modes_equals_the_cli(modaltyre):
    got = modaltyre.fit_modes(HAMMER)
    assert_same(got, cli_json("fit-modes", HAMMER))
    # README: orders 1,1,0,2,2,3,3,4,4,5,5 for modes 1-11, mode 14 the rigid rotation.
    assert [m["order"] for m in got["modes"][:11]] == [1, 1, 0, 2, 2, 3, 3, 4, 4, 5, 5]
    assert got["modes"][13]["kind"] == "rotation"
    assert [m["mode"] for m in got["modes"] if m["aliased"]] == [12, 13, 15, 16]
