"""The protocol of a structure scene: the mobility counted as the book counts it — moving links,
lower pairs (a compound hinge of k links as k − 1), higher pairs, local freedoms, redundant
constraints, F = 3n − (2p_l + p_h − p′) − F′ — checked against the constraint Jacobian's rank
at the drawn position, and the mechanism taken apart into its driver and Assur groups.

The counts, the rank and the groups are the check's own (:func:`analyse_structure`); a printed
case (counts without a topology) gets its formula written out.
"""
from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from graphmech.mechanisms.topology import roman
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, phrase
from graphmech.problems.structure.check import (
    StructureAnalysis,
    analyse_structure,
    formula_text,
)

if TYPE_CHECKING:
    from graphmech.mechanisms.topology import Mobility, Structure, Topology
    from graphmech.problems.reader import Scene
    from graphmech.problems.structure.scene import StructureScene

#: The structure's phrases: key → (English, 中文, русский). 孙桓: 活动构件, 低副, 高副, 复合铰链,
#: 局部自由度, 虚约束, 拆杆组; the Russian books: формула Чебышева, группы Ассура.
PHRASES: Phrases = {
    **COMMON,
    "case": ("{label}: {formula}", "{label}：{formula}", "{label}: {formula}"),
    "rigid": ("{label}: F = {F} ≤ 0 — a rigid structure, it cannot move", "{label}：F = {F} ≤ 0，为桁架，不能运动",
              "{label}: F = {F} ≤ 0 — ферма, движение невозможно"),
    "links": ("count the moving links ({frame} is the frame): {names} — n = {n}",
              "数活动构件（{frame}为机架）：{names}，n = {n}",
              "считаем подвижные звенья ({frame} — стойка): {names} — n = {n}"),
    "compound": ("{name} is a compound hinge of {k} links ({links}): it counts as {c} revolutes",
                 "{name}处为{k}个构件（{links}）组成的复合铰链，计{c}个转动副",
                 "{name} — составной шарнир {k} звеньев ({links}): считаем его за {c} вращательные пары"),
    "roller": ("the roller {link} turns about its own pin without moving the rest: a local freedom — F′ = {F}",
               "滚子{link}绕自身轴线的转动不影响其他构件的运动，为局部自由度：F′ = {F}",
               "ролик {link} вращается вокруг своей оси, не влияя на движение остальных: местная подвижность — F′ = {F}"),
    "lower": ("count the lower pairs: {names} — p_l = {n}", "数低副：{names}，p_l = {n}",
              "считаем низшие пары: {names} — p_l = {n}"),
    "higher": ("count the higher pairs: {names} — p_h = {n}", "数高副：{names}，p_h = {n}",
               "считаем высшие пары: {names} — p_h = {n}"),
    "no higher": ("no higher pairs: p_h = 0", "无高副：p_h = 0", "высших пар нет: p_h = 0"),
    "redundant stated": ("redundant constraints, as the scene states them: p′ = {n}", "虚约束（题给）：p′ = {n}",
                         "избыточные (пассивные) связи, как задано: p′ = {n}"),
    "formula": ("F = 3n − (2p_l + p_h − p′) − F′: {formula}", "F = 3n − (2p_l + p_h − p′) − F′：{formula}",
                "по формуле Чебышева F = 3n − (2p_l + p_h − p′) − F′: {formula}"),
    "jacobian": ("check at the drawn position: the {eq} constraint equations have rank {rank}: "
                 "F = 3·{n} − {rank} − {Fl} = {F}, p′ = {eq} − {rank} = {p}",
                 "在图示位置校核：{eq}个约束方程的秩为{rank}：F = 3·{n} − {rank} − {Fl} = {F}，p′ = {eq} − {rank} = {p}",
                 "проверка в изображённом положении: ранг {eq} уравнений связей равен {rank}: "
                 "F = 3·{n} − {rank} − {Fl} = {F}, p′ = {eq} − {rank} = {p}"),
    "determined": ("F = {F} = the number of drivers ({drivers}): the motion is determined",
                   "F = {F}，等于原动件数（{drivers}）：机构具有确定的运动",
                   "F = {F} = числу ведущих звеньев ({drivers}): движение определённое"),
    "not determined": ("F = {F}, but {k} driver(s) ({drivers}): the motion is not determined",
                       "F = {F}，原动件数为{k}（{drivers}）：机构运动不确定",
                       "F = {F}, а ведущих звеньев {k} ({drivers}): движение не определено"),
    "overdriven": ("F = {F}, but {k} driver(s) ({drivers}): the drivers fight each other",
                   "F = {F}，原动件数为{k}（{drivers}）：原动件多于自由度，机构将被破坏",
                   "F = {F}, а ведущих звеньев {k} ({drivers}): ведущие звенья мешают друг другу"),
    "cannot move": ("F = {F} ≤ 0: the links form a rigid structure and cannot move",
                    "F = {F} ≤ 0：各构件组成桁架，不能运动",
                    "F = {F} ≤ 0: звенья образуют ферму и двигаться не могут"),
    "replace higher": ("replace the higher pair {name} by a virtual link with two revolutes at the centres of curvature",
                       "高副低代：以一个虚拟构件和两个转动副代替高副{name}",
                       "заменяем высшую пару {name} условным звеном с двумя вращательными парами"),
    "drop roller": ("leave out the roller {link} (its local freedom): the contact moves onto its follower",
                    "去掉滚子{link}（局部自由度），接触点移至从动件上",
                    "убираем ролик {link} (местная подвижность): контакт переносим на толкатель"),
    "drop redundant": ("leave out the link(s) {links} that only repeat a motion already fixed (the redundant "
                       "constraints), as the book does", "去掉引入虚约束的构件{links}",
                       "отбрасываем звенья {links}, дающие избыточные связи"),
    "detach": ("detach the class {grade} Assur group of links {links} (pairs {pairs}): 3·{n} = 2·{p}, F = 0",
               "拆下由构件{links}（运动副{pairs}）组成的{grade}级杆组：3·{n} = 2·{p}，F = 0",
               "отделяем группу Ассура {grade} класса из звеньев {links} (пары {pairs}): 3·{n} = 2·{p}, F = 0"),
    "left": ("what is left: the frame {frame} and the driver(s) {drivers} — the class I mechanism",
             "剩下机架{frame}与原动件{drivers}，为I级机构",
             "остаются стойка {frame} и ведущее звено {drivers} — механизм I класса"),
    "no group": ("links {links} form no Assur group with these drivers", "构件{links}不能组成杆组",
                 "звенья {links} не образуют группы Ассура с этими ведущими звеньями"),
    "class": ("the highest group is of class {grade}: a class {grade} mechanism", "杆组的最高级别为{grade}级：该机构为{grade}级机构",
              "высший класс групп — {grade}: механизм {grade} класса"),
}


