#!/usr/bin/env python3
"""Write one HTML page about a run: settings and provenance, fitness over generations, the
lineage of the best, the operators' points of improvement, diversity, the workers' load, and
the best creatures of chosen generations in the browser viewer. It works on a finished run and
on one still going (the history is read as SWMR); the page is self-contained (figures and
viewer inside it).

    python3 analysis/report.py runs/walk                 # writes runs/walk/report.html
    python3 analysis/report.py runs/walk --generation 0 25 99 -o walk.html

Each section comes from the script that answers its question (plot_fitness, lineage,
improvements, diversity, load_balance, view); one that cannot be made says why and the rest of
the page is written. Exit codes: 0 written, 2 bad command line, 4 no readable history in
RUN_DIR (or no generation in it yet), 5 the page cannot be written.
"""

import argparse
import base64
import contextlib
import datetime
import fcntl
import html
import io
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import cambrian_history as ch  # noqa: E402

PROGRAM = "report"
PROVENANCE = ("cambrian_version", "git_hash", "start_time", "seed", "rank_count", "config_hash",
              "bullet_precision")


def run_is_live(run_dir):
    """True while a run holds DIR/run.lock (cambrian evolve's exclusive flock)."""
    path = os.path.join(run_dir, "run.lock")
    if not os.path.exists(path):
        return False
    try:
        with open(path) as handle:
            try:
                fcntl.flock(handle, fcntl.LOCK_SH | fcntl.LOCK_NB)
            except BlockingIOError:
                return True
            fcntl.flock(handle, fcntl.LOCK_UN)
    except OSError:
        return False
    return False


def run_script(module, arguments):
    """Runs analysis/<module>.py's main(arguments) here: (exit code, what it printed)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = __import__(module).main([str(a) for a in arguments])
        except SystemExit as exit_:
            code = exit_.code if isinstance(exit_.code, int) else 1
        except Exception as error:  # a section fails, not the report
            print(f"{module}: {type(error).__name__}: {error}", file=sys.stderr)
            code = 1
    return code or 0, out.getvalue(), err.getvalue()


def image(path, alt):
    """An <img> with the PNG inside it (a data: URI)."""
    with open(path, "rb") as handle:
        data = base64.b64encode(handle.read()).decode("ascii")
    return f'<img alt="{html.escape(alt)}" src="data:image/png;base64,{data}">'


def tsv_html(text, collapse_after=12):
    """What a script printed (TSV tables and '# ' comment lines) as HTML: comments as paragraphs,
    each table as a <table>, long ones folded."""
    parts, rows = [], []

    def flush():
        if not rows:
            return
        head = "".join(f"<th>{html.escape(c)}</th>" for c in rows[0])
        body = "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in row) + "</tr>"
                       for row in rows[1:])
        table = f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"
        if len(rows) - 1 > collapse_after:
            table = f"<details><summary>table of {len(rows) - 1} rows</summary>{table}</details>"
        parts.append(table)
        rows.clear()

    for line in text.splitlines():
        if line.startswith("#"):
            flush()
            comment = line.lstrip("#").strip()
            if comment and not comment.startswith("wrote "):
                parts.append(f'<p class="note">{html.escape(comment)}</p>')
        elif line.startswith("wrote ") or line.startswith(f"{PROGRAM}: "):
            continue  # where a script wrote its figure (a temporary file)
        elif line.strip():
            rows.append(line.split("\t"))
        else:
            flush()
    flush()
    return "\n".join(parts)


def section(title, anchor, body):
    return f'<section id="{anchor}"><h2>{html.escape(title)}</h2>\n{body}\n</section>'


def failed(module, code, err):
    message = err.strip().splitlines()[-1] if err.strip() else f"exit {code}"
    return f'<p class="failed">{html.escape(module)}.py could not make this section: {html.escape(message)}</p>'


def script_section(module, title, anchor, history, folder, extra=(), explain=""):
    """A section made by analysis/<module>.py: its figure and what it printed."""
    png = os.path.join(folder, f"{module}.png")
    code, out, err = run_script(module, [history, "--output", png, *extra])
    if code != 0 or not os.path.exists(png):
        return section(title, anchor, failed(module, code, err))
    body = (f"<p>{explain}</p>" if explain else "") + image(png, title) + tsv_html(out)
    return section(title, anchor, body)


def overview(attributes, generations, individuals, statuses, live, run_dir):
    """Settings and provenance, the run's size and cost, the statuses, the settings text."""
    rows = [("run directory", os.path.abspath(run_dir)),
            ("state", "going on (run.lock held): the page shows the generations written so far"
             if live else "finished or stopped")]
    rows += [(key, str(attributes.get(key, ""))) for key in PROVENANCE]
    configured = ch.config_value(attributes, "evolution", "generations", "?")
    count = len(generations["generation"])
    best = int(generations["best"].argmax())
    rows += [
        ("task", ch.config_value(attributes, "task", "name", "walk")),
        ("generations written", f"{count} of {configured}"),
        ("best fitness", f"{generations['best'][best]:.6g} (id {int(generations['best_id'][best])}, "
                         f"generation {int(generations['generation'][best])})"),
        ("evaluations", f"{int(generations['evaluations'].sum()):,}"),
        ("wall time", f"{generations['wall_seconds'].sum() / 60:.1f} min"),
        ("workers", str(ch.worker_count(attributes, generations))),
    ]
    busy, idle = generations["worker_busy_seconds"].sum(), generations["worker_idle_seconds"].sum()
    if busy + idle > 0:
        rows.append(("workers busy", f"{100 * busy / (busy + idle):.1f} %"))
    codes, counts = np.unique(individuals["status"], return_counts=True)
    rows.append(("statuses", ", ".join(f"{statuses[c]} {n:,}" for c, n in zip(codes, counts))))
    table = "".join(f"<tr><th>{html.escape(k)}</th><td>{html.escape(v)}</td></tr>" for k, v in rows)
    config = html.escape(str(attributes.get("config_text", "")))
    body = (f"<table class=\"facts\">{table}</table>"
            f"<details><summary>every setting of the run (config_text)</summary><pre>{config}</pre></details>")
    return section("Settings and provenance", "run", body)


