"""Tests of analysis/animate.py: geometry, frame selection, bad files, and rendering a small
trajectory to a GIF. A synthetic traj.h5 (written here with h5py in the documented layout) is
always used; the trajectory exported by `cambrian replay --export` is used too when the CTest
fixture names it in CAMBRIAN_TRAJECTORY."""

import os
import subprocess
import sys

import h5py
import numpy as np
import pytest
from PIL import Image

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import animate  # noqa: E402

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "animate.py")


def write_trajectory(path, frames=12, parts=2, format_name="cambrian-trajectory", held=0):
    """A small trajectory in the traj.h5 layout: two boxes sliding along x, and `held` objects
    (a catapult's projectile) beside them."""
    time = np.arange(frames) / 30.0
    with h5py.File(path, "w") as file:
        file.attrs["format"] = format_name
        file.attrs["format_version"] = np.int32(1)
        file.attrs["creature_id"] = np.uint64(7)
        file.attrs["source"] = "synthetic"
        file.attrs["fitness"] = 1.5
        file.attrs["status"] = "ok"
        file.attrs["task"] = "walk"
        file.attrs["time_step"] = 1 / 240
        file.attrs["frame_stride"] = np.uint64(8)
        file.attrs["frame_rate"] = 30.0
        file.attrs["genome_text"] = "cambrian-genome 1\n"
        file["time"] = time
        file["step"] = np.arange(frames, dtype=np.uint64) * 8
        file["phase"] = np.minimum(np.arange(frames) // 3, 3).astype(np.uint8)
        position = np.zeros((frames, parts, 3))
        position[:, :, 0] = time[:, None] + np.arange(parts)[None, :] * 0.4
        position[:, :, 2] = 0.1
        orientation = np.zeros((frames, parts, 4))
        orientation[:, :, 3] = 1.0
        file["position"] = position
        file["orientation"] = orientation
        file["center_of_mass"] = position.mean(axis=1)
        file["part/half_extents"] = np.full((parts, 3), 0.1)
        file["part/parent"] = np.arange(parts, dtype=np.int32) - 1
        if held:
            held_position = position[:, :held, :].copy()
            held_position[:, :, 1] += 0.3
            file["held/half_extents"] = np.full((held, 3), 0.1)
            file["held/part"] = np.zeros(held, dtype=np.int32)
            file["held/position"] = held_position
            file["held/orientation"] = orientation[:, :held, :]
            file["held/released"] = (np.arange(frames)[:, None] >= frames // 2).astype(np.uint8) * np.ones(
                (1, held), dtype=np.uint8
            )
    return path


def red_pixels(path):
    """Pixels of the first frame of a GIF near matplotlib's tab:red, the held objects' colour."""
    with Image.open(path) as image:
        pixels = np.asarray(image.convert("RGB"), dtype=int)
    return int(np.sum(np.abs(pixels - np.array([214, 39, 40])).sum(axis=2) < 60))


def test_held_objects_are_read_and_drawn(tmp_path):
    plain = animate.load_trajectory(write_trajectory(str(tmp_path / "plain.h5")))
    assert plain["held_half_extents"].shape == (0, 3)
    thrown = write_trajectory(str(tmp_path / "thrown.h5"), held=1)
    trajectory = animate.load_trajectory(thrown)
    assert trajectory["held_position"].shape == (12, 1, 3)
    assert list(trajectory["held_released"][:, 0]) == [0] * 6 + [1] * 6
    for name in ("plain", "thrown"):
        arguments = [str(tmp_path / f"{name}.h5"), "-o", str(tmp_path / f"{name}.gif")]
        assert animate.main(arguments + ["--size", "160x120", "--max-frames", "2"]) == 0
    assert red_pixels(str(tmp_path / "plain.gif")) == 0
    assert red_pixels(str(tmp_path / "thrown.gif")) > 20


def test_rotation_matrices_match_known_turns():
    # identity, and a quarter turn about z: x goes to y
    identity = animate.rotation_matrices(np.array([0.0, 0.0, 0.0, 1.0]))
    assert np.allclose(identity, np.eye(3))
    s = np.sqrt(0.5)
    quarter = animate.rotation_matrices(np.array([0.0, 0.0, s, s]))
    assert np.allclose(quarter @ np.array([1.0, 0.0, 0.0]), [0.0, 1.0, 0.0])


def test_box_faces_span_the_box():
    faces = animate.box_faces(np.array([[0.5, 0.25, 0.125]]), np.array([[1.0, 2.0, 3.0]]), np.array([[0, 0, 0, 1.0]]))
    assert faces.shape == (6, 4, 3)
    points = faces.reshape(-1, 3)
    assert np.allclose(points.min(axis=0), [0.5, 1.75, 2.875])
    assert np.allclose(points.max(axis=0), [1.5, 2.25, 3.125])


def test_select_frames_thins_evenly():
    assert list(animate.select_frames(10)) == list(range(10))
    assert list(animate.select_frames(10, stride=3)) == [0, 3, 6, 9]
    assert len(animate.select_frames(1000, max_frames=100)) <= 100
    assert animate.select_frames(1000, max_frames=100)[0] == 0
    assert len(animate.select_frames(0)) == 0


def test_foreign_and_missing_files_exit_4(tmp_path, capsys):
    missing = str(tmp_path / "missing.h5")
    assert animate.main([missing, "-o", str(tmp_path / "a.gif")]) == 4
    assert missing in capsys.readouterr().err
    foreign = write_trajectory(str(tmp_path / "foreign.h5"), format_name="cambrian-history")
    assert animate.main([foreign, "-o", str(tmp_path / "a.gif")]) == 4
    assert "not a cambrian trajectory" in capsys.readouterr().err
    text = tmp_path / "text.h5"
    text.write_text("not hdf5")
    assert animate.main([str(text), "-o", str(tmp_path / "a.gif")]) == 4


def test_unknown_suffix_exits_2(tmp_path):
    trajectory = write_trajectory(str(tmp_path / "t.h5"))
    assert animate.main([trajectory, "-o", str(tmp_path / "a.avi")]) == 2


def test_renders_a_gif_of_the_requested_size_and_frames(tmp_path):
    trajectory = write_trajectory(str(tmp_path / "t.h5"), frames=12)
    output = str(tmp_path / "t.gif")
    assert animate.main([trajectory, "-o", output, "--size", "160x120", "--max-frames", "4", "--fps", "10"]) == 0
    with Image.open(output) as image:
        assert image.size == (160, 120)
        assert image.n_frames == 4


def test_help_runs_headless():
    result = subprocess.run([sys.executable, SCRIPT, "--help"], capture_output=True, text=True, check=False)
    assert result.returncode == 0
    assert "--max-frames" in result.stdout


@pytest.mark.skipif(not os.environ.get("CAMBRIAN_TRAJECTORY"), reason="no exported trajectory (CTest fixture)")
def test_renders_an_exported_trajectory(tmp_path):
    path = os.environ["CAMBRIAN_TRAJECTORY"]
    trajectory = animate.load_trajectory(path)
    frames = len(trajectory["time"])
    assert frames > 1
    assert trajectory["position"].shape[1] == len(trajectory["half_extents"])
    assert set(np.unique(trajectory["phase"])) <= {0, 1, 2, 3}
    output = str(tmp_path / "exported.gif")
    result = subprocess.run(
        [sys.executable, SCRIPT, path, "-o", output, "--size", "200x150", "--max-frames", "6"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    with Image.open(output) as image:
        assert image.n_frames == len(animate.select_frames(frames, max_frames=6))
