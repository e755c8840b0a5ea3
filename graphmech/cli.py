"""The ``graphmech`` command: render, check, bench.

Exit status: 0 success; 1 a measured value is out of tolerance; 2 bad input (one line naming
the file, the key path and what is wrong — never a traceback). Output files are written to a
temporary file and renamed, so a failure leaves nothing half-written and an existing file
untouched.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import math
import os
import sys
from pathlib import Path
from typing import Any, Sequence

from graphmech.errors import DegenerateConstruction, GraphmechError, SceneError
from graphmech.files import write_atomic

EXIT_OK, EXIT_OUT_OF_TOLERANCE, EXIT_BAD_INPUT, EXIT_INTERNAL = 0, 1, 2, 3


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # one line, exit 2 (argparse's own convention too)
        self.exit(EXIT_BAD_INPUT, f"graphmech: {message}\n")


def _parser() -> argparse.ArgumentParser:
    p = _Parser(prog="graphmech", description="Textbook graphical methods as exact, checked constructions.")
    sub = p.add_subparsers(dest="command", required=True, parser_class=_Parser)
    r = sub.add_parser("render", help="draw a scene to SVG")
    r.add_argument("scenes", nargs="+", metavar="SCENE")
    r.add_argument("-o", "--output", help="output SVG (one scene only)")
    r.add_argument("-d", "--directory", help="write <scene name>.svg into this folder")
    c = sub.add_parser("check", help="the check table: graphical vs exact, and verdicts on measured values")
    c.add_argument("scene", metavar="SCENE")
    c.add_argument("--json", action="store_true", help="machine-readable output")
    c.add_argument("--measured", action="append", default=[], metavar="NAME=VALUE",
                   help="a value you measured: v_C=0.26 (SI) or pc=52 (drawn mm); repeatable, or comma-separated")
    c.add_argument("--precision", type=float, metavar="MM", help="drawing precision, mm (default: the scene's, else 0.5)")
    b = sub.add_parser("bench", help="run time and error of the graphical methods against the exact ones")
    b.add_argument("--json", action="store_true")
    b.add_argument("-o", "--output", metavar="DIR", help="also write bench.json and log-log plots of error and time into DIR")
    b.add_argument("--quick", action="store_true", help="fewer repetitions")
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        if args.command == "render":
            return _render(args)
        if args.command == "check":
            return _check(args)
        return _bench(args)
    except SceneError as e:
        print(e.one_line(), file=sys.stderr)
        return EXIT_BAD_INPUT
    except DegenerateConstruction as e:
        print(f"{getattr(args, 'scene', None) or args.current}: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except GraphmechError as e:
        print(f"graphmech: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except OSError as e:
        print(f"graphmech: {e.filename or ''}{': ' if e.filename else ''}{e.strerror or e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        return 130
    except Exception as e:  # a bug of ours: still one line, never a traceback
        print(f"graphmech: internal error ({type(e).__name__}: {e}); please report it with the scene",
              file=sys.stderr)
        return EXIT_INTERNAL


# ---------------------------------------------------------------------------- render


def render_scene(path: str | os.PathLike[str]) -> tuple[str, list[str]]:
    """The SVG text of a scene and its warnings."""
    import graphmech
    from graphmech.check import analyse, page_size, position_text, rows_that_fit
    from graphmech.methods.figures import linkage_sheet
    from graphmech.render.svg import render_svg
    from graphmech.scene import load_scene

    scene = load_scene(path)
    footer = (f"graphmech {graphmech.__version__}",)
    if scene.efficiency is not None or scene.balancing is not None:
        if scene.efficiency is not None:
            from graphmech.efficiency_check import analyse_efficiency as analyse_forces, efficiency_figure as figure
        else:
            from graphmech.balancing_check import analyse_balancing as analyse_forces, balancing_figure as figure
        fan = analyse_forces(scene)
        warnings = list(fan.warnings)
        svg = render_svg(figure(fan, page_size(scene), footer), _id_prefix(path), on_warning=warnings.append)
        return svg, warnings
    if scene.structure is not None:
        from graphmech.methods.structure_figures import structure_sheet
        from graphmech.structure_check import analyse_structure

        san = analyse_structure(scene)
        sheet = structure_sheet(scene.title, san, page_size(scene), footer)
        warnings = list(san.warnings)
        return render_svg(sheet, _id_prefix(path), on_warning=warnings.append), warnings
    if scene.flywheel is not None:
        from graphmech.flywheel_check import analyse_flywheel
        from graphmech.methods.flywheel_figures import flywheel_sheet
        from graphmech.render.primitives import Sheet

        fan = analyse_flywheel(scene)
        cycle_panels = [p for p in scene.show if p not in ("mechanism", "rundown")]
        if fan.design is None and not any(p in scene.show for p in ("mechanism", "rundown")):
            raise SceneError([("show", "nothing to draw: this flywheel scene asks for no diagram; "
                                       "use graphmech check")], scene.source)
        panels: list[Any] = []
        if "mechanism" in scene.show and scene.linkage is not None:
            panels += _mechanism_panels(scene, footer)
        if cycle_panels and fan.design is not None:
            panels += flywheel_sheet(scene.title, fan.design, cycle_panels, page_size(scene), footer).panels
        if "rundown" in scene.show:
            from graphmech.methods.braking_figures import rundown_panel

            b = scene.flywheel.braking
            panels.append(rundown_panel(fan.braking_inertia, scene.flywheel.machine.omega_m, b.moment, b.time_limit))
        sheet = Sheet(scene.title, tuple(panels), page_size(scene), footer)
        warnings = list(fan.warnings)
        return render_svg(sheet, _id_prefix(path), on_warning=warnings.append), warnings
    if scene.forces is not None:
        from graphmech.force_check import render_forces

        sheet, warnings = render_forces(scene, footer)
        return render_svg(sheet, _id_prefix(path), on_warning=warnings.append), warnings
    if scene.cam is not None:
        from graphmech.cam_check import analyse_cam
        from graphmech.methods.cam_figures import cam_sheet

        can = analyse_cam(scene)
        sheet = cam_sheet(scene.title, can.cam, can.drawn, can.scales, list(scene.show), page_size(scene),
                          roller_circles=scene.cam.roller_circles, marks=can.marks, footer=footer)
        warnings = list(can.warnings)
        return render_svg(sheet, _id_prefix(path), on_warning=warnings.append), warnings
    if scene.cycle is not None:
        from graphmech.cycle_check import analyse_cycle
        from graphmech.methods.cycle_figures import cycle_sheet

        can = analyse_cycle(scene)
        sheet = cycle_sheet(scene.title, can, list(scene.show), page_size(scene), footer)
        warnings = list(can.warnings)
        return render_svg(sheet, _id_prefix(path), on_warning=warnings.append), warnings
    fit = rows_that_fit(page_size(scene))
    if len(scene.positions.values) > fit:
        raise SceneError([("driver", f"{len(scene.positions.values)} positions do not fit one sheet of "
                                     f"{page_size(scene)[0]:g} × {page_size(scene)[1]:g} mm (at most {fit}, one row "
                                     "of panels each): split the scene or choose a larger [page] size; "
                                     "`graphmech check` takes up to 3600")], str(path))
    an = analyse(scene)
    b = an.build
    texts = [position_text(b, lab) for lab in an.labels]
    from graphmech.methods.polygons import PANELS

    sheet = linkage_sheet(scene.title, b.linkage, b, an.plan, an.solutions, an.labels, texts, an.scales,
                          [s for s in scene.show if s in PANELS],
                          page_size(scene), footer)
    if "instant_centres" in scene.show:
        from dataclasses import replace

        from graphmech.methods.ic_figures import ic_panels

        sheet = replace(sheet, panels=sheet.panels + tuple(ic_panels(an, page_size(scene))))
    warnings = list(an.warnings)
    svg = render_svg(sheet, _id_prefix(path), on_warning=warnings.append)
    return svg, warnings


def _mechanism_panels(scene: Any, footer: tuple[str, ...]) -> list[Any]:
    """A flywheel scene's mechanism, drawn at position 1 (where φ = 0) as a linkage scene would."""
    import dataclasses

    from graphmech.check import analyse, page_size, position_text
    from graphmech.methods.figures import linkage_sheet
    from graphmech.mechanisms.linkage import Positions

    first = Positions(scene.positions.values[:1], scene.positions.labels[:1])
    lscene = dataclasses.replace(scene, show=("mechanism",), find=(), measured=(), flywheel=None, positions=first)
    an = analyse(lscene)
    texts = [f"position 1 (φ = 0), {position_text(an.build, lab)}" for lab in an.labels]
    sheet = linkage_sheet(scene.title, an.build.linkage, an.build, an.plan, an.solutions, an.labels, texts,
                          an.scales, ["mechanism"], page_size(scene), footer)
    return [dataclasses.replace(p, row=0) for p in sheet.panels]


