"""The flywheel sheet in textbook conventions, asserted on the primitives and the stream of draw calls."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.methods.flywheel import design_flywheel
from graphmech.problems.flywheel.figures import (CLIP_MM, ENERGY_LEAST, ENERGY_MM, MOST_NUMBERS, PANELS, count_every,
                                                energy_factor, flywheel_sheet, inertia_phi_scale, panel_members)
from graphmech.render.labels import boxes_overlap
from graphmech.render.layout import layout_sheet
from graphmech.drawing.primitives import Arrow, Circle, Label, Panel, Polyline, Segment, Sheet
from graphmech.render.recording import RecordingBackend
from graphmech.render.sheet import draw_sheet, panel_labels, panel_shapes
from graphmech.render.svg import render_svg
from graphmech.render.style import DEFAULT
from graphmech.drawing.lettering import scale_text
from graphmech.drawing.lettering import number

TAU = 2.0 * math.pi
A3 = (420.0, 297.0)
WITT = "energy+inertia+wittenbauer"


@pytest.fixture(scope="module")
def compressor(problems):
    """fly.compressor_course_project at its 12 positions, both methods."""
    ex = problems["fly.compressor_course_project"]["exact"]
    return design_flywheel(np.radians(ex["positions_phi_deg"]), ex["Jp_kgm2"], ex["Mp_Nm"], cycle=TAU,
                           omega_m=ex["omega_m_rad_s"], delta=0.04, need=("wittenbauer", "indicator"))


def machine(n: int, delta: float = 0.05, **kw):
    phi = np.arange(n) * TAU / n
    return design_flywheel(phi, 0.5 + 0.2 * np.cos(phi) ** 2, -50.0 + 100.0 * np.sin(phi) + 30.0 * np.sin(3 * phi),
                           cycle=TAU, omega_m=kw.pop("omega_m", 20.0), delta=delta,
                           need=kw.pop("need", ("wittenbauer", "indicator")), **kw)


def sheet_of(design, show=PANELS) -> Sheet:
    return flywheel_sheet("Flywheel", design, list(show), A3)


def panel(sheet: Sheet, name: str) -> Panel:
    return next(p for p in sheet.panels if p.name == name)


def record(sheet: Sheet) -> tuple:
    return draw_sheet(sheet, RecordingBackend(), on_warning=lambda w: None)


def placements(sheet: Sheet):
    """Where draw_sheet puts each panel (the same layout it computes)."""
    boxes = [[pl.box for pl in panel_labels(p, panel_shapes(p))] for p in sheet.panels]
    return {pl.name: pl for pl in layout_sheet(sheet, DEFAULT, boxes).panels}


def group(calls: tuple, name: str) -> list:
    """The calls drawn inside the panel group named ``panel<i>-<name>`` (``+`` written ``-``)."""
    want = name.replace("+", "-")
    out, depth = [], 0  # how deep inside that panel's group (0: outside); labels have groups too
    for c in calls:
        if c[0] == "begin_group":
            depth = depth + 1 if depth else int(c[1].split("-", 1)[-1] == want)
        elif c[0] == "end_group":
            depth = max(depth - 1, 0)
        elif depth:
            out.append(c)
    return out


def labels(p: Panel) -> list[Label]:
    return [i for i in p.items if isinstance(i, Label)]


def texts(p: Panel) -> list[str]:
    return [i.text for i in labels(p)]


# ----------------------------------------------------------------------------- the panels
@pytest.mark.parametrize("show", [PANELS, ("moment",), ("work", "indicator"), ("energy", "inertia"),
                                  ("wittenbauer",), ("inertia", "wittenbauer"), ("energy", "wittenbauer", "moment")])
def test_the_panels_drawn_are_exactly_those_shown(compressor, show):
    sheet = sheet_of(compressor, show)
    names = [p.name for p in sheet.panels]
    assert sorted(m for n in names for m in n.split("+")) == sorted(show)
    assert [m for n in names for m in n.split("+")] == [p for p in PANELS if p in show]  # in the sheet's order
    groups = [c[1].split("-", 1)[1] for c in record(sheet) if c[0] == "begin_group" and c[1].startswith("panel")]
    assert groups == [n.replace("+", "-") for n in names]


def test_energy_and_inertia_stand_beside_the_wittenbauer_diagram_only_when_it_is_shown():
    assert panel_members(PANELS) == [("moment",), ("work",), ("energy", "inertia", "wittenbauer"), ("indicator",)]
    assert panel_members(["inertia", "energy"]) == [("energy",), ("inertia",)]


def test_every_panel_states_its_scales(compressor):
    sheet = sheet_of(compressor)
    s, H = compressor.scales, compressor.H_mm
    notes = {p.name: " | ".join(p.notes) for p in sheet.panels}
    assert "μ_{M} = 10 (N·m)/mm, μ_{φ} = 2.5 °/mm" in notes["moment"]  # as the scene states them: °/mm
    assert f"H = {H:g} mm" in notes["moment"]
    assert "μ_{A} = 13.09 J/mm" in notes["work"] and s["T"] == pytest.approx(13.0899694)  # 4 figures drawn
    for key in ("T", "J", "phi"):
        assert scale_text(key, s[key]) in notes[WITT]
    assert scale_text("phi", inertia_phi_scale(compressor), "′") in notes[WITT]  # J(φ)'s own μφ′
    assert f"J_{{F}} = μ_{{T}}·kl/(ω_{{m}}^{{2}}δ) = {number(compressor.J_F)} kg·m^{{2}}" in notes[WITT]
    assert scale_text("T", s["T"]) in notes["indicator"] and number(compressor.J_F_indicator) in notes["indicator"]
    # every panel's paper scales, for the scale bars
    scales = {p.name: dict(p.scales) for p in sheet.panels}
    assert scales["moment"] == {"M": s["M"], "phi": s["phi"]} and scales["work"] == {"T": s["T"], "phi": s["phi"]}
    assert scales[WITT]["T"] == s["T"] and scales[WITT]["J"] == s["J"]
    assert [v for k, v in panel(sheet, WITT).scales if k == "phi"] == [s["phi"], inertia_phi_scale(compressor)]
    # the captions are printed under the panels
    printed = {c[1] for c in record(sheet) if c[0] == "text" and c[6] == "text"}
    assert all(n in printed for p in sheet.panels for n in p.notes)


def test_axes_are_arrows_with_their_names(compressor):
    sheet = sheet_of(compressor)
    for name, symbols in (("moment", {"φ", "M_{red}"}), ("work", {"φ", "A"}), (WITT, {"φ", "ΔT", "J_{red}"})):
        p = panel(sheet, name)
        assert symbols <= set(texts(p))
        assert sum(isinstance(i, Arrow) and i.role == "label" for i in p.items) >= 2
    witt = panel(sheet, WITT)
    assert texts(witt).count("ΔT") == 2 and texts(witt).count("J_{red}") == 2  # ΔT(φ), J(φ) and the diagram


# ----------------------------------------------------------------------------- Mп and its integration
def test_moment_diagram_pole_rays_and_the_constant_moment(compressor):
    d, p = compressor, panel(sheet_of(compressor), "moment")
    g, H = d.moment, d.H_mm
    P = (-H, 0.0)
    assert any(isinstance(i, Circle) and i.center == P for i in p.items)
    rays = [i for i in p.items if isinstance(i, Segment) and i.p0 == P and i.role == "construction"]
    assert sorted(r.p1[1] for r in rays) == pytest.approx(sorted(g.mean_mm))  # N = 12: a ray per interval
    assert all(r.p1[0] == 0.0 for r in rays)
    # the Mп curve through the ordinates, the cycle closed at Φ
    [curve] = [i for i in p.items if isinstance(i, Polyline) and i.role == "given"]
    np.testing.assert_allclose(np.array(curve.points), np.column_stack([g.x_mm, g.y_mm]))
    # the ray from P ∥ the balancing work's line cuts the constant moment, drawn across the cycle
    [ray] = [i for i in p.items if isinstance(i, Segment) and i.p0 == P and i.dashed]
    assert ray.p1 == (0.0, pytest.approx(d.balancing_mm))
    assert (ray.p1[1] - 0.0) / H == pytest.approx(d.balance_work_mm[-1] / g.x_mm[-1])
    [line] = [i for i in p.items if isinstance(i, Segment) and i.role == "result"]
    assert line.p0 == (0.0, d.balancing_mm) and line.p1 == (g.x_mm[-1], d.balancing_mm)
    assert "M_{d}" in texts(p) and "P" in texts(p) and "H" in texts(p)


def test_positions_are_numbered_on_the_phi_axes(compressor):
    sheet = sheet_of(compressor)
    n = compressor.n
    for name in ("moment", "work"):
        nums = [i for i in labels(panel(sheet, name)) if i.text.isdigit()]
        assert [i.text for i in nums] == [str(k) for k in range(1, n + 1)] + ["1"]
        np.testing.assert_allclose([i.anchor[0] for i in nums], compressor.moment.x_mm)
        assert all(i.anchor[1] == 0.0 for i in nums)


def test_work_diagram_chords_parallel_to_the_rays_and_the_constant_moments_line(compressor):
    d, sheet = compressor, sheet_of(compressor)
    p = panel(sheet, "work")
    [chords] = [i for i in p.items if isinstance(i, Polyline) and i.role == "result"]
    pts = np.array(chords.points)
    np.testing.assert_allclose(pts, np.column_stack([d.moment.x_mm, d.work_mm]))
    slopes = np.diff(pts[:, 1]) / np.diff(pts[:, 0])
    rays = {round(i.p1[1], 9): i for i in panel(sheet, "moment").items
            if isinstance(i, Segment) and i.p0 == d.moment.pole and i.role == "construction"}
    for m, s in zip(d.moment.mean_mm, slopes):  # chord i ∥ ray i
        r = rays[round(float(m), 9)]
        assert s == pytest.approx((r.p1[1] - r.p0[1]) / (r.p1[0] - r.p0[0]), abs=1e-12)
    [line] = [i for i in p.items if isinstance(i, Segment) and i.role == "result" and i.dashed]
    assert line.p0 == (0.0, 0.0) and line.p1 == (pytest.approx(d.moment.x_mm[-1]), pytest.approx(-d.work_mm[-1]))
    assert {"A_{red}", "A_{d}"} <= set(texts(p))


def test_a_constant_resistance_is_named_mc():
    phi = np.arange(24) * math.pi / 24
    d = design_flywheel(phi, np.zeros(24), 200.0 * np.sin(phi) ** 2, cycle=math.pi, omega_m=60.0, delta=0.02,
                        balance="resisting", need=("wittenbauer",))
    sheet = sheet_of(d, ["moment", "work"])
    assert "M_{r}" in texts(panel(sheet, "moment")) and "A_{r}" in texts(panel(sheet, "work"))


# ----------------------------------------------------------------------------- ΔT(φ), Jп(φ) beside the diagram
def test_energy_curve_and_the_lines_carried_across(compressor):
    d = compressor
    p = panel(sheet_of(d), WITT)
    w = d.wittenbauer
    [curve] = [i for i in p.items if isinstance(i, Polyline) and i.role == "result"]
    pts = np.array(curve.points)
    dx = pts[0, 0]
    np.testing.assert_allclose(pts, np.column_stack([d.moment.x_mm + dx, d.energy_mm]))
    assert dx + d.moment.x_mm[-1] < -20.0  # to the left of the ΔT axis
    for k in range(d.n):  # from ΔT(φ) horizontally to the diagram's point k + 1
        assert any(isinstance(i, Segment) and i.role == "construction" and i.p0 == (pytest.approx(dx + d.moment.x_mm[k]),
                   pytest.approx(w.y_mm[k])) and i.p1 == (pytest.approx(w.x_mm[k]), pytest.approx(w.y_mm[k]))
                   for i in p.items)


def test_inertia_is_drawn_with_j_across_and_phi_down_below_the_diagram(compressor):
    d = compressor
    p = panel(sheet_of(d), WITT)
    [curve] = [i for i in p.items if isinstance(i, Polyline) and i.role == "given" and not i.closed]
    pts = np.array(curve.points)
    mu = inertia_phi_scale(d)
    np.testing.assert_allclose(pts[:, 0], np.append(d.inertia_mm, d.inertia_mm[0]))  # same μJ and J axis
    top = pts[0, 1]
    np.testing.assert_allclose(pts[:, 1], top - np.append(d.phi, d.cycle) / mu)  # φ downwards
    assert top < min(d.wittenbauer.y_mm.min(), d.wittenbauer.l_mm)
    alone = panel(sheet_of(d, ["inertia"]), "inertia")
    [c] = [i for i in alone.items if isinstance(i, Polyline)]
    np.testing.assert_allclose(np.array(c.points), pts - [0.0, top])


# ----------------------------------------------------------------------------- the Wittenbauer diagram
def test_points_numbered_one_to_n_at_their_places(compressor):
    w = compressor.wittenbauer
    p = panel(sheet_of(compressor, ["wittenbauer"]), "wittenbauer")
    nums = {i.text: i.anchor for i in labels(p) if i.text.isdigit()}
    assert sorted(nums, key=int) == [str(k) for k in range(1, 13)]
    for k, at in nums.items():
        assert at == (pytest.approx(w.x_mm[int(k) - 1]), pytest.approx(w.y_mm[int(k) - 1]))
    [curve] = [i for i in p.items if isinstance(i, Polyline) and i.closed]
    np.testing.assert_allclose(np.array(curve.points), np.column_stack([w.x_mm, w.y_mm]))
    assert sum(isinstance(i, Circle) for i in p.items) == 12  # the points as dots


def test_tangents_have_the_slopes_of_psi_and_cut_the_axis_at_k_and_l(compressor):
    w = compressor.wittenbauer
    sheet = sheet_of(compressor)
    p = panel(sheet, WITT)
    tangents = [i for i in p.items if isinstance(i, Segment) and i.role == "result"]
    assert len(tangents) == 2
    for t, slope, c in zip(tangents, (w.tan_psi_max, w.tan_psi_min), (w.k_mm, w.l_mm)):
        assert (t.p1[1] - t.p0[1]) / (t.p1[0] - t.p0[0]) == pytest.approx(slope, rel=1e-12)
        assert t.p0[1] - slope * t.p0[0] == pytest.approx(c, abs=1e-9)
        assert t.p0[0] < 0.0 < t.p1[0]  # across the ΔT axis
    k = next(i for i in labels(p) if i.text == "k")
    l_ = next(i for i in labels(p) if i.text == "l")
    assert k.anchor == (0.0, w.k_mm) and l_.anchor == (0.0, w.l_mm)
    assert {"ψ_{max}", "ψ_{min}", "kl"} <= set(texts(p))
    # on the page: two bold lines of slopes −tan ψ (y down), and the k, l ticks where the panel puts them
    calls = group(record(sheet), WITT)
    bold = [c for c in calls if c[0] == "line" and c[3] == "result"]
    page = sorted(-(c[2][1] - c[1][1]) / (c[2][0] - c[1][0]) for c in bold)
    assert page == pytest.approx(sorted([w.tan_psi_max, w.tan_psi_min]), rel=1e-9)
    place = placements(sheet)[WITT]
    ticks = {(c[1], c[2]) for c in calls if c[0] == "line" and c[3] == "label"}
    for c in (w.k_mm, w.l_mm):
        assert (place.to_page((-1.2, c)), place.to_page((1.2, c))) in ticks


def test_kl_is_dimensioned_and_the_axis_reaches_k_and_l(compressor):
    w = compressor.wittenbauer
    p = panel(sheet_of(compressor, ["wittenbauer"]), "wittenbauer")
    arrows = [i for i in p.items if isinstance(i, Arrow) and i.p0[0] == i.p1[0] < 0.0]
    assert sorted(a.p1[1] for a in arrows) == pytest.approx(sorted([w.k_mm, w.l_mm]))
    axis = next(i for i in p.items if isinstance(i, Arrow) and i.p0[0] == i.p1[0] == 0.0)
    assert axis.p0[1] < min(w.k_mm, w.l_mm)


def test_far_intercepts_clip_the_tangents_and_are_written_out():
    d = machine(24, omega_m=100.0)  # Jп·ω²/2 far above ΔT: k and l hundreds of mm below the points
    w = d.wittenbauer
    assert w.k_mm < w.y_mm.min() - 100.0
    p = panel(sheet_of(d, ["wittenbauer"]), "wittenbauer")
    bottom = w.y_mm.min() - CLIP_MM
    tangents = [i for i in p.items if isinstance(i, Segment) and i.role == "result"]
    assert len(tangents) == 2 and all(min(t.p0[1], t.p1[1]) == pytest.approx(bottom) for t in tangents)
    assert {f"k = {number(w.k_mm)} mm", f"l = {number(w.l_mm)} mm"} <= set(texts(p))
    assert "k" not in texts(p) and "kl" not in texts(p)
    assert f"kl = {number(w.kl_mm)} mm" in " ".join(p.notes)


def test_many_positions_are_numbered_every_kth():
    d = machine(360)
    p = panel(sheet_of(d, ["wittenbauer"]), "wittenbauer")
    nums = [int(t) for t in texts(p) if t.isdigit()]
    step = nums[1] - nums[0]
    assert nums[0] == 1 and len(nums) <= MOST_NUMBERS and nums == list(range(1, 361, step))
    assert step >= count_every(360, MOST_NUMBERS)
    assert sum(isinstance(i, Circle) for i in p.items) == 360


# ----------------------------------------------------------------------------- the energy indicator
def test_energy_indicator_chain_and_delta_w_max(compressor):
    e = compressor.indicator
    p = panel(sheet_of(compressor, ["indicator"]), "indicator")
    vectors = [i for i in p.items if isinstance(i, Arrow) and i.role == "result"]
    k = energy_factor(compressor)  # 16.4 mm at μT is too low to read: drawn at μT′ = μT/3
    assert k == 3 and ENERGY_LEAST <= k * e.dW_max_mm <= ENERGY_MM
    assert dict(p.scales)["T"] == pytest.approx(compressor.scales["T"] / 3)
    assert any(n.startswith("μ_{T}′ = μ_{T}/3 = 4.363 J/mm") for n in p.notes)
    assert [a.p1[1] - a.p0[1] for a in vectors] == pytest.approx(list(k * e.vectors_mm))
    assert all(a.p0[0] == a.p1[0] for a in vectors)  # vertical
    for a, b in zip(vectors[:-1], vectors[1:]):  # head to tail, one level
        assert a.p1[1] == b.p0[1] and b.p0[0] > a.p0[0]
    assert vectors[-1].p1[1] == vectors[0].p0[1]  # back at a's level: a′
    dims = [i for i in p.items if isinstance(i, Arrow) and i.role == "label"]
    assert max(a.p1[1] for a in dims) - min(a.p1[1] for a in dims) == pytest.approx(k * e.dW_max_mm)
    assert {"ΔW_{max}", "a", "b", "a′", "f_{1}", "f_{2}"} <= set(texts(p))


# ----------------------------------------------------------------------------- the whole sheet
def test_labels_do_not_collide_and_the_sheet_fits_a3(compressor):
    sheet = sheet_of(compressor)
    for p in sheet.panels:
        placed = panel_labels(p, panel_shapes(p))
        for i, a in enumerate(placed):
            for b in placed[i + 1:]:
                assert boxes_overlap(a.box, b.box) == 0.0, (p.name, a.label.text, b.label.text)
    warnings: list[str] = []
    draw_sheet(sheet, RecordingBackend(), on_warning=warnings.append)
    assert warnings == []


def test_the_svg_is_deterministic(compressor):
    sheet = sheet_of(compressor)
    assert render_svg(sheet, "gmfw") == render_svg(sheet_of(compressor), "gmfw")


def test_what_cannot_be_drawn_is_refused(compressor):
    with pytest.raises(ValueError, match="unknown panel"):
        sheet_of(compressor, ["moment", "polygon"])
    with pytest.raises(ValueError):
        sheet_of(compressor, [])
    bare = machine(12, need=())
    with pytest.raises(ValueError, match="Wittenbauer"):
        sheet_of(bare, ["wittenbauer"])
    with pytest.raises(ValueError, match="indicator"):
        sheet_of(bare, ["indicator"])


def test_thousands_of_positions_draw_with_thinned_numbers_and_rays():
    d = machine(3600)
    sheet = sheet_of(d, ["moment", "wittenbauer"])
    m = panel(sheet, "moment")
    rays = [i for i in m.items if isinstance(i, Segment) and i.p0 == d.moment.pole and i.role == "construction"]
    assert 0 < len(rays) <= 24
    nums = [t for t in texts(m) if t.isdigit()]
    assert 3 <= len(nums) <= 40 and nums[0] == "1"
    [curve] = [i for i in m.items if isinstance(i, Polyline) and i.role == "given"]
    assert len(curve.points) == 3601  # every position is in the curve
