"""Linkage synthesis (``[synthesis]``): a linkage designed by the book's construction — for now
from its time ratio K (``task = "time_ratio"``: a crank-rocker from the rocker, the frame and the
swing or one limit position, every design; an offset slider-crank from the stroke and the offset;
a guide bar from the frame and the ram's stroke) — its lengths measured at μl against the
closed forms, and each design re-analysed (Grashof, K, ψ, γ_min). The task is read, checked and
drawn by its own module (``time_ratio``); the positions and function tasks join beside it.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from graphmech.problems.kind import Bench, Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.judging import Verdict
    from graphmech.problems.reader import Reader, Scene
    from graphmech.problems.synthesis.check import SynthesisAnalysis
    from graphmech.problems.synthesis.scene import SynthesisScene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[SynthesisScene]:
    from graphmech.problems.synthesis.scene import parse_synthesis_scene

    return parse_synthesis_scene(data, source, top, order)


def _analyse(scene: Scene[SynthesisScene], extra: Extra) -> SynthesisAnalysis:
    from graphmech.problems.synthesis.check import analyse_synthesis

    return analyse_synthesis(scene, extra)


def _judge(an: SynthesisAnalysis, extra: Extra) -> list[Verdict]:
    from graphmech.problems.synthesis.check import judge_synthesis

    return judge_synthesis(an)


def _sheet(scene: Scene[SynthesisScene], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.judging import finite
    from graphmech.problems.reader import page_size
    from graphmech.problems.synthesis.check import analyse_synthesis
    from graphmech.problems.synthesis.figures import synthesis_sheet

    an = finite(analyse_synthesis(scene))
    return synthesis_sheet(an, page_size(scene), footer), list(an.warnings)


def _extras(an: SynthesisAnalysis) -> dict[str, Any]:
    return {"synthesis": {"task": an.scene.problem.task, "solutions": an.solutions}}


def _lines(an: SynthesisAnalysis) -> list[str]:
    from graphmech.problems.synthesis.check import text_lines

    return text_lines(an)


def _steps(scene: Scene[SynthesisScene]) -> list[str]:
    from graphmech.problems.synthesis.steps import synthesis_steps

    return synthesis_steps(scene)


def _bench(quick: bool) -> Bench:
    from graphmech.problems.synthesis.bench import bench

    return bench(quick)


KIND = Kind("synthesis", ("synthesis",), _read, _analyse, _judge, _sheet, _extras, _lines, steps=_steps, bench=_bench)
