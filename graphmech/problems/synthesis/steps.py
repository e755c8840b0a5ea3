"""The construction protocol of a synthesis scene: θ from K, the construction as the book words it
with every length drawn, each design's lengths measured and read, and its re-analysis.

The numbers are those of the check's own construction
(:func:`graphmech.problems.synthesis.check.analyse_synthesis`): the lengths drawn and measured are
the ones the check table reads.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, scale_choice
from graphmech.problems.synthesis.check import SELF_CONTAINED, SynthesisAnalysis, analyse_synthesis
from graphmech.problems.synthesis.time_ratio import GuideBar, Problem, SliderCrank, prefix

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene
    from graphmech.problems.synthesis.scene import SynthesisScene

#: The synthesis phrases: key → (English, 中文, русский). 孙桓 §8: 极位夹角 θ, 行程速比系数 K.
PHRASES: Phrases = {
    **COMMON,
    **{k: v for own in SELF_CONTAINED.values() for k, v in own.PHRASES.items()},
    "theta": ("θ = 180°(K − 1)/(K + 1) = 180° × ({K} − 1)/({K} + 1) = {th}°",
              "极位夹角 θ = 180°(K − 1)/(K + 1) = 180° × ({K} − 1)/({K} + 1) = {th}°",
              "угол перекрытия θ = 180°(K − 1)/(K + 1) = 180° × ({K} − 1)/({K} + 1) = {th}°"),
    "choose": ("choose {mu}", "取{mu}", "выбираем {mu}"),
    "frame": ("draw the frame line AD = {d}/μl = {mm} mm", "作机架线 AD = {d}/μl = {mm} mm",
              "проводим линию стойки AD = {d}/μl = {mm} mm"),
    "limit": ("from D lay off DC₁ = {c}/μl = {mm} mm at {lam}° to DA: the limit position C₁",
              "自D作DC₁ = {c}/μl = {mm} mm，与DA成{lam}°：极限位置C₁",
              "от D откладываем DC₁ = {c}/μl = {mm} mm под углом {lam}° к DA: крайнее положение C₁"),
    "ray": (("join AC₁; from A draw a ray at θ = {th}° to AC₁ (either side); the rocker's circle about D "
            "(radius {mm} mm) cuts it at C₂ — each cut that gives a Grashof crank is a design"),
            ("连AC₁；自A作与AC₁成θ = {th}°的射线（两侧）；以D为圆心、{mm} mm为半径的摇杆圆与之交于C₂，"
            "每个给出曲柄的交点即一个解"),
            ("соединяем AC₁; из A проводим луч под углом θ = {th}° к AC₁ (в обе стороны); окружность коромысла "
            "около D (радиус {mm} mm) пересекает его в C₂ — каждое пересечение с кривошипом даёт решение")),
    "swing": ("from D draw DC₁ and DC₂ = {c}/μl = {mm} mm, ψ = {psi}° apart",
              "自D作DC₁、DC₂ = {c}/μl = {mm} mm，夹角ψ = {psi}°",
              "от D откладываем DC₁ и DC₂ = {c}/μl = {mm} mm под углом ψ = {psi}° друг к другу"),
    "circle": (("the θ-circle: from C₁ a line at 90° − θ = {a}° to C₁C₂ meets the bisector of C₁C₂ at O; "
               "the circle about O through C₁ and C₂"),
               "作θ圆：自C₁作与C₁C₂成90° − θ = {a}°的直线，与C₁C₂的中垂线交于O；以O为圆心过C₁、C₂作圆",
               ("θ-окружность: из C₁ прямая под углом 90° − θ = {a}° к C₁C₂ пересекает серединный "
               "перпендикуляр C₁C₂ в O; окружность с центром O через C₁ и C₂")),
    "A on circle": ("the circle of radius AD = {d}/μl = {mm} mm about D cuts the θ-circle's arc at A",
                    "以D为圆心、AD = {d}/μl = {mm} mm为半径作圆，与θ圆交于A",
                    "окружность радиуса AD = {d}/μl = {mm} mm около D пересекает дугу θ-окружности в A"),
    "stroke": ("on the guide lay off C₁C₂ = H = {H}/μl = {mm} mm", "在导路上取C₁C₂ = H = {H}/μl = {mm} mm",
               "на направляющей откладываем C₁C₂ = H = {H}/μl = {mm} mm"),
    "offset": ("the line at the offset e = {e}/μl = {mm} mm from the guide cuts the θ-circle at A (behind C₁)",
               "作距导路偏距e = {e}/μl = {mm} mm的平行线，与θ圆交于A（在C₁之后）",
               "прямая на расстоянии e = {e}/μl = {mm} mm от направляющей пересекает θ-окружность в A (за C₁)"),
    "design": (("{name}: measure AC₁ = {ac1} mm and AC₂ = {ac2} mm: l_AB = (AC₂ − AC₁)/2 × μl = {a} m, "
               "l_BC = (AC₁ + AC₂)/2 × μl = {b} m"),
               ("{name}：量得AC₁ = {ac1} mm，AC₂ = {ac2} mm：l_AB = (AC₂ − AC₁)/2 × μl = {a} m，"
               "l_BC = (AC₁ + AC₂)/2 × μl = {b} m"),
               ("{name}: измеряем AC₁ = {ac1} mm и AC₂ = {ac2} mm: l_AB = (AC₂ − AC₁)/2 × μl = {a} m, "
               "l_BC = (AC₁ + AC₂)/2 × μl = {b} m")),
    "bar pivots": ("draw C and A above it at AC = {d}/μl = {mm} mm", "作C点，其上方AC = {d}/μl = {mm} mm处为A",
                   "отмечаем C и над ним A на расстоянии AC = {d}/μl = {mm} mm"),
    "bar limits": (("from C draw the bar's limit lines at ψ/2 = θ/2 = {half}° either side of CA; the perpendicular "
                   "from A to one is the crank: measure AB₁ = {mm} mm: l_AB = {a} m"),
                   "自C作与CA成ψ/2 = θ/2 = {half}°的两导杆极限位置线；自A作其垂线即曲柄：量得AB₁ = {mm} mm：l_AB = {a} m",
                   ("из C проводим крайние положения кулисы под углом ψ/2 = θ/2 = {half}° к CA; перпендикуляр из A "
                   "к одному из них — кривошип: измеряем AB₁ = {mm} mm: l_AB = {a} m")),
    "bar length": (("lay off D₁D₂ = H = {H}/μl = {Hmm} mm ⟂ CA between the limit lines: measure CD₂ = {mm} mm: "
                   "l_CD = {l} m"),
                   "在两极限位置线间作垂直于CA的D₁D₂ = H = {H}/μl = {Hmm} mm：量得CD₂ = {mm} mm：l_CD = {l} m",
                   ("между крайними положениями откладываем D₁D₂ = H = {H}/μl = {Hmm} mm ⟂ CA: измеряем "
                   "CD₂ = {mm} mm: l_CD = {l} m")),
    "check": ("check {name}: re-analysed, K = {K}, {what}, γ_min = {g}°",
              "校核{name}：重新分析得K = {K}，{what}，γ_min = {g}°",
              "проверка {name}: повторный анализ даёт K = {K}, {what}, γ_min = {g}°"),
}


def synthesis_steps(scene: Scene[SynthesisScene]) -> list[str]:
    """The protocol of a synthesis scene, one line per step (not numbered)."""
    return protocol(analyse_synthesis(scene))


def protocol(an: SynthesisAnalysis) -> list[str]:
    """The steps of an analysed synthesis scene."""
    notation = getattr(an.scene.page, "notation", "en")
    p = an.scene.problem.problem
    mu = an.scales["l"]

    def say(key: str, **fields: str) -> str:
        return phrase(key, notation, PHRASES, **fields)

    own = SELF_CONTAINED.get(an.scene.problem.task)
    if own is not None:  # the task words its own construction
        return [say("choose", mu=scale_choice("l", mu, "l" in an.stated, notation)),
                *own.steps(an.found, mu, say, num)]
    assert isinstance(p, Problem)
    th = math.degrees(p.theta)
    out = [say("theta", K=num(p.K), th=num(th)), say("choose", mu=scale_choice("l", mu, "l" in an.stated, notation))]
    if isinstance(p, GuideBar):
        g = an.guide
        assert g is not None
        out.append(say("bar pivots", d=num(p.frame), mm=num(p.frame / mu)))
        out.append(say("bar limits", half=num(th / 2), mm=num(g.lAB_mm), a=num(g.lAB_mm * mu)))
        if p.stroke is not None and g.lCD_mm is not None:
            out.append(say("bar length", H=num(p.stroke), Hmm=num(p.stroke / mu), mm=num(g.lCD_mm),
                           l=num(g.lCD_mm * mu)))
    elif isinstance(p, SliderCrank):
        s = an.slider
        assert s is not None
        out += [say("stroke", H=num(p.stroke), mm=num(p.stroke / mu)), say("circle", a=num(90 - th)),
                say("offset", e=num(p.offset), mm=num(p.offset / mu)),
                say("design", name="design", ac1=num(s.AC1_mm), ac2=num(s.AC2_mm), a=num(s.lAB_mm * mu),
                    b=num(s.lBC_mm * mu))]
    else:
        if p.limit_angle is not None:
            out += [say("frame", d=num(p.frame), mm=num(p.frame / mu)),
                    say("limit", c=num(p.rocker), mm=num(p.rocker / mu), lam=num(math.degrees(p.limit_angle))),
                    say("ray", th=num(th), mm=num(p.rocker / mu))]
        else:
            out += [say("swing", c=num(p.rocker), mm=num(p.rocker / mu), psi=num(math.degrees(p.swing or 0.0))),
                    say("circle", a=num(90 - th)), say("A on circle", d=num(p.frame), mm=num(p.frame / mu))]
        for k, d in enumerate(an.drawn):
            name = prefix(k, len(an.drawn)).rstrip("_") or "design"
            out.append(say("design", name=name, ac1=num(d.AC1_mm), ac2=num(d.AC2_mm), a=num(d.lAB_mm * mu),
                           b=num(d.lBC_mm * mu)))
    for sol in an.solutions:
        re = sol["reanalysis"]
        what = (f"H = {num(re['stroke'])} m" if "stroke" in re else f"ψ = {num(re['psi_deg'])}°")
        out.append(say("check", name=str(sol["name"]), K=num(re["K"]), what=what, g=num(re["gamma_min_deg"])))
    return out


__all__ = ["PHRASES", "protocol", "synthesis_steps"]
