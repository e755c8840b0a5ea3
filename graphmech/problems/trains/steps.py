"""The protocol of a gear-train scene, as the book solves it: the missing tooth numbers from the
coaxial condition, the split into basic trains, each basic train's equation with its numbers
(Willis' for a carrier's, (−1)^m ∏z/∏z for an ordinary chain), how they join, and the values the
check table reads — the numbers are those of the check's own split and solution.
"""
from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, read_row
from graphmech.problems.trains.check import TrainAnalysis, analyse

if TYPE_CHECKING:
    from graphmech.problems.reader import Scene
    from graphmech.problems.trains.scene import TrainScene

#: The gear train's phrases: key → (English, 中文 (孙桓), русский).
PHRASES: Phrases = {
    **COMMON,
    "coaxial": ("the coaxial condition (one module): {eq}", "由同心条件（模数相同）：{eq}",
                "из условия соосности (один модуль): {eq}"),
    "split": ("split the train: {trains}", "划分基本轮系：{trains}", "разбиваем механизм: {trains}"),
    "ordinary": ("the ordinary train {label}", "定轴轮系{label}", "рядовая передача {label}"),
    "planetary": ("the planetary train {label} (carrier {h})", "行星轮系{label}（系杆{h}）",
                  "планетарный механизм {label} (водило {h})"),
    "differential": ("the differential {label} (carrier {h})", "差动轮系{label}（系杆{h}）",
                     "дифференциал {label} (водило {h})"),
    "willis": ("in {train}, the converted train (carrier held): {eq}", "{train}的转化轮系：{eq}",
               "в {train}, обращённый механизм (водило неподвижно): {eq}"),
    "chain": ("in {train}: {eq}", "{train}：{eq}", "в {train}: {eq}"),
    "redundant": ("{label}: {k} redundant mesh(es) repeat a ratio (identical planets or idlers): counted once",
                  "{label}：{k}个虚约束啮合（相同的行星轮或惰轮），只计一次",
                  "{label}: {k} избыточн. зацепл. (одинаковые сателлиты или паразитные колёса): учитываем один раз"),
    "links": ("join them: {links}", "联立条件：{links}", "связи: {links}"),
    "fixed": ("{m} is fixed: n{m} = 0", "{m}固定：n{m} = 0", "{m} неподвижно: n{m} = 0"),
    "solve": ("solve the equations together", "联立求解", "решаем уравнения совместно"),
    "diagram": ("by the velocity diagram (μl = {mu_l} m/mm, μv = {mu_v} (m/s)/mm): each member's velocities a line "
                "through its axis and its pitch points; from the pole O at H = {H} mm the rays parallel to them cut "
                "the ω line, ω = ℓ·μv/(μl·H) = ℓ × {mu_w} (rad/s)/mm",
                "用速度图法（μl = {mu_l} m/mm，μv = {mu_v} (m/s)/mm）：各构件的速度线过其轴心和节点；自极点O作其平行线，"
                "截距H = {H} mm处的ω线，ω = ℓ·μv/(μl·H) = ℓ × {mu_w} (rad/s)/mm",
                "по плану скоростей (μl = {mu_l} м/мм, μv = {mu_v} (м/с)/мм): скорости звена — прямая через его ось и "
                "полюсы зацепления; лучи из полюса O параллельно им отсекают на прямой ω на расстоянии H = {H} мм "
                "отрезки ℓ, ω = ℓ·μv/(μl·H) = ℓ × {mu_w} (рад/с)/мм"),
}


def train_steps(scene: Scene[TrainScene]) -> list[str]:
    """The protocol of a gear-train scene, one line per step (not numbered)."""
    return protocol(analyse(scene, ()))


def protocol(an: TrainAnalysis) -> list[str]:
    p = an.problem
    nt = an.scene.page.notation
    out = [phrase("coaxial", nt, PHRASES, eq=eq) for eq in p.coaxial_equations.values()]
    sp = an.split
    words = [phrase(b.kind, nt, PHRASES, label=b.label, h=b.carrier or "") for b in sp.trains]
    out.append(phrase("split", nt, PHRASES, trains="; ".join(words)))
    for b, w in zip(sp.trains, words):
        for eq in b.equations():
            out.append(phrase("willis" if b.carrier else "chain", nt, PHRASES, train=w, eq=eq))
        if b.redundant:
            out.append(phrase("redundant", nt, PHRASES, label=b.label, k=str(b.redundant)))
    if sp.links:
        out.append(phrase("links", nt, PHRASES, links="; ".join(sp.links)))
    out += [phrase("fixed", nt, PHRASES, m=m) for m in p.train.fixed]
    out.append(phrase("solve", nt, PHRASES))
    out += [read_row(replace(r, drawn_mm=None, graphical=an.book[r.name]) if r.name in an.book else r, nt)
            for r in an.rows]
    d = next((d for d in an.diagrams.values() if d is not None), None)
    if d is not None and an.book:  # the graphical method, and what it reads
        out.append(phrase("diagram", nt, PHRASES, mu_l=num(d.mu_l), mu_v=num(d.mu_v), H=num(d.H),
                          mu_w=num(d.mu_omega)))
        out += [read_row(r, nt) for r in an.rows if r.name in an.book]
    return out


__all__ = ["PHRASES", "protocol", "train_steps"]
