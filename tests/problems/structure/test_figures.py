"""The structure sheet: groups outlined, every reference sheet on its page, no matplotlib, scales refused."""
from __future__ import annotations


import pytest

from tests.conftest import SCENES, run_cli


def test_structure_sheet_outlines_the_groups():
    from graphmech.scene import render_scene

    svg, warnings = render_scene(SCENES / "dof.hfut_cases-ic_engine_EG.toml")
    assert "III (2,3,4,5)" in svg and "II (7,8)" in svg and "special construction" in svg
    assert "I: 1 + 6" in svg and "rank J = 20 of 20" in svg


def test_rendering_instant_centres_and_structure_never_imports_matplotlib(tmp_path):
    import subprocess
    import sys

    from tests.conftest import ROOT

    scenes = [SCENES / "kin.fourbar_instant_centres.toml", SCENES / "dof.hfut_cases-3-2.toml"]
    code = ("import sys; from graphmech.cli import main; "
            f"rc = main(['render', *{[str(s) for s in scenes]!r}, '-d', r'{tmp_path}']); "
            "assert not any(m.split('.')[0] == 'matplotlib' for m in sys.modules), 'matplotlib imported'; "
            "sys.exit(rc)")
    r = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "dof.hfut_cases-3-2.svg").read_text().startswith("<svg")


@pytest.mark.parametrize("name", sorted(p.stem for p in SCENES.glob("*.toml")
                                        if p.stem.startswith(("dof.", "structure."))))
def test_every_structure_sheet_fits_its_page(name):
    """The class III message (IC engine from EG) made the block diagram's panel 403 mm wide on an
    A4 page; HFUT 3-2's diagram was drawn at μl = 0.005 (38 mm tall, labels on top of each other)."""
    from graphmech.scene import render_scene

    svg, warnings = render_scene(SCENES / f"{name}.toml")
    assert not [w for w in warnings if "runs off the page" in w], warnings
    if name == "dof.hfut_cases-3-2":
        assert "μ<tspan dy=\"0.875\" font-size=\"2.520\">l</tspan><tspan dy=\"-0.875\"> = 0.0025 m/mm" in svg  # μ_{l}


def test_a_stated_scale_that_cannot_draw_the_pairs_is_refused(tmp_path):
    """μl = 1e-300 m/mm drew the parallelogram 1e299 mm across: render exit 3. Now refused where
    every scale is read; within that range the structure sheet bounds the drawing itself."""
    text = (SCENES / "structure.parallelogram_redundant.toml").read_text(encoding="utf-8")
    p = tmp_path / "tiny.toml"
    p.write_text(text.replace('[units]', '[scales]\nl_m_per_mm = 1e-300\n\n[units]'), encoding="utf-8")
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "x.svg"))
    assert code == 2 and err.startswith("tiny.toml: scales.l_m_per_mm: 1e-300: under 1e-15 SI units per mm"), err
    p.write_text(text.replace('[units]', '[scales]\nl_m_per_mm = 1e-12\n\n[units]'), encoding="utf-8")
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "x.svg"))
    assert code == 2 and err.startswith("tiny.toml: scales: μl = 1e-12 m/mm draws the mechanism 1.3e+11 mm"), err
    assert not (tmp_path / "x.svg").exists()


# ----------------------------------------------------------------------------- the module's own pieces


def _five_bar(drivers=("2", "5")):
    from graphmech.mechanisms.topology import Pair, Topology

    pairs = (Pair("R", ("1", "2"), "A", (0.0, 0.0)), Pair("R", ("2", "3"), "B", (0.02, 0.05)),
             Pair("R", ("3", "4"), "C", (0.08, 0.09)), Pair("R", ("4", "5"), "D", (0.13, 0.04)),
             Pair("R", ("5", "1"), "E", (0.15, 0.0)))
    return Topology("1", ("2", "3", "4", "5"), pairs, drivers)


def test_the_scale_is_the_round_one_that_fits_the_pairs_in_the_room():
    from graphmech.problems.structure.figures import choose_scale

    # 0.15 m × 0.09 m in 100 × 100 mm: at least 0.0015 m/mm, the round 0.002
    assert choose_scale(_five_bar(), (100.0, 100.0)) == 0.002
    assert choose_scale(_five_bar(), (30.0, 100.0)) == 0.005  # 0.15 m in 30 mm