def _id_prefix(path: str | os.PathLike[str]) -> str:
    """Element ids start with a hash of the scene, so two figures inline on one page don't clash."""
    return "g" + hashlib.sha256(Path(path).read_bytes()).hexdigest()[:8]


def _render(args: argparse.Namespace) -> int:
    if args.output and len(args.scenes) > 1:
        print("graphmech: -o takes one scene; use -d DIR for several", file=sys.stderr)
        return EXIT_BAD_INPUT
    outputs = []
    for s in args.scenes:  # render everything first: one bad scene writes nothing
        args.current = s  # for the message if it cannot be constructed
        svg, warnings = render_scene(s)
        for w in warnings:
            print(f"{s}: warning: {w}", file=sys.stderr)
        if args.output:
            out = Path(args.output)
        else:
            out = Path(args.directory or ".") / (Path(s).stem + ".svg")
        outputs.append((out, svg))
    for out, svg in outputs:
        if not Path(os.path.realpath(out)).parent.is_dir():
            print(f"graphmech: {out}: folder does not exist", file=sys.stderr)
            return EXIT_BAD_INPUT
        if out.is_dir():
            print(f"graphmech: {out}: is a folder; give a file name", file=sys.stderr)
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
                                 "command line")
            out.append((name.strip(), v))
    return out


