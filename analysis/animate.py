#!/usr/bin/env python3
"""Render a cambrian trajectory (traj.h5, written by `cambrian replay --export` or
`cambrian simulate --export`) as an animation of its boxes: matplotlib 3D, headless (Agg),
a ground grid, the camera following the centre of mass, time and phase in the title.
The output suffix picks the format: .gif (Pillow) or .mp4 (ffmpeg, when it is on PATH).

    cambrian replay --history run/history.h5 --best --export best.h5
    python3 analysis/animate.py best.h5 -o best.gif --max-frames 150

Exit codes: 0 written, 2 bad command line (or .mp4 without ffmpeg), 4 unreadable or foreign
trajectory file, 5 the animation cannot be written.
"""

import argparse
import math
import os
import shutil
import sys

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import animation  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402

FORMAT_NAME = "cambrian-trajectory"
FORMAT_VERSION = 1
PHASE_NAMES = ("settle", "trial", "resettle", "measure")

# the six faces of a box as indices into its eight corners (corner bits: x, y, z sign)
BOX_FACES = np.array(
    [[0, 1, 3, 2], [4, 5, 7, 6], [0, 1, 5, 4], [2, 3, 7, 6], [0, 2, 6, 4], [1, 3, 7, 5]]
)
BOX_SIGNS = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float)


class TrajectoryError(Exception):
    """A trajectory file is missing, not HDF5, foreign, of a newer version or inconsistent."""


def _shape_names(file, name, count):
    """The shape name of each entry of a shape dataset (files of before have none: boxes)."""
    if name not in file:
        return ["box"] * count
    names = [n.decode() if isinstance(n, bytes) else str(n) for n in file[name].attrs["names"]]
    return [names[int(code)] for code in file[name][()]]


