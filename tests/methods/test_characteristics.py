"""The drawn characteristics of a basic loop, on linkages whose answers are known by hand (the
drawing against the closed forms over many linkages is tests/exact/test_characteristics.py)."""
from __future__ import annotations

import math

import pytest

from graphmech.mechanisms.linkage import RPR, RRP, RRR, Crank, Guide, Linkage, SliderInput
from graphmech.methods.characteristics import basic_loop, draw_characteristics, fourbar_lengths, grashof_class

MU = 0.001


def fourbar(a: float, b: float, c: float, d: float, omega: float = 10.0) -> Linkage:
    return Linkage({"A": (0.0, 0.0), "D": (d, 0.0)}, Crank("1", "A", "B", a, omega),
                   (RRR("B", "C", "D", ("2", "3"), (b, c), "left"),))


def test_basic_loop_of_each_kind() -> None:
    fb = basic_loop(fourbar(0.02, 0.05, 0.04, 0.06, omega=-3.0))
    assert (fb.kind, fb.links, fb.a, fb.b, fb.c, fb.sense) == ("fourbar", ("1", "2", "3"), 0.02, 0.05, 0.04, -1.0)
    assert fb.names == {"A": "A", "B": "B", "C": "C", "D": "D"}
    sc = basic_loop(Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.03, 1.0),
                            (RRP("B", "C", ("2", "3"), 0.06, Guide((0.0, 0.0), 0.0)),)))
    assert (sc.kind, sc.b, sc.c, sc.sense) == ("slider_crank", 0.06, 0.0, 1.0)
    gb = basic_loop(Linkage({"A": (0.0, 0.0), "C": (0.0, -0.1)}, Crank("1", "A", "B", 0.03, 1.0),
                            (RPR("B", "C", ("2", "3"), bar="second"),)))
    assert (gb.kind, gb.names["C"], gb.links) == ("guide_bar", "C", ("1", "2", "3"))


def test_a_dyad_written_from_the_frame_end_is_the_same_four_bar() -> None:
    """RRR D–C–B (the crank pin last): the roles and lengths are swapped back to A, B, C, D."""
    lk = Linkage({"A": (0.0, 0.0), "D": (0.06, 0.0)}, Crank("1", "A", "B", 0.02, 10.0),
                 (RRR("D", "C", "B", ("3", "2"), (0.04, 0.05), "right"),))
    loop = basic_loop(lk)
    assert (loop.b, loop.c, loop.links, loop.names["D"]) == (0.05, 0.04, ("1", "2", "3"), "D")
    same = draw_characteristics(fourbar(0.02, 0.05, 0.04, 0.06), MU)
    other = draw_characteristics(lk, MU)
    assert other.theta == pytest.approx(same.theta, abs=1e-12)
    assert other.psi == pytest.approx(same.psi, abs=1e-12)


@pytest.mark.parametrize("linkage, words", [
    (Linkage({"A": (0.0, 0.0)}, SliderInput("3", "C", Guide((0.0, 0.0), 0.0), 1.0),
             (RRR("C", "B", "A", ("2", "1"), (0.3, 0.1)),)), "slider"),
    (Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.03, 1.0)), "no dyad"),
    (Linkage({"A": (0.0, 0.0), "C": (0.0, -0.1)}, Crank("1", "A", "B", 0.03, 1.0),
             (RPR("B", "C", ("2", "3"), bar="first"),)), "guide bar"),
    (Linkage({"A": (0.0, 0.0), "D": (0.1, 0.0), "E": (0.0, 0.1)}, Crank("1", "A", "B", 0.03, 1.0),
             (RRR("D", "C", "E", ("2", "3"), (0.1, 0.1)),)), "four-bar"),
])
def test_a_linkage_without_a_basic_loop_is_refused(linkage: Linkage, words: str) -> None:
    with pytest.raises(ValueError, match=words):
        basic_loop(linkage)
    with pytest.raises(ValueError, match=words):
        draw_characteristics(linkage, MU)


@pytest.mark.parametrize("links, kind", [
    ((1.0, 1.0, 1.0, 5.0), "none"),               # the longest is longer than the rest together
    ((4.0, 5.0, 2.0, 6.0), "crank_rocker_CD"),    # the rocker is the shortest
    ((4.0, 2.0, 5.0, 6.0), "double_rocker"),      # the coupler is the shortest: Grashof, yet no crank
    ((3.0, 8.0, 4.0, 4.5), "double_rocker"),      # s + l > p + q
    ((2.0, 4.0, 2.0, 4.0), "change_point"),       # a parallelogram
])
def test_grashof_class(links: tuple[float, float, float, float], kind: str) -> None:
    assert grashof_class(*links) == kind


