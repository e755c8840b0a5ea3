"""The protocol of a gear scene, as the book words the construction: the circles from m, z, α,
h*a, c*, x; the involute by points (divide the base circle, draw the tangents, lay the unwound
arcs off along them); for a pair, O₁O₂ = a′, the line of action tangent to both base circles,
B₁ and B₂ where the tip circles cut it, ε = B₁B₂/p_b — each value read off the check's rows.
"""
from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from graphmech.exact import (
    gear as ex,  # the circles' sizes are definitions, not constructions
)
from graphmech.exact import profile_shift as exs
from graphmech.problems.gears.check import GearAnalysis, analyse
from graphmech.problems.judging import Row
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, read_row, scale_choice

if TYPE_CHECKING:
    from graphmech.problems.gears.scene import GearScene
    from graphmech.problems.reader import Scene

#: The gear protocol's phrases: key → (English, 中文 (孙桓), русский).
PHRASES: Phrases = {
    **COMMON,
    "circles": ("gear{g}: z = {z}, x = {x}: d = mz = {d} mm, d_b = d·cos α = {db} mm, d_a = {da} mm, d_f = {df} mm",
                "齿轮{g}：z = {z}，x = {x}：d = mz = {d} mm，d_b = d·cos α = {db} mm，d_a = {da} mm，d_f = {df} mm",
                "колесо{g}: z = {z}, x = {x}: d = mz = {d} mm, d_b = d·cos α = {db} mm, d_a = {da} mm, "
                "d_f = {df} mm"),
    "choose": ("choose {mu}{panel}", "取{mu}{panel}", "выбираем {mu}{panel}"),
    "for l": ("", "", ""),
    "for tooth": (" for the teeth", "（画轮齿）", " для зубьев"),
    "for zones": (" for the contact zones", "（画啮合区）", " для зон зацепления"),
    "for generation": (" for the generation", "（画范成）", " для нарезания"),
    "involute": ("the involute by points: divide the base circle from the flank's start, at each division N draw "
                 "the tangent and lay off along it the arc unwound from the start (NK = arc); join the points K",
                 "用展成点法作渐开线：自齿廓起点将基圆等分，过各分点N作基圆切线，在切线上量取NK等于相应的弧长，"
                 "光滑连接各K点",
                 "эвольвенту строим по точкам: делим основную окружность от начала профиля, в каждой точке деления N "
                 "проводим касательную и откладываем на ней длину развёрнутой дуги (NK = дуга); соединяем точки K"),
    "radius": ("at r_k = {r} mm: the tangent from K to the base circle touches at N, NK = √(r_k² − r_b²)",
               "在r_k = {r} mm处：自K作基圆切线，切点N，NK = √(r_k² − r_b²)",
               "при r_k = {r} mm: касательная из K к основной окружности касается её в N, NK = √(r_k² − r_b²)"),
    "pair": ("draw O₁O₂ = a′ = {aw} mm, the base circles, and their common tangent N₁N₂ through P (the line of "
             "action); α′ is its angle with the common tangent of the pitch circles",
             "作O₁O₂ = a′ = {aw} mm及两基圆，作两基圆的内公切线N₁N₂（啮合线），交O₁O₂于节点P；"
             "N₁N₂与节圆公切线的夹角即啮合角α′",
             "проводим O₁O₂ = a′ = {aw} mm, основные окружности и их общую касательную N₁N₂ через P (линию "
             "зацепления); α′ — её угол с общей касательной начальных окружностей"),
    "tips": ("the tip circle of gear 2 cuts N₁N₂ at B₂ (contact begins), that of gear 1 at B₁ (contact ends)",
             "从动轮2的齿顶圆与N₁N₂交于B₂（开始啮合点），主动轮1的齿顶圆与N₁N₂交于B₁（终止啮合点）",
             "окружность выступов колеса 2 пересекает N₁N₂ в B₂ (начало зацепления), колеса 1 — в B₁ (конец)"),
    "zones": ("lay p_b = {pb} mm off from B₁ and from B₂: two pairs are in contact at the ends (each (ε − 1)p_b), "
              "one pair in the middle ((2 − ε)p_b)",
              "自B₁、B₂分别量取p_b = {pb} mm：两端各(ε − 1)p_b为两对齿啮合区，中间(2 − ε)p_b为单对齿啮合区",
              "от B₁ и B₂ откладываем p_b = {pb} mm: у концов (по (ε − 1)p_b) — двухпарное зацепление, "
              "в середине ((2 − ε)p_b) — однопарное"),
    "eps": ("ε = B₁B₂/p_b = {eps}", "ε = B₁B₂/p_b = {eps}", "ε = B₁B₂/p_b = {eps}"),
    "drive": ("a = m(z₁ + z₂)/2 = {a} mm {cmp} a′ = {aw} mm: {kind}",
              "a = m(z₁ + z₂)/2 = {a} mm {cmp} a′ = {aw} mm，故为{kind}",
              "a = m(z₁ + z₂)/2 = {a} mm {cmp} a′ = {aw} mm: {kind}"),
    "standard": ("a standard drive", "标准齿轮传动", "передача без смещения"),
    "equal and opposite": ("an equal and opposite shift (x₁ + x₂ = 0)", "等变位（高度变位）齿轮传动",
                           "равносмещённая передача (x₁ + x₂ = 0)"),
    "positive": ("a positive drive (x₁ + x₂ > 0)", "正传动（x₁ + x₂ > 0）", "положительная передача (x₁ + x₂ > 0)"),
    "negative": ("a negative drive (x₁ + x₂ < 0)", "负传动（x₁ + x₂ < 0）", "отрицательная передача (x₁ + x₂ < 0)"),
    "shift sum": ("no backlash at a′: on the working pitch circles the two teeth fill the working pitch, s₁′ + s₂′ = "
                  "p′; each s′ grows in proportion to x, so x₁ + x₂ = {xs}",
                  "无侧隙啮合：两轮节圆上 s₁′ + s₂′ = p′，s′ 与 x 成线性关系，得 x₁ + x₂ = {xs}",
                  "беззазорное зацепление при a′: на начальных окружностях s₁′ + s₂′ = p′, s′ растёт "
                  "пропорционально x, откуда x₁ + x₂ = {xs}"),
    "shortening": ("y = (a′ − a)/m = {y}, Δy = x₁ + x₂ − y = {dy}: the tips shortened by Δy·m = {dym} mm",
                   "中心距变动系数 y = (a′ − a)/m = {y}，齿顶高降低系数 Δy = x₁ + x₂ − y = {dy}，齿顶降低 Δy·m = {dym} mm",
                   "y = (a′ − a)/m = {y}, Δy = x₁ + x₂ − y = {dy}: вершины укорочены на Δy·m = {dym} mm"),
    "least": ("no undercut: x ≥ x_min = h*a(z_min − z)/z_min = {x} (z_min = {zm})",
              "不根切：x ≥ x_min = h*a(z_min − z)/z_min = {x}（z_min = {zm}）",
              "без подреза: x ≥ x_min = h*a(z_min − z)/z_min = {x} (z_min = {zm})"),
    "repair": ("the wheel re-cut {loss} mm thinner: x₂ = −Δs/(2m·tan α) = {x2}; the new pinion x₁ = −x₂ = {x1}",
               "大齿轮修复：齿厚减薄 {loss} mm，x₂ = −Δs/(2m·tan α) = {x2}；新小齿轮 x₁ = −x₂ = {x1}",
               "колесо перерезается тоньше на {loss} mm: x₂ = −Δs/(2m·tg α) = {x2}; новая шестерня x₁ = −x₂ = {x1}"),
    "not continuous": ("ε < 1: the drive is not continuous", "ε < 1：传动不连续", "ε < 1: передача не непрерывна"),
}


