#!/usr/bin/env python3
"""Write one self-contained HTML page that shows creatures in the browser (three.js, bundled in
the page: it opens offline, from disk): their parts, the ground (plane or hills) or the water, a held projectile,
the light; play / pause / scrub, speed, orbit or follow camera, the phase and the fitness; several
creatures side by side on one timeline.

    cambrian replay --history run/history.h5 --best --export best.h5
    python3 analysis/view.py best.h5 -o best.html
    # or replayed on the fly: the best of generations 0, 10 and 30 side by side
    python3 analysis/view.py --history run/history.h5 --generation 0 10 30 -o run.html

Generations are numbered as in the history and in `cambrian replay --generation` (from 0; the
progress line "gen 1/100" is generation 0). The three.js bundle is built by `jobs/setup/install-deps.sh` (npm ci and npm run build in
viewer/, from its package-lock.json) into viewer/dist/cambrian-viewer.js.

Exit codes: 0 written, 2 bad command line, 4 unreadable or foreign trajectory or history, or a
creature the replay cannot give, 5 the page cannot be written or the viewer bundle is missing.
"""

import argparse
import html
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import animate  # noqa: E402
import cambrian_history as ch  # noqa: E402

EXIT_OK, EXIT_USAGE, EXIT_INPUT, EXIT_OUTPUT = 0, 2, 4, 5
ROOT = os.path.dirname(HERE)
# where the viewer's bundle is looked for: what install-deps.sh builds, then the build trees'
BUNDLES = [os.path.join(ROOT, "viewer", "dist", "cambrian-viewer.js")] + [
    os.path.join(ROOT, "build", tree, "viewer", "cambrian-viewer.js") for tree in ("release", "ci")]
POSITION_DECIMALS = 4  # 0.1 mm: what a page needs, a quarter of the bytes of full doubles
ORIENTATION_DECIMALS = 5


class ViewError(Exception):
    """Something the page cannot be made from; `code` is the exit code."""

    def __init__(self, message, code):
        super().__init__(message)
        self.code = code


def _rounded(array, decimals):
    """A flat list of floats rounded to `decimals` (JSON numbers)."""
    return np.round(np.asarray(array, dtype=float), decimals).ravel().tolist()


def scene_of(trajectory, label=""):
    """The JSON-ready description of one trajectory (animate.load_trajectory's dict)."""
    attributes = trajectory["attributes"]
    creature = int(attributes.get("creature_id", np.iinfo(np.uint64).max))
    scene = {
        "label": label,
        "source": str(attributes.get("source", "")),
        "creature_id": None if creature == np.iinfo(np.uint64).max else creature,
        "task": str(attributes.get("task", "")),
        "fitness": float(attributes.get("fitness", 0.0)),
        "status": str(attributes.get("status", "")),
        "frame_rate": float(attributes.get("frame_rate", 0.0)),
        "ground": trajectory["ground"],
        "viscosity": trajectory["viscosity"],
        "time": _rounded(trajectory["time"], 6),
        "phase": np.asarray(trajectory["phase"], dtype=int).tolist(),
        "phase_names": list(animate.PHASE_NAMES),
        "com": _rounded(trajectory["center_of_mass"], POSITION_DECIMALS),
        "parts": {
            "half_extents": np.asarray(trajectory["half_extents"], dtype=float).tolist(),
            "parent": np.asarray(trajectory["parent"], dtype=int).tolist(),
            "shape": list(trajectory["shape"]),
            "solid": np.asarray(trajectory["solid"], dtype=bool).tolist(),
        },
        "colliders": None,
        "position": _rounded(trajectory["position"], POSITION_DECIMALS),
        "orientation": _rounded(trajectory["orientation"], ORIENTATION_DECIMALS),
        "light": None if trajectory["light"] is None else _rounded(trajectory["light"], POSITION_DECIMALS),
        "held": None,
        "terrain": None,
    }
    carried = trajectory.get("colliders")
    if carried is not None and len(carried["part"]):
        scene["colliders"] = {
            "part": np.asarray(carried["part"], dtype=int).tolist(),
            "shape": list(carried["shape"]),
            "half_extents": np.asarray(carried["half_extents"], dtype=float).tolist(),
            "position": _rounded(carried["position"], POSITION_DECIMALS),
            "orientation": _rounded(carried["orientation"], ORIENTATION_DECIMALS),
        }
    terrain = trajectory.get("terrain")
    if terrain is not None:
        scene["terrain"] = {
            "samples": int(terrain["heights"].shape[0]),
            "spacing": float(terrain["spacing"]),
            "heights": _rounded(terrain["heights"], POSITION_DECIMALS),
        }
    if len(trajectory["held_half_extents"]):
        scene["held"] = {
            "half_extents": np.asarray(trajectory["held_half_extents"], dtype=float).tolist(),
            "shape": list(trajectory["held_shape"]),
            "position": _rounded(trajectory["held_position"], POSITION_DECIMALS),
            "orientation": _rounded(trajectory["held_orientation"], ORIENTATION_DECIMALS),
            "released": np.asarray(trajectory["held_released"], dtype=int).ravel().tolist(),
        }
    if not scene["time"] or not scene["parts"]["half_extents"]:
        raise ViewError(f"{trajectory['path']}: no frames to show (the creature never reached the "
                        "physics)", EXIT_INPUT)
    return scene