def load_trajectory(path):
    """Reads a traj.h5 into a dict of numpy arrays and attributes; TrajectoryError names the
    file and what is wrong."""
    if not os.path.isfile(path):
        raise TrajectoryError(f"{path}: no such trajectory file")
    try:
        with h5py.File(path, "r") as file:
            attributes = {key: file.attrs[key] for key in file.attrs}
            if attributes.get("format") != FORMAT_NAME:
                raise TrajectoryError(
                    f"{path}: not a cambrian trajectory (root attribute 'format' is "
                    f"{attributes.get('format')!r}, expected {FORMAT_NAME!r})"
                )
            version = int(attributes.get("format_version", 0))
            if version < 1 or version > FORMAT_VERSION:
                raise TrajectoryError(f"{path}: format_version {version} is not supported")
            data = {
                name: np.asarray(file[name][()])
                for name in ("time", "step", "phase", "center_of_mass", "position", "orientation")
            }
            data["half_extents"] = np.asarray(file["part/half_extents"][()])
            data["parent"] = np.asarray(file["part/parent"][()])
            data["shape"] = _shape_names(file, "part/shape", len(data["parent"]))
            # parts without a shape of their own (a springy organism's proxies) are not drawn
            parts = len(data["parent"])
            data["solid"] = (np.asarray(file["part/solid"][()], dtype=bool) if "part/solid" in file
                             else np.ones(parts, dtype=bool))
            # shapes the parts carry (a springy organism's tubes), posed in their part's frame
            carried = file["colliders"] if "colliders" in file else None
            data["colliders"] = None
            if carried is not None:
                data["colliders"] = {
                    "half_extents": np.asarray(carried["half_extents"][()], dtype=float),
                    "part": np.asarray(carried["part"][()], dtype=int),
                    "position": np.asarray(carried["position"][()], dtype=float),
                    "orientation": np.asarray(carried["orientation"][()], dtype=float),
                    "shape": _shape_names(file, "colliders/shape", len(carried["part"])),
                }
            # objects held at birth (a catapult's projectile): /held, absent when there are none
            held = file["held"] if "held" in file else None
            data["held_half_extents"] = np.asarray(held["half_extents"][()]) if held else np.zeros((0, 3))
            frames = len(data["time"])
            for name, width in (("position", 3), ("orientation", 4)):
                data["held_" + name] = (
                    np.asarray(held[name][()]) if held else np.zeros((frames, 0, width))
                )
            data["held_released"] = np.asarray(held["released"][()]) if held else np.zeros((frames, 0))
            data["held_shape"] = _shape_names(file, "held/shape", len(data["held_half_extents"]))
            # the light (absent in files of before) and the surroundings (plane, no fluid then)
            data["light"] = np.asarray(file["light/position"][()]) if "light" in file else None
            # a heightfield ground's terrain (hills): /ground
            data["terrain"] = None
            if "ground" in file and "heights" in file["ground"]:
                data["terrain"] = {
                    "heights": np.asarray(file["ground/heights"][()], dtype=float),
                    "spacing": float(file["ground"].attrs["spacing"]),
                }
    except OSError as error:
        raise TrajectoryError(f"{path}: not a readable HDF5 file ({error})") from error
    except KeyError as error:
        raise TrajectoryError(f"{path}: dataset missing ({error})") from error
    frames, parts = len(data["time"]), len(data["half_extents"])
    if data["position"].shape != (frames, parts, 3) or data["orientation"].shape != (frames, parts, 4):
        raise TrajectoryError(f"{path}: /position or /orientation does not match {frames} frames x {parts} parts")
    held = len(data["held_half_extents"])
    if data["held_position"].shape != (frames, held, 3) or data["held_orientation"].shape != (frames, held, 4):
        raise TrajectoryError(f"{path}: /held/position or /held/orientation does not match {frames} frames x {held} objects")
    if data["solid"].shape != (parts,):
        raise TrajectoryError(f"{path}: /part/solid does not match {parts} parts")
    carried = data["colliders"]
    if carried is not None:
        count = len(carried["part"])
        if carried["half_extents"].shape != (count, 3) or carried["position"].shape != (count, 3) \
                or carried["orientation"].shape != (count, 4):
            raise TrajectoryError(f"{path}: the /colliders datasets do not match {count} colliders")
        if count and (carried["part"].min() < 0 or carried["part"].max() >= parts):
            raise TrajectoryError(f"{path}: /colliders/part names a part outside 0..{parts - 1}")
    if data["light"] is not None and data["light"].shape != (frames, 3):
        raise TrajectoryError(f"{path}: /light/position does not match {frames} frames")
    data["attributes"] = {
        key: (value.decode() if isinstance(value, bytes) else value) for key, value in attributes.items()
    }
    data["ground"] = str(data["attributes"].get("ground", "plane"))
    data["viscosity"] = float(data["attributes"].get("viscosity", 0.0))
    terrain = data["terrain"]
    if (data["ground"] == "heightfield") != (terrain is not None):
        raise TrajectoryError(f"{path}: ground is {data['ground']!r} but /ground/heights is "
                              f"{'present' if terrain is not None else 'missing'}")
    if terrain is not None:
        heights = terrain["heights"]
        if heights.ndim != 2 or heights.shape[0] != heights.shape[1] or heights.shape[0] < 2 \
                or not terrain["spacing"] > 0:
            raise TrajectoryError(f"{path}: /ground/heights is not a square grid with a spacing > 0")
    data["path"] = path
    return data


def rotation_matrices(quaternions):
    """Rotation matrices (..., 3, 3) of unit quaternions (..., 4) stored as (x, y, z, w)."""
    x, y, z, w = (quaternions[..., i] for i in range(4))
    return np.stack(
        [
            np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)], -1),
            np.stack([2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)], -1),
            np.stack([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)], -1),
        ],
        -2,
    )


def quaternion_product(a, b):
    """a * b of quaternions (..., 4) stored as (x, y, z, w): b's turn, then a's."""
    ax, ay, az, aw = (a[..., i] for i in range(4))
    bx, by, bz, bw = (b[..., i] for i in range(4))
    return np.stack([aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw,
                     aw * bw - ax * bx - ay * by - az * bz], -1)


def collider_poses(colliders, positions, quaternions):
    """World positions (n, 3) and orientations (n, 4) of the shapes parts carry, from the parts'
    world poses in one frame (`positions` (parts, 3), `quaternions` (parts, 4))."""
    part = colliders["part"]
    turn = rotation_matrices(quaternions[part])
    world = np.einsum("nij,nj->ni", turn, colliders["position"]) + positions[part]
    return world, quaternion_product(quaternions[part], colliders["orientation"])


def body_faces(trajectory, index):
    """The faces of every drawn shape of the body in frame `index`: the parts that have a shape
    of their own, then the shapes they carry (each as its box)."""
    solid = trajectory["solid"]
    positions, quaternions = trajectory["position"][index], trajectory["orientation"][index]
    faces = [box_faces(trajectory["half_extents"][solid], positions[solid], quaternions[solid])]
    carried = trajectory["colliders"]
    if carried is not None and len(carried["part"]):
        world, turned = collider_poses(carried, positions, quaternions)
        faces.append(box_faces(carried["half_extents"], world, turned))
    return np.concatenate(faces)


