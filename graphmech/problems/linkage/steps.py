"""The construction protocol of a linkage scene: its kinematic diagram, velocity polygon and
acceleration polygon step by step, as the book words them, with every length drawn.

The steps are the construction's own (:mod:`graphmech.methods.polygons`), pruned to what the
scene's ``find`` asks for (everything of the panels it shows when it asks for nothing), in
the book's order — the diagram, then the velocity polygon, then the acceleration polygon —
once per position. Each step the builders marked with a phrase (``Step.say``) is worded here
in the scene's notation with the numbers of the very solution the check table and the drawing
are made from, so the protocol cannot disagree with them.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from graphmech.drawing.lettering import subscript
from graphmech.mechanisms.linkage import PRP, RPP, RPR, RRP, Crank, LinkGuide, SliderInput, Triad
from graphmech.methods.instant_centres import centre_name, pair
from graphmech.methods.polygons import PANELS
from graphmech.problems.instant_centres import check as ic_check
from graphmech.problems.judging import split_name
from graphmech.problems.linkage.check import SCALE_KEYS, Analysis, analyse
from graphmech.problems.linkage.sizes import position_text
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, scale_choice, sense

if TYPE_CHECKING:
    from graphmech.construction.graph import Solution, Step
    from graphmech.problems.reader import Scene

#: The linkage's phrases: key → (English, 中文, русский); fields in braces.
PHRASES: Phrases = {
    **COMMON,
    # the kinematic diagram
    "diagram": ("choose {mu} and draw the kinematic diagram at {pos}",
                "取{mu}，作{pos}时的机构运动简图",
                "выбираем {mu} и строим кинематическую схему при {pos}"),
    "frame first": ("mark the frame pivot {A}", "定出机架铰链{A}", "отмечаем неподвижный шарнир {A}"),
    "frame": ("mark the frame pivot {D} at x = {x} mm, y = {y} mm from {A}",
              "在距{A} x = {x} mm、y = {y} mm处定出机架铰链{D}",
              "отмечаем неподвижный шарнир {D} в точке x = {x} mm, y = {y} mm от {A}"),
    "crank": ("draw the crank {AB} at {pos}: {AB} = l_{AB}/μl = {l}/{mu} = {mm} mm",
              "按{pos}作曲柄{AB}：{AB} = l_{AB}/μl = {l}/{mu} = {mm} mm",
              "проводим кривошип {AB} при {pos}: {AB} = l_{AB}/μl = {l}/{mu} = {mm} mm"),
    "slider_at": ("mark {B} on its guide at {pos}: {mm} mm from the guide's origin",
                  "按{pos}在导路上定出{B}：距导路原点{mm} mm",
                  "отмечаем {B} на направляющей при {pos}: {mm} mm от начала направляющей"),
    "circles": ("arcs about {P} with radius {PC} = {r1} mm and about {Q} with radius {QC} = {r2} mm meet at {C}, "
                "{side} of {P}→{Q}",
                "分别以{P}、{Q}为圆心，{PC} = {r1} mm、{QC} = {r2} mm为半径作弧，交于{C}（在{P}→{Q}的{side}）",
                "из {P} радиусом {PC} = {r1} mm и из {Q} радиусом {QC} = {r2} mm проводим дуги; они пересекаются "
                "в точке {C} ({side} от {P}→{Q})"),
    "left": ("left", "左侧", "слева"),
    "right": ("right", "右侧", "справа"),
    "guide line": ("draw the guide of {C} through x = {x} mm, y = {y} mm at {angle}° to the x axis",
                   "过x = {x} mm、y = {y} mm作{C}的导路，与x轴成{angle}°",
                   "проводим направляющую {C} через точку x = {x} mm, y = {y} mm под углом {angle}° к оси x"),
    "circle_guide": ("{guide}; an arc about {P} with radius {PC} = {r} mm meets it at {C}",
                     "{guide}；以{P}为圆心、{PC} = {r} mm为半径作弧，与导路交于{C}",
                     "{guide}; из {P} радиусом {PC} = {r} mm проводим дугу до пересечения с ней в точке {C}"),
    "slot_guide": ("{guide}; the slot through {P} at {angle}° meets it at {C}",
                   "{guide}；过{P}作与x轴成{angle}°的导槽线，与导路交于{C}",
                   "{guide}; паз через {P} под углом {angle}° пересекает её в точке {C}"),
    "link line": ("extend the line {UV} of link {link}", "延长构件{link}上的直线{UV}",
                  "продолжаем прямую {UV} звена {link}"),
    "guides meet": ("{a}; {b}; they meet at {C}", "{a}；{b}；两线交于{C}", "{a}; {b}; они пересекаются в точке {C}"),
    "on_link": ("mark {D} on link {link}: {UD} = {along} mm along {U}→{V}, then {left} mm to its left",
                "在构件{link}上定出{D}：沿{U}→{V}取{UD} = {along} mm，再向左{left} mm",
                "отмечаем {D} на звене {link}: {UD} = {along} mm по {U}→{V}, затем {left} mm влево"),
    "on_link straight": ("mark {D} on link {link}: {UD} = {along} mm along {U}→{V}",
                         "在构件{link}上沿{U}→{V}取{UD} = {along} mm，得{D}",
                         "отмечаем {D} на звене {link}: {UD} = {along} mm по {U}→{V}"),
    "on_link shift": ("mark {D} on link {link}: x = {x} mm, y = {y} mm from {U}",
                      "在构件{link}上距{U} x = {x} mm、y = {y} mm处定出{D}",
                      "отмечаем {D} на звене {link}: x = {x} mm, y = {y} mm от {U}"),
    # a class III group (Triad)
    "triad": ("the class III group {group}: {C}, {D}, {E} where all three binary links fit the ternary link "
              "(its loop equations solved by Newton's method from the stated start; by hand, by trial)",
              "Ⅲ级杆组{group}：三个二副杆与三副杆同时装配时的{C}、{D}、{E}（由其封闭矢量方程从给定初位用牛顿法解出；手工作图时用试凑法）",
              "группа III класса {group}: {C}, {D}, {E}, при которых все три поводка сходятся с базисным звеном "
              "(уравнения замкнутости решены методом Ньютона от заданного начального положения; вручную — подбором)"),
    "triad_joint": ("mark {P}: {QP} = {r} mm", "定出{P}：{QP} = {r} mm", "отмечаем {P}: {QP} = {r} mm"),
    "triad_slider": ("mark {P} on its guide", "定出{P}（在其导路上）", "отмечаем {P} на её направляющей"),
    "normal_at": ("the normal to {X}'s guide at {X}", "过{X}作其导路的垂线", "нормаль к направляющей в точке {X}"),
    "assur": ("extend {PX} and {QZ}: they meet at S, Assur's special point of the ternary link",
              "延长{PX}与{QZ}交于S，即三副杆上的阿苏尔特殊点",
              "продолжаем {PX} и {QZ} до пересечения в точке S — особой точке Ассура базисного звена"),
    "tangent": (("draw the circle of radius |e| = {r} mm about {O} and the circle on {OX} as diameter: they meet "
                 "at F, {side} of {O}→{X}; {X}F is the offset guide bar's line, tangent to the first circle"),
                ("以{O}为圆心、|e| = {r} mm为半径作圆，再以{OX}为直径作圆，两圆交于F（在{O}→{X}的{side}）；"
                 "{X}F即偏置导杆的导路线，与前一圆相切"),
                ("из {O} проводим окружность радиусом |e| = {r} mm и окружность на {OX} как на диаметре; они "
                 "пересекаются в точке F ({side} от {O}→{X}); {X}F — линия смещённой кулисы, касательная к первой "
                 "окружности")),
    # the polygons
    "pole velocity": ("choose {mu} and mark the pole p of the velocity polygon",
                      "取{mu}，任取极点p作速度多边形",
                      "выбираем {mu} и полюс p плана скоростей"),
    "pole acceleration": ("choose {mu} and mark the pole p′ of the acceleration polygon",
                          "取{mu}，任取极点p′作加速度多边形",
                          "выбираем {mu} и полюс p′ плана ускорений"),
    "crank velocity": ("from p lay off {pb} ⟂ {AB} in the sense of ω{i} ({sense}): {pb} = ω{i}·l_{lAB}/μv = "
                       "{w} × {l}/{mu} = {mm} mm (v_{lB} = {v} m/s)",
                       "自p作{pb} ⟂ {AB}，指向与ω{i}转向（{sense}）一致：{pb} = ω{i}·l_{lAB}/μv = "
                       "{w} × {l}/{mu} = {mm} mm（v_{lB} = {v} m/s）",
                       "из полюса p откладываем {pb} ⟂ {AB} в сторону вращения ω{i} ({sense}): {pb} = ω{i}·l_{lAB}/μv = "
                       "{w} × {l}/{mu} = {mm} mm (v_{lB} = {v} m/s)"),
    "crank acceleration": ("from p′ lay off {pb} ∥ {BA}, from {B} towards {A}: {pb} = ω{i}²·l_{lAB}/μa = "
                           "{w}² × {l}/{mu} = {mm} mm (a_{lB} = {v} m/s²)",
                           "自p′作{pb} ∥ {BA}（由{B}指向{A}）：{pb} = ω{i}²·l_{lAB}/μa = "
                           "{w}² × {l}/{mu} = {mm} mm（a_{lB} = {v} m/s²）",
                           "из полюса p′ откладываем {pb} ∥ {BA} (от {B} к {A}): {pb} = ω{i}²·l_{lAB}/μa = "
                           "{w}² × {l}/{mu} = {mm} mm (a_{lB} = {v} m/s²)"),
    "crank acceleration eps": ("from p′ lay off {pb} = a_{lB}, the sum of ω{i}²·l_{lAB}/μa = {mmn} mm ∥ {BA} (towards {A}) "
                               "and ε{i}·l_{lAB}/μa = {mmt} mm ⟂ {AB}: {pb} = {mm} mm (a_{lB} = {v} m/s²)",
                               "自p′作{pb} = a_{lB}：ω{i}²·l_{lAB}/μa = {mmn} mm ∥ {BA}（指向{A}）与"
                               "ε{i}·l_{lAB}/μa = {mmt} mm ⟂ {AB}之和，{pb} = {mm} mm（a_{lB} = {v} m/s²）",
                               "из полюса p′ откладываем {pb} = a_{lB} — сумму ω{i}²·l_{lAB}/μa = {mmn} mm ∥ {BA} (к {A}) "
                               "и ε{i}·l_{lAB}/μa = {mmt} mm ⟂ {AB}: {pb} = {mm} mm (a_{lB} = {v} m/s²)"),
    "slider velocity": ("from p lay off {pb} ∥ the guide: {pb} = v_{lB}/μv = {v}/{mu} = {mm} mm",
                        "自p作{pb} ∥ 导路：{pb} = v_{lB}/μv = {v}/{mu} = {mm} mm",
                        "из полюса p откладываем {pb} ∥ направляющей: {pb} = v_{lB}/μv = {v}/{mu} = {mm} mm"),
    "slider acceleration": ("from p′ lay off {pb} ∥ the guide: {pb} = a_{lB}/μa = {v}/{mu} = {mm} mm",
                            "自p′作{pb} ∥ 导路：{pb} = a_{lB}/μa = {v}/{mu} = {mm} mm",
                            "из полюса p′ откладываем {pb} ∥ направляющей: {pb} = a_{lB}/μa = {v}/{mu} = {mm} mm"),
    "perp": ("through {x} draw a line ⟂ {XY}", "过{x}作{XY}的垂线", "через точку {x} проводим прямую ⟂ {XY}"),
    "par": ("through {x} draw a line ∥ {XY}", "过{x}作{XY}的平行线", "через точку {x} проводим прямую ∥ {XY}"),
    "guide": ("through {x} draw a line ∥ the guide of {C}", "过{x}作{C}导路的平行线",
              "через точку {x} проводим прямую ∥ направляющей {C}"),
    "slot": ("through {x} draw a line ∥ the slot", "过{x}作导槽的平行线", "через точку {x} проводим прямую ∥ пазу"),
    "direction of": (" (the direction of {c})", "（{c}的方向）", " (направление {c})"),
    "meet": ("{c} = the intersection of the two lines", "两线交于{c}", "точка пересечения прямых — {c}"),
    "image velocity": ("draw △{uvx} ∼ △{UVX}, the letters in the same order (velocity image): {x}",
                       "根据速度影像原理，作△{uvx} ∽ △{UVX}且字母顺序一致，得点{x}",
                       "по подобию строим △{uvx} ∼ △{UVX} с тем же порядком букв (теорема подобия), получаем {x}"),
    "image acceleration": ("draw △{uvx} ∼ △{UVX}, the letters in the same order (acceleration image): {x}",
                           "根据加速度影像原理，作△{uvx} ∽ △{UVX}且字母顺序一致，得点{x}",
                           "по подобию строим △{uvx} ∼ △{UVX} с тем же порядком букв (теорема подобия), получаем {x}"),
    "normal": ("from {y} lay off {yn} ∥ {XY}, from {X} towards {Y}: {yn} = ω{i}²·l_{lXY}/μa = {w}² × {l}/{mu} = {mm} mm",
               "自{y}作{yn} ∥ {XY}（由{X}指向{Y}）：{yn} = ω{i}²·l_{lXY}/μa = {w}² × {l}/{mu} = {mm} mm",
               "из точки {y} откладываем {yn} ∥ {XY} (от {X} к {Y}): {yn} = ω{i}²·l_{lXY}/μa = {w}² × {l}/{mu} = {mm} mm"),
    "coriolis": ("from {y} lay off {yk} = a^k_{lrel} = 2ω{i}·v_{lrel}/μa = 2 × {w} × {v}/{mu} = {mm} mm, "
                 "v_{lrel} turned 90° in the sense of ω{i} ({sense})",
                 "自{y}作{yk} = a^k_{lrel} = 2ω{i}·v_{lrel}/μa = 2 × {w} × {v}/{mu} = {mm} mm，"
                 "方向为v_{lrel}沿ω{i}的转向（{sense}）转过90°",
                 "из точки {y} откладываем {yk} = a^k_{lrel} = 2ω{i}·v_{lrel}/μa = 2 × {w} × {v}/{mu} = {mm} mm — "
                 "вектор v_{lrel}, повёрнутый на 90° в сторону ω{i} ({sense})"),
    # measurements
    "rate": ("{sym} = {seg}·{mu}/l_{UV} = {mm} × {scale}/{l} = {value} {unit}",
             "{sym} = {seg}·{mu}/l_{UV} = {mm} × {scale}/{l} = {value} {unit}",
             "{sym} = {seg}·{mu}/l_{UV} = {mm} × {scale}/{l} = {value} {unit}"),
    "translates": ("link {link} translates: {sym} = 0", "构件{link}平动：{sym} = 0",
                   "звено {link} движется поступательно: {sym} = 0"),
    "angle": ("measure the angle of link {link} from the x axis on the diagram: {sym} = {value}°",
              "在机构运动简图上量得构件{link}与x轴的夹角：{sym} = {value}°",
              "измеряем на схеме угол звена {link} с осью x: {sym} = {value}°"),
    "against the guide": (" ({seg} points against the guide's direction)", "（{seg}与导路正向相反）",
                          " ({seg} направлен против направляющей)"),
    # instant centres
    "centre at joint": ("{P} is at the joint {J}", "{P}位于转动副{J}处", "{P} — в шарнире {J}"),
    "centre at infinity": ("{P} is at infinity, ⟂ the sliding pair (at {angle}° to the x axis)",
                           "{P}在垂直于移动副导路的无穷远处（与x轴成{angle}°）",
                           "{P} — в бесконечности, ⟂ направляющей (под углом {angle}° к оси x)"),
    "centre by Kennedy": ("{P} = (line {a}{b}) ∩ (line {c}{d}) by Kennedy's theorem: x = {x} mm, y = {y} mm",
                          "由三心定理，{P} = 直线{a}{b}与直线{c}{d}的交点：x = {x} mm, y = {y} mm",
                          "по теореме Кеннеди {P} = (прямая {a}{b}) ∩ (прямая {c}{d}): x = {x} mm, y = {y} mm"),
    "centre by Kennedy at infinity": ("{P}: lines {a}{b} and {c}{d} are parallel (Kennedy): {P} at infinity, at {angle}° "
                                      "to the x axis",
                                      "由三心定理，直线{a}{b}与{c}{d}平行：{P}在无穷远处，与x轴成{angle}°",
                                      "по теореме Кеннеди прямые {a}{b} и {c}{d} параллельны: {P} — в бесконечности, "
                                      "под углом {angle}° к оси x"),
    "centre undetermined": ("{P} cannot be found: {why}", "{P}无法确定：{why}", "{P} найти нельзя: {why}"),
    "read": ("read off the drawing: {sym} = {mm} mm × {scale} = {value} {unit}",
             "由图量得：{sym} = {mm} mm × {scale} = {value} {unit}",
             "по чертежу: {sym} = {mm} mm × {scale} = {value} {unit}"),
    "read angle": ("read off the drawing: {sym} = {value}°", "由图量得：{sym} = {value}°", "по чертежу: {sym} = {value}°"),
    "impossible": ("at {pos} the construction is impossible: {why}", "{pos}时无法作图：{why}",
                   "при {pos} построение невозможно: {why}"),
}

#: The book's order of the figures.
_RANK = {panel: k for k, panel in enumerate(PANELS)}
#: A quantity's unit as the protocol writes it after a value.
_SCALE_SYMBOL = {"mechanism": "μl", "velocity": "μv", "acceleration": "μa"}


def linkage_steps(scene: Scene[Any]) -> list[str]:
    """The protocol of a linkage scene, one line per step (not numbered)."""
    return protocol(analyse(scene, ()))


def protocol(an: Analysis) -> list[str]:
    """The protocol of an analysed linkage scene: for each position, its steps in the book's order."""
    b = an.build
    notation = getattr(an.scene.page, "notation", "en")
    out: list[str] = []
    for i, label in enumerate(an.labels):
        targets = _targets(an, label)
        if not targets:
            continue
        sol = an.solutions[i]
        pos = position_text(b, label)
        if sol is None:
            out.append(phrase("impossible", notation, PHRASES, pos=pos, why=an.failures[i]))
            continue
        need = b.g.dependencies(targets)
        steps = sorted((s for s in b.g.steps.values() if s.name in need and s.say),
                       key=lambda s: _RANK.get(s.panel or "mechanism", 0))  # stable: construction order kept
        words = _Words(an, sol, notation, pos, float(an.positions[i]), need, targets)
        out.append(words.diagram())
        for s in steps:
            line = words.step(s)
            if line:
                out.append(line)
        if an.instant_centres is not None and an.instant_centres.centres[i] is not None:
            out += words.centres(an.instant_centres.centres[i], label)
    return out


