"""The ``graphmech`` command: render, check, batch, bench.

Exit status: 0 success; 1 a measured value is out of tolerance; 2 bad input (one line naming
the file, the key path and what is wrong — never a traceback). Output files are written to a
temporary file and renamed, so a failure leaves nothing half-written and an existing file
untouched. Nothing heavy is imported before a command needs it: ``--help`` loads no numpy.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import warnings
from pathlib import Path
from typing import Any, NoReturn, Sequence

from graphmech.errors import COMMAND_LINE, GraphmechError, SceneError, one_line, printable
from graphmech.files import write_atomic
from graphmech.scales import FIT, PAPER
from graphmech.version import __version__

EXIT_OK, EXIT_OUT_OF_TOLERANCE, EXIT_BAD_INPUT, EXIT_INTERNAL = 0, 1, 2, 3


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:  # one line, exit 2 (argparse's own convention too)
        self.exit(EXIT_BAD_INPUT, f"graphmech: {message}\n")


#: The paper sizes --page takes (graphmech.scales.PAPER and "fit").
PAPERS = ", ".join([*PAPER, FIT])
PAGE_HELP = f"the paper, instead of the scene's [page] size: {PAPERS} (fit: cropped to the drawing)"


def _paper(text: str) -> str:
    """--page's value: a paper name (any case) or fit; else the one-line error, exit 2."""
    names = {name.casefold(): name for name in [*PAPER, FIT]}
    if text.casefold() not in names:
        raise argparse.ArgumentTypeError(f"unknown paper {text!r}: choose from {PAPERS}")
    return names[text.casefold()]


#: What --help ends with: where the format is written, and the exit codes.
EPILOG = """\
The scene format, with an example of every feature: docs/scene-format.md, installed as
  {docs}
`graphmech examples` lists the example scenes, `graphmech new KIND` writes a commented one.

exit status:
  0  done; every measured value within tolerance
  1  a measured value is out of tolerance (check)
  2  bad input or a construction that cannot be made: one line on stderr naming the file, the
     key path and the reason; nothing is written (batch: the other jobs are)
  3  an internal error (a bug: please report it with the scene)
"""


def _epilog() -> str:
    """--help's end, with where the installed scene format is."""
    from graphmech.packaged import docs

    return EPILOG.format(docs=docs().joinpath("scene-format.md"))


