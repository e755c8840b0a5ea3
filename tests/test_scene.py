"""Loading a scene (graphmech/scene.py): the file read (size, UTF-8, TOML), the kind that reads it
chosen from its tables, and whatever the data, a Scene or one SceneError. What each kind reads is
tested beside it (tests/problems/<kind>/test_scene.py); the reading toolkit in
tests/problems/test_reader.py."""

from __future__ import annotations

import hashlib
import math
import re
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphmech.errors import SceneError
from graphmech.scene import MAX_BYTES, id_prefix, load_scene, parse_scene, render_scene
from tests.conftest import ROOT, SCENES
from tests.mutation import mutate, scene_or_refusal, toml_values
from tests.scenes import doc_blocks, refusal, scene_text, write_scene

DOCS = ROOT / "docs" / "scene-format.md"
#: The four-bar at φ = 30° with a coupler point E, valid.
GOOD = scene_text("linkage/fourbar_phi30")


write = write_scene


def message_of(text: str) -> str:
    return str(refusal(text))


def test_a_misspelt_kinds_table_gets_a_suggestion_in_any_scene() -> None:
    assert message_of(GOOD + "\n[efficency]\ntype = 'incline'\n") == (
        "scene.toml: efficency: unknown key; did you mean efficiency?"
    )


def test_a_table_of_another_kind_is_not_called_a_misspelling_of_itself() -> None:
    """Two kinds' tables in one file: one kind reads it and refuses the other's table in one line,
    never with "cycle: unknown key; did you mean cycle?" (the registry's tables are suggestions
    for a misspelt key only)."""
    from graphmech.problems import tables

    for a in tables():
        for b in tables():
            if a == b:
                continue
            with pytest.raises(SceneError) as info:
                parse_scene({a: {}, b: {}}, "mix.toml")
            err = info.value
            assert "\n" not in str(err)
            for path, reason in err.problems:
                assert not reason.endswith(f"did you mean {path}?"), (a, b, path, reason)


def test_oversized_file_is_refused_before_parsing(tmp_path: Path) -> None:
    text = GOOD + "# " + "x" * MAX_BYTES + "\n= broken toml"
    with pytest.raises(SceneError) as info:
        load_scene(write(tmp_path, text))
    assert str(info.value) == (
        "scene.toml: file is larger than 1 MiB; a scene is a few kilobytes, refusing to read it"
    )


def test_toml_syntax_error_gives_the_line(tmp_path: Path) -> None:
    text = GOOD.replace("angle = 30", "angle = 30 deg")
    line = GOOD.splitlines().index("angle = 30") + 1
    with pytest.raises(SceneError) as info:
        load_scene(write(tmp_path, text))
    message = str(info.value)
    assert message.startswith(f"scene.toml: line {line}: invalid TOML: ")
    assert "\n" not in message


def test_not_utf8(tmp_path: Path) -> None:
    raw = GOOD.replace("φ = 30°", "phi = 30\xb0").encode("latin-1")
    with pytest.raises(SceneError) as info:
        load_scene(write(tmp_path, raw))
    assert (
        str(info.value) == "scene.toml: line 1: not UTF-8 text (byte 0xb0); save the file as UTF-8"
    )


def test_utf8_with_bom_is_read(tmp_path: Path) -> None:
    assert load_scene(write(tmp_path, b"\xef\xbb\xbf" + GOOD.encode())).title == "Four-bar, φ = 30°"


def test_missing_file(tmp_path: Path) -> None:
    with pytest.raises(SceneError, match=r"^nothere\.toml: cannot read the file"):
        load_scene(tmp_path / "nothere.toml")


@pytest.mark.parametrize("index", range(len(doc_blocks())))
def test_each_doc_example_parses(index: int, tmp_path: Path) -> None:
    scene = load_scene(write(tmp_path, doc_blocks()[index], "example.toml"))
    assert scene.source == "example.toml"
    if scene.kind == "cam":  # a cam scene
        assert scene.linkage is None and scene.positions is None
        return
    if scene.kind == "flywheel" and scene.linkage is None:  # a machine without a linkage
        assert scene.positions is None
        return
    if scene.kind in ("efficiency", "balancing", "structure", "gears", "trains", "synthesis", "other",
                      "centres"):  # no linkage
        assert scene.linkage is None and scene.positions is None
        return
    assert scene.linkage.frame_link not in scene.linkage.links()


# ------------------------------------------------------------------------------------------
# Which kind reads a scene
# ------------------------------------------------------------------------------------------


def test_a_scene_without_any_kinds_table_is_a_linkage() -> None:
    scene = parse_scene(tomllib.loads(GOOD), "fourbar.toml")
    assert scene.kind == "linkage"
    assert scene.linkage is not None and scene.linkage.frame_points["D"] == (pytest.approx(0.12), 0.0)


