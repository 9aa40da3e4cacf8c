"""seflex.reduce, Superelement.save and seflex.load_superelement against `seflex reduce`."""
import gc
import sys

import numpy as np
import pytest

import seflex
from conftest import SOURCE, seflex_command

YOKE = SOURCE / "meshes" / "yoke.bdf"


@pytest.fixture(scope="module")
def yoke_pair(tmp_path_factory):
    """The yoke reduced by the command and by Python with the same options (3 interface grids, 5 modes)."""
    tmp = tmp_path_factory.mktemp("se")
    p = seflex_command("reduce", YOKE, "--interface", "1,3,4", "--modes", 5, "-o", tmp / "cmd.se")
    assert p.returncode == 0, p.stderr
    se = seflex.reduce(seflex.read_model(YOKE), interface=[1, 3, 4], modes=5)
    return tmp, se, seflex.load_superelement(tmp / "cmd.se")


def test_reduce_writes_the_commands_file_bit_for_bit(yoke_pair):
    tmp, se, cmd = yoke_pair
    assert se.size == 6 * 3 + 5 and se.num_modes == 5
    np.testing.assert_array_equal(se.interface, [1, 3, 4])
    # The matrices are the command's, bit for bit.
    for name in ("K", "M", "Phi_f", "mode_frequencies", "recovery"):
        np.testing.assert_array_equal(getattr(se, name), getattr(cmd, name), err_msg=name)
    assert se.source_file == cmd.source_file == str(YOKE)
    assert se.source_hash == cmd.source_hash
    # The whole file too, once `created` (the time of each reduction) is the same.
    se.created = cmd.created
    se.save(tmp / "py.se")
    assert (tmp / "py.se").read_bytes() == (tmp / "cmd.se").read_bytes()


def test_save_refuses_to_overwrite_and_load_round_trips(yoke_pair):
    tmp, se, _ = yoke_pair
    se.save(tmp / "again.se")
    with pytest.raises(seflex.InputError) as e:
        se.save(tmp / "again.se")
    assert str(e.value) == f"{tmp / 'again.se'}: exists already; refusing to overwrite it (use --force to replace it)"
    se.save(tmp / "again.se", overwrite=True)
    back = seflex.load_superelement(tmp / "again.se")
    np.testing.assert_array_equal(back.K, se.K)
    np.testing.assert_array_equal(back.M, se.M)


def test_matrices_are_read_only_views_owned_by_the_superelement(yoke_pair):
    _, se, _ = yoke_pair
    K = se.K
    assert not K.flags.writeable and not K.flags.owndata
    assert K.__array_interface__["data"][0] == se.K.__array_interface__["data"][0]  # no copy per access
    # The view keeps its superelement alive: drop every other reference, the numbers stay.
    other = seflex.load_superelement(yoke_pair[0] / "cmd.se")
    K2 = other.K
    expected = np.array(K2)
    refs = sys.getrefcount(other)
    del other
    gc.collect()
    np.testing.assert_array_equal(K2, expected)
    assert refs >= 3  # the local name, getrefcount's argument and K2's base


def test_no_reference_leak_over_1000_calls(yoke_pair):
    _, se, _ = yoke_pair
    before = sys.getrefcount(se)
    for _ in range(1000):
        se.K.sum()
        se.interface
    assert sys.getrefcount(se) == before


def test_bad_interface_raises_the_commands_message(yoke_pair, tmp_path):
    model = seflex.read_model(YOKE)
    with pytest.raises(seflex.InputError) as e:
        seflex.reduce(model, interface=[1, 999], modes=2)
    p = seflex_command("reduce", YOKE, "--interface", "1,999", "--modes", 2, "-o", tmp_path / "x.se")
    assert p.returncode == 3
    assert p.stderr.splitlines()[-1] == "error: " + str(e.value)
    with pytest.raises(seflex.InputError, match="give either modes or fmax"):
        seflex.reduce(model, interface=[1, 3, 4], modes=2, fmax=100.0)


def test_fmax_keeps_every_mode_up_to_the_limit():
    se = seflex.reduce(seflex.read_model(YOKE), interface=[1, 5], fmax=200.0, mesh=False)
    assert se.num_modes == len(se.mode_frequencies)
    assert (se.mode_frequencies <= 200.0).all()
    assert se.recovery.size == 0 and len(se.fe_node_ids) == 0


def rss_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096


def test_no_memory_growth_over_1000_loads(yoke_pair):
    tmp, _, _ = yoke_pair
    path = tmp / "cmd.se"
    size = path.stat().st_size
    for _ in range(50):  # warm up the allocator
        seflex.load_superelement(path).K.sum()
    before = rss_bytes()
    for _ in range(1000):
        se = seflex.load_superelement(path)
        se.K.sum()
        del se
    # A leak of each superelement would grow the process by 1000 file sizes (414 kB each for the yoke);
    # measured growth: 0 bytes. The bound is a tenth of the leak.
    assert rss_bytes() - before < 100 * size