def _parser() -> argparse.ArgumentParser:
    epilog = _epilog()
    p = _Parser(prog="graphmech", description="Textbook graphical methods as exact, checked constructions.",
                epilog=epilog, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--version", action="version", version=f"graphmech {__version__}")
    quiet = _Parser(add_help=False)
    quiet.add_argument("-q", "--quiet", action="store_true", help="no warnings on stderr (errors still)")
    varied = _Parser(add_help=False)
    varied.add_argument("--set", action="append", default=[], metavar="KEY=V1[,V2…]", dest="assign",
                        help="vary the scene: a key path as messages print it (driver.angle, dyad[0].lengths[1]) "
                             "and values in the scene's unit; repeatable: one run per combination")
    varied.add_argument("--page", type=_paper, metavar="SIZE", help=PAGE_HELP)
    figure = _Parser(add_help=False)
    figure.add_argument("--format", metavar="svg|pdf|png",
                        help="the format to write (default: -o's extension, else svg; must agree with it); PDF (true "
                             "size) and PNG are printed by headless Chromium")
    figure.add_argument("--dpi", type=float, metavar="N", help="the PNG's resolution, dots per inch (default 150)")
    sub = p.add_subparsers(dest="command", required=True, parser_class=_Parser)
    r = sub.add_parser("render", help="draw a scene to SVG, PDF or PNG", parents=[quiet, varied, figure],
                       epilog=epilog, formatter_class=argparse.RawDescriptionHelpFormatter)
    r.add_argument("scenes", nargs="+", metavar="SCENE")
    r.add_argument("-o", "--output", help="the output file, its format by its extension: .svg, .pdf or .png (one figure only)")
    r.add_argument("-d", "--directory", help="write <scene name>[-<key>=<value>…].svg (or .pdf, .png: --format) into this folder")
    c = sub.add_parser("check", help="the check table: graphical vs exact, and verdicts on measured values",
                       parents=[quiet, varied], epilog=epilog, formatter_class=argparse.RawDescriptionHelpFormatter)
    c.add_argument("scene", metavar="SCENE")
    c.add_argument("--json", action="store_true", help="machine-readable output")
    c.add_argument("--measured", action="append", default=[], metavar="NAME=VALUE",
                   help="a value you measured: v_C=0.26 (SI) or pc=52 (drawn mm), judged as written (its significant "
                        "figures; its sign only when you write one); repeatable, or comma-separated")
    c.add_argument("--precision", type=float, metavar="MM", help="drawing precision, mm (default: the scene's, else 0.5)")
    t = sub.add_parser("batch", help="figures and checks of many scenes and variants, on all cores",
                       parents=[quiet, varied, figure], epilog=epilog,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    t.add_argument("scenes", nargs="+", metavar="SCENE")
    t.add_argument("-d", "--directory", required=True, metavar="DIR",
                   help="write <name>.svg (or .pdf, .png) and <name>.json, its check, for each")
    t.add_argument("-j", "--jobs", type=_jobs, metavar="N", help="processes (default: every core)")
    st = sub.add_parser("steps", help="the construction protocol: the numbered steps of the drawing, with every length",
                        parents=[varied], epilog=epilog, formatter_class=argparse.RawDescriptionHelpFormatter)
    st.add_argument("scene", metavar="SCENE")
    b = sub.add_parser("bench", help="run time and error of the graphical methods against the exact ones")
    b.add_argument("--json", action="store_true")
    b.add_argument("-o", "--output", metavar="DIR",
                   help="also write bench.json and log-log plots of error and time into DIR (and of error "
                        "against time for each discretised method)")
    b.add_argument("--quick", action="store_true", help="fewer repetitions")
    b.add_argument("--compare", metavar="OLD.json", help="print each record's change against an earlier bench.json")
    b.add_argument("--explicit", action="store_true",
                   help="also count explicit RK45's steps on the stiff flywheel (about 13 s more)")
    # what is installed besides the code (graphmech.packaged) and the gallery (graphmech.gallery)
    e = sub.add_parser("examples", help="list the example scenes installed with graphmech, or copy one")
    e.add_argument("name", nargs="?", metavar="NAME", help="the example to copy (as listed)")
    e.add_argument("-o", "--output", metavar="FILE", help="copy it to FILE (default: ./NAME.toml; never overwrites)")
    e.add_argument("-d", "--directory", metavar="DIR", help="copy it into DIR as NAME.toml")
    n = sub.add_parser("new", help="a commented scene template to start from (stdout, or -o FILE)")
    n.add_argument("kind", metavar="KIND", help="linkage, cam, flywheel, forces, balancing, efficiency, structure "
                                                "or cycle")
    n.add_argument("-o", "--output", metavar="FILE", help="write it to FILE (never overwrites)")
    g = sub.add_parser("gallery", help="a static HTML page of the figures and checks of the scenes in DIR")
    g.add_argument("folder", metavar="DIR", help="the scenes: DIR/*.toml")
    g.add_argument("-d", "--directory", metavar="SITE", required=True,
                   help="write SITE/index.html, each figure and a copy of each scene (exit 2 if a scene failed)")
    return p


def _jobs(text: str) -> int:
    if not text.isdigit() or not 1 <= int(text) <= 256:
        raise argparse.ArgumentTypeError(f"{text!r}: give a number of processes from 1 to 256")
    return int(text)


def say(text: str) -> None:
    """One line on stderr, whatever a user's names and titles hold."""
    print(printable(text), file=sys.stderr)


def main(argv: Sequence[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    args.current = None  # the scene being read, for the messages
    try:
        import numpy as np  # here, not at the top: --help and --version need no numpy (~50 ms)

        # Numerical trouble is ours to detect and say in words (a warning naming the value, or a
        # refusal); numpy's and the libraries' own warnings never reach the user's stderr.
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            if args.command == "render":
                return _render(args)
            if args.command == "check":
                return _check(args)
            if args.command == "batch":
                return _batch(args)
            if args.command == "steps":
                return _steps(args)
            if args.command in ("examples", "new", "gallery"):
                return _packaged(args)
            return _bench(args)
    except GraphmechError as e:  # a bad scene, a construction that cannot be made, another refusal
        say(one_line(e, _file_name(args)))
        return EXIT_BAD_INPUT
    except BrokenPipeError:  # `graphmech steps … | head`: the reader has all it wants
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return EXIT_OK
    except OSError as e:
        say(f"graphmech: {e.filename or ''}{': ' if e.filename else ''}{e.strerror or e}")
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        return 130
    except Exception as e:  # a bug of ours: still one line, never a traceback
        say(f"{_file_name(args) or 'graphmech'}: internal error ({type(e).__name__}: {e}); please report it with the scene")
        return EXIT_INTERNAL


def _file_name(args: argparse.Namespace) -> str | None:
    """The scene file the messages name, as the scene readers name it."""
    return Path(args.current).name if args.current else None


def _warn(args: argparse.Namespace, where: str, found: Sequence[str]) -> None:
    """The warnings found while doing ``where``, one line each, unless -q."""
    if not args.quiet:
        for w in found:
            say(f"{where}: warning: {w}")


def _variants(args: argparse.Namespace) -> list[dict[str, Any]]:
    from graphmech.variants import combinations, parse_assignment

    return combinations([parse_assignment(a) for a in args.assign])


# ---------------------------------------------------------------------------- render


def _figure_format(args: argparse.Namespace) -> tuple[str, float]:
    """The format of the figures and the PNG's dpi: --format, else -o's extension, else SVG
    (-o's extension must be that format's: never SVG bytes in a .png); refused before anything
    is drawn, and so is a PDF or PNG with no browser to print it."""
    from graphmech.render.export import DPI, check_dpi, format_of, require_browser

    fmt = format_of(args.output or "", args.format)
    dpi = DPI if args.dpi is None else check_dpi(args.dpi)
    require_browser(fmt)
    return fmt, dpi


def _render(args: argparse.Namespace) -> int:
    from graphmech import batch

    variants = _variants(args)
    todo = batch.jobs(args.scenes, variants, args.page)
    if args.output and args.directory:
        say("graphmech: give -o FILE or -d DIR, not both")
        return EXIT_BAD_INPUT
    if args.output and len(todo) > 1:
        many = "scene" if len(args.scenes) > 1 else "variant"
        say(f"graphmech: -o takes one figure; this makes {len(todo)} (one per {many}): use -d DIR")
        return EXIT_BAD_INPUT
    if not args.output:
        batch.distinct_names(todo)
    fmt, dpi = _figure_format(args)
    options = batch.Options(figure=fmt, dpi=dpi)
    out_dir = Path(args.directory or ".")
    if args.directory and not out_dir.is_dir():
        say(f"graphmech: {out_dir}: folder does not exist")
        return EXIT_BAD_INPUT
    results = batch.run(todo, options)  # everything first: one bad scene writes nothing
    for r in results:
        if r.error is not None:
            say(r.error)
            return EXIT_BAD_INPUT
        _warn(args, r.job.label, r.warnings)
    outputs = [(Path(args.output) if args.output else out_dir / f"{r.name}.{fmt}", r.figure) for r in results]
    for out, _ in outputs:
        if not Path(os.path.realpath(out)).parent.is_dir():
            say(f"graphmech: {out}: folder does not exist")
            return EXIT_BAD_INPUT
        if out.is_dir():
            say(f"graphmech: {out}: is a folder; give a file name")
            return EXIT_BAD_INPUT
    for out, data in outputs:
        assert data is not None
        write_atomic(out, data)
        print(out)
    return EXIT_OK


# ---------------------------------------------------------------------------- check


def _parse_measured(items: Sequence[str]) -> list[tuple[str, float]]:
    """NAME=VALUE pairs, each value as written (its digits and sign are judged)."""
    from graphmech.problems.reader import Written

    out: list[tuple[str, float]] = []
    for item in items:
        for part in item.split(","):
            name, sep, value = part.partition("=")
            if not sep or not name.strip():
                raise SceneError([(f"--measured {part.strip()}", "expected NAME=VALUE with a finite number")],
                                 COMMAND_LINE)
            try:
                out.append((name.strip(), Written(value)))
            except ValueError as e:
                raise SceneError([(f"--measured {name.strip()}", str(e))],
                                 COMMAND_LINE) from None
    return out


def _check(args: argparse.Namespace) -> int:
    from graphmech import batch
    from graphmech.tolerances import MAX_PRECISION_MM

    if args.precision is not None and not 0 < args.precision <= MAX_PRECISION_MM:
        say(f"graphmech: --precision must be a number of mm above 0 and at most {MAX_PRECISION_MM:g}")
        return EXIT_BAD_INPUT
    extra = tuple(_parse_measured(args.measured))
    variants = _variants(args)
    args.current = args.scene
    options = batch.Options(figure=None, check=True, measured=extra, precision=args.precision)
    if not args.assign:  # one scene as written: its table, or its refusal
        table = batch.problem(batch.Job(args.scene, {}, args.page)).check(extra, args.precision)
        print(table.to_json() if args.json else table.text())
        if not args.json:
            _warn(args, _file_name(args) or "", table.warnings)
        return EXIT_OUT_OF_TOLERANCE if not table.ok else EXIT_OK
    results = batch.run(batch.jobs([args.scene], variants, args.page), options)
    good = [r for r in results if r.table is not None]
    if args.json:
        print(json.dumps(batch.check_documents(results), indent=1, ensure_ascii=False, allow_nan=False))
    elif good:
        print(batch.variants_table(results))
    for r in results:
        if r.error is not None:
            say(r.error)
        elif not args.json:
            _warn(args, r.job.label, r.warnings)
    if len(good) < len(results):
        return EXIT_BAD_INPUT
    return EXIT_OUT_OF_TOLERANCE if any(not r.table.ok for r in good if r.table) else EXIT_OK


# ---------------------------------------------------------------------------- batch


def _batch(args: argparse.Namespace) -> int:
    from graphmech import batch

    out_dir = Path(args.directory)
    if not out_dir.is_dir():
        say(f"graphmech: {out_dir}: {'not a folder' if out_dir.exists() else 'folder does not exist'}")
        return EXIT_BAD_INPUT
    args.output = None
    fmt, dpi = _figure_format(args)
    todo = batch.jobs(args.scenes, _variants(args), args.page)
    batch.distinct_names(todo)
    failed = 0

    def write(r: batch.Result) -> None:  # as each job is done: the others go on whatever it met
        nonlocal failed
        if r.error is None:
            assert r.figure is not None and r.table is not None
            try:
                write_atomic(out_dir / f"{r.name}.{fmt}", r.figure)
                write_atomic(out_dir / f"{r.name}.json", r.table.to_json() + "\n")
            except OSError as e:
                r = batch.Result(r.job, error=f"{r.job.label}: {e.strerror or e}")
        if r.error is not None:
            failed += 1
            say(r.error)
            return
        _warn(args, r.job.label, r.warnings)
        print(out_dir / f"{r.name}.{fmt}")

    batch.run(todo, batch.Options(figure=fmt, dpi=dpi, check=True), args.jobs, done=write)
    if failed:
        say(f"graphmech: {failed} of {len(todo)} failed; the other {len(todo) - failed} written")
    return EXIT_BAD_INPUT if failed else EXIT_OK


# ---------------------------------------------------------------------------- steps


def _steps(args: argparse.Namespace) -> int:
    """The construction protocol on stdout, one numbered step a line (Problem.steps)."""
    from graphmech import batch

    variants = _variants(args)
    if len(variants) > 1:
        say(f"graphmech: steps takes one variant; --set makes {len(variants)}: give one value per key")
        return EXIT_BAD_INPUT
    args.current = args.scene
    lines = batch.problem(batch.Job(args.scene, variants[0], args.page)).steps()
    print("\n".join(f"{k}. {line}" for k, line in enumerate(lines, 1)))
    return EXIT_OK


# ---------------------------------------------------------------------------- examples, new, gallery


def _packaged(args: argparse.Namespace) -> int:
    from graphmech import packaged

    if args.command == "gallery":
        from graphmech.gallery import make_gallery

        index, entries = make_gallery(args.folder, args.directory)
        for e in entries:
            if e.error is not None:
                say(f"graphmech gallery: {e.error}")
        print(index)
        return EXIT_BAD_INPUT if any(e.error is not None for e in entries) else EXIT_OK
    if args.command == "new":
        text = packaged.template(args.kind)
        if args.output is None:
            sys.stdout.write(text)
        else:
            packaged.write_new(args.output, text)
            print(args.output)
        return EXIT_OK
    if args.name is None:
        names = packaged.example_names()
        width = max(map(len, names))
        for name in names:
            print(f"{name:<{width}}  {packaged.example_title(name)}")
        return EXIT_OK
    if args.output and args.directory:
        say("graphmech: give -o FILE or -d DIR, not both")
        return EXIT_BAD_INPUT
    scene = packaged.example(args.name)
    out = Path(args.output) if args.output else Path(args.directory or ".") / scene.name
    packaged.write_new(out, scene.read_text(encoding="utf-8"))
    print(out)
    return EXIT_OK


# ---------------------------------------------------------------------------- bench


def _bench(args: argparse.Namespace) -> int:
    from graphmech.bench import compare, read_records, run_bench

    old = read_records(args.compare) if args.compare else None  # a bad file: refused before the run
    doc = run_bench(quick=args.quick, explicit=args.explicit)
    changes = compare(old, doc["records"]) if old is not None else None
    text = json.dumps(doc, indent=1, allow_nan=False)
    if args.output:
        out = Path(args.output)
        out.mkdir(parents=True, exist_ok=True)
        write_atomic(out / "bench.json", text + "\n")
    if args.json:
        print(text if changes is None else json.dumps({**doc, "compare": changes}, indent=1, allow_nan=False))
    else:
        for r in doc["records"]:
            err = r["max_rel_error"]
            tail = f"max rel error {err:.1e}" if err is not None else r.get("note", "")
            print(f"{r['method']:<18} {r['case']:<24} n={r['n']:<6}{r['seconds'] * 1e6:>12.1f} µs   {tail}")
        for note in doc.get("notes", []):
            print(note)
        if changes is not None:
            print(f"against {args.compare}:")
            for line in changes:
                print("  " + line)
    if args.output:  # the plots last: without graphmech[plots] the results above still stand
        from graphmech.render.plots import error_against_time_plots, error_time_plots  # matplotlib only here

        error_time_plots(doc["records"], Path(args.output))
        error_against_time_plots(doc["records"], Path(args.output))
    return EXIT_OK


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
