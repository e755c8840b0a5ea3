"""The construction protocol of a flywheel scene: the positions and the reduction, the scales,
the method's diagrams in the order the book draws them — Mп(φ), its integral by chords, the
energy–mass (Wittenbauer) diagram and its tangents, or the energy indicator, or the run-down ω(t)
of a brake — and every value of the check table read off as the table reads it, with how
accurate the method says it is (N positions).

The numbers are the check's own (:func:`graphmech.problems.flywheel.check.analyse_flywheel`).
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from graphmech.problems.flywheel.check import analyse_flywheel
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, read_row, scale_choice

if TYPE_CHECKING:
    from graphmech.problems.flywheel.scene import FlywheelScene
    from graphmech.problems.reader import Scene

#: The flywheel's phrases: key → (English, 中文, русский). 孙桓: 等效转动惯量 J_e, 等效力矩 M_e,
#: 最大盈亏功 ΔW_max, 能量指示图; the Russian course: приведённый момент инерции J_п, приведённый
#: момент М_п, диаграмма энергомасс (Виттенбауэра).
PHRASES: Phrases = {
    **COMMON,
    "machine": ("the machine: ω_m = {w} rad/s, δ = {d}; the cycle {cycle}° of the crank",
                "机器：平均角速度ω_m = {w} rad/s，速度波动系数δ = {d}；一个运动循环为曲柄转角{cycle}°",
                "машина: ω_ср = {w} rad/s, δ = {d}; цикл — {cycle}° поворота кривошипа"),
    "positions": ("divide the cycle into {n} positions, {step}° apart; at each, from the velocity polygons, "
                  "reduce the masses to Jп (equal kinetic energy) and the forces to Mп (equal power)",
                  "将一个循环分为{n}个位置，每隔{step}°；在各位置由速度多边形求等效转动惯量Jп（动能相等）和等效力矩Mп（功率相等）",
                  "делим цикл на {n} положений через {step}°; в каждом по планам скоростей приводим массы к Jп "
                  "(равенство кинетических энергий) и силы к Mп (равенство мощностей)"),
    "scales": ("choose {mus}", "取{mus}", "выбираем {mus}"),
    "moments": ("draw Mп(φ) over the cycle, one ordinate per position, and the resisting (or driving) "
                "moment that balances it over the cycle",
                "作等效力矩曲线Mп(φ)，每个位置一条纵坐标，并作在一个循环内与之平衡的阻抗（或驱动）力矩",
                "строим график Mп(φ) по ординатам положений и момент сопротивления (или движущий), "
                "уравновешивающий его за цикл"),
    "chords": ("integrate Mп(φ) by chords (pole distance H = {H} mm): the work A(φ), and ΔT(φ) = A_d − A_r "
               "at μT = μM·μφ·H",
               "用弦线法（极距H = {H} mm）对Mп(φ)积分得功A(φ)，ΔT(φ) = A_d − A_r，比例尺μT = μM·μφ·H",
               "интегрируем Mп(φ) методом хорд (полюсное расстояние H = {H} mm): работа A(φ) и ΔT(φ) = A_д − A_с "
               "в масштабе μT = μM·μφ·H"),
    "wittenbauer": ("draw the energy–mass (Wittenbauer) diagram: ΔT against Jп, one point per position, joined "
                    "in order",
                    "作能量—质量（维滕鲍尔）图：以Jп为横坐标、ΔT为纵坐标，各位置一点，依次连成封闭曲线",
                    "строим диаграмму энергомасс (Виттенбауэра): ΔT по Jп, по точке на положение, соединяя по порядку"),
    "tangents": ("draw its tangents at ψ_max and ψ_min to the Jп axis, tan ψ = μJ·ω_m²·(1 ± δ)/(2μT); they cut "
                 "k and l off the ΔT axis",
                 "作与Jп轴成ψ_max、ψ_min的两切线，tan ψ = μJ·ω_m²·(1 ± δ)/(2μT)，在ΔT轴上截得k、l",
                 "проводим касательные под углами ψ_max и ψ_min к оси Jп, tg ψ = μJ·ω²_ср·(1 ± δ)/(2μT); они "
                 "отсекают на оси ΔT отрезки k и l"),
    "J_F": ("J_F = kl·μT/(ω_m²·δ) = |k − l|/(ω_m²·δ) (the flywheel on the crank's shaft)",
            "J_F = kl·μT/(ω_m²·δ) = |k − l|/(ω_m²·δ)（飞轮装在曲柄轴上）",
            "J_м = kl·μT/(ω²_ср·δ) = |k − l|/(ω²_ср·δ) (маховик на валу кривошипа)"),
    "indicator": ("draw the energy indicator: ΔW(φ) between the driving and the resisting work; read ΔW_max "
                  "between its highest and lowest points",
                  "作能量指示图：驱动功与阻抗功之差ΔW(φ)；量取其最高点与最低点之差为最大盈亏功ΔW_max",
                  "строим диаграмму избыточной работы ΔW(φ); ΔW_max — между её наибольшей и наименьшей точками"),
    "J_F indicator": ("J_F = ΔW_max/(ω_m²·δ) − J_e, J_e the mean of Jп over the cycle (the machine's own inertia)",
                      "J_F = ΔW_max/(ω_m²·δ) − J_e，J_e为一个循环内Jп的平均值（机器原有的等效转动惯量）",
                      "J_м = ΔW_max/(ω²_ср·δ) − J_п, J_п — среднее Jп за цикл (собственная инерция машины)"),
    "braking": ("the run-down: ω falls from {w0} rad/s at ε = M/J = {M} N·m / {J} kg·m²; draw ω(t), a straight "
                "line, and read where it reaches 0",
                "制动过程：ω自{w0} rad/s以ε = M/J = {M} N·m / {J} kg·m²均匀减小；作ω(t)直线，量取ω = 0处的时间",
                "выбег: ω падает от {w0} rad/s с ε = M/J = {M} N·m / {J} kg·m²; строим ω(t) — прямую — и "
                "находим, где ω = 0"),
}


def flywheel_steps(scene: Scene[FlywheelScene]) -> list[str]:
    """The protocol's lines (unnumbered)."""
    an = analyse_flywheel(scene)
    notation = scene.page.notation
    fw = scene.problem

    def say(key: str, **fields: str) -> str:
        return phrase(key, notation, PHRASES, **fields)

    out: list[str] = []
    sep = "，" if notation == "zh" else ", "
    mus = sep.join(scale_choice(s, v, s in an.stated, notation) for s, v in an.scales.items())
    if fw.braking is not None:
        b = fw.braking
        out.append(say("scales", mus=mus))
        out.append(say("braking", w0=num(fw.machine.omega_m), M=num(b.moment), J=num(fw.machine.inertia)))
    else:
        m = fw.machine
        out.append(say("machine", w=num(m.omega_m), d=num(m.delta), cycle=num(math.degrees(m.cycle))))
        n = len(an.phi)
        out.append(say("positions", n=str(n), step=num(math.degrees(m.cycle) / max(n, 1))))
        out.append(say("scales", mus=mus))
        out.append(say("moments"))
        H = getattr(an.design, "H_mm", None)
        out.append(say("chords", H=num(H) if H else "—"))
        if fw.method == "wittenbauer":
            out += [say("wittenbauer"), say("tangents"), say("J_F")]
        else:
            out += [say("indicator"), say("J_F indicator")]
    out += [read_row(r, notation) for r in an.rows]
    return out


__all__ = ["PHRASES", "flywheel_steps"]