def structure_steps(scene: Scene[StructureScene]) -> list[str]:
    """The protocol of a structure scene, one line per step (not numbered)."""
    return protocol(analyse_structure(scene))


def protocol(an: StructureAnalysis) -> list[str]:
    notation = getattr(an.scene.page, "notation", "en")

    def say(key: str, **fields: str) -> str:
        return phrase(key, notation, PHRASES, **fields)

    out = []
    for c in an.cases:
        out.append(say("case", label=c["label"], formula=formula_text(c["n"], c["pl"], c["ph"], c["p_redundant"],
                                                                     c["F_local"], c["F"])))
        if c["F"] <= 0:
            out.append(say("rigid", label=c["label"], F=str(c["F"])))
    topo, m = an.scene.problem.topology, an.mobility
    if topo is None or m is None:
        return out
    out += _count(topo, m, say)
    if an.structure is not None:
        out += _groups(topo, an.structure, say)
    return out


def _join(names: list[str]) -> str:
    return ", ".join(names) if names else "—"


def _count(topo: Topology, m: Mobility, say: Callable[..., str]) -> list[str]:
    out = [say("links", frame=topo.frame, names=_join(list(topo.links)), n=str(m.n))]
    for p in topo.compound:
        out.append(say("compound", name=p.name, k=str(len(p.links)), links=", ".join(p.links), c=str(p.count)))
    lower = [p.name + (f" ×{p.count}" if p.count > 1 else "") for p in topo.pairs if p.kind in ("R", "P")]
    out.append(say("lower", names=_join(lower), n=str(m.pl)))
    higher = [p.name for p in topo.pairs if p.kind == "higher"]
    out.append(say("higher", names=_join(higher), n=str(m.ph)) if higher else say("no higher"))
    for r in m.rollers:
        out.append(say("roller", link=r, F=str(m.F_local)))
    if topo.redundant is not None:
        out.append(say("redundant stated", n=str(m.p_redundant)))
    out.append(say("formula", formula=formula_text(m.n, m.pl, m.ph, m.p_redundant, m.F_local, m.F)))
    f = m.F
    if m.rank is not None and m.F_actual is not None and m.p_redundant_actual is not None and m.equations is not None:
        out.append(say("jacobian", eq=str(m.equations), rank=str(m.rank), n=str(m.n), Fl=str(m.F_local),
                       F=str(m.F_actual), p=str(m.p_redundant_actual)))
        f = m.F_actual
    drivers, k = _join(list(topo.drivers)), len(topo.drivers)
    if f <= 0:
        out.append(say("cannot move", F=str(f)))
    elif topo.drivers:
        out.append(say("determined" if f == k else "not determined" if f > k else "overdriven",
                       F=str(f), k=str(k), drivers=drivers))
    return out


def _groups(topo: Topology, st: Structure, say: Callable[..., str]) -> list[str]:
    """The book takes the groups off from the one furthest from the driver: the attaching order
    reversed."""
    out = [say("drop roller", link=r) for r in st.removed]
    out += [say("replace higher", name=h) for h in st.replaced]
    if st.leftover:
        out.append(say("drop redundant" if topo.redundant else "no group", links=", ".join(st.leftover)))
    for g in reversed(st.groups):
        n = len(g.links)
        out.append(say("detach", grade=roman(g.grade), links=", ".join(g.links), pairs=", ".join(g.pairs),
                       n=str(n), p=str(3 * n // 2)))
    out.append(say("left", frame=topo.frame, drivers=_join(list(st.drivers))))
    out.append(say("class", grade=roman(st.grade)))
    return out


__all__ = ["PHRASES", "protocol", "structure_steps"]