def viewer_section(arguments, attributes, generations, folder):
    """The best creatures of the chosen generations in the viewer, inside an iframe."""
    import view

    title = "The best creatures"
    task = ch.config_value(attributes, "task", "name", "walk")
    if arguments.no_viewer:
        return section(title, "creatures", "<p>Left out (--no-viewer).</p>")
    if task == "synthetic":
        return section(title, "creatures", "<p>The synthetic task has no bodies to show.</p>")
    last = int(generations["generation"][-1])
    chosen = arguments.generation or sorted({0, last // 2, last})
    chosen = [g for g in chosen if g <= last]
    options = ["--history", arguments.history, "--generation", *chosen, "--output",
               os.path.join(folder, "view.html"), "--title", "the best of generations " +
               ", ".join(map(str, chosen))]
    if arguments.cambrian:
        options += ["--cambrian", arguments.cambrian]
    if arguments.bundle:
        options += ["--bundle", arguments.bundle]
    code, _, err = run_script("view", options)
    if code != 0:
        return section(title, "creatures", failed("view", code, err))
    with open(os.path.join(folder, "view.html"), encoding="utf-8") as handle:
        page = handle.read()
    frame = f'<iframe class="viewer" title="viewer" srcdoc="{html.escape(page, quote=True)}"></iframe>'
    note = (f"<p>The best of generations {', '.join(map(str, chosen))} (numbered from 0), replayed "
            "for this page (<code>cambrian replay --best --generation G</code>). Space or the "
            "button plays and pauses; drag to turn the camera.</p>")
    return section(title, "creatures", note + frame)


STYLE = """
body { font: 15px/1.45 system-ui, sans-serif; margin: 0 auto; max-width: 1100px; padding: 0 1em 3em; color: #222; }
h1 { margin-bottom: 0.2em; } nav a { margin-right: 1em; }
section { margin-top: 2em; border-top: 1px solid #ddd; }
img { max-width: 100%; display: block; margin: 0.5em 0; }
table { border-collapse: collapse; margin: 0.5em 0; font-size: 13px; }
th, td { border: 1px solid #ddd; padding: 0.15em 0.5em; text-align: left; vertical-align: top; }
table.facts th { background: #f4f4f4; width: 12em; }
pre { background: #f6f6f6; padding: 0.7em; overflow-x: auto; font-size: 12px; }
.note { color: #444; margin: 0.2em 0; } .failed { color: #b00; }
iframe.viewer { width: 100%; height: 560px; border: 1px solid #ccc; }
"""


def report(arguments):
    """The page's HTML; SystemExit(EXIT_INPUT) when the history cannot be read."""
    history = arguments.history
    attributes, individuals, generations, _, statuses = ch.open_or_exit(history, PROGRAM)
    live = run_is_live(arguments.run_dir)
    with tempfile.TemporaryDirectory(prefix="cambrian-report-") as folder:
        sections = [
            overview(attributes, generations, individuals, statuses, live, arguments.run_dir),
            script_section("plot_fitness", "Fitness over generations", "fitness", history, folder,
                           explain="Best, mean and median of each generation, with the middle half shaded."),
            script_section("lineage", "Lineage of the best", "lineage", history, folder,
                           explain="The best creature's line of descent: each ancestor's fitness and the "
                                   "operator that made the next step."),
            script_section("improvements", "Operators and points of improvement", "operators", history,
                           folder, explain="How often each operator made a child better than its parents."),
            script_section("diversity", "Diversity", "diversity", history, folder,
                           explain="Distinct genomes and the mean genome distance within each generation."),
            script_section("load_balance", "The workers' load", "load", history, folder,
                           explain="Evaluations and busy time per worker, idle time per generation."),
            viewer_section(arguments, attributes, generations, folder),
        ]
    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    title = f"cambrian run report: {os.path.basename(os.path.abspath(arguments.run_dir))}"
    nav = " ".join(f'<a href="#{a}">{t}</a>' for a, t in (
        ("run", "run"), ("fitness", "fitness"), ("lineage", "lineage"), ("operators", "operators"),
        ("diversity", "diversity"), ("load", "load"), ("creatures", "creatures")))
    state = "a run still going on" if live else "a finished run"
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>
<meta name="generator" content="cambrian analysis/report.py"><style>{STYLE}</style></head>
<body><h1>{html.escape(title)}</h1>
<p>Written {stamp} from {html.escape(os.path.abspath(history))}, {state}, {len(generations['generation'])} generations.</p>
<nav>{nav}</nav>
{chr(10).join(sections)}
</body></html>
"""


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="Write one self-contained HTML report of a run (finished or still going): "
        "settings and provenance, fitness, lineage of the best, operators' points of improvement, "
        "diversity, load balance, and the best creatures in the browser viewer. Exit codes: 2 bad "
        "arguments, 4 no readable history, 5 page not written.")
    parser.add_argument("run_dir", help="the run's directory (with history.h5)")
    parser.add_argument("-o", "--output", default=None, help="page to write (default: RUN_DIR/report.html)")
    parser.add_argument("--generation", type=int, nargs="+", default=None,
                        help="generations whose best the viewer shows (from 0; default: first, middle, last)")
    parser.add_argument("--no-viewer", action="store_true", help="leave the viewer out (no replays)")
    parser.add_argument("--cambrian", default=None, help="the cambrian binary for the replays")
    parser.add_argument("--bundle", default=None, help="the viewer's JavaScript bundle")
    arguments = parser.parse_args(argv)
    if arguments.generation and min(arguments.generation) < 0:
        parser.error("--generation: generations are numbered from 0")
    arguments.history = os.path.join(arguments.run_dir, "history.h5")
    arguments.output = arguments.output or os.path.join(arguments.run_dir, "report.html")
    return arguments


def main(argv=None):
    import matplotlib

    matplotlib.use("Agg")
    import view

    arguments = parse_arguments(sys.argv[1:] if argv is None else argv)
    if not os.path.isdir(arguments.run_dir):
        print(f"{PROGRAM}: error: {arguments.run_dir}: no such run directory", file=sys.stderr)
        return ch.EXIT_INPUT
    text = report(arguments)
    try:
        view.write_page(arguments.output, text)
    except OSError as error:
        print(f"{PROGRAM}: error: {arguments.output}: cannot write the report ({error})", file=sys.stderr)
        return 5
    print(f"{PROGRAM}: {arguments.output}")
    return ch.EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