def body_colours(trajectory):
    """One colour per face of body_faces: a part's own, and its colour on what it carries."""
    parts = len(trajectory["half_extents"])
    colours = plt.get_cmap("tab10")(np.arange(parts) % 10)
    drawn = [colours[trajectory["solid"]]]
    carried = trajectory["colliders"]
    if carried is not None and len(carried["part"]):
        drawn.append(colours[carried["part"]])
    return np.repeat(np.concatenate(drawn), 6, axis=0)


def box_corners(half_extents, positions, quaternions):
    """World corners (parts, 8, 3) of boxes with `half_extents` (parts, 3) at `positions`
    (parts, 3) turned by `quaternions` (parts, 4; x, y, z, w)."""
    local = BOX_SIGNS[None, :, :] * half_extents[:, None, :]
    return np.einsum("pij,pkj->pki", rotation_matrices(quaternions), local) + positions[:, None, :]


def box_faces(half_extents, positions, quaternions):
    """The six faces (parts * 6, 4, 3) of every box, for a Poly3DCollection."""
    corners = box_corners(half_extents, positions, quaternions)
    return corners[:, BOX_FACES, :].reshape(-1, 4, 3)


def select_frames(count, stride=1, max_frames=None):
    """Indices of the frames to draw: every `stride`-th, thinned further (evenly, first frame
    kept) so that at most `max_frames` remain."""
    if count <= 0:
        return np.zeros(0, dtype=int)
    stride = max(1, int(stride))
    if max_frames is not None and max_frames > 0:
        stride = max(stride, math.ceil(count / max_frames))
    return np.arange(0, count, stride)


def terrain_height(terrain, x, y):
    """The ground's z at points (x, y) (arrays) on a heightfield terrain, on the triangles Bullet
    makes of each grid square (split from (c + 1, r) to (c, r + 1)); outside, the edge's."""
    heights, spacing = terrain["heights"], terrain["spacing"]
    n = heights.shape[0]
    half = (n - 1) / 2
    gx = np.clip(np.asarray(x, dtype=float) / spacing + half, 0, n - 1)
    gy = np.clip(np.asarray(y, dtype=float) / spacing + half, 0, n - 1)
    c = np.minimum(gx.astype(int), n - 2)
    r = np.minimum(gy.astype(int), n - 2)
    u, v = gx - c, gy - r
    h00, h10, h01, h11 = heights[r, c], heights[r, c + 1], heights[r + 1, c], heights[r + 1, c + 1]
    lower = h00 + u * (h10 - h00) + v * (h01 - h00)
    upper = h11 + (1 - u) * (h01 - h11) + (1 - v) * (h10 - h11)
    return np.where(u + v <= 1, lower, upper)


def ground_segments(center, radius, spacing, terrain=None):
    """Grid lines on the ground around `center` (x, y), `radius` m to each side, on multiples of
    `spacing` so the grid stays fixed in the world while the camera moves: on z = 0, or over a
    heightfield `terrain` in pieces of its own spacing."""
    x0, y0 = center
    xs = np.arange(math.floor((x0 - radius) / spacing), math.ceil((x0 + radius) / spacing) + 1) * spacing
    ys = np.arange(math.floor((y0 - radius) / spacing), math.ceil((y0 + radius) / spacing) + 1) * spacing
    if terrain is None:
        segments = [[(x, ys[0], 0), (x, ys[-1], 0)] for x in xs]
        segments += [[(xs[0], y, 0), (xs[-1], y, 0)] for y in ys]
        return segments
    step = min(spacing, terrain["spacing"])
    along_y = np.linspace(ys[0], ys[-1], max(2, int(math.ceil((ys[-1] - ys[0]) / step)) + 1))
    along_x = np.linspace(xs[0], xs[-1], max(2, int(math.ceil((xs[-1] - xs[0]) / step)) + 1))
    segments = []
    for x in xs:
        z = terrain_height(terrain, np.full(len(along_y), x), along_y)
        points = np.column_stack([np.full(len(along_y), x), along_y, z])
        segments += [[tuple(a), tuple(b)] for a, b in zip(points[:-1], points[1:])]
    for y in ys:
        z = terrain_height(terrain, along_x, np.full(len(along_x), y))
        points = np.column_stack([along_x, np.full(len(along_x), y), z])
        segments += [[tuple(a), tuple(b)] for a, b in zip(points[:-1], points[1:])]
    return segments


