"""seflex.run against `seflex run` on the same scene: the histories to the printed digits."""
import csv
import shutil

import numpy as np
import pytest

import seflex
from conftest import SOURCE, seflex_command

SCENES = SOURCE / "examples" / "scenes"


@pytest.fixture(scope="module")
def pendulum(tmp_path_factory):
    """examples/scenes/double_pendulum.yaml with its link.se reduced from Python (the scene's header command)."""
    tmp = tmp_path_factory.mktemp("run")
    shutil.copy(SCENES / "double_pendulum.yaml", tmp)
    shutil.copy(SCENES / "link.bdf", tmp)
    seflex.reduce(seflex.read_model(tmp / "link.bdf"), interface=[1, 5], frame=3, modes=3).save(tmp / "link.se")
    return tmp / "double_pendulum.yaml"


def test_histories_equal_the_commands_csv(pendulum, tmp_path):
    p = seflex_command("run", pendulum, "-o", tmp_path / "cli", "--t-end", 0.1, "--no-animation")
    assert p.returncode == 0, p.stderr
    r = seflex.run(pendulum, output=tmp_path / "py", t_end=0.1)
    with open(tmp_path / "cli" / "history.csv") as f:
        rows = list(csv.reader(f))
    assert r.columns == rows[0]
    assert list(r.history) == rows[0]
    cli = np.array([[float(x) for x in row] for row in rows[1:]])
    # The command writes the shortest decimal that reads back as the same double: equal to the bit.
    for j, name in enumerate(rows[0]):
        np.testing.assert_array_equal(r.history[name], cli[:, j], err_msg=name)
    assert r.history["t"][-1] == pytest.approx(0.1, abs=1e-12)
    assert r.summary["status"] == "ok" and r.summary["steps"] > 0
    assert (tmp_path / "py" / "history.csv").read_text() == (tmp_path / "cli" / "history.csv").read_text()


def test_progress_is_called_with_the_gil_and_can_stop_the_run(pendulum, tmp_path):
    calls = []
    r = seflex.run(pendulum, t_end=0.05, progress=lambda t, t_end: calls.append((t, t_end)), progress_interval=0.0)
    assert len(calls) == r.summary["steps"]  # interval 0: after every accepted step
    assert calls[-1][0] == pytest.approx(0.05) and calls[-1][1] == 0.05

    class Stop(Exception):
        pass

    def stop(t, t_end):
        raise Stop(t)

    with pytest.raises(Stop):
        seflex.run(pendulum, t_end=0.05, progress=stop, progress_interval=0.0)


def test_bad_scene_raises_the_commands_message(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("title: x\nbodies:\n  - name: a\n    superelement: missing.se\n")
    with pytest.raises(seflex.InputError) as e:
        seflex.run(bad)
    p = seflex_command("run", bad, "-o", tmp_path / "out")
    assert p.returncode == 3
    assert p.stderr.splitlines()[-1] == "error: " + str(e.value)