def test_the_first_kind_whose_table_the_file_has_reads_it() -> None:
    """[structure] comes first in the registry: with a linkage's tables beside it, the structure
    reader reads the file (and refuses the linkage's show), not the linkage reader."""
    with pytest.raises(SceneError) as info:
        parse_scene({**tomllib.loads(GOOD), "structure": {}}, "mix.toml")
    assert info.value.problems[:2] == [
        ("show[0]", "unknown value 'mechanism': use structure"),
        ("show[1]", "unknown value 'velocity': use structure"),
    ]
    forces = parse_scene({**tomllib.loads(GOOD), "forces": {}}, "forces.toml")
    assert forces.kind == "forces"


def test_a_kinds_mixture_rule_refuses_in_one_problem() -> None:
    with pytest.raises(SceneError) as info:
        parse_scene({**tomllib.loads(GOOD), "cam": {}}, "mix.toml")
    assert info.value.problems == [
        ("cam", "a scene is a linkage ([driver]) or a disc cam ([cam]), not both: "
                "put the cam in a scene of its own"),
    ]


@pytest.mark.parametrize("data", [[], "title", 5, None])
def test_a_scene_must_be_a_table(data: object) -> None:
    with pytest.raises(SceneError) as info:
        parse_scene(data, "odd.toml")  # type: ignore[arg-type]
    assert str(info.value) == "odd.toml: a scene must be a TOML table"


# ------------------------------------------------------------------------------------------
# render_scene and id_prefix
# ------------------------------------------------------------------------------------------


def test_render_scene_makes_the_reference_figure() -> None:
    svg, warnings = render_scene(SCENES / "kin.fourbar_instant_centres.toml")
    assert warnings == []
    assert svg == (ROOT / "figures" / "kin.fourbar_instant_centres.svg").read_text(encoding="utf-8")


def test_every_element_id_starts_with_the_scenes_prefix(tmp_path: Path) -> None:
    path = write(tmp_path, GOOD)
    svg, _ = render_scene(path)
    prefix = id_prefix(path)
    ids = re.findall(r' id="([^"]+)"', svg)
    assert len(ids) > 3
    assert all(i.startswith(prefix + "-") for i in ids), [i for i in ids if not i.startswith(prefix)]


def test_id_prefix_is_a_hash_of_the_bytes_not_of_the_name(tmp_path: Path) -> None:
    a = write(tmp_path, GOOD, "a.toml")
    b = write(tmp_path, GOOD, "b.toml")
    c = write(tmp_path, GOOD.replace("angle = 30", "angle = 31"), "c.toml")
    assert id_prefix(a) == id_prefix(b) == "g" + hashlib.sha256(GOOD.encode()).hexdigest()[:8]
    assert id_prefix(c) != id_prefix(a)
    assert re.fullmatch(r"g[0-9a-f]{8}", id_prefix(c))


def test_render_scene_refuses_a_bad_scene_before_drawing(tmp_path: Path) -> None:
    with pytest.raises(SceneError, match=r"^scene\.toml: dyad\[0\]\.lengths\[1\]: must be > 0$"):
        render_scene(write(tmp_path, GOOD.replace("lengths = [120, 90]", "lengths = [120, 0]")))



# ------------------------------------------------------------------------------------------
# Robustness: whatever the data, the answer is a Scene or a SceneError
# ------------------------------------------------------------------------------------------

