"""Checking a helical, bevel or worm pair: the constructions of :mod:`graphmech.methods.helix` (the
developed reference cylinder, the normal section, the transverse meshing, the back cone, the
developed thread) against the closed forms of :mod:`graphmech.exact.gear_spatial`.

Dispatched from the kind's functions (:mod:`graphmech.problems.gears`) for the meshings
``"helical"``, ``"bevel"``, ``"worm"``; the analysis is a :class:`~graphmech.problems.gears.check.GearAnalysis`
with the constructions beside it, so the rest of graphmech reads it as any gear scene's.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from graphmech.errors import (
    GraphmechError,
    NoSolution,
    NotApplicable,
    OutOfDomain,
    SceneError,
)
from graphmech.exact import gear_spatial as ex
from graphmech.methods import helix
from graphmech.problems.gears.check import GearAnalysis
from graphmech.problems.gears.scene import GearScene, quantity_unit
from graphmech.problems.gears.spatial_scene import NEEDS_B
from graphmech.problems.judging import (
    Row,
    Verdict,
    in_double_precision,
    judge_value,
    measured_entries,
)
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, read_row, scale_choice
from graphmech.problems.reader import page_size
from graphmech.scales import drawn_size_problem, format_scale, round_scale

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene

#: The defaults of ``find``: the bank's names (gear.helical_20_40_mn8, gear.worm_i20.5_m5).
DEFAULT_HELICAL = ("a_initial", "a", "beta", "alpha_t", "d1", "d2", "da1", "da2", "df1", "df2", "db1", "db2",
                   "alpha_at1", "alpha_at2", "zv1", "zv2", "ha", "hf", "sn", "st", "pn", "pt", "eps_alpha",
                   "eps_beta", "eps_gamma")
DEFAULT_BEVEL = ("delta1", "delta2", "R_cone", "theta_a", "theta_f", "d1", "d2", "da1", "da2", "df1", "df2", "zv1",
                 "zv2")
DEFAULT_WORM = ("z2", "q", "gamma1", "beta2", "d1", "d2", "da1", "da2", "df1", "df2", "a")
#: The main drawing's share of the page (the other drawings of the helix panel take the rest).
MAIN_SHARE = 0.55
#: The page's title and a panel's notes, the side margins, mm (as check.py's).
TITLE_MM, CAPTION_MM, SIDE_MM = 38.0, 40.0, 40.0
#: Teeth shown on the developed strip of a helical gear.
STRIP_TEETH = 4
#: The book's bevel face width: B ≤ R/3.
BEVEL_B_MOST = 1.0 / 3.0


@dataclass
class SpatialAnalysis(GearAnalysis):
    """A helical, bevel or worm scene's analysis: the rows as any gear scene's, the construction
    and the closed forms of its meshing."""

    construction: Any = None
    exact: Any = None

    def scale_notes(self) -> list[str]:
        return [format_scale(k, v) + (" (stated)" if k in self.stated else " (chosen)") for k, v in self.scales.items()]


def default_find(p: GearScene) -> tuple[str, ...]:
    kind = p.gears.meshing
    names = DEFAULT_HELICAL if kind == "helical" else DEFAULT_BEVEL if kind == "bevel" else DEFAULT_WORM
    return tuple(n for n in names if quantity_unit(n, p) is not None)


def analyse_spatial(scene: Scene[GearScene], extra_measured: tuple[tuple[str, float], ...] = ()) -> SpatialAnalysis:
    """Construct the pair, measure what the scene asks for, and set it against the closed forms."""
    p = scene.problem
    an = SpatialAnalysis(scene, p, extra_measured=tuple(extra_measured))
    problems = [(k, f"unknown gear quantity {n!r}") for k, n, _ in measured_entries(scene, extra_measured)
                if quantity_unit(n, p) is None]
    if problems:
        raise SceneError(problems, scene.source)
    an.names = list(scene.find) or list(default_find(p))
    an.panels = scene.show or ("helix",)
    kind = p.gears.meshing
    with in_double_precision(f"the {kind} construction"):
        try:
            if kind == "helical":
                an.exact, an.construction = ex.helical(p.gears), helix.construct_helical(p.gears)
            elif kind == "bevel":
                an.exact, an.construction = ex.bevel(p.gears), helix.construct_bevel(p.gears)
            else:
                an.exact, an.construction = ex.worm(p.gears), helix.construct_worm(p.gears)
        except (OutOfDomain, NotApplicable, NoSolution) as err:
            key = p.centre_distance_key if kind == "helical" and p.gears.centre_distance is not None else "gear"
            raise SceneError([(key, str(err))], scene.source) from None
        _warn(an)
        _choose_scale(an)
        for i, name in enumerate(an.names):
            try:
                row = _row(an, name)
            except GraphmechError as err:
                raise SceneError([(f"find[{i}]" if scene.find else "gear", f"{name}: {err}")], scene.source) from None
            if row is not None:
                an.rows.append(row)
    return an


def _warn(an: SpatialAnalysis) -> None:
    """Undercut of the virtual gear (z_v below the rack's limit 2h*a/sin²α), a helical pair's β
    recomputed or at 0, a bevel face wider than R/3, ε_γ < 1."""
    s = an.gears.system
    e = an.exact
    z_min = 2.0 * s.ha_star / math.sin(s.alpha) ** 2
    zv = getattr(e, "zv", None)
    for i, v in enumerate(zv or ()):
        if v < z_min:
            an.warnings.append(f"gear {i + 1}'s virtual gear has z_v = {v:.4g} < z_min = {z_min:.4g}: it is undercut "
                               "when cut by a rack")
    if an.gears.meshing == "helical":
        if e.beta == 0.0:
            an.warnings.append("β = 0: a spur pair (m_t = m_n, z_v = z, no lead)")
        if e.eps_gamma is not None and e.eps_gamma < 1.0:
            an.warnings.append(f"ε_γ = {e.eps_gamma:.4g} < 1: the drive is not continuous")
    if an.gears.meshing == "bevel":
        sp = an.gears.spatial
        if sp is not None and sp.face_width is not None and sp.face_width > BEVEL_B_MOST * e.R + 1e-12 * e.R:
            an.warnings.append(f"the face width B = {sp.face_width * 1e3:.4g} mm exceeds R/3 = {e.R / 3.0 * 1e3:.4g} mm "
                               "(the book's limit for a bevel gear)")
        if sp is not None and sp.face_width is not None and sp.face_width >= e.R:
            raise SceneError([("gear.face_width", f"B = {sp.face_width * 1e3:.4g} mm reaches the apex "
                                                  f"(R = {e.R * 1e3:.4g} mm)")], an.scene.source)


def main_extent(an: SpatialAnalysis) -> tuple[float, float]:
    """The main drawing's size (m): the developed strip of a helical gear (a few pitches by B),
    the worm's developed turn (πd₁ by p_z + p_x), the bevel pair's axial section."""
    c = an.construction
    if an.gears.meshing == "helical":
        d = c.development
        return STRIP_TEETH * d.pt + abs(d.advance), d.height
    if an.gears.meshing == "worm":
        return c.pi_d1, c.pz1 + c.px * len(c.threads)
    pts = [(0.0, 0.0), c.P, *c.A, *c.F, c.V1, c.V2]
    for u in ((1.0, 0.0), c.u2):  # each gear's section is symmetric about its axis
        pts += [(2.0 * (p[0] * u[0] + p[1] * u[1]) * u[0] - p[0], 2.0 * (p[0] * u[0] + p[1] * u[1]) * u[1] - p[1])
                for p in (c.P, *c.A, *c.F)]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return max(xs) - min(xs), max(ys) - min(ys)


def _choose_scale(an: SpatialAnalysis) -> None:
    """μl of the main drawing: stated, or round so that it takes its share of the page."""
    wide, tall = main_extent(an)
    if "l" in an.scene.scales:
        an.scales["l"] = an.scene.scales["l"]
        an.stated.add("l")
        why = drawn_size_problem(max(wide, tall), an.scales["l"], "l", "the pair's drawing")
        if why is not None:
            raise SceneError([("scales.l", why)], an.scene.source)
        return
    w, h = page_size(an.scene)
    room_w = (w - SIDE_MM) * MAIN_SHARE
    rows = 2 if an.gears.meshing == "helical" else 1
    room_h = max((h - TITLE_MM) / rows - CAPTION_MM - (30.0 if rows == 2 else 0.0), 15.0)
    an.scales["l"] = round_scale(max(wide / room_w, tall / room_h))


def _values(an: SpatialAnalysis, name: str) -> tuple[float, float, float | None, float] | None:
    """(graphical, exact, the length drawn in mm or None, μ) of a name, SI (angles in rad)."""
    kind = an.gears.meshing
    if kind == "helical":
        return _helical(an, name)
    if kind == "bevel":
        return _bevel(an, name)
    return _worm(an, name)


def _drawn(an: SpatialAnalysis, v: float) -> tuple[float | None, float]:
    mu = an.scales["l"]
    return v / mu, mu


def _split(name: str) -> tuple[str, int]:
    """``"da2"`` → (``da``, 1); a set's name → (name, 0)."""
    if name[-1] in "12" and name not in ("B1B2",):
        return name[:-1], int(name[-1]) - 1
    return name, 0


def _helical(an: SpatialAnalysis, name: str) -> tuple[float, float, float | None, float] | None:
    c: helix.HelicalConstruction = an.construction
    e: ex.HelicalValues = an.exact
    s = an.gears.system
    d = c.development
    stem, i = _split(name)
    z = an.gears.gears[i].z
    none: tuple[None, float] = (None, 1.0)
    if name == "beta":
        return c.angle.beta, e.beta, *none
    if name == "a_initial":
        return c.angle.a_initial, e.a_initial, *none
    if name == "a":
        return c.mesh.a_w, e.a, *none
    if name == "mt":
        return d.mt, e.mt, *none
    if name == "alpha_t":
        return d.alpha_t, e.alpha_t, *none
    if name in ("pn", "pt", "sn", "st"):
        got = {"pn": math.hypot(*d.Pn), "pt": d.pt, "sn": d.sn, "st": d.st}[name]
        return got, getattr(e, name), *_drawn(an, got)
    if name in ("ha", "hf"):  # the normal rack's: definitions
        got = s.ha_star * s.m if name == "ha" else (s.ha_star + s.c_star) * s.m
        return got, getattr(e, name), *none
    if name == "beta_b":
        return (c.leads[0].beta_b if c.leads is not None else 0.0), e.beta_b, *none
    if name in ("eps_alpha", "eps_beta", "eps_gamma"):
        got_e, want_e = getattr(c, name), getattr(e, name)
        if got_e is None or want_e is None:
            return None
        return got_e, want_e, *none
    if stem in ("d", "da", "df", "db"):
        # the transverse circles at the measured m_t and α_t: definitions (d = m_t z …)
        dd = d.mt * z
        got = {"d": dd, "da": dd + 2.0 * s.ha_star * s.m, "df": dd - 2.0 * (s.ha_star + s.c_star) * s.m,
               "db": dd * math.cos(d.alpha_t)}[stem]
        return got, getattr(e, stem)[i], *none
    if stem == "alpha_at":
        return c.alpha_at[i], e.alpha_at[i], *none
    if stem == "zv":
        return c.sections[i].zv, e.zv[i], *none
    if stem == "pz":
        if c.leads is None or e.pz is None:
            return None
        return c.leads[i].pz, e.pz[i], *none
    return None


def _bevel(an: SpatialAnalysis, name: str) -> tuple[float, float, float | None, float] | None:
    c: helix.BevelConstruction = an.construction
    e: ex.BevelValues = an.exact
    s = an.gears.system
    stem, i = _split(name)
    none: tuple[None, float] = (None, 1.0)
    if name == "R_cone":
        return c.R, e.R, *_drawn(an, c.R)
    if name in ("theta_a", "theta_f"):
        return getattr(c, name), getattr(e, name), *none
    if name in ("ha", "hf"):
        got = s.ha_star * s.m if name == "ha" else (s.ha_star + s.c_star) * s.m
        return got, getattr(e, name), *none
    if stem == "delta":
        return c.delta[i], e.delta[i], *none
    if stem == "d":  # d = mz: a definition
        got = s.m * an.gears.gears[i].z
        return got, e.d[i], *_drawn(an, got)
    if stem in ("da", "df"):
        got = getattr(c, stem)[i]
        return got, getattr(e, stem)[i], *_drawn(an, got)
    if stem == "zv":
        return c.zv[i], e.zv[i], *none
    return None


def _worm(an: SpatialAnalysis, name: str) -> tuple[float, float, float | None, float] | None:
    c: helix.WormConstruction = an.construction
    e: ex.WormValues = an.exact
    s = an.gears.system
    sp = an.gears.spatial
    assert sp is not None and sp.worm_diameter is not None
    d1, z2 = sp.worm_diameter, an.gears.gears[1].z
    none: tuple[None, float] = (None, 1.0)
    if name in ("gamma1", "beta2"):
        return getattr(c, name), getattr(e, name), *none
    if name in ("px", "pz1"):
        got = getattr(c, name)
        return got, getattr(e, name), *_drawn(an, got)
    # the sizes are definitions: q = d₁/m, d₂ = mz₂, tips and roots ± h_a, h_f, a = (d₁ + d₂)/2
    ha, hf = s.ha_star * s.m, (s.ha_star + s.c_star) * s.m
    d2 = s.m * z2
    got = {"z2": float(z2), "q": d1 / s.m, "d1": d1, "d2": d2, "da1": d1 + 2.0 * ha, "da2": d2 + 2.0 * ha,
           "df1": d1 - 2.0 * hf, "df2": d2 - 2.0 * hf, "a": 0.5 * (d1 + d2)}.get(name)
    if got is None:
        return None
    return got, float(getattr(e, name)), *none


def _row(an: SpatialAnalysis, name: str) -> Row | None:
    v = _values(an, name)
    if v is None:
        an.warnings.append(f"{name}: not defined for this pair" + (" (β = 0: a spur gear's helix has no lead)"
                                                                 if name.startswith("pz") else ""))
        return None
    g, e, drawn, scale = v
    unit = quantity_unit(name, an.problem) or ""
    if unit == "deg":
        g, e = math.degrees(g), math.degrees(e)
    return Row(name, unit, drawn, scale, g, e, abs(g - e) / max(abs(e), 1e-300))


def judge(an: SpatialAnalysis, precision_mm: float | None = None) -> list[Verdict]:
    """A student's values against the construction: a length drawn on the main drawing within the
    precision × μl; an angle within what a precision-long slip turns the drawing's shorter side;
    any other value within 0.1 % (judging.judge_value)."""
    prec = precision_mm if precision_mm is not None else an.scene.precision_mm
    wide, tall = main_extent(an)
    arm = max(min(wide, tall) / an.scales["l"], prec)
    out = []
    for _key, name, value in measured_entries(an.scene, an.extra_measured):
        v = _values(an, name)
        unit = quantity_unit(name, an.problem) or ""
        if v is None:
            out.append(Verdict(name, value, 0.0, 0.0, False, unit))
            continue
        g, _e, drawn, scale = v
        if unit == "deg":
            tol = math.degrees(math.atan2(prec, arm))
            out.append(Verdict(name, value, math.degrees(g), tol, abs(value - math.degrees(g)) <= tol, unit))
        else:
            out.append(judge_value(name, value, g, drawn, scale, prec, unit))
    return out


def lines(an: SpatialAnalysis) -> list[str]:
    """Under the table: β recomputed from the rounded a; the contact ratios in words."""
    e = an.exact
    out = []
    if an.gears.meshing == "helical":
        if an.gears.centre_distance is not None and an.gears.spatial is not None:
            out.append(f"β = {math.degrees(e.beta):.6g}° recomputed from a = {e.a * 1e3:.6g} mm (the initial "
                       f"β = {math.degrees(an.gears.spatial.beta):.6g}° gave a = {e.a_initial * 1e3:.6g} mm)")
        if e.eps_gamma is not None:
            out.append(f"ε_γ = ε_α + ε_β = {e.eps_alpha:.4g} + {e.eps_beta:.4g} = {e.eps_gamma:.4g}")
    if an.gears.meshing == "worm":
        out.append(f"i = z2/z1 = {e.ratio:.6g}; γ1 = atan(z1/q) = {math.degrees(e.gamma1):.6g}°")
    return out


def extras(an: SpatialAnalysis) -> dict[str, Any]:
    """``check --json``'s "gear" section: the meshing, and for a helical pair whether ε_γ ≥ 1."""
    out: dict[str, Any] = {"meshing": an.gears.meshing}
    if an.gears.meshing == "helical" and an.exact.eps_gamma is not None:
        out["continuous"] = an.exact.eps_gamma >= 1.0
    return {"gear": out}


#: The protocol's phrases: key → (English, 中文 (孙桓), русский).
PHRASES: Phrases = {
    **COMMON,
    "choose": ("choose {mu}", "取{mu}", "выбираем {mu}"),
    "beta": ("lay off L = m_n(z₁ + z₂)/2 = {L} mm; the circle of radius a = {a} mm cuts the perpendicular at L in "
             "A: β = ∠LOA = {beta}°",
             "量取L = m_n(z₁ + z₂)/2 = {L} mm，以a = {a} mm为半径画圆交L处垂线于A：β = ∠LOA = {beta}°",
             "откладываем L = m_n(z₁ + z₂)/2 = {L} mm; окружность радиуса a = {a} mm пересекает перпендикуляр в L "
             "в точке A: β = ∠LOA = {beta}°"),
    "develop": ("develop the reference cylinder: the helices are straight lines at β to the axis; lay off p_n = {pn} "
                "mm normal to them: they cut the circumference at p_t = {pt} mm, m_t = p_t/π",
                "将分度圆柱面展开：螺旋线为与轴线成β角的直线；沿其法向量取p_n = {pn} mm，在端面上截得p_t = {pt} mm，"
                "m_t = p_t/π",
                "развёртываем делительный цилиндр: винтовые линии — прямые под углом β к оси; откладываем по нормали "
                "p_n = {pn} mm, на окружности получаем p_t = {pt} mm, m_t = p_t/π"),
    "section": ("the normal section is an ellipse of semi-axes r/cos β and r; its radius of curvature at the pitch "
                "point ρ = r/cos²β is the virtual gear's radius: z_v = 2ρ/m_n",
                "法面截分度圆柱得椭圆，半轴r/cos β与r；节点处曲率半径ρ = r/cos²β即当量齿轮分度圆半径：z_v = 2ρ/m_n",
                "нормальное сечение — эллипс с полуосями r/cos β и r; его радиус кривизны в полюсе ρ = r/cos²β — "
                "радиус эквивалентного колеса: z_v = 2ρ/m_n"),
    "transverse": ("the transverse section is a spur pair of m_t, α_t: its line of action cut by the tip circles gives "
                   "B₁B₂ and ε_α; ε_β = B·tan β/p_t from the development",
                   "端面为m_t、α_t的直齿轮传动：齿顶圆截啮合线得B₁B₂与ε_α；由展开图得ε_β = B·tan β/p_t",
                   "торцовое сечение — прямозубая пара m_t, α_t: окружности вершин отсекают B₁B₂ и ε_α; по развёртке "
                   "ε_β = B·tg β/p_t"),
    "cones": ("draw the axes at Σ = {sigma}°, the lines r₁ and r₂ from them cross at P: the pitch cones OP, R = OP; "
              "the back cone ⟂ OP at P cuts the axes at the virtual gears' centres: r_v = r/cos δ",
              "作两轴夹角Σ = {sigma}°，距两轴r₁、r₂的直线交于P：OP为分度圆锥母线，R = OP；过P作OP的垂线（背锥）交两轴，"
              "得当量齿轮半径r_v = r/cos δ",
              "проводим оси под углом Σ = {sigma}°, прямые на расстоянии r₁ и r₂ от них пересекаются в P: OP — "
              "образующая делительных конусов, R = OP; дополнительный конус ⟂ OP в P пересекает оси: r_v = r/cos δ"),
    "thread": ("develop one turn of the worm's reference cylinder, πd₁ = {pid} mm; the lead p_z = z₁p_x = {pz} mm "
               "along the axis: the thread's angle to the circumference is the lead angle γ₁ = {gamma}°",
               "将蜗杆分度圆柱展开一周，πd₁ = {pid} mm；沿轴向取导程p_z = z₁p_x = {pz} mm：螺旋线与端面的夹角即导程角"
               "γ₁ = {gamma}°",
               "развёртываем один виток делительного цилиндра червяка, πd₁ = {pid} mm; ход p_z = z₁p_x = {pz} mm "
               "вдоль оси: угол витка с окружностью — угол подъёма γ₁ = {gamma}°"),
}


def protocol(an: SpatialAnalysis) -> list[str]:
    """The steps of a helical, bevel or worm scene."""
    notation = getattr(an.scene.page, "notation", "en")
    s = an.gears.system
    c = an.construction

    def say(key: str, **fields: str) -> str:
        return phrase(key, notation, PHRASES, **fields)

    out = [say("choose", mu=scale_choice(k, v, k in an.stated, notation)) for k, v in an.scales.items()]
    if an.gears.meshing == "helical":
        z = an.gears.gears[0].z + an.gears.gears[1].z
        if an.gears.centre_distance is not None:
            out.append(say("beta", L=num(s.m * z / 2.0 * 1e3), a=num(an.gears.centre_distance * 1e3),
                           beta=num(math.degrees(c.angle.beta))))
        out += [say("develop", pn=num(c.development.pn * 1e3), pt=num(c.development.pt * 1e3)), say("section"),
                say("transverse")]
    elif an.gears.meshing == "bevel":
        assert an.gears.spatial is not None
        out.append(say("cones", sigma=num(math.degrees(an.gears.spatial.shaft_angle))))
    else:
        out.append(say("thread", pid=num(c.pi_d1 * 1e3), pz=num(c.pz1 * 1e3), gamma=num(math.degrees(c.gamma1))))
    rows = {r.name: r for r in an.rows}
    out += [read_row(rows[n], notation) for n in an.names if n in rows]
    return out


__all__ = ["DEFAULT_BEVEL", "DEFAULT_HELICAL", "DEFAULT_WORM", "NEEDS_B", "SpatialAnalysis", "analyse_spatial",
           "default_find", "extras", "judge", "lines", "main_extent", "protocol"]