def load_scene(path, label=""):
    """The scene of a traj.h5 file; ViewError(EXIT_INPUT) naming the file when it is unreadable."""
    try:
        return scene_of(animate.load_trajectory(path), label)
    except animate.TrajectoryError as error:
        raise ViewError(str(error), EXIT_INPUT) from error


def replayed_scene(history, folder, cambrian, frame_rate, generation=None, individual=None):
    """A creature of a history replayed on the fly (`cambrian replay --export`): the best of
    `generation` (from 0, as the history counts) or the individual `individual`."""
    if generation is not None:
        which, label = ["--best", "--generation", str(generation)], f"generation {generation}"
        path = os.path.join(folder, f"generation-{generation}.h5")
    else:
        which, label = ["--id", str(individual)], ""
        path = os.path.join(folder, f"id-{individual}.h5")
    command = [cambrian, "replay", "--history", history, *which, "--export", path,
               "--frame-rate", repr(frame_rate)]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode not in (0, 10):  # 10: replayed, but not bit-identical (shown all the same)
        message = (done.stderr.strip() or done.stdout.strip()).splitlines()
        raise ViewError(f"{history}: cambrian replay {' '.join(which)} failed (exit "
                        f"{done.returncode}): {message[-1] if message else ''}", EXIT_INPUT)
    return load_scene(path, label)


