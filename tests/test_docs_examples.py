"""Every scene in docs/scene-format.md is not only valid but constructs and checks."""
from __future__ import annotations

import math
import re

import pytest

from graphmech.problems.linkage.check import analyse, judge
from graphmech.scene import parse_scene
from tests.conftest import ROOT

import tomllib

BLOCKS = re.findall(r"```toml\n(.*?)```", (ROOT / "docs" / "scene-format.md").read_text(encoding="utf-8"), re.S)


@pytest.mark.parametrize("text", BLOCKS, ids=[f"example{i}" for i in range(len(BLOCKS))])
def test_documented_scene_constructs_and_agrees_with_exact(text):
    scene = parse_scene(tomllib.loads(text), "doc.toml")
    if scene.kind == "flywheel":  # its analysis is graphmech.problems.flywheel.check's; here it is parsed
        pytest.importorskip("graphmech.problems.flywheel.check")
        return
    if scene.kind == "forces":  # the force polygons against the matrix method and the lever
        from graphmech.problems.forces.check import analyse_forces

        fan = analyse_forces(scene)
        assert fan.rows
        for row in fan.rows:
            assert row.rel_error <= 1e-9 or row.ill_conditioned, row
        return
    if scene.kind == "efficiency" or scene.kind == "balancing":
        if scene.kind == "efficiency":
            from graphmech.problems.efficiency.check import analyse_efficiency as analyse_, judge_efficiency as judge_
        else:
            from graphmech.problems.balancing.check import analyse_balancing as analyse_, judge_balancing as judge_
        fan = analyse_(scene)
        assert fan.rows
        for row in fan.rows:  # polygons against the closed forms
            assert row.rel_error <= 1e-9 or row.ill_conditioned, row
        for verdict in judge_(fan):
            assert verdict.ok, verdict
        return
    if scene.kind == "other":  # the Geneva wheel's construction, the screw's branches against exact/geneva
        from graphmech.problems.other.check import analyse_other

        oan = analyse_other(scene)
        assert oan.rows and all(row.rel_error <= 1e-12 for row in oan.rows), oan.rows
        return
    if scene.kind == "centres":  # the centres by Kennedy against the pairs' exact velocity equations
        from graphmech.problems.centres.check import analyse_centres

        can = analyse_centres(scene)
        assert can.rows and all(row.rel_error <= 1e-12 for row in can.rows), can.rows
        return
    if scene.kind == "structure":  # the count against the Jacobian's rank (graphmech.problems.structure.check)
        from graphmech.problems.structure.check import analyse_structure

        san = analyse_structure(scene)
        assert san.mobility is not None or san.cases
        for row in san.rows:
            assert row.graphical == row.exact, row
        return
    if scene.kind == "trains":  # the book's split against the exact linear system
        from graphmech.problems import check as check_train

        tan, verdicts, _, _ = check_train(scene)
        assert tan.rows
        for row in tan.rows:
            assert row.rel_error <= 1e-12, row
        for verdict in verdicts:
            assert verdict.ok, verdict
        return
    if scene.kind == "synthesis":  # the construction against the closed forms, each design re-analysed
        from graphmech.problems import check as check_synthesis

        san, verdicts, _, _ = check_synthesis(scene)
        assert san.rows
        for row in san.rows:
            assert row.rel_error <= 1e-9, row
        for verdict in verdicts:
            assert verdict.ok, verdict
        return
    if scene.kind == "gears":  # the constructions against the closed forms (spur or helical/bevel/worm: the kind decides)
        from graphmech.problems import check as check_kind

        gan, verdicts, _, _ = check_kind(scene)
        assert gan.rows
        for row in gan.rows:
            assert row.rel_error <= 1e-9, row
        for verdict in verdicts:
            assert verdict.ok, verdict
        return
    if scene.kind == "cam":  # through the kind: a motion law's inversion, or a given profile's analysis
        from graphmech.problems import check as check_cam

        can, cam_verdicts, _, _ = check_cam(scene)
        for row in can.rows:  # a discretising method: finite, and within a few % at the scene's step
            assert math.isfinite(row.graphical) and math.isfinite(row.exact), row
        for verdict in cam_verdicts:
            assert verdict.ok, verdict
        return
    if scene.kind == "cycle":  # a full cycle / the characteristics: drawn against closed forms
        from graphmech.problems.cycle.check import analyse_cycle, judge_cycle

        can = analyse_cycle(scene)
        for row in can.rows:  # the diagrams' chords carry O(1/N²); everything else is exact
            limit = 0.1 if "_diagram@" in row.name else 1e-9
            assert math.isfinite(row.graphical) and row.rel_error <= limit, row
        for verdict in judge_cycle(can):
            assert verdict.ok, verdict
        return
    an = analyse(scene)
    assert any(s is not None for s in an.solutions)
    for row in an.rows:
        assert row.rel_error <= 1e-9 or row.ill_conditioned, row
    for verdict in judge(an):  # what the documented student measured is right
        assert verdict.ok, verdict
