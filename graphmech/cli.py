"""The ``graphmech`` command: render, check, bench.

Exit status: 0 success; 1 a measured value is out of tolerance; 2 bad input (one line naming
the file, the key path and what is wrong — never a traceback). Output files are written to a
temporary file and renamed, so a failure leaves nothing half-written and an existing file
untouched.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys
import warnings
from pathlib import Path
from typing import Any, NoReturn, Sequence

from graphmech.errors import COMMAND_LINE, GraphmechError, SceneError, printable
from graphmech.files import write_atomic
from graphmech.scales import FIT, PAPER

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


def _parser() -> argparse.ArgumentParser:
    import graphmech

    p = _Parser(prog="graphmech", description="Textbook graphical methods as exact, checked constructions.")
    p.add_argument("--version", action="version", version=f"graphmech {graphmech.__version__}")
    sub = p.add_subparsers(dest="command", required=True, parser_class=_Parser)
    r = sub.add_parser("render", help="draw a scene to SVG")
    r.add_argument("scenes", nargs="+", metavar="SCENE")
    r.add_argument("-o", "--output", help="output SVG (one scene only)")
    r.add_argument("-d", "--directory", help="write <scene name>.svg into this folder")
    r.add_argument("--page", type=_paper, metavar="SIZE", help=PAGE_HELP)
    c = sub.add_parser("check", help="the check table: graphical vs exact, and verdicts on measured values")
    c.add_argument("scene", metavar="SCENE")
    c.add_argument("--json", action="store_true", help="machine-readable output")
    c.add_argument("--measured", action="append", default=[], metavar="NAME=VALUE",
                   help="a value you measured: v_C=0.26 (SI) or pc=52 (drawn mm); repeatable, or comma-separated")
    c.add_argument("--precision", type=float, metavar="MM", help="drawing precision, mm (default: the scene's, else 0.5)")
    c.add_argument("--page", type=_paper, metavar="SIZE",
                   help="the paper the scales are chosen for, instead of the scene's [page] size: " + PAPERS)
    b = sub.add_parser("bench", help="run time and error of the graphical methods against the exact ones")
    b.add_argument("--json", action="store_true")
    b.add_argument("-o", "--output", metavar="DIR", help="also write bench.json and log-log plots of error and time into DIR")
    b.add_argument("--quick", action="store_true", help="fewer repetitions")
    return p


def say(text: str) -> None:
    """One line on stderr, whatever a user's names and titles hold."""
    print(printable(text), file=sys.stderr)