def test_the_block_diagram_holds_class_I_then_each_group_inscribed_in_the_middle_of_its_box():
    from graphmech.drawing.primitives import Arrow, Polyline, Text
    from graphmech.mechanisms.topology import structure
    from graphmech.problems.structure.figures import block_panel

    topo = _five_bar()
    panel = block_panel(structure(topo), topo)
    texts = [i for i in panel.items if isinstance(i, Text)]
    assert [t.text for t in texts] == ["I: 1 + 2, 5", "II: 3, 4"]
    boxes = [i.points for i in panel.items if isinstance(i, Polyline)]
    for t, box in zip(texts, boxes):  # set at the box's centre, not placed around it
        assert t.at == pytest.approx(((box[0][0] + box[2][0]) / 2, (box[0][1] + box[2][1]) / 2))
    assert sum(isinstance(i, Arrow) for i in panel.items) == 1 and panel.notes == ("a class II mechanism",)
    assert block_panel(structure(topo), topo, "zh").notes == ("II级机构",)
    assert block_panel(structure(topo), topo, "ru").notes == ("механизм II класса",)


CASES = [{"label": "punch_press_initial", "n": 3, "pl": 4, "ph": 1, "p_redundant": 0, "F_local": 0, "F": 0},
         {"label": "3-1", "n": 7, "pl": 10, "ph": 0, "p_redundant": 0, "F_local": 0, "F": 1},
         {"label": "closed_gear_train", "n": 7, "pl": 7, "ph": 8, "p_redundant": 2, "F_local": 0, "F": 1}]


def cells(panel):
    """The table's text by row (top first), each row left to right."""
    from graphmech.drawing.primitives import Text

    rows: dict[float, list] = {}
    for t in panel.items:
        if isinstance(t, Text) and t.at[1] < 0:
            rows.setdefault(round(t.at[1], 6), []).append(t)
    return [[t.text for t in sorted(r, key=lambda t: t.at[0])] for _, r in sorted(rows.items(), reverse=True)]


def test_printed_counts_are_a_table_of_n_pl_ph_p_and_f_under_the_formula():
    from graphmech.drawing.lettering import text_box_size
    from graphmech.drawing.primitives import Polyline, Segment, Text
    from graphmech.problems.structure.figures import cases_panel

    panel = cases_panel(CASES)
    assert cells(panel) == [["case", "n", "p_{l}", "p_{h}", "p′", "F"],  # no F′ column: no case has one
                            ["punch press initial", "3", "4", "1", "0", "0", "rigid"],
                            ["3-1", "7", "10", "0", "0", "1"],
                            ["closed gear train", "7", "7", "8", "2", "1"]]
    [formula] = [t for t in panel.items if isinstance(t, Text) and t.at[1] > 0]
    assert formula.text == "F = 3n − (2p_{l} + p_{h} − p′)"
    [frame] = [i for i in panel.items if isinstance(i, Polyline)]
    x0, x1 = frame.points[0][0], frame.points[1][0]
    depth = -frame.points[2][1]
    assert formula.at[0] == pytest.approx((x0 + x1) / 2) and depth == pytest.approx(4 * 7.5)  # head + 3 rows
    rules = [i for i in panel.items if isinstance(i, Segment)]
    across = sorted(-r.p0[1] for r in rules if r.p0[1] == r.p1[1])
    downs = sorted(r.p0[0] for r in rules if r.p0[0] == r.p1[0])
    assert across == pytest.approx([7.5, 15.0, 22.5]) and len(downs) == 6  # 7 columns
    # every cell's text inside its cell: no rule crosses it
    for t in panel.items:
        if isinstance(t, Text) and t.at[1] < 0:
            w, h = text_box_size(t.text, t.size)
            left = t.at[0] - (0.0 if t.anchor == "start" else w / 2)
            assert not [x for x in [x0, x1, *downs] if left < x < left + w], t
            assert not [y for y in [0.0, depth, *across] if -(t.at[1] + h / 2) < y < -(t.at[1] - h / 2)], t
    plain = cases_panel(CASES[1:2], "zh")
    assert cells(plain)[0] == ["机构", "n", "p_{l}", "p_{h}", "F"] and plain.title == "由题给数据计算自由度"
    assert [t.text for t in plain.items if isinstance(t, Text) and t.at[1] > 0] == ["F = 3n − 2p_{l} − p_{h}"]