scene_values = toml_values(["A", "B", "C", "D", "2", "mm", "deg", "RRR", "left", "crank", "slider"])


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data())
def test_any_mutation_gives_a_scene_or_a_scene_error(data: st.DataObject) -> None:
    base = tomllib.loads(data.draw(st.sampled_from([GOOD, *doc_blocks()])))
    mutated = mutate(data, base, scene_values)
    scene = scene_or_refusal(mutated)
    if scene is None:
        return
    if scene.kind == "cam" and type(scene.problem).__name__ == "GivenCamScene":  # a cam given by its profile
        assert scene.linkage is None and scene.positions is None and 0 < scene.problem.step <= math.pi / 2
        return
    if scene.kind == "cam":
        cam = scene.problem.cam
        assert scene.linkage is None and scene.positions is None
        assert cam.base_radius > 0 and cam.omega > 0 and cam.rotation in (1, -1)
        assert 0 < scene.problem.step <= math.pi / 2
        assert math.isclose(sum(seg.angle for seg in cam.program.segments), 2 * math.pi)
        return
    if scene.kind == "flywheel" and scene.linkage is None:
        assert scene.positions is None
        return
    if scene.kind == "efficiency" or scene.kind == "balancing":  # fuzzed further in tests/test_efficiency.py
        assert scene.linkage is None and scene.positions is None
        return
    if scene.kind == "centres":  # a drive by its direct centres: no linkage, no positions
        assert scene.linkage is None and scene.positions is None and scene.problem.drive.wheels
        return
    if scene.kind == "other":  # the Geneva wheel, the differential screw: no linkage, no positions
        assert scene.linkage is None and scene.positions is None
        return
    if scene.kind == "trains":  # fuzzed further in tests/problems/trains/test_robustness.py
        t = scene.problem.train
        assert scene.linkage is None and all(g.z >= 1 for g in t.gears) and t.meshes
        return
    if scene.kind == "gears":  # fuzzed further in tests/problems/gears/test_robustness.py
        g = scene.problem.gears
        assert scene.linkage is None and g.system.m > 0 and all(x.z >= 1 for x in g.gears)
        return
    if scene.kind == "synthesis":  # a design asked in SI: its analysis is fuzzed in tests/problems/synthesis
        p = scene.problem.problem
        from graphmech.problems.synthesis import positions
        from graphmech.problems.synthesis.time_ratio import size

        if isinstance(p, positions.CouplerPositions):
            assert scene.linkage is None and len(p.B) == len(p.C) in (2, 3) and positions.size(p) > 0
        elif isinstance(p, positions.FourbarPositions):  # the input/output form
            assert scene.linkage is None and len(p.phi) == len(p.psi) in (2, 3) and positions.size(p) > 0
        elif isinstance(p, positions.inversions.Form):  # the forms by inversion on a slider, rocker, coupler
            assert scene.linkage is None and positions.size(p) > 0
        elif scene.problem.task == "function":  # Freudenstein's function generator
            assert scene.linkage is None and 2 <= p.points <= 5 and p.dphi != 0 and p.dpsi != 0 and p.frame > 0
        else:
            assert scene.linkage is None and 1.0 <= p.K < 35.0 and size(p) > 0
        return
    if scene.kind == "structure":  # a topology: its analysis must not fail either
        import json

        from graphmech.problems.structure.check import analyse_structure

        assert scene.linkage is None and scene.positions is None
        json.dumps(analyse_structure(scene).summary(), allow_nan=False)
        return
    assert all(math.isfinite(v) for v in scene.positions.values)
    assert 1 <= len(scene.positions.values) <= 3600


@settings(max_examples=100, deadline=None)
@given(st.binary(max_size=300))
def test_any_bytes_give_a_scene_error(tmp_path_factory: pytest.TempPathFactory, raw: bytes) -> None:
    path = tmp_path_factory.mktemp("fuzz") / "fuzz.toml"
    path.write_bytes(raw)
    with pytest.raises(SceneError):
        load_scene(path)


def test_a_page_given_to_the_loader_replaces_the_scenes_size(tmp_path: Path) -> None:
    from graphmech.scales import FIT_WORKING_AREA, PAPER

    path = SCENES / "linkage.fourbar_28_52_50_72-cycle.toml"  # [page] size = "A3"
    assert load_scene(path).page.size == PAPER["A3"]
    assert load_scene(path, "A2").page.size == PAPER["A2"]
    fit = load_scene(path, "fit").page
    assert fit.fit and fit.size == FIT_WORKING_AREA
    # the rest of [page] stays the scene's
    p = tmp_path / "zh.toml"
    p.write_text(path.read_text(encoding="utf-8").replace('size = "A3"', 'size = "A3"\nnotation = "zh"'),
                 encoding="utf-8")
    assert load_scene(p, "A1").page.notation == "zh"
    # a [page] that is no table is still refused, --page or not
    bad = tmp_path / "bad.toml"
    bad.write_text("page = 3\n" + path.read_text(encoding="utf-8").replace('[page]\nsize = "A3"', ""), encoding="utf-8")
    with pytest.raises(SceneError, match="page: must be a table"):
        load_scene(bad, "A2")


def test_the_same_scene_with_a_title_block_gives_the_same_bytes(tmp_path: Path) -> None:
    text = (SCENES / "linkage.fourbar_28_52_50_72.toml").read_text(encoding="utf-8")
    text += ('\n[page.title_block]\nname = "Li Lei"\ngroup = "ME 2101"\ndate = "2024-06-01"\nsheet = "1"\n'
             if "[page]" in text else
             '\n[page]\nsize = "fit"\n[page.title_block]\nname = "Li Lei"\ndate = "2024-06-01"\nsheet = "1"\n')
    p = tmp_path / "block.toml"
    p.write_text(text, encoding="utf-8")
    first, _ = render_scene(p)
    assert render_scene(p)[0] == first and "-title-block" in first and "Li Lei" in first