def grid_spacing(radius):
    """A round grid spacing (1, 2 or 5 times a power of ten) giving about five lines per radius."""
    target = radius / 5
    power = 10 ** math.floor(math.log10(target))
    for factor in (1, 2, 5, 10):
        if factor * power >= target:
            return factor * power
    return 10 * power


def view_radius(trajectory):
    """Half the side of the box the camera shows: the creature's size, at least 0.5 m."""
    extent = np.max(np.linalg.norm(trajectory["half_extents"], axis=1)) if len(trajectory["half_extents"]) else 0
    spread = 0.0
    if len(trajectory["time"]):
        offsets = trajectory["position"] - trajectory["center_of_mass"][:, None, :]
        spread = float(np.max(np.linalg.norm(offsets, axis=2)))
    return max(0.5, 1.3 * (spread + extent))


def frame_title(trajectory, index):
    """The title of frame `index`: creature, time, phase, fitness."""
    attributes = trajectory["attributes"]
    creature = attributes.get("creature_id")
    label = (
        f"creature {creature}"
        if creature is not None and int(creature) != 2**64 - 1
        else os.path.basename(str(attributes.get("source", "creature")))
    )
    phase = int(trajectory["phase"][index])
    phase_name = PHASE_NAMES[phase] if 0 <= phase < len(PHASE_NAMES) else str(phase)
    return (
        f"{label}  {attributes.get('task', '')}  fitness {float(attributes.get('fitness', 0)):.3g}\n"
        f"t = {trajectory['time'][index]:6.2f} s   {phase_name}"
    )


def render(trajectory, output, fps=None, size=(640, 480), stride=1, max_frames=None, dpi=100):
    """Draws the selected frames of `trajectory` into `output` (.gif or .mp4). Returns the
    number of frames written. Raises ValueError for an unknown suffix or .mp4 without ffmpeg,
    TrajectoryError for a trajectory without frames."""
    suffix = os.path.splitext(output)[1].lower()
    if suffix not in (".gif", ".mp4"):
        raise ValueError(f"{output}: unknown animation format {suffix!r} (use .gif or .mp4)")
    if suffix == ".mp4" and shutil.which("ffmpeg") is None:
        raise ValueError(f"{output}: .mp4 needs ffmpeg on PATH (write a .gif instead)")
    indices = select_frames(len(trajectory["time"]), stride, max_frames)
    if len(indices) == 0:
        raise TrajectoryError(f"{trajectory['path']}: the trajectory has no frames to draw")
    if fps is None:
        # real time: the file's frame rate thinned by the frame selection
        step = indices[1] - indices[0] if len(indices) > 1 else 1
        fps = max(1.0, float(trajectory["attributes"].get("frame_rate", 30)) / step)

    # the figure: a 3D axes without panes, one polygon collection for every box face
    figure = plt.figure(figsize=(size[0] / dpi, size[1] / dpi), dpi=dpi)
    figure.subplots_adjust(left=0, right=1, bottom=0, top=0.88)
    axes = figure.add_subplot(projection="3d", computed_zorder=False)
    axes.set_axis_off()
    axes.view_init(elev=25, azim=-60)
    boxes = Poly3DCollection(
        [], facecolors=body_colours(trajectory), edgecolors="k", linewidths=0.4, alpha=0.95, zorder=3
    )
    grid = Line3DCollection([], colors="0.75", linewidths=0.5, zorder=1)
    axes.add_collection3d(grid)
    (trail,) = axes.plot([], [], [], color="0.35", linewidth=1.0, zorder=2)
    axes.add_collection3d(boxes)
    # held objects (a catapult's projectile) in one colour, drawn over the body
    held = Poly3DCollection([], facecolors="tab:red", edgecolors="k", linewidths=0.4, alpha=0.95, zorder=4)
    axes.add_collection3d(held)
    radius = view_radius(trajectory)
    spacing = grid_spacing(radius)
    com = trajectory["center_of_mass"]

    # one frame: boxes, ground around the camera, the path of the centre of mass so far
    def draw(k):
        index = indices[k]
        boxes.set_verts(body_faces(trajectory, index))
        if len(trajectory["held_half_extents"]):
            held.set_verts(
                box_faces(
                    trajectory["held_half_extents"],
                    trajectory["held_position"][index],
                    trajectory["held_orientation"][index],
                )
            )
        cx, cy = com[index, 0], com[index, 1]
        terrain = trajectory.get("terrain")
        grid.set_segments(ground_segments((cx, cy), radius, spacing, terrain))
        path = com[indices[: k + 1]]
        path = path[(np.abs(path[:, 0] - cx) <= radius) & (np.abs(path[:, 1] - cy) <= radius)]
        on = terrain_height(terrain, path[:, 0], path[:, 1]) if terrain is not None else np.zeros(len(path))
        trail.set_data_3d(path[:, 0], path[:, 1], on)
        base = float(terrain_height(terrain, cx, cy)) - radius / 4 if terrain is not None else 0
        axes.set_xlim(cx - radius, cx + radius)
        axes.set_ylim(cy - radius, cy + radius)
        axes.set_zlim(base, base + radius)
        axes.set_box_aspect((1, 1, 0.5), zoom=1.4)
        axes.set_title(frame_title(trajectory, index), fontsize=9)
        return boxes, held, grid, trail

    writer = animation.PillowWriter(fps=fps) if suffix == ".gif" else animation.FFMpegWriter(fps=fps)
    movie = animation.FuncAnimation(figure, draw, frames=len(indices), blit=False)
    try:
        movie.save(output, writer=writer, dpi=dpi)
    finally:
        plt.close(figure)
    return len(indices)


