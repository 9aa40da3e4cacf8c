"""seflex.read_model, seflex.modes, seflex.static against published results and the command line."""
import csv
import math

import numpy as np
import pytest

import seflex
from conftest import SOURCE, VALIDATION, seflex_command

CANTILEVER = VALIDATION / "mystran_cbar_cantilever_and_freefree_modes" / "BAR-CC-GIV.DAT"


def test_modes_match_mystran_and_the_command(tmp_path):
    model = seflex.read_model(CANTILEVER)
    r = seflex.modes(model, 4)
    # MYSTRAN 12.0 (tests/data/validation/README.md): 10.68719 / 62.81653 / 166.3460 / 289.9396 Hz,
    # printed to 7 digits (rounding up to 5e-7 relative); measured agreement 2.9e-7.
    np.testing.assert_allclose(r.frequencies, [10.68719, 62.81653, 166.3460, 289.9396], rtol=1e-6)
    np.testing.assert_array_equal(r.radians, np.sqrt(np.abs(r.eigenvalues)))
    # The command on the same deck writes the same numbers (shortest round-trip decimal: bit for bit).
    out = tmp_path / "f.csv"
    p = seflex_command("modes", CANTILEVER, "--count", 4, "--csv", out)
    assert p.returncode == 0, p.stderr
    with open(out) as f:
        rows = list(csv.DictReader(f))
    assert [float(x["eigenvalue"]) for x in rows] == list(r.eigenvalues)
    assert [float(x["frequency_hz"]) for x in rows] == list(r.frequencies)


def test_mode_shapes_are_keyed_by_grid_and_mass_normalised():
    model = seflex.read_model(CANTILEVER)
    r = seflex.modes(model, 2)
    assert r.shapes.shape == (2, len(model.grid_ids), 6)
    np.testing.assert_array_equal(r.grids, model.grid_ids)
    # The deck asks for NORM=MAX: the largest component of each shape is 1, and the generalized
    # masses are MYSTRAN's 6.800571E-04 and 9.499997E-04 (7 printed digits; measured 4.5e-8 relative).
    # Generalized stiffness = eigenvalue x generalized mass: measured 2.8e-14 relative.
    np.testing.assert_allclose(np.abs(r.shapes).max(axis=(1, 2)), 1.0, rtol=1e-12)
    np.testing.assert_allclose(r.generalized_mass, [6.800571e-04, 9.499997e-04], rtol=1e-6)
    np.testing.assert_allclose(r.generalized_stiffness, r.eigenvalues * r.generalized_mass, rtol=1e-12)
    # The shapes are a read-only view owned by the result (no copy per access).
    a, b = r.shapes, r.shapes
    assert not a.flags.writeable
    assert a.__array_interface__["data"][0] == b.__array_interface__["data"][0]


def test_cantilever_tip_deflection_is_euler_bernoulli(tmp_path):
    # A steel cantilever of 4 CBARs, tip load P along z: w = P L^3 / (3 E I), theta = P L^2 / (2 E I)
    # (the cubic beam element is exact for nodal loads). Measured agreement: 5e-14 relative.
    L, E, I, P = 2.0, 2.0e11, 8.0e-8, 150.0
    grids = "".join(f"GRID,{k + 1},,{k * L / 4},0.,0.\n" for k in range(5))
    bars = "".join(f"CBAR,{k + 1},1,{k + 1},{k + 2},0.,1.,0.\n" for k in range(4))
    deck = tmp_path / "cantilever.bdf"
    deck.write_text("SOL 101\nCEND\nSUBCASE 1\n  SPC = 1\n  LOAD = 2\nBEGIN BULK\n" + grids + bars +
                    f"PBAR,1,1,1.0E-3,{I},{I},1.0E-7\nMAT1,1,{E},,0.3,7800.\n"
                    f"SPC1,1,123456,1\nFORCE,2,5,,{P},0.,0.,1.\nENDDATA\n")
    model = seflex.read_model(deck)
    s = seflex.static(model)
    assert s.subcase == 1
    tip = s.displacements[5]
    assert tip[2] == pytest.approx(P * L**3 / (3 * E * I), rel=1e-12)
    assert tip[4] == pytest.approx(-P * L**2 / (2 * E * I), rel=1e-12)
    # The reaction at the root balances the load (equilibrium).
    assert s.spc_forces[1][2] == pytest.approx(-P, rel=1e-12)
    assert s.loads.values.shape == (5, 6)
    with pytest.raises(KeyError):
        s.displacements[99]


def test_model_counts_and_mass():
    model = seflex.read_model(SOURCE / "meshes" / "yoke.bdf")
    assert model.counts["grids"] == len(model.grid_ids) > 0
    assert model.counts["elements"] == sum(model.element_counts.values()) > 0
    assert model.element_counts["CBAR"] > 0
    mp = model.mass_properties()
    assert mp["mass"] > 0
    assert mp["I_cg"].shape == (3, 3)
    np.testing.assert_allclose(mp["I_cg"], mp["I_cg"].T, rtol=0, atol=1e-12 * np.abs(mp["I_cg"]).max())
    assert math.isfinite(mp["cg"].sum())


def error_of_command(*args):
    p = seflex_command(*args)
    assert p.returncode != 0
    lines = [x for x in p.stderr.splitlines() if x.startswith("error: ")]
    assert len(lines) == 1, p.stderr
    return lines[0][len("error: "):]


def test_bad_card_raises_input_error_with_the_commands_message(tmp_path):
    deck = tmp_path / "bad.bdf"
    deck.write_text("SOL 103\nCEND\nBEGIN BULK\nGRID,1,,0.,0.,0.\nGRID,2,,abc,0.,0.\nENDDATA\n")
    with pytest.raises(seflex.InputError) as e:
        seflex.read_model(deck)
    assert isinstance(e.value, ValueError)
    assert str(e.value) == error_of_command("modes", deck, "--count", 1)
    assert str(e.value).startswith(f"{deck}:5: ")


def test_missing_file_raises_input_error(tmp_path):
    missing = tmp_path / "none.bdf"
    with pytest.raises(seflex.InputError) as e:
        seflex.read_model(missing)
    assert str(e.value) == error_of_command("modes", missing, "--count", 1)