def test_a_ternary_link_is_a_filled_plate_with_its_number_inside_and_a_bar_is_a_line():
    from graphmech.drawing.primitives import Label, Plate, Segment
    from graphmech.problems.structure.check import analyse_structure
    from graphmech.problems.structure.figures import structure_sheet
    from graphmech.scene import load_scene

    an = analyse_structure(load_scene(SCENES / "dof.hfut_cases-ic_engine_EG.toml"))
    sheet = structure_sheet("IC engine", an, (297.0, 210.0))
    mech = next(p for p in sheet.panels if p.name == "structure")
    plates = [i for i in mech.items if isinstance(i, Plate)]
    assert len(plates) == 2 and all(len(p.points) == 3 for p in plates)  # links 3 (B, C, D) and 6 (E, G, H)
    inside = {p.number: p.number_at for p in plates}  # drawn with the plate, in its group
    assert set(inside) == {"3", "6"}
    for plate in plates:  # each number at its triangle's centroid
        c = tuple(sum(q[k] for q in plate.points) / 3 for k in (0, 1))
        assert any(at == pytest.approx(c) for at in inside.values())
    assert {"2", "5", "7"} <= {i.text for i in mech.items if isinstance(i, Label)}
    assert not any(isinstance(i, Segment) and i.dashed for i in mech.items)  # nothing redundant here
    assert mech.scales == (("l", an.scales["l"]),)


def test_a_redundant_link_is_dashed_and_named_under_the_block_diagram():
    from graphmech.drawing.primitives import Label, Segment
    from graphmech.problems.structure.check import analyse_structure
    from graphmech.problems.structure.figures import structure_sheet
    from graphmech.scene import load_scene

    an = analyse_structure(load_scene(SCENES / "structure.parallelogram_redundant.toml"))
    sheet = structure_sheet("P", an, (297.0, 210.0))
    mech = next(p for p in sheet.panels if p.name == "structure")
    bars = [i for i in mech.items if isinstance(i, Segment) and i.role == "given"]
    mu = an.scales["l"]
    dashed = [(round(b.p0[0] * mu * 1e3, 6), round(b.p1[0] * mu * 1e3, 6)) for b in bars if b.dashed]
    assert dashed == [(50.0, 80.0)]  # EF, link 5, only
    assert len([b for b in bars if not b.dashed]) == 3  # AB, BFC (one bar through F), CD
    # link 3's number beside a piece of its bar, not on the middle pair F
    three = next(i for i in mech.items if isinstance(i, Label) and i.text == "3")
    assert three.anchor[0] * mu * 1e3 == pytest.approx(55.0)
    groups = next(p for p in sheet.panels if p.name == "groups")
    assert groups.notes[-1] == "redundant links (dashed, p′ = 1) left out of the groups: 5"


def test_point_names_with_a_number_are_lettered_with_a_subscript():
    from graphmech.drawing.primitives import Label
    from graphmech.problems.structure.check import analyse_structure
    from graphmech.problems.structure.figures import structure_sheet
    from graphmech.scene import load_scene

    an = analyse_structure(load_scene(SCENES / "dof.hfut_cases-precision_press_1.toml"))
    sheet = structure_sheet("P", an, (297.0, 210.0))
    mech = next(p for p in sheet.panels if p.name == "structure")
    names = {i.text for i in mech.items if isinstance(i, Label) and i.italic}
    assert {"D_{1}", "D_{2}", "K_{1}", "K_{2}", "C′", "M"} <= names and "K1" not in names
    assert "compound hinges (k − 1 pairs each): M, K_{1}, K_{2}, E" in mech.notes


@pytest.mark.parametrize("name", sorted(p.stem for p in SCENES.glob("*.toml")
                                        if p.stem.startswith(("dof.", "structure."))))
