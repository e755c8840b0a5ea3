"""The construction protocol of a kinetostatic scene: the accelerations taken from the linkage's
polygons, the inertia loads, then group by group from the farthest Assur group to the driver the
force polygon laid off head to tail at μF and closed, the reactions read off, and the balancing
moment — as the book words it, with every length drawn.

The numbers are the check's own (:func:`graphmech.problems.forces.check.analyse_forces`): the
polygons' vectors are the ones drawn, and every value of the check table is read off as the
table reads it (drawn mm × μ), so the protocol and the table agree to the last printed figure.
The acceleration polygon itself is the linkage's protocol (``graphmech steps`` of a linkage
scene with the same mechanism).
"""
from __future__ import annotations

import cmath
import math
from typing import TYPE_CHECKING

from graphmech.problems.forces.check import ForceAnalysis, analyse_forces
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, read_row, scale_choice

if TYPE_CHECKING:
    from graphmech.problems.forces.scene import ForceScene
    from graphmech.problems.reader import Scene

#: The kinetostatics' phrases: key → (English, 中文, русский). 孙桓: 惯性力 F_I = −m·a_S, 惯性力偶矩,
#: 杆组, 力多边形, 平衡力矩; the Russian books: силы инерции, группа Ассура, план сил, уравновешивающий момент.
PHRASES: Phrases = {
    **COMMON,
    "position": ("position φ₁ = {phi}°", "位置φ₁ = {phi}°", "положение φ₁ = {phi}°"),
    "kinematics": ("the accelerations from the acceleration polygon at {mu} (its construction: graphmech steps "
                   "of the linkage)",
                   "由加速度多边形求各加速度，{mu}（作图步骤见机构的graphmech steps）",
                   "ускорения — из плана ускорений, {mu} (его построение: graphmech steps механизма)"),
    "force": ("on link {i}: F_i{i} = m{i}·a_{S} = {m} kg × {a} m/s² = {F} N, at {S}, opposite a_{S}",
              "构件{i}：惯性力F_i{i} = m{i}·a_{S} = {m} kg × {a} m/s² = {F} N，作用于{S}，与a_{S}反向",
              "звено {i}: сила инерции F_i{i} = m{i}·a_{S} = {m} kg × {a} m/s² = {F} N, в точке {S}, против a_{S}"),
    "moment": ("on link {i}: M_i{i} = J_S{i}·α{i} = {J} kg·m² × {al} rad/s² = {M} N·m, opposite α{i}",
               "构件{i}：惯性力偶矩M_i{i} = J_S{i}·α{i} = {J} kg·m² × {al} rad/s² = {M} N·m，与α{i}反向",
               "звено {i}: момент сил инерции M_i{i} = J_S{i}·α{i} = {J} kg·m² × {al} rad/s² = {M} N·m, против α{i}"),
    "offset": ("one resultant: F_i{i} moved off {S} by h{i} = M_i{i}/F_i{i} = {h} m ({mm} mm on the diagram), "
               "so that its moment about {S} has the sense of M_i{i}",
               "合成为一个总惯性力：F_i{i}自{S}平移h{i} = M_i{i}/F_i{i} = {h} m（图上{mm} mm），使其对{S}之矩与M_i{i}同向",
               "приводим к одной силе: F_i{i} переносим от {S} на h{i} = M_i{i}/F_i{i} = {h} m ({mm} mm на схеме), "
               "чтобы её момент относительно {S} совпал по знаку с M_i{i}"),
    "choose": ("choose {mu} for the force polygons", "取力多边形比例尺{mu}", "выбираем масштаб планов сил {mu}"),
    "group": ("{name} ({links}): its free body with every load; the unknowns: {unknown}",
              "{name}（{links}）：取分离体，画出全部外力；待求：{unknown}",
              "{name} ({links}): освобождаем от связей, прикладываем все силы; неизвестные: {unknown}"),
    "links": ("links {links}", "构件{links}", "звенья {links}"),
    "link": ("link {links}", "构件{links}", "звено {links}"),
    "couple": ("the couple {name} = {M} N·m acts on it", "其上作用力偶{name} = {M} N·m",
               "на неё действует момент {name} = {M} N·m"),
    "tangential": ("{name} from the moments about the group's middle joint: {F} N", "由对中间运动副之矩求得{name} = {F} N",
                   "{name} — из уравнения моментов относительно среднего шарнира группы: {F} N"),
    "lay off": ("lay off {name} = {F}/μF = {mm} mm at {th}°", "作{name} = {F}/μF = {mm} mm，方向{th}°",
                "откладываем {name} = {F}/μF = {mm} mm под углом {th}°"),
    "close": ("close the polygon with the known directions of {name}: measure {mm} mm at {th}°: {name} = {mm} × μF = {F} N",
              "按{name}的已知方向封闭力多边形：量得{mm} mm，方向{th}°：{name} = {mm} × μF = {F} N",
              "замыкаем план сил по известному направлению {name}: измеряем {mm} mm под углом {th}°: "
              "{name} = {mm} × μF = {F} N"),
    "impossible": ("position φ₁ = {phi}°: the polygons cannot be drawn here", "位置φ₁ = {phi}°：此位置无法作图",
                   "положение φ₁ = {phi}°: здесь планы построить нельзя"),
}


