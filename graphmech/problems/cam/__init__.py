"""A disc cam (``[cam]``) drawn by inversion (反转法): the pitch curve and the working profile as
the rollers' envelope, the s–δ, v–δ, a–δ diagrams, the largest pressure angle and any undercut,
checked against the exact envelope solution.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from graphmech.problems.kind import Bench, Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.cam.scene import CamScene
    from graphmech.problems.judging import Verdict
    from graphmech.problems.reader import Reader, Scene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[Any]:
    from graphmech.problems.cam.scene import parse_cam_scene

    if isinstance(data.get("cam"), dict) and "profile" in data["cam"]:  # the profile given: its analysis
        from graphmech.problems.cam.profile_given import parse_given_scene

        return parse_given_scene(data, source, top, order)
    return parse_cam_scene(data, source, top, order)


def _given(scene: Scene[Any]) -> bool:
    return type(scene.problem).__name__ == "GivenCamScene"


def _analyse(scene: Scene[Any], extra: Extra) -> Any:
    from graphmech.problems.cam.check import analyse_cam

    if _given(scene):
        from graphmech.problems.cam.profile_given import analyse_given

        return analyse_given(scene, extra)
    return analyse_cam(scene, extra)


def _judge(an: Any, extra: Extra) -> list[Verdict]:
    from graphmech.problems.cam.check import judge_cam

    if _given(an.scene):
        from graphmech.problems.cam.profile_given import judge_given

        return judge_given(an)
    return judge_cam(an)


def _sheet(scene: Scene[Any], footer: Footer) -> tuple[Sheet, list[str]]:
    if _given(scene):
        from graphmech.problems.cam.given_figures import given_sheet

        return given_sheet(scene, footer)
    return _law_sheet(scene, footer)


def _law_sheet(scene: Scene[CamScene], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.cam.check import analyse_cam
    from graphmech.problems.cam.figures import cam_sheet
    from graphmech.problems.judging import finite
    from graphmech.problems.reader import page_size

    an = finite(analyse_cam(scene, (), estimates=False))  # a drawing needs no error estimates
    sheet = cam_sheet(scene.title, an.cam, an.drawn, an.scales, list(scene.show), page_size(scene),
                      roller_circles=scene.problem.roller_circles, marks=an.marks, footer=footer,
                      notation=scene.page.notation)
    if scene.problem.coordinates:  # the working profile's table as handed in, beside the drawing
        from dataclasses import replace

        from graphmech.problems.cam.coordinates import coordinates_panel

        row = max((p.row or 0 for p in sheet.panels), default=-1) + 1  # a row of its own, under the drawing
        sheet = replace(sheet, panels=sheet.panels + (coordinates_panel(an.cam, an.divisions, scene.page.notation, row),))
    if scene.problem.forces is not None:  # the follower's force polygon with friction: beside a lone panel, else below
        from dataclasses import replace as _replace

        from graphmech.problems.cam.forces import forces_panel

        last = max((p.row or 0 for p in sheet.panels), default=-1)
        row = last if sum((p.row or 0) == last for p in sheet.panels) == 1 else last + 1
        panel = forces_panel(an.cam, scene.problem.forces, an.scales["F"], scene.page.notation)
        more: tuple[Any, ...] = (_replace(panel, row=row),)
        if an.drawn is not None and "l" in an.scales:  # the free body at δ, the polygon beside it
            from graphmech.problems.cam.forces import sketch_panel

            body = sketch_panel(an.cam, scene.problem.forces, an.drawn, an.scales["l"], scene.page.notation)
            row = last + 1
            more = (_replace(body, row=row), _replace(panel, row=row))
        sheet = _replace(sheet, panels=sheet.panels + more)
    return sheet, list(an.warnings)


def _extras(an: Any) -> dict[str, Any]:
    if _given(an.scene):
        from graphmech.problems.cam.profile_given import given_extras

        return given_extras(an)
    return {"impacts": an.impacts, **({"divisions": an.divisions} if an.divisions else {})}


def _steps(scene: Scene[Any]) -> list[str]:
    from graphmech.problems.cam.steps import cam_steps

    if _given(scene):
        from graphmech.problems.cam.profile_given import given_steps

        return given_steps(scene)

    return cam_steps(scene)


def _bench(quick: bool) -> Bench:
    from graphmech.problems.cam.bench import bench

    return bench(quick)


def _mixture(data: Mapping[str, Any]) -> tuple[str, str] | None:
    if "flywheel" in data:
        return ("flywheel", "a scene is a disc cam ([cam]) or a flywheel problem ([flywheel]), not both: "
                            "put each in a scene of its own")
    if "driver" in data:  # which of the two to read is anyone's guess
        return ("cam", "a scene is a linkage ([driver]) or a disc cam ([cam]), not both: "
                       "put the cam in a scene of its own")
    return None


KIND = Kind("cam", ("cam",), _read, _analyse, _judge, _sheet, _extras, bench=_bench, mixture=_mixture,
            steps=_steps)