def parse_size(text):
    """'640x480' -> (640, 480); argparse error otherwise."""
    try:
        width, height = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"size {text!r}: expected WIDTHxHEIGHT in pixels, e.g. 640x480")
    if width < 64 or height < 64 or width > 4096 or height > 4096:
        raise argparse.ArgumentTypeError(f"size {text!r}: each side must be in 64..4096 pixels")
    return width, height


def positive_int(text):
    """argparse type: an integer >= 1."""
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"{text}: must be >= 1")
    return value


def positive_float(text):
    """argparse type: a number > 0."""
    value = float(text)
    if not value > 0:
        raise argparse.ArgumentTypeError(f"{text}: must be > 0")
    return value


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="Render a cambrian trajectory (traj.h5 from `cambrian replay --export` or "
        "`cambrian simulate --export`) as a GIF (Pillow) or MP4 (ffmpeg on PATH), headless: the "
        "boxes of the creature, a ground grid, the camera following the centre of mass, time "
        "and phase in the title. Exit codes: 2 bad arguments, 4 bad trajectory, 5 write error."
    )
    parser.add_argument("trajectory", help="traj.h5 written by cambrian --export")
    parser.add_argument("-o", "--output", default="creature.gif", help="animation to write, .gif or .mp4 (default: creature.gif)")
    parser.add_argument("--fps", type=positive_float, default=None, help="frames per second of the animation (default: real time)")
    parser.add_argument("--size", type=parse_size, default=(640, 480), help="WIDTHxHEIGHT in pixels (default: 640x480)")
    parser.add_argument("--stride", type=positive_int, default=1, help="draw every N-th stored frame (default: 1)")
    parser.add_argument("--max-frames", type=positive_int, default=240, help="draw at most this many frames, thinning evenly (default: 240)")
    parser.add_argument("--dpi", type=positive_int, default=100, help="dots per inch of the figure (default: 100)")
    return parser.parse_args(argv)


def main(argv=None):
    arguments = parse_arguments(sys.argv[1:] if argv is None else argv)
    try:
        trajectory = load_trajectory(arguments.trajectory)
    except TrajectoryError as error:
        print(f"animate: error: {error}", file=sys.stderr)
        return 4
    try:
        frames = render(
            trajectory,
            arguments.output,
            fps=arguments.fps,
            size=arguments.size,
            stride=arguments.stride,
            max_frames=arguments.max_frames,
            dpi=arguments.dpi,
        )
    except TrajectoryError as error:
        print(f"animate: error: {error}", file=sys.stderr)
        return 4
    except ValueError as error:
        print(f"animate: error: {error}", file=sys.stderr)
        return 2
    except OSError as error:
        print(f"animate: error: {arguments.output}: cannot write the animation ({error})", file=sys.stderr)
        return 5
    print(f"animate: {arguments.output} ({frames} frames)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