def gear_steps(scene: Scene[GearScene]) -> list[str]:
    """The protocol of a gear scene, one line per step (not numbered)."""
    return protocol(analyse(scene, ()))


def protocol(an: GearAnalysis) -> list[str]:
    """The steps of an analysed gear scene."""
    notation = getattr(an.scene.page, "notation", "en")
    s = an.gears.system
    rows: dict[str, Row] = {r.name: r for r in an.rows}

    def say(key: str, **fields: str) -> str:
        return phrase(key, notation, PHRASES, **fields)

    out = _shift_steps(an, say)
    for label in an.problem.labels:
        g = an.gear(label)
        t = ex.tooth(s, g)
        out.append(say("circles", g=f" {label}" if label else "", z=str(g.z), x=num(g.x), d=num(t.d * 1000),
                       db=num(t.db * 1000), da=num(t.da * 1000), df=num(t.df * 1000)))
    for key in an.scales:
        out.append(say("choose", mu=scale_choice(key, an.scales[key], key in an.stated, notation),
                       panel=say(f"for {key}")))
    if an.radii or an.pointed or an.spans or an.pins:
        out.append(say("involute"))
    for (_label, r) in an.radii:
        out.append(say("radius", r=num(r * 1000)))
    if an.mesh is not None:
        out.append(say("pair", aw=num(an.mesh.a_w * 1000)))
        out.append(say("tips"))
        if 1.0 <= an.mesh.eps_alpha < 2.0:
            out.append(say("zones", pb=num(an.mesh.pb * 1000)))
    for name in an.names:
        if name in rows:
            out.append(read_row(rows[name], notation))
    if an.mesh is not None:
        out.append(say("eps", eps=num(an.mesh.eps_alpha)))
        if an.mesh.eps_alpha < 1.0:
            out.append(say("not continuous"))
    return out


def _shift_steps(an: GearAnalysis, say: Callable[..., str]) -> list[str]:
    """How the shifts were chosen, before the circles they give."""
    p = an.problem
    s = an.gears.system
    out = []
    if p.shift in ("least", "least_exact"):
        for label in p.labels:
            g = an.gear(label)
            out.append(say("least", x=num(g.x), zm=num(exs.z_min_book(s) if p.shift == "least" else exs.z_min_exact(s))))
    if p.shift == "repair":
        g1, g2 = an.gears.gears
        out.append(say("repair", loss=num(float(p.thickness_loss or 0.0) * 1000), x1=num(g1.x), x2=num(g2.x)))
    if an.gears.meshing == "external":
        g1, g2 = an.gears.gears
        e = an.exact_mesh
        kind = exs.drive_kind(g1.x, g2.x)
        if p.shift == "for_centre_distance" or kind != "standard":
            cmp = "=" if kind in ("standard", "equal and opposite") else "<" if kind == "positive" else ">"
            out.append(say("drive", a=num(e.a * 1000), aw=num(e.a_w * 1000), cmp=cmp, kind=say(kind)))
        if p.shift == "for_centre_distance":
            out.append(say("shift sum", xs=num(g1.x + g2.x)))
        if g1.delta_y:
            out.append(say("shortening", y=num((e.a_w - e.a) / s.m), dy=num(g1.delta_y),
                           dym=num(g1.delta_y * s.m * 1000)))
    return out


__all__ = ["gear_steps", "protocol"]
