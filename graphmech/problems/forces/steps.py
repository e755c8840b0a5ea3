"""The construction protocol of a force scene (kinetostatics): the kinematics the loads need, the
inertia loads, then the Assur groups from the last one to the driver — each free body, its force
polygon laid off at μF with every length in mm, the closing lines, the reactions measured — the
balancing moment (force) and, when the scene asks for it, Zhukovsky's lever.

The numbers are the check's own: the kinematic steps are the linkage protocol of the very
construction the force analysis reads (:func:`graphmech.problems.linkage.steps.protocol`), the
polygons are :func:`graphmech.methods.kinetostatics.kinetostatics`' groups at the check's μF, and
every value the check table has is taken from :func:`graphmech.problems.forces.check.force_value`.
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import TYPE_CHECKING, Any

import numpy as np

from graphmech.drawing.lettering import subscript
from graphmech.mechanisms.linkage import PRP, RPP, RPR, RRP, RRR, Crank, Guide, Triad
from graphmech.methods.kinetostatics import construction_targets, kinetostatics
from graphmech.problems.forces.check import (
    ForceAnalysis,
    analyse_forces,
    force_value,
    is_force_name,
    solved,
)
from graphmech.problems.forces.figures import DRAWN_MIN_MM
from graphmech.problems.judging import split_name
from graphmech.problems.linkage.sizes import position_text
from graphmech.problems.linkage.steps import letter
from graphmech.problems.linkage.steps import protocol as linkage_protocol
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, scale_choice, sense

if TYPE_CHECKING:
    from graphmech.construction.graph import Solution
    from graphmech.methods.kinetostatics import GroupPolygon, KinetostaticSolution
    from graphmech.problems.forces.scene import ForceScene
    from graphmech.problems.reader import Scene

#: The phrases of kinetostatics: key → (English, 中文, русский); fields in braces.
PHRASES: Phrases = {
    **COMMON,
    "force scale": ("choose {mu} for the force polygons", "取力比例尺{mu}作力多边形",
                    "выбираем масштаб планов сил {mu}"),
    "inertia": ("the loads on the links (d'Alembert: the inertia loads from the acceleration polygon)",
                "确定各构件所受外力及惯性力（达朗贝尔原理：由加速度多边形求惯性力和惯性力矩）",
                "нагрузки на звенья (принцип Даламбера: силы инерции по плану ускорений)"),
    "weight": ("G_{i} = m{s}·g = {m} × {g} = {F} N, downward at {S} ({mm} mm at μF)",
               "G_{i} = m{s}·g = {m} × {g} = {F} N，竖直向下，作用于{S}（按μF为{mm} mm）",
               "G_{i} = m{s}·g = {m} × {g} = {F} N, вниз, в точке {S} ({mm} mm в масштабе μF)"),
    "inertia force": ("F_i{i} = −m{s}·a_{Sa}: F_i{i} = {m} × {a} = {F} N at {S}, opposite to p′{ss} ({mm} mm at μF)",
                      "F_i{i} = −m{s}·a_{Sa}：F_i{i} = {m} × {a} = {F} N，作用于{S}，与p′{ss}反向（按μF为{mm} mm）",
                      "F_i{i} = −m{s}·a_{Sa}: F_i{i} = {m} × {a} = {F} N в точке {S}, противоположно p′{ss} "
                      "({mm} mm в масштабе μF)"),
    "no inertia force": ("a_{Sa} = 0 ({S} does not move): F_i{i} = 0", "a_{Sa} = 0（{S}不动）：F_i{i} = 0",
                         "a_{Sa} = 0 (точка {S} неподвижна): F_i{i} = 0"),
    "inertia moment": ("M_i{i} = −J_S{i}·α{s} = −{J} × {al} = {M} N·m{turn}",
                       "M_i{i} = −J_S{i}·α{s} = −{J} × {al} = {M} N·m{turn}",
                       "M_i{i} = −J_S{i}·α{s} = −{J} × {al} = {M} N·m{turn}"),
    "offset": ("h_{i} = |M_i{i}|/F_i{i} = {M}/{F} = {h} m, h_{i}/μl = {mm} mm: move F_i{i} by h_{i} to the side where "
               "its moment about {S} has the sense of M_i{i} (F′_i{i}, the single resultant)",
               "h_{i} = |M_i{i}|/F_i{i} = {M}/{F} = {h} m，h_{i}/μl = {mm} mm：将F_i{i}平移h_{i}，使其对{S}之矩与M_i{i}同向"
               "（总惯性力F′_i{i}）",
               "h_{i} = |M_i{i}|/F_i{i} = {M}/{F} = {h} m, h_{i}/μl = {mm} mm: смещаем F_i{i} на h_{i} так, чтобы её "
               "момент относительно {S} был направлен как M_i{i} (результирующая F′_i{i})"),
    "force": ("{name} = {F} N at {P}, at {angle}° to the x axis ({mm} mm at μF)",
              "{name} = {F} N，作用于{P}，与x轴成{angle}°（按μF为{mm} mm）",
              "{name} = {F} N в точке {P} под углом {angle}° к оси x ({mm} mm в масштабе μF)"),
    "idle resistance": ("{name} = 0 here: {P} moves with it (a working resistance acts only against the motion)",
                        "此位置{name} = 0：{P}顺着它运动（工作阻力只在阻碍运动时作用）",
                        "здесь {name} = 0: точка {P} движется по её направлению (сила сопротивления действует "
                        "только против движения)"),
    "couple": ("{name} = {M} N·m on link {link}{turn}", "构件{link}上的{name} = {M} N·m{turn}",
               "{name} = {M} N·m на звене {link}{turn}"),
    # friction
    "friction circle": ("friction circle about {P}: ρ = f_v·r = {fv} × {r} = {rho} m ({mm} mm at μl)",
                        "以{P}为圆心作摩擦圆：ρ = f_v·r = {fv} × {r} = {rho} m（按μl为{mm} mm）",
                        "круг трения вокруг {P}: ρ = f_v·r = {fv} × {r} = {rho} m ({mm} mm в масштабе μl)"),
    "friction angle": ("friction angle on the guide of link {link}: φ = arctan f = arctan {f} = {phi}°",
                       "构件{link}导路的摩擦角：φ = arctan f = arctan {f} = {phi}°",
                       "угол трения на направляющей звена {link}: φ = arctg f = arctg {f} = {phi}°"),
    "approximation": ("solve without friction first; then round by round put each reaction of the round before "
                      "tangent to its friction circle (its moment ρ·|R| against the relative rotation) and tilt each "
                      "guide's reaction by φ against the sliding: after {n} rounds no reaction changes by more than "
                      "{tol} N — the polygons below are the last round's",
                      "先不计摩擦求解；再逐次逼近：每一轮使上一轮的各总反力切于摩擦圆（其矩ρ·|R|与相对转动方向相反），"
                      "移动副总反力偏转摩擦角φ（与相对滑动方向相反）；{n}轮后各反力变化均小于{tol} N，下列力多边形为最后一轮",
                      "сначала решаем без трения; затем последовательными приближениями: реакции предыдущего шага "
                      "касаются кругов трения (момент ρ·|R| против относительного вращения), реакции направляющих "
                      "отклонены на φ против скольжения; после {n} шагов реакции меняются меньше чем на {tol} N — "
                      "ниже планы сил последнего шага"),
    # the groups
    "free body": ("free body of {group}{links}: known {known}; unknown {unknown}",
                  "取{group}{links}为分离体：已知力{known}；待求{unknown}",
                  "расчётная схема: {group}{links}; известны {known}; неизвестны {unknown}"),
    "links": (" (links {links})", "（构件{links}）", " (звенья {links})"),
    "at": ("{name} at {P}", "{name}（作用于{P}）", "{name} в {P}"),
    "from guide": ("{name} from the guide", "导路反力{name}", "{name} со стороны направляющей"),
    "nothing": ("nothing", "无", "нет"),
    "tangential": ("moments of link {link} about {C}: R^t_{ai}·l_{PC} = ΣM_{C}: R^t_{ai} = {F} N ⟂ {PC} "
                   "({mm} mm at μF)",
                   "由构件{link}对{C}点取矩：R^t_{ai}·l_{PC} = ΣM_{C}，R^t_{ai} = {F} N ⟂ {PC}（按μF为{mm} mm）",
                   "моменты звена {link} относительно {C}: R^t_{ai}·l_{PC} = ΣM_{C}: R^t_{ai} = {F} N ⟂ {PC} "
                   "({mm} mm в масштабе μF)"),
    "assur moments": ("moments of the whole group about S, where {PX} and {QZ} meet: only R^n_{ak} of link {k} has "
                      "an arm there: R^n_{ak} = {F} N ∥ {RY} ({mm} mm at μF)",
                      "整个杆组对{PX}与{QZ}的交点S取矩，只有构件{k}的R^n_{ak}有力臂：R^n_{ak} = {F} N ∥ {RY}（按μF为{mm} mm）",
                      "моменты всей группы относительно точки S пересечения {PX} и {QZ}: плечо есть только у "
                      "R^n_{ak} звена {k}: R^n_{ak} = {F} N ∥ {RY} ({mm} mm в масштабе μF)"),
    "bar reaction": ("moments of the bar {b} about {P} and of the block {k} about {X}: the bar's reaction on the "
                     "block R_{bk} = {F} N ⟂ the bar ({mm} mm at μF)",
                     "由导杆{b}对{P}、滑块{k}对{X}取矩：导杆对滑块的反力R_{bk} = {F} N ⟂ 导杆（按μF为{mm} mm）",
                     "моменты кулисы {b} относительно {P} и камня {k} относительно {X}: реакция кулисы на камень "
                     "R_{bk} = {F} N ⟂ кулисе ({mm} mm в масштабе μF)"),
    "lay first": ("from o lay off {name} = {F} N: {mm} mm at {angle}° to the x axis",
                  "自o点起作{name} = {F} N：{mm} mm，与x轴成{angle}°",
                  "из точки o откладываем {name} = {F} N: {mm} mm под углом {angle}° к оси x"),
    "lay": ("then {name} = {F} N: {mm} mm at {angle}°", "接着作{name} = {F} N：{mm} mm，与x轴成{angle}°",
            "затем {name} = {F} N: {mm} mm под углом {angle}°"),
    "too short": (" (under 0.1 mm: not drawn)", "（不足0.1 mm，不画）", " (меньше 0.1 mm: не чертим)"),
    "close two": ("through the end of {last} draw a line {d1} (the line of {u1}), through o a line {d2} "
                  "(the line of {u2}); they meet at the polygon's closing vertex",
                  "过{last}的末端作直线{d1}（{u1}的方向），过o点作直线{d2}（{u2}的方向），两线交点即力多边形的封闭点",
                  "через конец {last} проводим прямую {d1} (линия {u1}), через o — прямую {d2} (линия {u2}); "
                  "их пересечение замыкает план сил"),
    "close one": ("{name} closes the polygon, from the end of {last} back to o",
                  "由{last}的末端指向o点的矢量即{name}，力多边形封闭",
                  "{name} замыкает план сил: от конца {last} к точке o"),
    "par": ("∥ {PC}", "∥ {PC}", "∥ {PC}"),
    "normal": ("⟂ the {what}", "⟂ {what}", "⟂ {what}"),
    "tilted": ("at φ = {phi}° to the {what}'s normal", "与{what}法线成φ = {phi}°", "под углом φ = {phi}° к нормали {what}"),
    "along": ("∥ the {what}", "∥ {what}", "∥ {what}"),
    "guide": ("guide", "导路", "направляющей"),
    "slot": ("slot", "导槽", "паза"),
    "read": ("measure {name} = {mm} mm: {name} = {mm} × {mu} = {F} N",
             "量得{name} = {mm} mm：{name} = {mm} × {mu} = {F} N",
             "измеряем {name} = {mm} mm: {name} = {mm} × {mu} = {F} N"),
    "sum": ("R_{ai} = R^n_{ai} + R^t_{ai}: measure from the start of R^n_{ai} to the end of R^t_{ai}, {mm} mm: "
            "R_{ai} = {mm} × {mu} = {F} N{also}",
            "R_{ai} = R^n_{ai} + R^t_{ai}：量得R^n_{ai}起点至R^t_{ai}终点{mm} mm：R_{ai} = {mm} × {mu} = {F} N{also}",
            "R_{ai} = R^n_{ai} + R^t_{ai}: от начала R^n_{ai} до конца R^t_{ai} {mm} mm: "
            "R_{ai} = {mm} × {mu} = {F} N{also}"),
    "middle": ("the polygon of link {i} alone closes with R_{ki} at {C}: R_{ki} = −(R_{ai} + ΣF_{i}): measure {mm} mm: "
               "R_{ki} = {mm} × {mu} = {F} N{also}",
               "再取构件{i}为分离体，其力多边形由{C}处的R_{ki}封闭：R_{ki} = −(R_{ai} + ΣF_{i})，量得{mm} mm："
               "R_{ki} = {mm} × {mu} = {F} N{also}",
               "план сил одного звена {i} замыкает реакция R_{ki} в {C}: R_{ki} = −(R_{ai} + ΣF_{i}): измеряем {mm} mm: "
               "R_{ki} = {mm} × {mu} = {F} N{also}"),
    "also": (" (R_{ba} = −R_{ab})", "（R_{ba} = −R_{ab}）", " (R_{ba} = −R_{ab})"),
    "reaction": ("measure {name} = {mm} mm: {name} = {mm} × {mu} = {F} N{also}",
                 "量得{name} = {mm} mm：{name} = {mm} × {mu} = {F} N{also}",
                 "измеряем {name} = {mm} mm: {name} = {mm} × {mu} = {F} N{also}"),
    "components": ("project {name} on the axes: {x}, {y}", "将{name}向坐标轴投影：{x}，{y}",
                   "проецируем {name} на оси: {x}, {y}"),
    "guide line": ("moments of slider {k} about {C} give where {name} acts: M_{ak} = {M} N·m; "
                   "e_{ak} = {e} m along the guide from {C} ({mm} mm at μl)",
                   "由滑块{k}对{C}取矩确定{name}的作用线：M_{ak} = {M} N·m；e_{ak} = {e} m（沿导路自{C}量起，按μl为{mm} mm）",
                   "моменты ползуна {k} относительно {C} дают линию действия {name}: M_{ak} = {M} N·m; "
                   "e_{ak} = {e} m вдоль направляющей от {C} ({mm} mm в масштабе μl)"),
    "journal": ("{name} is tangent to the friction circle about {P}: M_f = ρ·|{name}| = {rho} × {F} = {M} N·m, "
                "against the rotation of {b} relative to {a}",
                "{name}切于{P}处的摩擦圆：M_f = ρ·|{name}| = {rho} × {F} = {M} N·m，与构件{b}相对{a}的转向相反",
                "{name} касается круга трения вокруг {P}: M_f = ρ·|{name}| = {rho} × {F} = {M} N·m, против вращения "
                "{b} относительно {a}"),
    "balancing moment": ("moments of the driver {link} about {A}: M_b = −ΣM_{A} = {M} N·m{turn}",
                         "由原动件{link}对{A}取矩：平衡力矩M_b = −ΣM_{A} = {M} N·m{turn}",
                         "моменты начального звена {link} относительно {A}: уравновешивающий момент "
                         "M_b = −ΣM_{A} = {M} N·m{turn}"),
    "balancing force": ("F_b along the guide: measure {mm} mm: |F_b| = {mm} × {mu} = {F} N{against}",
                        "沿导路的平衡力F_b：量得{mm} mm：|F_b| = {mm} × {mu} = {F} N{against}",
                        "уравновешивающая сила F_b вдоль направляющей: измеряем {mm} mm: |F_b| = {mm} × {mu} = {F} N"
                        "{against}"),
    "against": (" (F_b points against the guide's direction)", "（F_b与导路正向相反）",
                " (F_b направлена против направляющей)"),
    "lever": ("Zhukovsky's lever: turn the velocity polygon 90° about p and apply every load at the image of its "
              "point (a couple as two forces ±M/l ⟂ a side of its link)",
              "儒可夫斯基杠杆：将速度多边形绕p转过90°，把各力移到其作用点的影像上（力偶化为作用于构件两点影像上的一对力±M/l）",
              "рычаг Жуковского: поворачиваем план скоростей на 90° вокруг p и прикладываем каждую силу в "
              "изображении её точки (пару — как две силы ±M/l ⟂ стороне звена)"),
    "arm": ("{name} at {x}: its moment about p = {M} N·mm", "{name}作用于{x}：对p之矩 = {M} N·mm",
            "{name} в точке {x}: момент относительно p = {M} N·mm"),
    "lever moment": ("ΣM_p = {S} N·mm: M_b = μv·ΣM_p/ω{s} = {mu} × {Sp}/{w} = {M} N·m{label}",
                     "ΣM_p = {S} N·mm：M_b = μv·ΣM_p/ω{s} = {mu} × {Sp}/{w} = {M} N·m{label}",
                     "ΣM_p = {S} N·mm: M_b = μv·ΣM_p/ω{s} = {mu} × {Sp}/{w} = {M} N·m{label}"),
    "lever force": ("ΣM_p = {S} N·mm: F_b = μv·ΣM_p/v = {mu} × {Sp}/{v} = {F} N{label}",
                    "ΣM_p = {S} N·mm：F_b = μv·ΣM_p/v = {mu} × {Sp}/{v} = {F} N{label}",
                    "ΣM_p = {S} N·mm: F_b = μv·ΣM_p/v = {mu} × {Sp}/{v} = {F} N{label}"),
    "at μF": (" ({mm} mm at μF)", "（按μF为{mm} mm）", " ({mm} mm в масштабе μF)"),
    "frictionless": ("the same polygons without friction give {name} = {value}",
                     "不计摩擦时同样作图得{name} = {value}",
                     "те же планы сил без трения дают {name} = {value}"),
    "efficiency": ("η = {a}/{b} = {A}/{B} = {eta}", "η = {a}/{b} = {A}/{B} = {eta}", "η = {a}/{b} = {A}/{B} = {eta}"),
    "unsolved": ("at {pos} the forces cannot be found: {why}", "{pos}时无法求力：{why}",
                 "при {pos} силы найти нельзя: {why}"),
}


def force_steps(scene: Scene[ForceScene]) -> list[str]:
    """The protocol of a force scene, one line per step (not numbered)."""
    return protocol(analyse_forces(scene))


def protocol(fa: ForceAnalysis) -> list[str]:
    """The protocol of an analysed force scene: per position, the kinematics its loads need,
    then the loads, the groups from the last to the driver, and the lever."""
    sol = fa.solution
    if not sol.groups:  # the check keeps the polygons only when it draws them: the same round, kept
        sol = _with_groups(fa)
    out: list[str] = []
    kin = _kinematic_targets(fa, _Forces(fa, sol, 0).groups_needed() > 0 if fa.labels else False)
    b = fa.build
    # the polygons the force analysis reads its accelerations from, evaluated as it evaluates them
    # (with the measurements the protocol states)
    slots = [b.quantities[split_name(n)[0]].slot for n in kin]
    batch = b.g.prune(construction_targets(b) + slots).evaluate_batch({b.param: fa.kinematics.positions})
    for i in range(len(fa.labels)):
        if batch.valid[i]:
            out += linkage_protocol(_one_position(fa, i, kin, batch.at(i)))
        if not solved(fa, i):
            why = fa.kinematics.failures[i] or "the equilibrium equations are singular here"
            out.append(phrase("unsolved", _notation(fa), PHRASES, pos=position_text(fa.build, fa.labels[i]), why=why))
            continue
        out += _Forces(fa, sol, i).lines()
    return out


def _notation(fa: ForceAnalysis) -> str:
    return getattr(fa.scene.page, "notation", "en")


def _with_groups(fa: ForceAnalysis) -> KinetostaticSolution:
    """The check's solution with its free bodies and polygons kept: the same method on the same
    kinematics (with friction, the same rounds), which the check runs without keeping them."""
    return kinetostatics(fa.build.linkage, fa.scene.problem.model, fa.kin, polygons=True)


def _kinematic_targets(fa: ForceAnalysis, groups: bool) -> tuple[str, ...]:
    """What the loads need from the polygons (a_S of each mass, α of each link with J_S; the
    velocities the lever and the friction's senses read), what the scene itself asks, and, when
    groups are solved, the dyads' sides on the diagram (the arms of the moments about C)."""
    b, model = fa.build, fa.scene.problem.model
    linkage = b.linkage
    fixed = set(linkage.frame_points)
    out = list(fa.kinematics.scene.find)
    for lm in model.masses:
        if lm.link == linkage.frame_link:
            continue
        if lm.mass > 0 and lm.point not in fixed:
            out.append(f"a_{lm.point}")
        if lm.inertia > 0 and lm.link != linkage.driver.link:
            out.append(f"alpha_{lm.link}")
    if fa.lever is not None:
        out += [f"v_{p}" for p in dict.fromkeys(f.point for f in model.forces) if p not in fixed]
        out += [f"v_{lm.point}" for lm in model.masses if lm.mass > 0 and lm.point not in fixed]
    if model.has_friction:
        out += [f"omega_{link}" for link in b.omega if link != linkage.driver.link]
    if groups:
        for y in linkage.dyads:
            if isinstance(y, (PRP, Triad)):  # no dyad sides: a PRP's moments are about C, a triad's its own
                continue
            ends = (y.p, y.q) if isinstance(y, (RRR, RPR)) else (y.p,)
            out += [f"l_{P}{y.c}" for P in ends if not isinstance(y, RPR)] + (
                [f"l_{y.p}{y.q}"] if isinstance(y, RPR) else [])
    return tuple(n for n in dict.fromkeys(out) if split_name(n)[0] in b.quantities)


def _one_position(fa: ForceAnalysis, i: int, find: tuple[str, ...], sol: Solution) -> Any:
    """The kinematic analysis at position i alone, asked for ``find``, with the polygons the force
    analysis read (for the linkage protocol)."""
    an = fa.kinematics
    return replace(an, scene=replace(an.scene, find=find), positions=an.positions[i:i + 1], labels=(an.labels[i],),
                   solutions=[sol], failures=[""], instant_centres=None)


def _par(x: float) -> str:
    """A factor as a formula writes it: a negative one in parentheses."""
    return num(x) if x >= 0 else f"({num(x)})"


def _angle(z: complex) -> str:
    return num(math.degrees(math.atan2(z.imag, z.real)) + 0.0)


class _Forces:
    """The force steps of one position, with the numbers of the check's solution."""

    def __init__(self, fa: ForceAnalysis, sol: KinetostaticSolution, i: int) -> None:
        self.fa, self.sol, self.i = fa, sol, i
        self.notation = _notation(fa)
        self.mu_F, self.mu_l = fa.scales["F"], fa.scales["l"]
        self.model = fa.scene.problem.model
        self.linkage = fa.build.linkage
        self.asked = {split_name(n)[0] for n in fa.scene.find if is_force_name(n)
                      and split_name(n)[1] in (None, fa.labels[i])}
        self.sep = "；" if self.notation == "zh" else "; "
        self.comma = "，" if self.notation == "zh" else ", "

    def say(self, key: str, **fields: str) -> str:
        return phrase(key, self.notation, PHRASES, **fields)

    def value(self, base: str) -> tuple[float | None, float, float]:
        """(drawn mm, scale, value) of a quantity, as the check table has it."""
        drawn, scale, g, _, _ = force_value(self.fa, base, self.i)
        return drawn, scale, g

    def vec(self, arr: Any) -> complex:
        return complex(arr[self.i])

    def turn(self, x: float) -> str:
        s = sense(x, self.notation)
        return "" if not s else f"（{s}）" if self.notation == "zh" else f" ({s})"

    # ------------------------------------------------------------------ the steps
    def lines(self) -> list[str]:
        out = [self.say("force scale", mu=scale_choice("F", self.mu_F, "F" in self.fa.stated, self.notation))]
        out += self.loads()
        groups = self.sol.groups[:self.groups_needed()]
        if groups and self.model.has_friction:
            out += self.friction()
        for g in groups:
            out += self.group(g)
        if self.fa.lever is not None:
            out += self.lever()
        out += self.efficiency()
        return out

    def groups_needed(self) -> int:
        """How many groups, from the last one, the scene's questions need: every one when the
        polygons are drawn or the driver's balancing load is asked for, else up to the group that
        finds the last reaction asked (none for the inertia loads or the lever alone)."""
        if "force_polygons" in self.fa.scene.show:
            return len(self.sol.groups)
        need = 0
        for name in self.asked:
            if name in ("M_b", "F_b", "M_b0", "F_b0", "eta"):
                return len(self.sol.groups)
            pair = name[2:4] if name.startswith(("R_", "M_", "e_")) and len(name) in (4, 6) else None
            if pair is None or name.startswith(("M_i", "M_b")):
                continue
            for k, g in enumerate(self.sol.groups):
                if pair[1] in g.links or (pair[0] in g.links and not self._solved_before(pair[1], g)):
                    need = max(need, k + 1)
                    break
        return need

    def loads(self) -> list[str]:
        out = [self.say("inertia")]
        g = self.model.gravity
        fixed = set(self.linkage.frame_points)
        for lm in self.model.masses:
            if lm.link == self.linkage.frame_link:
                continue
            i, S = lm.link, letter(lm.point)
            s = subscript(i)
            if g > 0 and lm.mass > 0:
                out.append(self.say("weight", i=i, s=s, m=num(lm.mass), g=num(g), F=num(lm.mass * g), S=S,
                                    mm=num(lm.mass * g / self.mu_F)))
            il = self.sol.inertia[i]
            F = self.vec(il.force)
            if lm.mass > 0:
                if lm.point in fixed or abs(F) == 0.0:
                    out.append(self.say("no inertia force", S=S, Sa=lm.point, i=i))
                else:
                    drawn, _, val = self.value(f"F_i{i}")
                    a = abs(self.vec(self.fa.kin.acc[lm.point]))
                    out.append(self.say("inertia force", i=i, s=s, S=S, Sa=lm.point, m=num(lm.mass), a=num(a), F=num(val),
                                        ss=letter(lm.point.lower()) + "′", mm=num(drawn or 0.0)))
            if lm.inertia > 0:
                al = float(self.fa.kin.alpha.get(i, np.zeros(len(self.fa.labels)))[self.i])
                _, _, M = self.value(f"M_i{i}")
                out.append(self.say("inertia moment", i=i, s=s, J=num(lm.inertia), al=_par(al),
                                    M=num(M),
                                    turn=self.turn(M)))
                if lm.mass > 0 and abs(F) > 0.0 and M != 0.0:
                    drawn, _, h = self.value(f"h_{i}")
                    out.append(self.say("offset", i=i, S=S, M=num(abs(M)), F=num(abs(F)), h=num(h),
                                        mm=num(drawn or 0.0)))
        for pf in self.model.forces:
            vec = self.vec(next(f.vector for f in self._loads_of(pf.link) if f.name == pf.name))
            if vec == 0:
                out.append(self.say("idle resistance", name=pf.name, P=letter(pf.point)))
            else:
                out.append(self.say("force", name=pf.name, F=num(abs(vec)), P=letter(pf.point), angle=_angle(vec),
                                    mm=num(abs(vec) / self.mu_F)))
        for c in self.model.couples:
            out.append(self.say("couple", name=c.name, M=num(c.moment), link=c.link, turn=self.turn(c.moment)))
        return out

    def _loads_of(self, link: str) -> list[Any]:
        return [f for g in self.sol.groups if link in g.links for f in g.free_body]

    def friction(self) -> list[str]:
        out = []
        for fr in self.model.revolute_friction:
            if fr.rho > 0:
                out.append(self.say("friction circle", P=letter(fr.point), fv=num(fr.f_v), r=num(fr.radius),
                                    rho=num(fr.rho), mm=num(fr.rho / self.mu_l)))
        for sf in self.model.sliding_friction:
            if sf.f > 0:
                out.append(self.say("friction angle", link=sf.link, f=num(sf.f), phi=num(math.degrees(math.atan(sf.f)))))
        out.append(self.say("approximation", n=str(self.sol.iterations), tol=f"{self.model.tolerance:g}"))
        return out

    # ------------------------------------------------------------------ one group
    def group(self, g: GroupPolygon) -> list[str]:
        dyad = next((y for y in self.linkage.dyads if tuple(y.links) == g.links), None)
        out = [self.free_body(g, dyad)]
        if isinstance(dyad, (RRR, RRP)):
            out += self.tangential(g, dyad)
        elif isinstance(dyad, Triad):
            out += self.triad_moments(g, dyad)
        elif isinstance(dyad, RPR):
            b, k = dyad.bar_link, dyad.block_link
            r = self.vec(self.sol.reactions[(b, k)])
            out.append(self.say("bar reaction", b=b, k=k, P=letter(dyad.bar_pivot), X=letter(dyad.block_pivot),
                                bk=b + k, F=num(abs(r)), mm=num(abs(r) / self.mu_F)))
        out += self.laid_off(g)
        out += self.closing(g, dyad)
        out += self.found(g, dyad)
        return out

    def free_body(self, g: GroupPolygon, dyad: Any) -> str:
        from graphmech.problems.forces.figures import group_text

        known = [f.name for f in g.free_body if not self._unknown_force(f.name, g) and np.any(f.vector[self.i] != 0)]
        known += [c.name for c in g.couples if c.name != "M_b" and not c.name.startswith("M_f")]
        found = []
        for f in g.free_body:
            if self._unknown_force(f.name, g):
                found.append(self.say("at", name=f.name, P=letter(f.point)) if f.point
                             else self.say("from guide", name=f.name))
        if g.name.startswith("driver") and isinstance(self.linkage.driver, Crank):
            found.append("M_b")
        return self.say("free body", group=group_text(g, self.notation),
                        links="" if len(g.links) == 1 else self.say("links", links=", ".join(g.links)),
                        known=", ".join(known) or self.say("nothing"), unknown=", ".join(dict.fromkeys(found)))

    def _unknown_force(self, name: str, g: GroupPolygon) -> bool:
        """Whether a force of the free body is one the group's polygon finds (its reactions with
        the frame and with the links of the groups still to come)."""
        if not name.startswith("R_") or len(name) != 4:
            return name == "F_b"
        a, b = name[2], name[3]
        return b in g.links and a not in g.links and not self._solved_before(a, g)

    def _solved_before(self, link: str, g: GroupPolygon) -> bool:
        """Whether ``link`` belongs to a group solved before ``g`` (its reaction is known then)."""
        for other in self.sol.groups:
            if other is g:
                return False
            if link in other.links:
                return True
        return False

    def tangential(self, g: GroupPolygon, y: RRR | RRP) -> list[str]:
        out = []
        C = letter(y.c)
        ends = [(y.links[0], y.p)] + ([(y.links[1], y.q)] if isinstance(y, RRR) else [])
        for link, P in ends:
            name = next(n for n, _ in g.chain if n.startswith("R^t_") and n.endswith(link))
            v = self.vec(dict(g.chain)[name])
            a = name[4:-len(link)]
            out.append(self.say("tangential", link=link, C=C, ai=a + link, PC=letter(P) + C, F=num(abs(v)),
                                mm=num(abs(v) / self.mu_F)))
        return out

    def triad_moments(self, g: GroupPolygon, y: Triad) -> list[str]:
        """A class III group: each Rᵗ from its binary link's moments, the third Rⁿ from the group's about S."""
        out = []
        chain = dict(g.chain)
        for link, P, X in zip(y.links, y.outer, y.inner):
            name = next(n for n in chain if n.startswith("R^t_") and n.endswith(link))
            v = self.vec(chain[name])
            out.append(self.say("tangential", link=link, C=letter(X), ai=name[4:], PC=letter(P) + letter(X),
                                F=num(abs(v)), mm=num(abs(v) / self.mu_F)))
        i, j = y.assur
        k = 3 - i - j
        name = next(n for n in chain if n.startswith("R^n_") and n.endswith(y.links[k]))
        v = self.vec(chain[name])
        out.append(self.say("assur moments", PX=letter(y.outer[i]) + letter(y.inner[i]),
                            QZ=letter(y.outer[j]) + letter(y.inner[j]), ak=name[4:], k=y.links[k],
                            RY=letter(y.outer[k]) + letter(y.inner[k]), F=num(abs(v)), mm=num(abs(v) / self.mu_F)))
        return out

    def laid_off(self, g: GroupPolygon) -> list[str]:
        out = []
        first = True
        for name, arr in g.chain:
            if name in g.unknown:
                continue
            v = self.vec(arr)
            if v == 0:
                continue
            mm = abs(v) / self.mu_F
            line = self.say("lay first" if first else "lay", name=name, F=num(abs(v)), mm=num(mm), angle=_angle(v))
            if mm < DRAWN_MIN_MM:
                line += self.say("too short")
            out.append(line)
            first = False
        return out

    def closing(self, g: GroupPolygon, y: Any) -> list[str]:
        known = [n for n, arr in g.chain if n not in g.unknown and self.vec(arr) != 0]
        last = known[-1] if known else "o"
        if len(g.unknown) == 1:
            return [self.say("close one", name=g.unknown[0], last=last)]
        u1, u2 = g.unknown
        return [self.say("close two", last=last, u1=u1, u2=u2, d1=self.direction(u1, y), d2=self.direction(u2, y))]

    def direction(self, name: str, y: Any) -> str:
        """The direction of an unknown of the polygon, as the draftsman rules it."""
        if name.startswith("R^n_") and isinstance(y, Triad):
            k = next(k for k in range(3) if name.endswith(y.links[k]))
            return self.say("par", PC=letter(y.outer[k]) + letter(y.inner[k]))
        if name.startswith("R^n_"):
            link = name[-1]
            P = y.p if link == y.links[0] else y.q
            return self.say("par", PC=letter(P) + letter(y.c))
        if name == "F_b":
            return self.say("along", what=self.say("guide"))
        what = self.say("slot") if isinstance(y, RPP) and name == f"R_{y.links[0]}{y.links[1]}" else self.say("guide")
        slider = name[-1]
        f = next((sf.f for sf in self.model.sliding_friction if sf.link == (y.links[0] if what == self.say("slot")
                                                                             else slider)), 0.0)
        on = list(zip(y.links, y.guides)) if isinstance(y, PRP) else [(y.links[1], y.guide)] if isinstance(y, RRP) else []
        moving = [g for b, g in on if b == slider and not isinstance(g, Guide)]
        if moving:  # a slot on a moving link: named by its line, which turns with it
            what += ("" if self.notation == "zh" else " ") + letter(moving[0].through) + letter(moving[0].towards)
        if f > 0:
            return self.say("tilted", phi=num(math.degrees(math.atan(f))), what=what)
        return self.say("normal", what=what)

    def also(self, a: str, b: str) -> str:
        """" (R_21 = −R_12)" when the scene asks for the reaction the other way round."""
        if f"R_{b}{a}" in self.asked and f"R_{a}{b}" not in self.asked:
            return self.say("also", ab=a + b, ba=b + a)
        return ""

    def reaction(self, a: str, b: str) -> tuple[float, float]:
        """(drawn mm, value N) of |R_ab| as the check table has it."""
        drawn, _, val = self.value(f"R_{a}{b}")
        return float(drawn or 0.0), val

    def found(self, g: GroupPolygon, y: Any) -> list[str]:
        out = []
        mu = num(self.mu_F)
        for name in g.unknown:
            if name.startswith("R^n_"):
                v = self.vec(dict(g.chain)[name])
                out.append(self.say("read", name=name, mm=num(abs(v) / self.mu_F), mu=mu, F=num(abs(v))))
        if isinstance(y, Triad):
            t = y.links[3]
            for link, P, X in zip(y.links, y.outer, y.inner):
                a = next(n for n, _ in g.chain if n.startswith("R^t_") and n.endswith(link))[4:-len(link)]
                mm, val = self.reaction(a, link)
                out.append(self.say("sum", ai=a + link, mm=num(mm), mu=mu, F=num(val), also=self.also(a, link)))
                out += self.components(a, link)
                out += self.journal(a, link, P)
                mm, val = self.reaction(t, link)
                out.append(self.say("middle", i=link, ki=t + link, ai=a + link, C=letter(X), mm=num(mm), mu=mu,
                                    F=num(val), also=self.also(t, link)))
                out += self.components(t, link)
                out += self.journal(t, link, X)
        elif isinstance(y, (RRR, RRP)):
            i, k = y.links
            ends = [(i, y.p)] + ([(k, y.q)] if isinstance(y, RRR) else [])
            for link, P in ends:
                a = next(n for n, _ in g.chain if n.startswith("R^t_") and n.endswith(link))[4:-len(link)]
                mm, val = self.reaction(a, link)
                out.append(self.say("sum", ai=a + link, mm=num(mm), mu=mu, F=num(val), also=self.also(a, link)))
                out += self.components(a, link)
                out += self.journal(a, link, P)
            if isinstance(y, RRP):
                frame = self.linkage.frame_link if isinstance(y.guide, Guide) else y.guide.link
                mm, val = self.reaction(frame, k)
                out.append(self.say("reaction", name=f"R_{frame}{k}", mm=num(mm), mu=mu, F=num(val),
                                    also=self.also(frame, k)))
                out += self.components(frame, k)
                out += self.guide_line(frame, k, y.c)
            a = next(n for n, _ in g.chain if n.startswith("R^t_") and n.endswith(i))[4:-len(i)]
            mm, val = self.reaction(k, i)
            out.append(self.say("middle", i=i, ki=k + i, ai=a + i, C=letter(y.c), mm=num(mm), mu=mu, F=num(val),
                                also=self.also(k, i)))
            out += self.components(k, i)
            out += self.journal(i, k, y.c)
        elif isinstance(y, RPR):
            b, k = y.bar_link, y.block_link
            for link, P in ((b, y.bar_pivot), (k, y.block_pivot)):
                a = next(j.a for j in self.sol.joints if j.b == link and j.point == P)
                mm, val = self.reaction(a, link)
                out.append(self.say("reaction", name=f"R_{a}{link}", mm=num(mm), mu=mu, F=num(val),
                                    also=self.also(a, link)))
                out += self.components(a, link)
                out += self.journal(a, link, P)
            mm, val = self.reaction(b, k)
            out.append(self.say("reaction", name=f"R_{b}{k}", mm=num(mm), mu=mu, F=num(val), also=self.also(b, k)))
            out += self.components(b, k)
        elif isinstance(y, RPP):
            i, j = y.links
            frame = self.linkage.frame_link
            for a, b in ((frame, j), (i, j)):
                mm, val = self.reaction(a, b)
                out.append(self.say("reaction", name=f"R_{a}{b}", mm=num(mm), mu=mu, F=num(val), also=self.also(a, b)))
                out += self.components(a, b)
            out += self.guide_line(frame, j, y.c)
            a = next(jt.a for jt in self.sol.joints if jt.b == i and jt.point == y.p)
            mm, val = self.reaction(a, i)
            out.append(self.say("reaction", name=f"R_{a}{i}", mm=num(mm), mu=mu, F=num(val), also=self.also(a, i)))
            out += self.components(a, i)
            out += self.journal(a, i, y.p)
        elif isinstance(y, PRP):  # each block's guide reaction and its line, then the pin C
            i, j = y.links
            for b, line in zip(y.links, y.guides):
                a = self.linkage.frame_link if isinstance(line, Guide) else line.link
                mm, val = self.reaction(a, b)
                out.append(self.say("reaction", name=f"R_{a}{b}", mm=num(mm), mu=mu, F=num(val), also=self.also(a, b)))
                out += self.components(a, b)
                out += self.guide_line(a, b, y.c)
            mm, val = self.reaction(j, i)
            out.append(self.say("reaction", name=f"R_{j}{i}", mm=num(mm), mu=mu, F=num(val), also=self.also(j, i)))
            out += self.components(j, i)
            out += self.journal(j, i, y.c)
        else:
            out += self.driver()
        return out

    def components(self, a: str, b: str) -> list[str]:
        """R_ab's x and y components, where the scene asks for them."""
        for first, second in ((a, b), (b, a)):
            names = [f"R_{first}{second}_x", f"R_{first}{second}_y"]
            if any(n in self.asked for n in names):
                parts = []
                for n in names:
                    drawn, _, val = self.value(n)
                    parts.append(f"{n} = {num(drawn or 0.0)} mm × {num(self.mu_F)} = {num(val)} N")
                return [self.say("components", name=f"R_{first}{second}", x=parts[0], y=parts[1])]
        return []

    def journal(self, a: str, b: str, point: str) -> list[str]:
        """The friction circle the reaction R_ab is tangent to (with friction in that journal)."""
        rho = next((fr.rho for fr in self.model.revolute_friction if fr.point == point and fr.rho > 0), 0.0)
        if rho == 0.0 or a == b:
            return []
        m = float(self.sol.friction_moments.get((a, b), np.zeros(self.i + 1))[self.i])
        if m == 0.0:  # the two links turn together here: no friction couple
            return []
        _, val = self.reaction(a, b)
        return [self.say("journal", name=f"R_{a}{b}", P=letter(point), rho=num(rho), F=num(val), M=num(abs(m)),
                         a=a, b=b)]

    def guide_line(self, frame: str, k: str, C: str) -> list[str]:
        _, _, M = self.value(f"M_{frame}{k}")
        drawn, _, e = self.value(f"e_{frame}{k}")
        return [self.say("guide line", k=k, C=letter(C), name=f"R_{frame}{k}", ak=frame + k, M=num(M), e=num(e),
                         mm=num(drawn or 0.0))]

    def driver(self) -> list[str]:
        d = self.linkage.driver
        frame = self.linkage.frame_link
        mu = num(self.mu_F)
        out = []
        mm, val = self.reaction(frame, d.link)
        out.append(self.say("reaction", name=f"R_{frame}{d.link}", mm=num(mm), mu=mu, F=num(val),
                            also=self.also(frame, d.link)))
        out += self.components(frame, d.link)
        if isinstance(d, Crank):
            out += self.journal(frame, d.link, d.pivot)
            _, _, M = self.value("M_b")
            out.append(self.say("balancing moment", link=d.link, A=letter(d.pivot), M=num(M), turn=self.turn(M)))
        else:
            out += self.guide_line(frame, d.link, d.point)
            drawn, _, F = self.value("F_b")
            against = self.say("against") if F < 0 else ""
            out.append(self.say("balancing force", mm=num(abs(drawn or 0.0)), mu=mu, F=num(abs(F)), against=against))
        return out

    # ------------------------------------------------------------------ the lever, the efficiency
    def lever(self) -> list[str]:
        lever = self.fa.lever
        assert lever is not None
        out = [self.say("lever")]
        for name, image, force in lever.arms:
            z, f = self.vec(image), self.vec(force)
            if f == 0 or z == 0:  # no load, or a load at a fixed point (its image is the pole)
                continue
            M = (z.conjugate() * f).imag
            out.append(self.say("arm", name=name, x=f"({num(z.real)}, {num(z.imag)}) mm", M=num(M)))
        S = float(lever.moment[self.i])
        d = self.linkage.driver
        label = " (M_b_lever)" if "M_b_lever" in self.asked else ""
        if isinstance(d, Crank):
            _, _, M = self.value("M_b_lever") if "M_b_lever" in self.asked else (None, 1.0, float(
                lever.balancing_moment[self.i]))
            out.append(self.say("lever moment", S=num(S), Sp=_par(S), s=subscript(d.link), mu=num(self.fa.kin.mu_v), w=_par(d.omega),
                                M=num(M), label=label))
        else:
            label = " (F_b_lever)" if "F_b_lever" in self.asked else ""
            assert lever.balancing_force is not None
            F = float(lever.balancing_force[self.i])
            label += self.say("at μF", mm=num(F / self.mu_F))
            out.append(self.say("lever force", S=num(S), Sp=_par(S), mu=num(self.fa.kin.mu_v), v=_par(d.velocity), F=num(F),
                                label=label))
        return out

    def efficiency(self) -> list[str]:
        out = []
        for name in ("M_b0", "F_b0"):
            if name in self.asked:
                drawn, _, v = self.value(name)
                at = "" if drawn is None else self.say("at μF", mm=num(drawn))
                out.append(self.say("frictionless", name=name, value=f"{num(v)} {'N·m' if name == 'M_b0' else 'N'}{at}"))
        if "eta" in self.asked:
            _, _, eta = self.value("eta")
            crank = isinstance(self.linkage.driver, Crank)
            ideal, actual = ("M_b0", "M_b") if crank else ("F_b0", "F_b")
            _, _, A = self.value(ideal)
            _, _, B = self.value(actual)
            if not math.isclose(A / B if B else math.inf, eta, rel_tol=1e-9):  # the loads drive: actual over ideal
                ideal, actual, A, B = actual, ideal, B, A
            out.append(self.say("efficiency", a=ideal, b=actual, A=_par(A), B=_par(B), eta=num(eta)))
        return out


__all__ = ["PHRASES", "force_steps", "protocol"]
