"""The efficiency sheet: the polygon panels (ideal dashed, real bold), byte-stable SVG without
matplotlib, escaped text, a long chain of machines wrapped on its page."""
from __future__ import annotations

import math
import subprocess
import sys

import pytest

from graphmech.problems.efficiency.check import analyse_efficiency, efficiency_figure
from graphmech.drawing.primitives import Arrow, Label, Segment
from graphmech.scene import load_scene
from tests.conftest import ROOT, SCENES, run_cli


def scene(text: str, tmp_path, name: str = "s.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def test_polygon_panels_hold_the_ideal_dashed_and_the_real_bold():
    an = analyse_efficiency(load_scene(SCENES / "force.wedge_F1430.toml"))
    sheet = efficiency_figure(an, (297.0, 210.0))
    assert [p.name for p in sheet.panels] == ["diagram", "polygon-forward", "polygon-reverse"]
    poly = sheet.panels[1]
    bold = [i for i in poly.items if isinstance(i, Arrow) and i.role == "result"]
    dashed = [i for i in poly.items if isinstance(i, Segment) and i.dashed]
    assert len(bold) == 4 and len(dashed) == 6  # F, R12, R32, R31 bold (Q given); two ideal triangles
    assert any("μ_{F} = 25 N/mm" in n for n in poly.notes) and poly.scales == (("F", 25.0),)
    f_arrow = next(i for i in poly.items if isinstance(i, Arrow) and any(
        getattr(l, "text", "") == "F" and l.anchor == ((i.p0[0] + i.p1[0]) / 2, (i.p0[1] + i.p1[1]) / 2)
        for l in poly.items))
    assert math.dist(f_arrow.p0, f_arrow.p1) * 25 == pytest.approx(1430.7004224765801, rel=1e-12)


def test_render_is_byte_stable_and_lazy(tmp_path):
    code = ("import sys; from graphmech.cli import main; "
            f"rc = main(['render', r'{SCENES / 'force.wedge_F1430.toml'}', '-o', r'{tmp_path / 'a.svg'}']); "
            f"main(['render', r'{SCENES / 'bal.rotor_dynamic.toml'}', '-o', r'{tmp_path / 'b.svg'}']); "
            "assert 'matplotlib' not in sys.modules, 'matplotlib imported'; sys.exit(rc)")
    r = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    run_cli("render", str(SCENES / "force.wedge_F1430.toml"), "-o", str(tmp_path / "c.svg"))
    assert (tmp_path / "a.svg").read_bytes() == (tmp_path / "c.svg").read_bytes()
    assert (tmp_path / "a.svg").read_bytes() == (ROOT / "figures" / "force.wedge_F1430.svg").read_bytes()


def test_scene_text_is_escaped_in_the_svg(tmp_path):
    import xml.etree.ElementTree as ET

    p = scene('title = "a <b> & \\"c\\""\n[efficiency]\ntype = "chain"\nload_N = 1\nspeed_m_s = 1\n'
              '[[efficiency.stage]]\nname = "</text><script>x</script>"\neta = 0.9\n', tmp_path)
    code, out, err = run_cli("render", str(p), "-o", str(tmp_path / "e.svg"))
    assert code == 0, err
    svg = (tmp_path / "e.svg").read_text(encoding="utf-8")
    ET.fromstring(svg)  # well-formed
    assert "<script>" not in svg and "&lt;script&gt;" in svg


def test_a_long_chain_of_machines_wraps_on_its_page(tmp_path):
    # the boxes stood in one row: 4 stages were 288.6 mm wide on an A4 page leaving 277 mm, 6 were 408.6
    stages = "".join(f'[[efficiency.stage]]\nname = "gear pair {k}"\neta = 0.97\n' for k in range(6))
    p = scene('find = ["eta", "P_in"]\n[efficiency]\ntype = "chain"\nload_N = 5500\nspeed_m_s = 1.2\n' + stages,
              tmp_path)
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "c.svg"))
    assert code == 0 and "runs off the page" not in err and "run off the page" not in err
    an = analyse_efficiency(load_scene(p))
    assert an.rows[0].exact == pytest.approx(0.97 ** 6, rel=1e-14)
    panel = efficiency_figure(an, (297.0, 210.0)).panels[0]
    xs = [q[0] for item in panel.items if hasattr(item, "points") for q in item.points]
    assert max(xs) - min(xs) < 277.0 and len({round(q[1]) for item in panel.items if hasattr(item, "points")
                                               for q in item.points}) > 4  # two rows of boxes


