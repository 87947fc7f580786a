"""ga_rs.rigid: the command's checks and messages, dict and file scenes alike, and the
exact free-body flow vectorised over time."""

import os
import shutil
import subprocess

import numpy as np
import pytest

from ga_rs import rigid

SCENE = {
    "body": {"moments": [1.0, 2.0, 2.5]},
    "initial": {"rotor": [1.0, 0.0, 0.0, 0.0], "omega": [0.1, 2.0, 0.05]},
    "run": {"t_end": 2.0, "samples": 11},
}
TEXT = """[body]
moments = [1.0, 2.0, 2.5]
[initial]
rotor = [1.0, 0.0, 0.0, 0.0]
omega = [0.1, 2.0, 0.05]
[run]
t_end = 2.0
samples = 11
"""


def test_a_dict_and_a_file_give_the_same_run(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(TEXT)
    a = rigid.simulate(SCENE, "rk4", dt=1e-3)
    for scene in (path, str(path)):
        b = rigid.simulate(scene, "rk4", dt=1e-3)
        for key in ("time", "rotor", "omega", "energy", "momentum"):
            assert np.array_equal(a[key], b[key]), key
    assert a["time"].shape == (11,) and a["rotor"].shape == (11, 4)
    assert a["omega"].shape == (11, 3) and a["energy"].shape == (11,)
    assert a["momentum"].shape == (11, 3)


def test_the_run_can_be_overridden(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(TEXT)
    for scene in (SCENE, path):
        out = rigid.simulate(scene, "exact", t_end=3.0, samples=7)
        assert out["time"].shape == (7,) and out["time"][-1] == 3.0


def test_the_exact_method_matches_exact_free_body_and_keeps_the_invariants():
    out = rigid.simulate(SCENE, "exact")
    assert np.ptp(out["energy"]) < 1e-12 * out["energy"][0]
    size = np.linalg.norm(out["momentum"], axis=-1)
    assert np.ptp(size) < 1e-12 * size[0]
    moments = np.array(SCENE["body"]["moments"])
    m0 = moments * SCENE["initial"]["omega"]
    rotor, m = rigid.exact_free_body(moments, m0, [1, 0, 0, 0], out["time"])
    np.testing.assert_allclose(rotor, out["rotor"], atol=1e-12)
    np.testing.assert_allclose(m / moments, out["omega"], atol=1e-12)


def test_exact_free_body_is_vectorised_over_any_shape_of_times():
    t = np.linspace(-1, 5, 6).reshape(2, 3)
    rotor, m = rigid.exact_free_body([1, 2, 3], [0.01, 2, 0], [1, 0, 0, 0], t)
    assert rotor.shape == (2, 3, 4) and m.shape == (2, 3, 3)
    for index in np.ndindex(t.shape):
        r1, m1 = rigid.exact_free_body([1, 2, 3], [0.01, 2, 0], [1, 0, 0, 0], t[index])
        assert np.array_equal(r1, rotor[index]) and np.array_equal(m1, m[index])
    assert np.isnan(rigid.exact_free_body([1, -2, 3], [0, 1, 0], [1, 0, 0, 0], [1.0])[0]).all()
    with pytest.raises(ValueError, match="moments"):
        rigid.exact_free_body([1, 2], [0, 1, 0], [1, 0, 0, 0], 1.0)


@pytest.mark.parametrize("kwargs, message", [
    (dict(method="rk4", dt=-1.0), "--dt: the step size must be positive and finite, got -1"),
    (dict(method="lie-rk4", tol=1e-9), "--tol: method lie-rk4 takes a fixed step: give --dt, not --tol"),
    (dict(method="dopri", dt=0.1), "--dt: method dopri is adaptive: give --tol, not --dt"),
    (dict(method="rk4", dt=0.1, tol=1e-9), "--dt: --dt and --tol are mutually exclusive: give one"),
    (dict(method="dopri", tol=1e-20), "--tol: the tolerance must be between 1e-14 and 1, got 1e-20"),
    (dict(method="rk4", dt=1e-9), "--max-"),
    (dict(method="no-such"), "method: unknown method 'no-such'"),
])
def test_errors_are_the_commands_lines(kwargs, message):
    with pytest.raises(ValueError) as e:
        rigid.simulate(SCENE, **kwargs)
    assert message in str(e.value)
    assert "\n" not in str(e.value)


def test_scene_errors_name_the_field(tmp_path):
    bad = {**SCENE, "body": {"moments": [1.0, -1.0, 2.0]}}
    with pytest.raises(ValueError, match="body.moments"):
        rigid.simulate(bad, "exact")
    with pytest.raises(ValueError, match="run.samples"):
        rigid.simulate(SCENE, "exact", samples=1)
    with pytest.raises(ValueError, match="SCENE"):
        rigid.simulate(tmp_path / "missing.toml", "exact")
    with pytest.raises(TypeError, match="dict or a path"):
        rigid.simulate(42, "exact")
    # A file whose run is overridden is read twice; its errors still name it.
    path = tmp_path / "scene.toml"
    path.write_text(TEXT)
    with pytest.raises(ValueError, match="scene.toml.*run.samples"):
        rigid.simulate(path, "exact", samples=1)
    with pytest.raises(TypeError, match="body.moments"):
        rigid.simulate({**SCENE, "body": {"moments": {1, 2, 3}}}, "exact")


def test_inertia_of_a_solid():
    box = {**SCENE, "body": {"shape": {"kind": "box", "mass": 2.0, "size": [1.0, 2.0, 3.0]}}}
    props = rigid.inertia(box)
    assert props["mass"] == 2.0
    np.testing.assert_allclose(np.sort(props["moments"]),
                               np.sort(2.0 / 12 * np.array([4 + 9, 1 + 9, 1 + 4])), rtol=1e-14)
    assert rigid.inertia(SCENE)["mass"] is None


def _command():
    """The `ga-rigid` binary to compare messages with: $GA_RIGID_BIN or one on PATH."""
    return os.environ.get("GA_RIGID_BIN") or shutil.which("ga-rigid")


@pytest.mark.parametrize("out, message", [
    ("file", "--out: file exists and is not a directory"),
    ("missing/out", "--out: the directory missing does not exist (only the last part of --out is created)"),
    ("out", "--out: out/index.html is a directory, not a regular file"),
    ("-x", "--out: -x exists and is not a directory"),  # a name like a flag is the value
])
def test_report_errors_are_value_errors_with_the_commands_line(tmp_path, monkeypatch, capfd,
                                                               out, message):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "file").write_text("x")
    (tmp_path / "-x").write_text("x")
    (tmp_path / "out" / "index.html").mkdir(parents=True)
    before = sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*"))
    with pytest.raises(ValueError) as e:
        rigid.report(out, quick=True)
    assert str(e.value) == message
    assert capfd.readouterr().err == ""  # the line is in the exception, not printed
    assert sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*")) == before
    command = _command()
    if command:  # the command itself: the same line, status 2
        run = subprocess.run([command, "report", f"--out={out}", "--quick"],
                             capture_output=True, text=True, timeout=60)
        assert (run.returncode, run.stderr) == (2, message + "\n")