def forces_steps(scene: Scene[ForceScene]) -> list[str]:
    """The protocol's lines (unnumbered) for every position the scene gives."""
    fa = analyse_forces(scene)
    notation = scene.page.notation

    def say(key: str, **fields: str) -> str:
        return phrase(key, notation, PHRASES, **fields)

    several = len(fa.labels) > 1
    out: list[str] = []
    for i, label in enumerate(fa.labels):
        if several:
            out.append(say("position", phi=label))
        if not bool(fa.kin.valid[i]):
            out.append(say("impossible", phi=label))
            continue
        rows = [r for r in fa.rows if _at(r.name, label, several)]
        done: set[str] = set()
        out.append(say("kinematics", mu=scale_choice("a", fa.scales["a"], "a" in fa.stated, notation)))
        for r in rows:  # the accelerations the table asks for
            if r.unit in ("m/s²", "rad/s²"):
                out.append(read_row(r, notation))
                done.add(r.name)
        out += _inertia(fa, i, say)
        out.append(say("choose", mu=scale_choice("F", fa.scales["F"], "F" in fa.stated, notation)))
        out += _polygons(fa, i, say)
        for r in rows:  # every value of the table as the table reads it
            if r.name not in done:
                out.append(read_row(r, notation))
    return out


def _at(name: str, label: str, several: bool) -> bool:
    """Whether a row belongs to the position ``label`` (``R_12@120`` when there are several)."""
    return name.endswith(f"@{label}") if several else "@" not in name


def _inertia(fa: ForceAnalysis, i: int, say: object) -> list[str]:
    assert callable(say)
    out: list[str] = []
    masses = {m.link: m for m in fa.scene.problem.model.masses}
    for link, load in fa.solution.inertia.items():
        m = masses.get(link)
        F, M = abs(complex(load.force[i])), float(load.moment[i])
        if m is None or (F == 0.0 and M == 0.0):
            continue
        a = abs(complex(fa.kin.acc[load.point][i]))
        if F > 0.0:
            out.append(say("force", i=link, S=load.point, m=num(m.mass), a=num(a), F=num(F)))
        if M != 0.0:
            alpha = abs(float(fa.kin.alpha[link][i]))
            out.append(say("moment", i=link, J=num(m.inertia), al=num(alpha), M=num(abs(M))))
            h = float(load.offset[i])
            if F > 0.0 and h > 0.0:
                out.append(say("offset", i=link, S=load.point, h=num(h), mm=num(h / fa.scales["l"])))
    return out


def _polygons(fa: ForceAnalysis, i: int, say: object) -> list[str]:
    assert callable(say)
    out: list[str] = []
    mu = fa.scales["F"]
    for g in fa.solution.groups:
        links = say("links" if len(g.links) > 1 else "link", links=", ".join(g.links))
        out.append(say("group", name=g.name, links=links, unknown=", ".join(g.unknown) or "—"))
        for c in g.couples:
            M = float(c.moment[i])
            if M != 0.0 and c.name != "M_b":
                out.append(say("couple", name=c.name, M=num(M)))
        for name, vector in g.chain:
            v = complex(vector[i])
            F = abs(v)
            if F == 0.0:
                continue
            th = num(math.degrees(cmath.phase(v)) % 360.0)
            if name in g.unknown:
                out.append(say("close", name=name, mm=num(F / mu), th=th, F=num(F)))
            else:
                if name.startswith("R^t"):
                    out.append(say("tangential", name=name, F=num(F)))
                out.append(say("lay off", name=name, F=num(F), mm=num(F / mu), th=th))
    return out


__all__ = ["PHRASES", "forces_steps"]