# ---------------------------------------------------------------------------- the module's own pieces


def test_force_names_take_their_numbers_as_subscripts():
    from graphmech.drawing.lettering import point_name  # a force's name is lettered as a point's

    assert (point_name("R12"), point_name("F0"), point_name("R31"), point_name("Q")) == ("R_{12}", "F_{0}", "R_{31}", "Q")


def test_polygon_items_draw_the_real_sides_once_and_the_ideal_ones_dashed():
    from graphmech.drawing.primitives import Label
    from graphmech.methods import efficiency as gm
    from graphmech.problems.efficiency.figures import polygon_items

    s = gm.wedge(1000.0, math.radians(60), math.radians(60), math.atan(0.15), "forward", 25.0)
    items = polygon_items(s.polygons)
    arrows = [i for i in items if isinstance(i, Arrow)]
    labels = {i.text for i in items if isinstance(i, Label)}
    assert len(arrows) == 5 and labels == {"Q", "F", "R_{12}", "R_{32}", "R_{31}"}  # R21 is R12 reversed: not again
    assert sum(isinstance(i, Segment) and i.dashed for i in items) == 6  # the two ideal triangles
    forces = {"F": s.F, **dict(s.reactions)}
    for a in arrows:
        name = next(i.text for i in items if isinstance(i, Label) and
                    i.anchor == ((a.p0[0] + a.p1[0]) / 2, (a.p0[1] + a.p1[1]) / 2))
        if name != "Q":
            assert a.role == "result"
            assert math.dist(a.p0, a.p1) * 25.0 == pytest.approx(forces[name.replace("_{", "").replace("}", "")],
                                                                 rel=1e-12)
        else:
            assert a.role == "given" and math.dist(a.p0, a.p1) * 25.0 == pytest.approx(1000.0, rel=1e-12)


def test_recorded_draw_calls_of_the_wedge_sheet():
    from graphmech.render.recording import RecordingBackend
    from graphmech.render.sheet import draw_sheet

    an = analyse_efficiency(load_scene(SCENES / "force.wedge_F1430.toml"))
    calls = draw_sheet(efficiency_figure(an, (297.0, 210.0)), RecordingBackend())
    dashed = [c for c in calls if c[0] == "line" and c[4]]
    assert len(dashed) == 6 + 6 + 3  # each stroke's two ideal triangles, and the diagram's three dashes
    texts = [c[1] for c in calls if c[0] == "text"]
    assert texts.count("μ_{F} = 25 N/mm") == 2 and "F" in texts and "R_{12}" in texts


def test_a_thread_diagram_alone_fills_its_page_and_letters_in_the_notation(tmp_path):
    """thread.m20_lead_angles-coarse on A4: the unrolled thread (no force scale) is enlarged to fill
    the sheet (it was 70 mm of 297); in русский its caption is the book's; d_{2} a subscript mark."""
    from graphmech.problems.efficiency.check import analyse_efficiency, efficiency_figure
    from graphmech.problems.efficiency.figures import MOST_ENLARGED, _extent
    from graphmech.scene import load_scene

    ref = SCENES / "thread.m20_lead_angles-coarse.toml"
    an = analyse_efficiency(load_scene(ref))
    [p] = efficiency_figure(an, (297.0, 210.0)).panels
    width, _ = _extent(p.items)
    assert 150.0 <= width <= 297.0 - 60.0 and width <= 70.0 * MOST_ENLARGED + 1e-9
    assert p.title == "Screw thread unrolled: ψ = 2.48°"
    assert "π·d_{2}" in {i.text for i in p.items if isinstance(i, Label)}
    ru = tmp_path / "ru.toml"
    ru.write_text(ref.read_text(encoding="utf-8") + '\n[page]\nnotation = "ru"\n', encoding="utf-8")
    [q] = efficiency_figure(analyse_efficiency(load_scene(ru)), (297.0, 210.0)).panels
    assert q.title == "Развёртка резьбы: ψ = 2.48°"
