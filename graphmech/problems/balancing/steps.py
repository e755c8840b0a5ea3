"""The construction protocol of a balancing scene: the mass-radius products, (for a dynamic
balance) their shares in the two correction planes, and each plane's mass-radius polygon laid
off side by side, closed, and read off — as the book words it, with every length drawn.

The numbers are those of the check's own polygons
(:func:`graphmech.problems.balancing.check.analyse_balancing`): the sides are the drawn ones,
the closing side's length and direction the ones the check table reads.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING

from graphmech.geometry.primitives import degrees_0_360
from graphmech.problems.balancing.check import BalancingAnalysis, analyse_balancing
from graphmech.problems.judging import Row
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, scale_choice, text

if TYPE_CHECKING:
    from graphmech.methods.balancing import Correction
    from graphmech.problems.balancing.scene import BalancingProblem
    from graphmech.problems.reader import Scene

#: The balancing's phrases: key → (English, 中文, русский). 孙桓: 质径积 W = m·r, 质径积矢量多边形,
#: 平衡平面; the Russian books: дисбаланс D = m·r, план векторов дисбалансов, плоскости коррекции.
PHRASES: Phrases = {
    **COMMON,
    "product": ("mass {m}: {W} = {m}·{r} = {mv} kg × {rv} m = {Wv} kg·m, at θ{i} = {th}°",
                "质量{m}：质径积{W} = {m}·{r} = {mv} kg × {rv} m = {Wv} kg·m，方向θ{i} = {th}°",
                "масса {m}: дисбаланс {W} = {m}·{r} = {mv} kg × {rv} m = {Wv} kg·m, под углом θ{i} = {th}°"),
    "planes": ("the correction planes: I at z = {z1} m, II at z = {z2} m, Δ = z_II − z_I = {span} m",
               "平衡平面：I在z = {z1} m处，II在z = {z2} m处，Δ = z_II − z_I = {span} m",
               "плоскости коррекции: I при z = {z1} m, II при z = {z2} m, Δ = z_II − z_I = {span} m"),
    "shares": ("resolve {W} (z{i} = {z} m) into the planes: {WI} = {W}·(z_II − z{i})/Δ = {WIv} kg·m, "
               "{WII} = {W}·(z{i} − z_I)/Δ = {WIIv} kg·m",
               "将{W}（z{i} = {z} m）分解到两平衡平面：{WI} = {W}·(z_II − z{i})/Δ = {WIv} kg·m，"
               "{WII} = {W}·(z{i} − z_I)/Δ = {WIIv} kg·m",
               "раскладываем {W} (z{i} = {z} m) на плоскости коррекции: {WI} = {W}·(z_II − z{i})/Δ = {WIv} kg·m, "
               "{WII} = {W}·(z{i} − z_I)/Δ = {WIIv} kg·m"),
    "reversed": ("{W} < 0: it is laid off reversed, at θ + 180°", "{W} < 0：反向画出，方向θ + 180°",
                 "{W} < 0: откладываем в обратную сторону, под углом θ + 180°"),
    "choose": ("choose {mu}", "取{mu}", "выбираем {mu}"),
    "polygon": ("the mass-radius polygon{plane}: from o lay the products off head to tail, each ∥ its mass's radius",
                "作质径积矢量多边形{plane}：自o点起将各质径积首尾相接依次画出，方向与各质量的向径一致",
                "строим план векторов дисбалансов{plane}: от точки o откладываем векторы один за другим, каждый ∥ "
                "радиусу своей массы"),
    "in plane": (" of plane {p}", "（平衡平面{p}）", " плоскости {p}"),
    "side": ("from {frm} lay off {W} = {Wv}/{mu} = {mm} mm at {th}° to the x axis",
             "自{frm}作{W} = {Wv}/{mu} = {mm} mm，与x轴成{th}°",
             "от {frm} откладываем {W} = {Wv}/{mu} = {mm} mm под углом {th}° к оси x"),
    "no share": ("{W} = 0: nothing to lay off", "{W} = 0：无需画出", "{W} = 0: откладывать нечего"),
    "o": ("o", "o点", "точки o"),
    "end of": ("the end of {W}", "{W}的末端", "конца {W}"),
    "closing": ("the closing side {Wb}, from the end of {last} back to o: measure {mm} mm: "
                "{Wb} = {mm} × {mu} = {Wv} kg·m",
                "由{last}的末端指向o点的封闭矢量即{Wb}：量得{mm} mm，{Wb} = {mm} × {mu} = {Wv} kg·m",
                "замыкающий вектор {Wb} — от конца {last} к точке o: измеряем {mm} mm: {Wb} = {mm} × {mu} = {Wv} kg·m"),
    "closes": ("the polygon{plane} closes by itself: {Wb} = 0, no correction mass needed",
               "质径积矢量多边形{plane}自行封闭：{Wb} = 0，无需加平衡质量",
               "план{plane} замыкается сам: {Wb} = 0, корректирующая масса не нужна"),
    "mass": ("the correction mass at r_b = {rb} m: {mb} = {Wb}/r_b = {mm} mm × {mu}/{rb} = {mv} kg",
             "平衡质量（r_b = {rb} m）：{mb} = {Wb}/r_b = {mm} mm × {mu}/{rb} = {mv} kg",
             "корректирующая масса на радиусе r_b = {rb} m: {mb} = {Wb}/r_b = {mm} mm × {mu}/{rb} = {mv} kg"),
    "angle": ("measure the direction of {Wb} from the x axis: {th} = {value}° — the correction mass goes there",
              "量得{Wb}与x轴的夹角：{th} = {value}°，平衡质量即加在此方向上",
              "измеряем угол {Wb} с осью x: {th} = {value}° — в этом направлении ставим корректирующую массу"),
    "split": ("split {Wb} along the given directions α₁ = {a1}° and α₂ = {a2}°: through the start of {Wb} draw a "
              "line ∥ α₁, through o a line ∥ α₂; they meet at K: {Wb1} = {mm1} mm × {mu} = {W1} kg·m, "
              "{Wb2} = {mm2} mm × {mu} = {W2} kg·m (a negative one points against its direction); the masses "
              "at r_b: m_b1 = {m1} kg, m_b2 = {m2} kg",
              "将{Wb}沿给定的α₁ = {a1}°、α₂ = {a2}°两方向分解：过{Wb}的起点作α₁方向的直线，过o点作α₂方向的直线，"
              "交于K：{Wb1} = {mm1} mm × {mu} = {W1} kg·m，{Wb2} = {mm2} mm × {mu} = {W2} kg·m（负值表示与该方向相反）；"
              "r_b处的平衡质量m_b1 = {m1} kg，m_b2 = {m2} kg",
              "раскладываем {Wb} по заданным направлениям α₁ = {a1}° и α₂ = {a2}°: через начало {Wb} проводим "
              "прямую ∥ α₁, через o — прямую ∥ α₂; они пересекаются в K: {Wb1} = {mm1} mm × {mu} = {W1} kg·m, "
              "{Wb2} = {mm2} mm × {mu} = {W2} kg·m (отрицательное — против направления); массы на r_b: m_b1 = {m1} kg, "
              "m_b2 = {m2} kg"),
    "centrifugal": ("before balancing, at ω = {w} rad/s the rotor's centrifugal force F = ω²·|Σ mᵢrᵢ| = {w}² × "
                    "{W} kg·m = {F} N",
                    "平衡前，ω = {w} rad/s时转子的离心力F = ω²·|Σ mᵢrᵢ| = {w}² × {W} kg·m = {F} N",
                    "до балансировки при ω = {w} rad/s центробежная сила ротора F = ω²·|Σ mᵢrᵢ| = {w}² × "
                    "{W} kg·m = {F} N"),
    "residual force": ("check: with the correction masses added, |Σ mᵢrᵢ| = {value} kg·m — the force polygon closes",
                       "校核：加平衡质量后，|Σ mᵢrᵢ| = {value} kg·m，多边形封闭",
                       "проверка: с корректирующими массами |Σ mᵢrᵢ| = {value} kg·m — план замкнут"),
    "residual moment": ("and |Σ mᵢrᵢzᵢ| about plane I = {value} kg·m² — the moments balance too",
                        "且对平面I的|Σ mᵢrᵢzᵢ| = {value} kg·m²，力矩亦平衡",
                        "и |Σ mᵢrᵢzᵢ| относительно плоскости I = {value} kg·m² — моменты тоже уравновешены"),
}


def balancing_steps(scene: Scene[BalancingProblem]) -> list[str]:
    """The protocol of a balancing scene, one line per step (not numbered)."""
    return protocol(analyse_balancing(scene, ()))


def _sub(s: str) -> str:
    return text(f"_{{{s}}}")


def _w(name: str, plane: str = "") -> str:
    """W₁, W₁ᴵ, W_bᴵᴵ as the drawing letters them (W_{1}^{I})."""
    sup = plane.replace("I", "ᴵ")
    return f"W{_sub(name)}{sup}"


def protocol(an: BalancingAnalysis) -> list[str]:
    """The steps of an analysed balancing scene."""
    p, notation = an.problem, getattr(an.scene.page, "notation", "en")
    rows: dict[str, Row] = {r.name: r for r in an.rows}
    mu = an.scales["W"]

    def say(key: str, **fields: str) -> str:
        return phrase(key, notation, PHRASES, **fields)

    out = []
    for u in p.masses:
        out.append(say("product", m=f"m{_sub(u.name)}", W=_w(u.name), r=f"r{_sub(u.name)}", mv=num(u.m), rv=num(u.r),
                       Wv=num(u.m * u.r), i=_sub(u.name), th=num(degrees_0_360(u.theta))))
    if p.planes is not None:
        z1, z2 = p.planes
        out.append(say("planes", z1=num(z1), z2=num(z2), span=num(z2 - z1)))
        for u in p.masses:
            k1, k2 = (z2 - u.z) / (z2 - z1), (u.z - z1) / (z2 - z1)
            out.append(say("shares", W=_w(u.name), i=_sub(u.name), z=num(u.z), WI=_w(u.name, "I"), WII=_w(u.name, "II"),
                           WIv=num(u.m * u.r * k1), WIIv=num(u.m * u.r * k2)))
            for plane, k in (("I", k1), ("II", k2)):
                if k < 0:
                    out.append(say("reversed", W=_w(u.name, plane)))
    out.append(say("choose", mu=scale_choice("W", mu, "W" in an.stated, notation)))
    for c in an.corrections:
        out += _polygon(c, p, rows, mu, say)
    split = [rows.get(n) for n in ("W_b1", "W_b2")]
    if p.split is not None and split[0] is not None and split[1] is not None:
        c = an.corrections[0]
        out.append(say("split", Wb="W_b", Wb1="W_b1", Wb2="W_b2",
                       a1=num(degrees_0_360(p.split[0])), a2=num(degrees_0_360(p.split[1])), mu=num(mu),
                       mm1=num(split[0].drawn_mm or 0.0), mm2=num(split[1].drawn_mm or 0.0),
                       W1=num(split[0].graphical), W2=num(split[1].graphical),
                       m1=num(split[0].graphical / c.r_b), m2=num(split[1].graphical / c.r_b)))
    if "F_unbalanced" in rows and p.omega is not None:
        F = rows["F_unbalanced"].graphical
        out.append(say("centrifugal", w=num(p.omega), W=num(F / p.omega ** 2), F=num(F)))
    if "residual_force" in rows:
        out.append(say("residual force", value=num(rows["residual_force"].graphical)))
    if "residual_moment" in rows:
        out.append(say("residual moment", value=num(rows["residual_moment"].graphical)))
    return out


def _polygon(c: Correction, p: BalancingProblem, rows: dict[str, Row], mu: float,
             words: Callable[..., str]) -> list[str]:
    """One plane's polygon: its sides laid off, the closing side measured, the mass and its angle."""
    plane = c.plane
    suffix = plane or "b"  # the check's names: W_b (static), W_I, W_II
    there = words("in plane", p=plane) if plane else ""
    out = [words("polygon", plane=there)]
    last = ""
    for s, u in zip(c.sides, p.masses):
        name = _w(u.name, plane)
        dx, dy = s.end[0] - s.start[0], s.end[1] - s.start[1]
        mm = math.hypot(dx, dy)
        if mm < 1e-9:
            out.append(words("no share", W=name))
            continue
        frm = words("end of", W=last) if last else words("o")
        out.append(words("side", frm=frm, W=name, Wv=num(mm * mu), mu="μW", mm=num(mm),
                         th=num(degrees_0_360(math.atan2(dy, dx)))))
        last = name
    sup = plane.replace("I", "ᴵ")
    wb = f"W_b{sup}"
    if c.balanced:
        out.append(words("closes", plane=there, Wb=wb))
        return out
    out.append(words("closing", Wb=wb, last=last, mm=num(c.drawn_mm), mu=num(mu), Wv=num(c.W)))
    if f"m_{suffix}" in rows:
        out.append(words("mass", rb=num(c.r_b), mb=f"m_b{sup}", Wb=wb, mm=num(c.drawn_mm),
                         mu=num(mu), mv=num(c.m_b)))
    if f"theta_{suffix}" in rows and c.theta is not None:
        out.append(words("angle", Wb=wb, th=f"θ_b{sup}",
                         value=num(degrees_0_360(c.theta))))
    return out


__all__ = ["PHRASES", "balancing_steps", "protocol"]