def test_each_structure_sheet_is_lettered_in_zh_and_ru_and_checks_the_same(tmp_path, name):
    import re

    captions = {"en": ("Mobility from the printed counts", "Structure: drivers and Assur groups"),
                "zh": ("由题给数据计算自由度", "机构的组成"), "ru": ("подвижность по заданным числам", "строение механизма")}
    text = (SCENES / f"{name}.toml").read_text(encoding="utf-8")
    shown, checked = {}, {}
    for notation in captions:
        d = tmp_path / notation
        d.mkdir()
        (d / f"{name}.toml").write_text(text + f'\n[page]\nnotation = "{notation}"\n', encoding="utf-8")
        code, out, err = run_cli("render", str(d / f"{name}.toml"), "-o", str(d / "x.svg"))
        assert code == 0, err
        shown[notation] = (d / "x.svg").read_text(encoding="utf-8")
        code, checked[notation], err = run_cli("check", str(d / f"{name}.toml"))
        assert code in (0, 1), err
    assert checked["en"] == checked["zh"] == checked["ru"]
    for notation, words in captions.items():
        present = [w for w in words if w in shown[notation]]
        assert present, (notation, words)
        assert not any(w in shown[o] for o in captions if o != notation for w in present)
    # what graphmech composes holds no bare "_" (the title is the scene's own text)
    body = re.sub(r'<g id="[^"]*-title">.*?</g>', "", shown["en"])
    assert not re.findall(r">[^<]*_[^<]*<", body)


def test_a_links_outline_is_the_hull_of_its_pairs():
    from graphmech.problems.structure.figures import _hull

    square = _hull([(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.5, 0.5), (0.0, 1.0)])
    assert sorted(square) == [(0.0, 0.0), (0.0, 1.0), (1.0, 0.0), (1.0, 1.0)]  # the inner pair is no corner
    assert _hull([(0.0, 0.0), (2.0, 0.0), (1.0, 0.0)]) == [(0.0, 0.0), (2.0, 0.0)]  # a binary link: its line


def test_recorded_draw_calls_of_the_ic_engine_sheet():
    from graphmech.drawing.primitives import Polyline
    from graphmech.problems.structure.check import analyse_structure
    from graphmech.problems.structure.figures import structure_sheet
    from graphmech.render.recording import RecordingBackend
    from graphmech.render.sheet import draw_sheet
    from graphmech.scene import load_scene

    an = analyse_structure(load_scene(SCENES / "dof.hfut_cases-ic_engine_EG.toml"))
    calls = draw_sheet(structure_sheet("IC engine", an, (297.0, 210.0)), RecordingBackend())
    texts = [c[1] for c in calls if c[0] == "text"]
    assert "III: 2, 3, 4, 5" in texts and "II: 7, 8" in texts and "a class III mechanism" in texts
    # each group outlined by a dashed contour on the mechanism
    mechanism = next(p for p in structure_sheet("IC engine", an, (297.0, 210.0)).panels if p.name == "structure")
    outlines = [i for i in mechanism.items if isinstance(i, Polyline) and i.dashed]
    assert len(outlines) == len(an.structure.groups) == 2


def test_a_plate_number_an_assur_outline_crosses_becomes_a_placed_label():
    """dof.hfut_cases-3-2: the dashed outlines of groups run over plates 4 and 7, so their numbers
    leave the plates (placed clear of every stroke, with a leader); the others stay inside."""
    from graphmech.drawing.primitives import Label, Plate
    from graphmech.problems.structure.check import analyse_structure
    from graphmech.problems.structure.figures import structure_sheet
    from graphmech.scene import load_scene

    an = analyse_structure(load_scene(SCENES / "dof.hfut_cases-3-2.toml"))
    mech = next(p for p in structure_sheet("3-2", an, (297.0, 210.0)).panels if p.name == "structure")
    plates = [i for i in mech.items if isinstance(i, Plate)]
    moved = {i.text for i in mech.items if isinstance(i, Label)} & {"4", "7"}
    assert moved == {"4", "7"} and not any(p.number in moved for p in plates)
