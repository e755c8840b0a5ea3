"""The construction protocol of a full-cycle scene: the positions drawn through a turn, the extreme
positions and the timing, the diagrams against φ by chords — in the order the book draws the
sheet — then every value of the check table read off as the table reads it, and the check's
notes (the class of the linkage, the chords' own error).

A single position's polygons are the linkage's protocol (``graphmech steps`` of a linkage scene);
the numbers here are the check's own (:func:`graphmech.problems.cycle.check.analyse_cycle`).
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from graphmech.mechanisms.linkage import Crank
from graphmech.problems.cycle.check import analyse_cycle
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, read_row
from graphmech.problems.reader import linkage_of, positions_of

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene

#: The full cycle's phrases: key → (English, 中文, русский).
PHRASES: Phrases = {
    **COMMON,
    "scales": ("choose {mus}", "取{mus}", "выбираем {mus}"),
    "positions": ("divide the crank's turn into {n} positions from φ₁ = {start}° and draw the mechanism in each "
                  "(one position's construction: graphmech steps of the linkage); number the positions",
                  "将曲柄一周分为{n}个位置（自φ₁ = {start}°起），作出各位置的机构运动简图（单个位置的作图见机构的graphmech "
                  "steps），并依次编号",
                  "делим оборот кривошипа на {n} положений от φ₁ = {start}° и строим механизм в каждом (построение "
                  "одного положения — graphmech steps механизма); нумеруем положения"),
    "swing": ("the driver swings from {a} to {b}{how}: {n} positions, 1 … {h} out and the rest back in equal steps; "
              "draw the mechanism in each and number the positions (k and {n2} − k are one place)",
              "原动件在{a}与{b}之间摆动{how}：共{n}个位置，1 … {h}为去程，其余为回程，步长相等；作出各位置的机构运动简图并编号"
              "（k与{n2} − k为同一位置）",
              "ведущее звено качается от {a} до {b}{how}: {n} положений, 1 … {h} прямой ход, остальные обратный, равными "
              "шагами; строим механизм в каждом и нумеруем положения (k и {n2} − k — одно место)"),
    "limits": (" (its limits: the dyad on its point toggles — its two links in one line)",
               "（其极限位置：与之相连的杆组两杆共线）",
               " (его крайние положения: звенья присоединённой группы на одной прямой)"),
    "extremes": ("the extreme positions: crank and coupler in one line (stretched out and folded); θ = the angle "
                 "between the crank's two extreme positions, K = (180° + θ)/(180° − θ)",
                 "作极限位置：曲柄与连杆共线（拉直与重叠）；极位夹角θ为曲柄两极限位置间的夹角，行程速比系数K = (180° + θ)/(180° − θ)",
                 "крайние положения: кривошип и шатун на одной прямой (вытянуты и сложены); θ — угол между двумя "
                 "крайними положениями кривошипа, K = (180° + θ)/(180° − θ)"),
    "diagrams": ("the diagrams against φ: lay off each position's displacement from the extreme position, join the "
                 "ordinates, and differentiate by chords (pole distances H) for the velocity and the acceleration",
                 "作运动线图：自极限位置量取各位置的位移为纵坐标并连成曲线，用弦线法（极距H）图解微分得速度、加速度线图",
                 "строим кинематические диаграммы: перемещения от крайнего положения по положениям, затем графическое "
                 "дифференцирование методом хорд (полюсные расстояния H) — скорость и ускорение"),
}


def cycle_steps(scene: Scene[Any]) -> list[str]:
    """The protocol's lines (unnumbered)."""
    an = analyse_cycle(scene)
    lines = an.summary_lines()
    notation = scene.page.notation

    def say(key: str, **fields: str) -> str:
        return phrase(key, notation, PHRASES, **fields)

    names = [r.name.split("@")[0] for r in an.rows]
    out = [say("scales", mus=("，" if notation == "zh" else ", ").join(an.scale_notes()))]
    swing = scene.problem.swing
    if swing is not None:
        crank = isinstance(linkage_of(scene).driver, Crank)
        a, b = ((num(math.degrees(q)) + "°") if crank else (num(q * 1000) + " mm") for q in swing)
        n = len(positions_of(scene).labels)
        how = say("limits") if scene.problem.cycle.between == "limits" else ""
        out.append(say("swing", a=a, b=b, how=how, n=str(n), h=str(n // 2 + 1), n2=str(n + 2)))
    elif scene.positions is not None and len(scene.positions.labels) > 1:
        start = num(math.degrees(scene.problem.start_angle) % 360.0)
        out.append(say("positions", n=str(len(scene.positions.labels)), start=start))
    if any(n in ("theta", "K", "stroke", "phi_work", "phi_return") for n in names):
        out.append(say("extremes"))
    if any(n.endswith("_diagram") or n.startswith("s_") for n in names):
        out.append(say("diagrams"))
    out += [read_row(r, notation) for r in an.rows]
    return out + list(lines)


__all__ = ["PHRASES", "cycle_steps"]