def _check(args: argparse.Namespace) -> int:
    from graphmech.check import analyse, judge
    from graphmech.scene import load_scene

    from graphmech.tolerances import MAX_PRECISION_MM

    if args.precision is not None and not 0 < args.precision <= MAX_PRECISION_MM:
        print(f"graphmech: --precision must be a number of mm above 0 and at most {MAX_PRECISION_MM:g}",
              file=sys.stderr)
        return EXIT_BAD_INPUT
    extra = _parse_measured(args.measured)
    scene = load_scene(args.scene)
    extra_doc: dict[str, Any] = {}
    if scene.efficiency is not None:
        from graphmech.efficiency_check import analyse_efficiency, judge_efficiency

        an = analyse_efficiency(scene, tuple(extra))
        verdicts = judge_efficiency(an, args.precision)
    elif scene.balancing is not None:
        from graphmech.balancing_check import analyse_balancing, judge_balancing

        an = analyse_balancing(scene, tuple(extra))
        verdicts = judge_balancing(an, args.precision)
    elif scene.flywheel is not None:
        from graphmech.flywheel_check import analyse_flywheel, judge_flywheel

        an = analyse_flywheel(scene, tuple(extra))
        verdicts = judge_flywheel(an, args.precision)
        if an.motion is not None:
            extra_doc["true_motion"] = an.motion_summary()
        if an.braking is not None:
            extra_doc["braking"] = an.braking_summary()
    elif scene.forces is not None:
        from graphmech.force_check import analyse_forces

        an = analyse_forces(scene, tuple(extra))
        verdicts = an.verdicts
        if scene.forces.model.has_friction:
            extra_doc["friction"] = an.friction_summary()
    elif scene.structure is not None:
        from graphmech.structure_check import analyse_structure, judge_structure

        an = analyse_structure(scene)
        verdicts = judge_structure(an, tuple(extra))
        extra_doc["structure"] = an.summary()
    elif scene.cam is not None:
        from graphmech.cam_check import analyse_cam, judge_cam

        an = analyse_cam(scene, tuple(extra))
        verdicts = judge_cam(an, args.precision)
        extra_doc["impacts"] = an.impacts
        if an.divisions:
            extra_doc["divisions"] = an.divisions
    elif scene.cycle is not None:
        from graphmech.cycle_check import analyse_cycle, judge_cycle

        an = analyse_cycle(scene, tuple(extra))
        verdicts = judge_cycle(an, args.precision)
        extra_doc.update(an.summary)
    else:
        an = analyse(scene, tuple(extra))
        verdicts = judge(an, args.precision)
        if an.instant_centres is not None:
            from graphmech.ic_check import summary

            extra_doc["instant_centres"] = summary(an)
    bad = any(not v.ok for v in verdicts)
    if args.json:
        doc = {"quantities": [r.as_dict() for r in an.rows], "measured": [v.as_dict() for v in verdicts],
               "warnings": list(an.warnings), "scales": an.scales, **extra_doc}
        print(json.dumps(doc, indent=1, ensure_ascii=False, allow_nan=False))
    else:
        print(_table(an, verdicts))
        if scene.structure is not None:
            from graphmech.structure_check import text_summary

            print("\n".join(text_summary(an)))
        if extra_doc.get("braking"):
            br = extra_doc["braking"]
            verdict = "" if br["ok"] is None else (f" ≤ {br['time_limit']:g} s: meets the requirement" if br["ok"]
                                                     else f" > {br['time_limit']:g} s: DOES NOT meet the requirement")
            print(f"stopping time {br['t_stop']:.6g} s{verdict}")
        for line in getattr(an, "summary_lines", lambda: [])():  # a cycle's class, ranges and diagrams
            print(line)
        for w in an.warnings:
            print(f"warning: {w}", file=sys.stderr)
    return EXIT_OUT_OF_TOLERANCE if bad else EXIT_OK