def page(scenes, title, bundle_text):
    """The HTML page: style, the scenes as JSON, the viewer bundle, nothing fetched."""
    data = json.dumps({"title": title, "scenes": scenes}, separators=(",", ":"))
    data = data.replace("</", "<\\/")  # no "</script>" inside the data block
    bundle_text = bundle_text.replace("</script", "<\\/script")
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="cambrian analysis/view.py">
<title>{html.escape(title)}</title>
<style>
  html, body {{ margin: 0; height: 100%; font: 14px system-ui, sans-serif; background: #20242a; color: #eee; }}
  body {{ display: flex; flex-direction: column; }}
  #bar {{ display: flex; gap: 0.7em; align-items: center; padding: 0.4em 0.8em; background: #111; flex-wrap: wrap; }}
  #bar input[type=range] {{ flex: 1; min-width: 10em; }}
  #time {{ font-variant-numeric: tabular-nums; min-width: 9em; }}
  #panels {{ flex: 1; display: grid; gap: 2px; min-height: 0; }}
  .panel {{ position: relative; min-height: 240px; }}
  .panel canvas {{ width: 100%; height: 100%; display: block; }}
  .caption, .clock {{ position: absolute; left: 0.5em; background: rgba(0,0,0,0.55); padding: 0.15em 0.5em;
                      border-radius: 3px; pointer-events: none; }}
  .caption {{ top: 0.5em; }}
  .clock {{ bottom: 0.5em; font-variant-numeric: tabular-nums; }}
  #cambrian-error {{ color: #f66; padding: 1em; }}
</style>
</head>
<body>
<script type="application/json" id="cambrian-data">{data}</script>
<script>{bundle_text}</script>
</body>
</html>
"""


def write_page(path, text):
    """Writes the page atomically (a temporary file beside it, then rename)."""
    directory = os.path.dirname(os.path.abspath(path))
    handle, temporary = tempfile.mkstemp(prefix=".view-", suffix=".html", dir=directory)
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as out:
            out.write(text)
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(temporary, 0o666 & ~mask)  # as open() would have made it
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


def default_bundle():
    """$CAMBRIAN_VIEWER_BUNDLE, else the newest of BUNDLES that exists (else the first)."""
    if os.environ.get("CAMBRIAN_VIEWER_BUNDLE"):
        return os.environ["CAMBRIAN_VIEWER_BUNDLE"]
    present = [path for path in BUNDLES if os.path.isfile(path)]
    return max(present, key=os.path.getmtime) if present else BUNDLES[0]


def read_bundle(path):
    if not os.path.isfile(path):
        raise ViewError(f"{path}: the viewer bundle is missing; build it with "
                        "`bash jobs/setup/install-deps.sh` (npm ci && npm run build in viewer/)",
                        EXIT_OUTPUT)
    with open(path, encoding="utf-8") as handle:
        return handle.read()


def non_negative_int(text):
    value = int(text)
    if value < 0:
        raise argparse.ArgumentTypeError(f"{text}: must be >= 0")
    return value


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="Write one self-contained HTML page (three.js bundled, opens offline) that "
        "plays creatures' trajectories side by side: traj.h5 files from `cambrian replay "
        "--export` / `cambrian simulate --export`, or creatures of a history replayed on the "
        "fly. Exit codes: 2 bad arguments, 4 bad trajectory or history, 5 page not written.")
    parser.add_argument("trajectories", nargs="*", help="traj.h5 files, one panel each")
    parser.add_argument("--history", help="history.h5 of a run: creatures replayed on the fly")
    parser.add_argument("--generation", type=non_negative_int, nargs="+", default=[],
                        help="with --history: the best of these generations (from 0, as the "
                        "history and cambrian replay count)")
    parser.add_argument("--id", type=int, nargs="+", default=[], dest="ids",
                        help="with --history: these individuals")
    parser.add_argument("--label", action="append", default=[],
                        help="a panel's caption, in order (default: the generation, or none)")
    parser.add_argument("-o", "--output", default="view.html", help="page to write (default: view.html)")
    parser.add_argument("--title", default=None, help="page title (default: from the inputs)")
    parser.add_argument("--frame-rate", type=animate.positive_float, default=30.0,
                        help="frames per simulated second of replays on the fly (default: 30)")
    parser.add_argument("--cambrian", default=None,
                        help="the cambrian binary for replays (default: $CAMBRIAN_BINARY, the "
                        "build tree, PATH)")
    parser.add_argument("--bundle", default=None,
                        help="the viewer's JavaScript bundle (default: $CAMBRIAN_VIEWER_BUNDLE, "
                        "viewer/dist/cambrian-viewer.js, then build/*/viewer/)")
    arguments = parser.parse_args(argv)
    if (arguments.generation or arguments.ids) and not arguments.history:
        parser.error("--generation and --id need --history")
    if arguments.history and not (arguments.generation or arguments.ids):
        parser.error("--history needs --generation G... or --id I...")
    if not arguments.trajectories and not arguments.history:
        parser.error("give traj.h5 files, or --history with --generation or --id")
    return arguments


def build(arguments):
    """The page's scenes and title from the arguments; ViewError on bad input."""
    bundle_text = read_bundle(arguments.bundle or default_bundle())
    scenes = [load_scene(path) for path in arguments.trajectories]
    if arguments.history:
        if not os.path.isfile(arguments.history):
            raise ViewError(f"{arguments.history}: no such history file", EXIT_INPUT)
        try:
            cambrian = ch.find_cambrian(arguments.cambrian)
        except FileNotFoundError as error:
            raise ViewError(str(error), EXIT_USAGE) from error
        with tempfile.TemporaryDirectory(prefix="cambrian-view-") as folder:
            for generation in arguments.generation:
                scenes.append(replayed_scene(arguments.history, folder, cambrian,
                                             arguments.frame_rate, generation=generation))
            for individual in arguments.ids:
                scenes.append(replayed_scene(arguments.history, folder, cambrian,
                                             arguments.frame_rate, individual=individual))
    for scene, label in zip(scenes, arguments.label):
        scene["label"] = label
    title = arguments.title
    if title is None:
        source = arguments.history or arguments.trajectories[0]
        title = f"cambrian · {os.path.basename(os.path.dirname(os.path.abspath(source))) or source}"
    return page(scenes, title, bundle_text), len(scenes)


def main(argv=None):
    arguments = parse_arguments(sys.argv[1:] if argv is None else argv)
    try:
        text, count = build(arguments)
    except ViewError as error:
        print(f"view: error: {error}", file=sys.stderr)
        return error.code
    try:
        write_page(arguments.output, text)
    except OSError as error:
        print(f"view: error: {arguments.output}: cannot write the page ({error})", file=sys.stderr)
        return EXIT_OUTPUT
    print(f"view: {arguments.output} ({count} creature{'s' if count != 1 else ''}, "
          f"{len(text) / 1e6:.1f} MB)")
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