def test_a_four_bar_with_no_quick_return() -> None:
    """b² − a² = d² − c²: A lies on the line C₁C₂, so θ = 0 and ψ = 2·asin(a/c)."""
    a, b, d = 0.02, 0.05, 0.06
    c = math.sqrt(d * d - b * b + a * a)
    ch = draw_characteristics(fourbar(a, b, c, d), MU)
    assert ch.grashof == "crank_rocker_AB"
    assert ch.theta == pytest.approx(0.0, abs=1e-12)
    assert (ch.phi_end - ch.phi_start) % (2 * math.pi) == pytest.approx(math.pi, abs=1e-12)
    assert ch.psi == pytest.approx(2.0 * math.asin(a / c), abs=1e-12)
    assert ch.stroke_mm is None
    p = ch.points
    # folded AC = b − a and extended AC = b + a (equal strokes: which is 1 is the convention's)
    reach = sorted(math.dist(p["A"], p[k]) for k in ("C1", "C2"))
    assert reach == pytest.approx([(b - a) / MU, (b + a) / MU], rel=1e-12)
    for k, l in (("B1", "C1"), ("B2", "C2")):
        assert math.dist(p[k], p[l]) == pytest.approx(b / MU, rel=1e-12)
    for k in ("C1", "C2", "Cg"):
        assert math.dist(p["D"], p[k]) == pytest.approx(c / MU, rel=1e-12)
    # the crank along the frame line, either way, makes cos∠BCD = ±(b² + c² − (d − a)²)/(2bc)
    assert ch.gamma_min == pytest.approx(math.acos((b * b + c * c - (d - a) ** 2) / (2 * b * c)), abs=1e-12)


def test_a_centred_slider_crank() -> None:
    """θ = 0, H = 2a, γ_min = acos(a/b) with the crank at right angles to the guide."""
    a, b = 0.03, 0.06
    lk = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", a, 10.0),
                 (RRP("B", "C", ("2", "3"), b, Guide((0.0, 0.0), 0.0)),))
    ch = draw_characteristics(lk, MU)
    assert (ch.grashof, ch.psi) == ("crank", None)
    assert ch.theta == pytest.approx(0.0, abs=1e-12)
    assert ch.stroke_mm == pytest.approx(2 * a / MU, rel=1e-12)
    assert ch.gamma_min == pytest.approx(math.radians(60.0), abs=1e-12)
    assert abs(math.sin(ch.gamma_min_at)) == pytest.approx(1.0, abs=1e-12)
    assert sorted((ch.points["C1"][0], ch.points["C2"][0])) == pytest.approx([(b - a) / MU, (b + a) / MU])
    assert ch.points["G0"][0] < min(ch.points["C1"][0], 0.0) and ch.points["G1"][0] > ch.points["C2"][0]


def test_a_double_crank_has_only_its_transmission_angle() -> None:
    ch = draw_characteristics(fourbar(0.05, 0.06, 0.055, 0.02), MU)
    assert ch.grashof == "double_crank"
    assert (ch.theta, ch.psi, ch.phi_start, ch.phi_end, ch.stroke_mm) == (None, None, None, None, None)
    assert 0.0 < ch.gamma_min < math.pi / 2


def test_a_rotating_guide_bar_is_refused() -> None:
    lk = Linkage({"A": (0.0, 0.0), "C": (0.0, -0.03)}, Crank("1", "A", "B", 0.05, 1.0),
                 (RPR("B", "C", ("2", "3"), bar="second"),))
    with pytest.raises(ValueError, match="turns fully"):
        draw_characteristics(lk, MU)


def test_fourbar_lengths() -> None:
    lk = Linkage({"A": (0.01, 0.02), "D": (0.04, 0.06)}, Crank("1", "A", "B", 0.02, 1.0),
                 (RRR("B", "C", "D", ("2", "3"), (0.05, 0.04)),))
    assert fourbar_lengths(lk) == pytest.approx({"AB": 0.02, "BC": 0.05, "CD": 0.04, "AD": 0.05})
    sc = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.03, 1.0),
                 (RRP("B", "C", ("2", "3"), 0.06, Guide((0.0, 0.0), 0.0)),))
    with pytest.raises(ValueError, match="hinged four-bar"):
        fourbar_lengths(sc)