def _table(an: Any, verdicts: Sequence[Any]) -> str:
    lines = [f"{an.scene.title}", "  ".join(an.scale_notes())]
    if an.rows:
        lines.append(f"{'quantity':<16} {'drawn mm':>11} {'μ':>11} {'graphical':>16} {'exact':>16} {'rel.error':>9}  unit")
        for r in an.rows:
            drawn = "" if r.drawn_mm is None else f"{r.drawn_mm:.3f}"
            flag = "  ILL-CONDITIONED" if r.ill_conditioned else ""
            lines.append(f"{r.name:<16} {drawn:>11} {r.scale:>11.5g} {r.graphical:>16.9g} {r.exact:>16.9g}"
                         f" {r.rel_error:>9.1e}  {r.unit}{flag}")
    if verdicts:
        lines.append(f"{'measured':<16} {'value':>11} {'expected':>13} {'± tol':>9}  verdict")
        for v in verdicts:
            lines.append(f"{v.name:<16} {v.measured:>11.6g} {v.expected:>13.6g} {v.tolerance:>9.3g}  "
                         f"{'ok' if v.ok else 'OUT OF TOLERANCE'} ({v.unit})")
    return "\n".join(lines)


# ---------------------------------------------------------------------------- bench


def _bench(args: argparse.Namespace) -> int:
    from graphmech.bench import run_bench

    doc = run_bench(quick=args.quick)
    text = json.dumps(doc, indent=1, allow_nan=False)
    if args.output:
        out = Path(args.output)
        out.mkdir(parents=True, exist_ok=True)
        write_atomic(out / "bench.json", text + "\n")
        from graphmech.render.plots import error_time_plots  # matplotlib only when plots are asked for

        error_time_plots(doc["records"], out)
    if args.json:
        print(text)
    else:
        for r in doc["records"]:
            err = r["max_rel_error"]
            tail = f"max rel error {err:.1e}" if err is not None else r.get("note", "")
            print(f"{r['method']:<18} {r['case']:<24} n={r['n']:<6}{r['seconds'] * 1e6:>12.1f} µs   {tail}")
        for note in doc.get("notes", []):
            print(note)
    return EXIT_OK


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