def main(argv: Sequence[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    import numpy as np  # here, not at the top: --help and --version need no numpy (~50 ms)

    args.current = None  # the scene being read, for the messages
    try:
        # Numerical trouble is ours to detect and say in words (a warning naming the value, or a
        # refusal); numpy's and the libraries' own warnings never reach the user's stderr.
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            if args.command == "render":
                return _render(args)
            if args.command == "check":
                return _check(args)
            return _bench(args)
    except SceneError as e:
        say(e.one_line(_file_name(args)))
        return EXIT_BAD_INPUT
    except GraphmechError as e:  # a construction that cannot be made, or another refusal
        say(f"{_file_name(args) or 'graphmech'}: {e}")
        return EXIT_BAD_INPUT
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


# ---------------------------------------------------------------------------- render


def _render(args: argparse.Namespace) -> int:
    from graphmech.scene import render_scene

    if args.output and len(args.scenes) > 1:
        say("graphmech: -o takes one scene; use -d DIR for several")
        return EXIT_BAD_INPUT
    outputs = []
    for s in args.scenes:  # render everything first: one bad scene writes nothing
        args.current = s  # for the message if it cannot be constructed
        svg, found = render_scene(s, args.page)
        for w in found:
            say(f"{_file_name(args)}: warning: {w}")
        if args.output:
            out = Path(args.output)
        else:
            out = Path(args.directory or ".") / (Path(s).stem + ".svg")
        outputs.append((out, svg))
    for out, svg in outputs:
        if not Path(os.path.realpath(out)).parent.is_dir():
            say(f"graphmech: {out}: folder does not exist")
            return EXIT_BAD_INPUT
        if out.is_dir():
            say(f"graphmech: {out}: is a folder; give a file name")
            return EXIT_BAD_INPUT
    for out, svg in outputs:
        write_atomic(out, svg)
        print(out)
    return EXIT_OK


# ---------------------------------------------------------------------------- check


def _parse_measured(items: Sequence[str]) -> list[tuple[str, float]]:
    out = []
    for item in items:
        for part in item.split(","):
            name, sep, value = part.partition("=")
            try:
                v = float(value)
            except ValueError:
                v = math.nan
            if not sep or not name.strip() or not math.isfinite(v):
                raise SceneError([(f"--measured {part.strip()}", "expected NAME=VALUE with a finite number")],
                                 COMMAND_LINE)
            out.append((name.strip(), v))
    return out


def _check(args: argparse.Namespace) -> int:
    from graphmech.problems import check, with_precision
    from graphmech.scene import load_scene

    from graphmech.tolerances import MAX_PRECISION_MM

    if args.precision is not None and not 0 < args.precision <= MAX_PRECISION_MM:
        say(f"graphmech: --precision must be a number of mm above 0 and at most {MAX_PRECISION_MM:g}")
        return EXIT_BAD_INPUT
    extra = _parse_measured(args.measured)
    args.current = args.scene
    scene = with_precision(load_scene(args.scene, args.page), args.precision)
    an, verdicts, extra_doc, lines = check(scene, tuple(extra))
    bad = any(not v.ok for v in verdicts)
    if args.json:
        doc = {"quantities": [r.as_dict() for r in an.rows], "measured": [v.as_dict() for v in verdicts],
               "warnings": list(an.warnings), "scales": an.scales, **extra_doc}
        print(json.dumps(doc, indent=1, ensure_ascii=False, allow_nan=False))
    else:
        print(_table(an, verdicts))
        for line in lines:
            print(line)
        for w in an.warnings:
            say(f"{_file_name(args)}: warning: {w}")
    return EXIT_OUT_OF_TOLERANCE if bad else EXIT_OK


def _table(an: Any, verdicts: Sequence[Any]) -> str:
    lines = [f"{an.scene.title}", "  ".join(an.scale_notes())]
    if an.rows:
        lines.append(f"{'quantity':<16} {'drawn mm':>11} {'μ':>11} {'graphical':>16} {'exact':>16} {'rel.error':>9}  unit")
        for r in an.rows:
            drawn = "" if r.drawn_mm is None else f"{r.drawn_mm:.3f}"
            flag = "  ILL-CONDITIONED" if r.ill_conditioned else ""
            if r.error_estimate is not None:  # a discretised or read-off value: how accurate it says it is
                flag += f"  ±{_percent(r.error_estimate)} ({r.basis or r.error_source})"
            lines.append(f"{r.name:<16} {drawn:>11} {r.scale:>11.5g} {r.graphical:>16.9g} {r.exact:>16.9g}"
                         f" {r.rel_error:>9.1e}  {r.unit}{flag}")
    if verdicts:
        lines.append(f"{'measured':<16} {'value':>11} {'expected':>13} {'± tol':>9}  verdict")
        for v in verdicts:
            lines.append(f"{v.name:<16} {v.measured:>11.6g} {v.expected:>13.6g} {v.tolerance:>9.3g}  "
                         f"{'ok' if v.ok else 'OUT OF TOLERANCE'} ({v.unit})")
    return "\n".join(lines)


def _percent(fraction: float) -> str:
    """A relative error as the table prints it: '8 %', '0.013 %', '<1e-10 %'."""
    p = 100.0 * fraction
    return "<1e-10 %" if p < 1e-10 else f"{p:.2g} %"


# ---------------------------------------------------------------------------- bench


def _bench(args: argparse.Namespace) -> int:
    from graphmech.bench import run_bench

    doc = run_bench(quick=args.quick)
    text = json.dumps(doc, indent=1, allow_nan=False)
    if args.output:
        out = Path(args.output)
        out.mkdir(parents=True, exist_ok=True)
        write_atomic(out / "bench.json", text + "\n")
    if args.json:
        print(text)
    else:
        for r in doc["records"]:
            err = r["max_rel_error"]
            tail = f"max rel error {err:.1e}" if err is not None else r.get("note", "")
            print(f"{r['method']:<18} {r['case']:<24} n={r['n']:<6}{r['seconds'] * 1e6:>12.1f} µs   {tail}")
        for note in doc.get("notes", []):
            print(note)
    if args.output:  # the plots last: without graphmech[plots] the results above still stand
        from graphmech.render.plots import error_time_plots  # matplotlib only when plots are asked for

        error_time_plots(doc["records"], Path(args.output))
    return EXIT_OK


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