def _targets(an: Analysis, label: str) -> list[str]:
    """The measurement steps the scene's ``find`` asks for at this position (each point of the
    panels it shows when it asks for none)."""
    b = an.build
    out = []
    for raw in an.scene.find:
        base, at = split_name(raw)
        if ic_check.claims(raw) or base not in b.quantities or at not in (None, label):
            continue
        out.append(b.quantities[base].slot)
    if an.instant_centres is not None:  # the centres are found on the whole kinematic diagram
        out += list(b.mech.values())
    if not an.scene.find:
        for panel in PANELS:
            if panel in an.scene.show:
                out += [n for n in b.steps_of_panel(panel) if b.g.steps[n].kind == "point"]
    return list(dict.fromkeys(out))


def _drawn(mm: float, size: float) -> float:
    """A drawn length as a student measures it: round-off far below the drawing's size is 0."""
    return 0.0 if abs(mm) <= 1e-9 * size else float(mm)


def letter(label: str) -> str:
    """A point or image letter as the drawing writes it: C2 → C₂, c2' → c₂′."""
    return subscript(label).replace("'", "′")


class _Words:
    """The words of one position's steps, with the numbers of its solution."""

    def __init__(self, an: Analysis, sol: Solution, notation: str, pos: str, param: float,
                 need: set[str], targets: list[str]) -> None:
        self.an, self.b, self.values, self.notation = an, an.build, sol.values, notation
        self.pos, self.param, self.need = pos, param, need
        self.asked = [split_name(raw)[0] for raw in an.scene.find]
        self.first_frame = next(iter(self.b.linkage.frame_points), None)

    # ------------------------------------------------------------------ helpers
    def say(self, key: str, **fields: str) -> str:
        return phrase(key, self.notation, PHRASES, **fields)

    def lab(self, name: str) -> str:
        return letter(self.b.g.steps[name].label or "")

    def xy(self, name: str) -> tuple[float, float]:
        v = self.values[name]
        return (float(v[0]), float(v[1]))

    def mm(self, a: str, c: str) -> float:
        return math.dist(self.xy(a), self.xy(c))

    def mu(self, key: str) -> str:
        return scale_choice(key, self.an.scales[key], key in self.an.stated, self.notation)

    def part(self, name: str) -> Any:
        """The linkage's point (LinkPoint) named ``name``."""
        return next(p for p in self.b.linkage.points if p.name == name)

    def lengths(self, image: str) -> str:
        """The drawn vectors and sides that end at ``image``: "pc = 52.1 mm, bc = 23.4 mm"."""
        out = []
        for s in self.b.g.steps.values():
            if s.kind in ("vector", "segment") and s.inputs[1] == image and s.inputs[0] in self.need:
                out.append(f"{self.lab(s.inputs[0])}{self.lab(image)} = {num(self.mm(s.inputs[0], image))} mm")
        return ("，" if self.notation == "zh" else ", ").join(out)

    def guide(self, C: str) -> str:
        """Drawing the guide that the slider at ``C`` moves on."""
        driver = self.b.linkage.driver
        g = driver.guide if isinstance(driver, SliderInput) and driver.point == C else next(
            d.guide for d in self.b.linkage.dyads if isinstance(d, (RRP, RPP)) and d.c == C)
        if isinstance(g, LinkGuide):  # a slotted link's line, where it stands now
            return self.say("link line", UV=letter(g.through) + letter(g.towards), link=g.link)
        x, y = self.b.to_drawing(g.through)
        return self.say("guide line", C=letter(C), x=num(x), y=num(y), angle=num(math.degrees(g.angle)))

    def centres(self, ic: Any, label: str) -> list[str]:
        """The instant centres in the order they are found, then the values the scene asks of them."""
        out = []
        for key in ic.order:
            c = ic.centres[key]
            P = centre_name(*key)
            if c.kind == "undetermined":
                out.append(self.say("centre undetermined", P=P, why=c.why))
            elif c.kind == "direct":
                angle = num(math.degrees(math.atan2(c.direction[1], c.direction[0])) % 180.0) if c.direction else ""
                out.append(self.say("centre at joint", P=P, J=letter(c.via[0])) if c.point is not None and c.via
                           else self.say("centre at infinity", P=P, angle=angle))
            else:
                i, j = key
                k, m = c.via[:2]
                a, bb = (centre_name(*pair(ic.links, i, k)), centre_name(*pair(ic.links, k, j)))
                cc, d = (centre_name(*pair(ic.links, i, m)), centre_name(*pair(ic.links, m, j)))
                if c.point is not None:
                    x, y = (_drawn(v, ic.size) for v in c.point)
                    out.append(self.say("centre by Kennedy", P=P, a=a, b=bb, c=cc, d=d, x=num(x), y=num(y)))
                else:
                    angle = num(math.degrees(math.atan2(c.direction[1], c.direction[0])) % 180.0)
                    out.append(self.say("centre by Kennedy at infinity", P=P, a=a, b=bb, c=cc, d=d, angle=angle))
        multi = len(self.an.labels) > 1
        for r in self.an.rows:
            base, at = split_name(r.name)
            if not ic_check.claims(base) or (multi and at != label):
                continue
            if r.drawn_mm is None:
                out.append(self.say("read angle", sym=symbol(base), value=num(r.graphical)))
            else:
                zero = _drawn(r.drawn_mm, ic.size) == 0.0
                out.append(self.say("read", sym=symbol(base), mm=num(0.0 if zero else r.drawn_mm), scale=num(r.scale),
                                    value=num(0.0 if zero else r.graphical), unit=r.unit))
        return out

    # ------------------------------------------------------------------ steps
    def diagram(self) -> str:
        return self.say("diagram", mu=self.mu("l"), pos=self.pos)

    def step(self, s: Step) -> str:
        key, *args = s.say
        if key == "measure":
            return self.measure(s, args[0])
        if s.panel == "mechanism":
            return self.mechanism(s, key, args)
        return self.polygon(s, key, args)

    def mechanism(self, s: Step, key: str, args: list[str]) -> str:
        mu_l = self.an.scales["l"]
        if key == "frame":
            D = args[0]
            if D == self.first_frame or self.first_frame is None:
                return self.say("frame first", A=letter(D))
            x, y = self.xy(self.b.mech[D])
            return self.say("frame", D=letter(D), A=letter(self.first_frame), x=num(x), y=num(y))
        if key == "crank":
            A, B, _ = args
            mm = self.mm(self.b.mech[A], self.b.mech[B])
            return self.say("crank", AB=letter(A) + letter(B), pos=self.pos, l=num(mm * mu_l), mu=num(mu_l), mm=num(mm))
        if key == "slider_at":
            line = self.say("slider_at", B=letter(args[0]), pos=self.pos, mm=num(self.param / mu_l))
            return f"{self.guide(args[0])}; {line}" if self.notation != "zh" else f"{self.guide(args[0])}；{line}"
        if key == "circles":
            C, P, Q, branch = args
            return self.say("circles", P=letter(P), Q=letter(Q), C=letter(C), PC=letter(P) + letter(C),
                            QC=letter(Q) + letter(C), r1=num(self.mm(self.b.mech[P], s.name)),
                            r2=num(self.mm(self.b.mech[Q], s.name)), side=self.say(branch))
        if key == "circle_guide":
            C, P = args
            return self.say("circle_guide", guide=self.guide(C), P=letter(P), C=letter(C), PC=letter(P) + letter(C),
                            r=num(self.mm(self.b.mech[P], s.name)))
        if key == "slot_guide":
            C, P = args
            slot = next(d.slot_angle for d in self.b.linkage.dyads if isinstance(d, RPP) and d.c == C)
            return self.say("slot_guide", guide=self.guide(C), C=letter(C), P=letter(P), angle=num(math.degrees(slot)))
        if key == "guides_meet":  # a PRP's pin where its two guides' lines meet
            C = args[0]
            prp = next(d for d in self.b.linkage.dyads if isinstance(d, PRP) and d.c == C)
            words = []
            for g in prp.guides:
                if isinstance(g, LinkGuide):
                    words.append(self.say("link line", UV=letter(g.through) + letter(g.towards), link=g.link))
                else:
                    x, yy = self.b.to_drawing(g.through)
                    words.append(self.say("guide line", C=letter(C), x=num(x), y=num(yy),
                                          angle=num(math.degrees(g.angle))))
            return self.say("guides meet", a=words[0], b=words[1], C=letter(C))
        if key == "triad":
            group = next(d.name for d in self.b.linkage.dyads if isinstance(d, Triad) and d.inner == tuple(args))
            return self.say("triad", group=group, C=letter(args[0]), D=letter(args[1]), E=letter(args[2]))
        if key == "triad_joint":
            P, Q = args
            return self.say("triad_joint", P=letter(P), QP=letter(Q) + letter(P), r=num(self.mm(self.b.mech[Q], s.name)))
        if key == "tangent":  # an offset guide bar's line, tangent to the circle of radius |e| about its pivot
            O, X = args
            e = next(d.offset for d in self.b.linkage.dyads
                     if isinstance(d, RPR) and d.bar_pivot == O and d.block_pivot == X and d.offset != 0.0)
            return self.say("tangent", O=letter(O), X=letter(X), OX=letter(O) + letter(X), r=num(abs(e) / mu_l),
                            side=self.say("left" if e > 0.0 else "right"))
        if key == "triad_slider":
            return self.say("triad_slider", P=letter(args[0]))
        if key == "assur":  # a slider leg's line (its outer joint is its pin) is the normal to its guide
            P, X, Q, Z = args
            return self.say("assur", PX=self.say("normal_at", X=letter(X)) if P == X else letter(P) + letter(X),
                            QZ=self.say("normal_at", X=letter(Z)) if Q == Z else letter(Q) + letter(Z))
        # on_link: a point fixed on a link
        D, link, U, *V = args
        pt = self.part(D)
        if not V:
            return self.say("on_link shift", D=letter(D), link=link, U=letter(U), x=num(pt.along / mu_l),
                            y=num(pt.left / mu_l))
        fields = {"D": letter(D), "link": link, "U": letter(U), "V": letter(V[0]), "UD": letter(U) + letter(D),
                  "along": num(pt.along / mu_l), "left": num(pt.left / mu_l)}
        return self.say("on_link straight" if pt.left == 0.0 else "on_link", **fields)

    def polygon(self, s: Step, key: str, args: list[str]) -> str:
        panel = s.panel or "velocity"
        k = SCALE_KEYS[panel]
        mu = self.an.scales[k]
        driver = self.b.linkage.driver
        if key == "pole":
            return self.say(f"pole {panel}", mu=self.mu(k))
        if key == "crank" and isinstance(driver, Crank):
            A, B, link = args
            pole = s.inputs[0]
            pb = self.lab(pole) + self.lab(s.name)
            mm = self.mm(pole, s.name)
            fields = {"pb": pb, "AB": letter(A) + letter(B), "BA": letter(B) + letter(A), "A": letter(A),
                      "B": letter(B), "lAB": A + B, "lB": B, "i": subscript(link), "l": num(driver.length),
                      "mu": num(mu), "mm": num(mm), "v": num(mm * mu)}
            if panel == "velocity":
                return self.say("crank velocity", sense=sense(driver.omega, self.notation), w=num(abs(driver.omega)),
                                **fields)
            if driver.epsilon == 0.0:
                return self.say("crank acceleration", w=num(abs(driver.omega)), **fields)
            return self.say("crank acceleration eps", mmn=num(driver.omega ** 2 * driver.length / mu),
                            mmt=num(abs(driver.epsilon) * driver.length / mu), **fields)
        if key == "slider" and isinstance(driver, SliderInput):
            pole = s.inputs[0]
            value = driver.velocity if panel == "velocity" else driver.acceleration
            return self.say(f"slider {panel}", pb=self.lab(pole) + self.lab(s.name), lB=args[0],
                            v=num(value), mu=num(mu), mm=num(self.mm(pole, s.name)))
        if key in ("perp", "par", "guide", "slot"):
            x = self.lab(s.inputs[0])
            if key in ("perp", "par"):
                line = self.say(key, x=x, XY=letter(args[0]) + letter(args[1]))
                return line + (self.say("direction of", c=args[2]) if len(args) > 2 else "")  # a^t_CB, a^r_C2C3
            return self.say(key, x=x, C=letter(args[0]) if args else "")
        if key == "meet":
            found = self.say("meet", c=self.lab(s.name))
            more = self.lengths(s.name)
            return f"{found}: {more}" if more and self.notation != "zh" else f"{found}：{more}" if more else found
        if key == "image":
            U, V, X = args
            u, v = self.lab(s.inputs[3]), self.lab(s.inputs[4])
            line = self.say(f"image {panel}", uvx=u + v + self.lab(s.name), UVX=letter(U) + letter(V) + letter(X),
                            x=self.lab(s.name))
            more = self.lengths(s.name)
            return f"{line}: {more}" if self.notation != "zh" else f"{line}：{more}"
        if key == "normal":
            link, X, Y = args
            start, mx, my, om = s.inputs
            drawn, scale = self.values[om]
            w = float(drawn) * float(scale)
            l_m = self.mm(mx, my) * self.an.scales["l"]
            return self.say("normal", y=self.lab(start), yn=self.lab(start) + self.lab(s.name),
                            XY=letter(X) + letter(Y), lXY=X + Y, X=letter(X), Y=letter(Y), i=subscript(link),
                            w=num(abs(w)), l=num(l_m), mu=num(mu), mm=num(self.mm(start, s.name)))
        if key == "coriolis":
            bar, xbar, xblock = args
            start, vbar, vblock, om = s.inputs
            drawn, scale = self.values[om]
            w = float(drawn) * float(scale)
            v_rel = self.mm(vbar, vblock) * self.an.scales["v"]
            return self.say("coriolis", y=self.lab(start), yk=self.lab(start) + self.lab(s.name),
                            lrel=xbar + xblock, i=subscript(bar), w=num(abs(w)), v=num(v_rel),
                            mu=num(mu), mm=num(self.mm(start, s.name)), sense=sense(w, self.notation))
        return ""

    def measure(self, s: Step, name: str) -> str:
        b = self.b
        q = b.quantities[name]
        names = [n for n in dict.fromkeys(self.asked) if n in b.quantities and b.quantities[n].slot == s.name]
        sym = " = ".join(symbol(n) for n in (names or [name]))
        drawn, scale = (float(x) for x in self.values[s.name])
        value = drawn * scale
        kind = q.exact[0]
        if kind in ("omega", "alpha") and not q.segment:
            return self.say("translates", link=q.exact[1], sym=sym)
        if kind == "angle":
            return self.say("angle", link=q.exact[1], sym=sym, value=num(value))
        seg = "".join(letter(x) for x in q.segment)
        unit = q.unit
        if kind in ("omega", "alpha"):
            # the rate's first input is the direction step "dir:U->V" between two diagram points
            U, _, V = s.inputs[0].removeprefix("dir:").partition("->")
            l_m = b.scales["v" if kind == "omega" else "a"] / scale
            rate = self.say("rate", sym=sym, seg=seg, mu=_SCALE_SYMBOL[q.panel], UV=letter(U) + letter(V),
                            mm=num(abs(drawn)), scale=num(b.scales[SCALE_KEYS[q.panel]]), l=num(l_m),
                            value=num(value), unit=unit)
            turn = sense(value, self.notation)
            rate += (f"（{turn}）" if self.notation == "zh" else f" ({turn})") if turn else ""
            return self.say("measure", seg=seg, mm=num(abs(drawn)), value=rate)
        formula = f"{sym} = {seg}·{_SCALE_SYMBOL[q.panel]} = {num(value)} {unit}"
        if value < 0:  # a slide's velocity or acceleration against its guide's direction
            formula += self.say("against the guide", seg=seg)
        return self.say("measure", seg=seg, mm=num(abs(drawn)), value=formula)


def symbol(name: str) -> str:
    """A quantity's name as the book writes it: omega_2 → ω₂, a_k_C2C3 → a^k_C2C3, a_CB_t → a^t_CB.

    >>> symbol("omega_2"), symbol("a_k_C2C3"), symbol("a_CB_n"), symbol("v_C"), symbol("epsilon_3"), symbol("theta_a")
    ('ω₂', 'a^k_C2C3', 'a^n_CB', 'v_C', 'ε₃', 'θ_a')
    """
    for word_, greek in (("omega_", "ω"), ("alpha_", "α"), ("epsilon_", "ε"), ("theta_", "θ")):
        if name.startswith(word_):
            link = name[len(word_):]
            return greek + (subscript(link) if link.isdigit() else "_" + link)
    for c in ("k", "r"):
        if name.startswith(f"a_{c}_"):
            return f"a^{c}_" + name[4:]
    if name.startswith("a_") and name[-2:] in ("_n", "_t"):
        return f"a^{name[-1]}_" + name[2:-2]
    return name


__all__ = ["PHRASES", "letter", "linkage_steps", "protocol", "symbol"]
