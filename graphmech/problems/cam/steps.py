"""The construction protocol of a cam scene: the motion diagrams and the profile by inversion
(反转法) step by step, as the book words them, with every length drawn.

The steps are those of the check's own analysis (:func:`graphmech.problems.cam.check.analyse_cam`):
the s–δ diagram with its divisions and the ordinate at each; the base circle, the offset (or
pivot) circle, the follower turned the −ω way division by division, the displacement laid off
on each of its positions, the pitch curve, the roller circles and their envelope; then what is
read off — the pressure angle at each division, the largest, the smallest radius of curvature —
with the numbers of the very drawing the check table and the figure are made from. Only what
the scene shows or asks for is protocolled; a value read at the divisions says at how many.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from graphmech.drawing.notation import word
from graphmech.mechanisms.cam import OscillatingFollower, TranslatingFollower
from graphmech.problems.cam.check import CamAnalysis, analyse_cam
from graphmech.problems.cam.figures import DRAWN_SCALE, SYMBOLS, WORDS, kind_word
from graphmech.problems.judging import Row
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import (
    Phrases,
    num,
    phrase,
    scale,
    scale_choice,
    sense,
    text,
)

if TYPE_CHECKING:
    from graphmech.problems.cam.scene import CamScene
    from graphmech.problems.reader import Scene

#: The cam's phrases: key → (English, 中文, русский); fields in braces. 孙桓 words the inversion
#: "沿−ω方向…过各分点作偏距圆的切线…自基圆量取C₁B₁ = 11′"; the Russian books "метод обращения
#: движения", "центровой профиль", "огибающая окружностей ролика".
PHRASES: Phrases = {
    **COMMON,
    # the motion diagrams
    "diagram axes": ("choose {mus} and {muphi} and draw the axes of the {s}–{d} diagram",
                     "取{mus}、{muphi}，作{s}–{d}位移线图的坐标轴",
                     "выбираем {mus} и {muphi} и проводим оси графика {s}–{d}"),
    "segments": ("along the {d} axis lay off {parts}", "在{d}轴上依次截取{parts}", "по оси {d} откладываем {parts}"),
    "segment": ("{name} {deg}° = {mm} mm", "{name}{deg}° = {mm} mm", "{name} {deg}° = {mm} mm"),
    "divide": ("divide the {d} axis every {step}° ({mm} mm), the segments' joints among the divisions: "
               "{n} divisions, numbered 0 … {last}",
               "将{d}轴每隔{step}°（{mm} mm）等分，各段分界点亦为分点：共{n}个分点，编号0 … {last}",
               "делим ось {d} через {step}° ({mm} mm), точки стыка участков — тоже точки деления: "
               "число делений {n}, номера 0 … {last}"),
    "ordinate": ("at division {k} ({d} = {deg}°, {mmx} mm along the axis) draw the ordinate {k}′: "
                 "{sk}/{mu} = {v}/{scale} = {mm} mm ({what})",
                 "分点{k}（{d} = {deg}°，距原点{mmx} mm）：作纵坐标{k}′，{sk}/{mu} = {v}/{scale} = {mm} mm（{what}）",
                 "в точке деления {k} ({d} = {deg}°, {mmx} mm по оси) откладываем ординату {k}′: "
                 "{sk}/{mu} = {v}/{scale} = {mm} mm ({what})"),
    "curve s": ("join 0′, 1′ … {last}′ with a smooth curve: the {s}–{d} diagram",
                "将0′、1′ … {last}′连成光滑曲线，即得{s}–{d}位移线图",
                "соединяем точки 0′, 1′ … {last}′ плавной кривой: график {s}–{d}"),
    "impact rigid": ("{d} = {deg}°: the velocity jumps — a rigid impact", "{d} = {deg}°处速度突变：刚性冲击",
                     "{d} = {deg}°: скорость меняется скачком — жёсткий удар"),
    "impact soft": ("{d} = {deg}°: the acceleration jumps — a soft impact", "{d} = {deg}°处加速度突变：柔性冲击",
                    "{d} = {deg}°: ускорение меняется скачком — мягкий удар"),
    "diagram v": ("choose {mu} and draw the {v}–{d} diagram: {v} = ω·d{s}/d{d} by the law, ω = {w} rad/s",
                  "取{mu}，按运动规律作{v}–{d}速度线图：{v} = ω·d{s}/d{d}，ω = {w} rad/s",
                  "выбираем {mu} и строим по закону движения график {v}–{d}: {v} = ω·d{s}/d{d}, ω = {w} rad/s"),
    "diagram a": ("choose {mu} and draw the {a}–{d} diagram: {a} = ω²·d²{s}/d{d}² by the law",
                  "取{mu}，按运动规律作{a}–{d}加速度线图：{a} = ω²·d²{s}/d{d}²",
                  "выбираем {mu} и строим по закону движения график {a}–{d}: {a} = ω²·d²{s}/d{d}²"),
    "largest ordinate": ("the largest ordinate of the {v}–{d} diagram is at division {k}: "
                         "measure {mm} mm: {sym} = {mm} × {scale} = {value} {unit}{basis}",
                         "{v}–{d}线图的最大纵坐标在分点{k}：量得{mm} mm，{sym} = {mm} × {scale} = {value} {unit}{basis}",
                         "наибольшая ордината графика {v}–{d} — в точке деления {k}: "
                         "измеряем {mm} mm: {sym} = {mm} × {scale} = {value} {unit}{basis}"),
    "largest value": ("the largest |{v}| by the law at the divisions is at division {k}: {sym} = {value} {unit}{basis}",
                      "按运动规律，各分点中|{v}|最大在分点{k}：{sym} = {value} {unit}{basis}",
                      "наибольшее |{v}| по закону движения в точках деления — в точке {k}: {sym} = {value} {unit}{basis}"),
    "where": ("{sym} is at {d} = {value}°{basis}", "{sym}的位置为{d} = {value}°{basis}", "{sym} — при {d} = {value}°{basis}"),
    "stroke": ("measure the stroke: {mm} mm: {sym} = {mm} × {scale} = {value} {unit}",
               "量得行程{mm} mm：{sym} = {mm} × {scale} = {value} {unit}",
               "измеряем ход: {mm} mm: {sym} = {mm} × {scale} = {value} {unit}"),
    "at divisions": (" (read at {n} divisions of {step}°)", "（按{n}等分、每份{step}°读取）",
                     " (прочитано при числе делений {n}, шаг {step}°)"),
    # the profile by inversion
    "base circle": ("choose {mu}; about O draw the base circle r₀/μl = {r}/{scale} = {mm} mm",
                    "取{mu}；以O为圆心、r₀/μl = {r}/{scale} = {mm} mm为半径作基圆",
                    "выбираем {mu}; из центра O проводим основную окружность r₀/μl = {r}/{scale} = {mm} mm"),
    "offset circle": ("about O draw the offset circle e/μl = {e}/{scale} = {mm} mm; the follower's axis at the start is its "
                      "tangent at K₀ ({side} of O, ∥ the y axis); it meets the base circle at B₀, "
                      "{mmy} mm from K₀ (√(r₀² − e²))",
                      "以O为圆心、e/μl = {e}/{scale} = {mm} mm为半径作偏距圆；推杆导路的起始位置为偏距圆在K₀处的切线"
                      "（在O的{side}，∥ y轴），与基圆交于B₀，K₀B₀ = √(r₀² − e²) = {mmy} mm",
                      "из O проводим окружность смещения e/μl = {e}/{scale} = {mm} mm; ось толкателя в начальном "
                      "положении — касательная к ней в точке K₀ ({side} от O, ∥ оси y); она пересекает основную "
                      "окружность в точке B₀, K₀B₀ = √(r₀² − e²) = {mmy} mm"),
    "right": ("right", "右侧", "справа"),
    "left": ("left", "左侧", "слева"),
    "centred axis": ("the follower's axis at the start is the y axis through O; it meets the base circle at B₀",
                     "对心推杆导路的起始位置为过O的y轴，与基圆交于B₀",
                     "ось толкателя в начальном положении — ось y через O; она пересекает основную окружность в точке B₀"),
    "pivot circle": ("about O draw the circle of the pivot, l_OA/μl = {a}/{scale} = {mm} mm; the pivot A₀ on it at "
                     "x = {mm} mm", "以O为圆心、l_OA/μl = {a}/{scale} = {mm} mm为半径作摆杆转轴圆，起始转轴A₀在x = {mm} mm处",
                     "из O проводим окружность центров качания l_OA/μl = {a}/{scale} = {mm} mm; ось коромысла A₀ — "
                     "на ней при x = {mm} mm"),
    "start arm": ("an arc about A₀ with radius A₀B₀ = l_AB/μl = {l}/{scale} = {mm} mm meets the base circle at B₀: "
                  "ψ₀ = ∠OA₀B₀ = {psi0}°",
                  "以A₀为圆心、A₀B₀ = l_AB/μl = {l}/{scale} = {mm} mm为半径作弧，与基圆交于B₀：ψ₀ = ∠OA₀B₀ = {psi0}°",
                  "из A₀ радиусом A₀B₀ = l_AB/μl = {l}/{scale} = {mm} mm проводим дугу до основной окружности: B₀, "
                  "ψ₀ = ∠OA₀B₀ = {psi0}°"),
    "start face": ("the face at the start: the line through A₀ tangent to the base circle, ψ₀ = arcsin(r₀/l_OA) = {psi0}°",
                   "起始位置的平底：过A₀与基圆相切的直线，ψ₀ = arcsin(r₀/l_OA) = {psi0}°",
                   "тарелка в начальном положении — прямая через A₀, касательная к основной окружности, "
                   "ψ₀ = arcsin(r₀/l_OA) = {psi0}°"),
    "invert": ("the cam turns {sense}: keep it still and turn the follower the opposite way, −ω ({opposite})",
               "凸轮{sense}转动：令凸轮静止，使推杆沿−ω方向（{opposite}）反转",
               "кулачок вращается {sense}: по методу обращения движения останавливаем кулачок и поворачиваем "
               "толкатель в обратную сторону, −ω ({opposite})"),
    "divide offset": ("from K₀ divide the offset circle {opposite} at the divisions' angles {d}ₖ: K₁ … K{last}; the "
                      "tangent at Kₖ is the follower's axis in position k; it meets the base circle at Cₖ",
                      "自K₀沿−ω方向（{opposite}）按各分点的{d}ₖ等分偏距圆，得K₁ … K{last}；过Kₖ作偏距圆的切线，即反转后"
                      "推杆导路的位置k，与基圆交于Cₖ",
                      "от K₀ делим окружность смещения {opposite} на углы {d}ₖ точек деления: K₁ … K{last}; касательная "
                      "в Kₖ — ось толкателя в положении k; она пересекает основную окружность в точке Cₖ"),
    "divide rays": ("from OB₀ draw rays from O {opposite} at the divisions' angles {d}ₖ: the follower's axis in "
                    "position k; it meets the base circle at Cₖ",
                    "自OB₀沿−ω方向（{opposite}）按各分点的{d}ₖ作射线，即反转后推杆导路的位置k，与基圆交于Cₖ",
                    "от OB₀ проводим лучи {opposite} под углами {d}ₖ точек деления: ось толкателя в положении k; "
                    "она пересекает основную окружность в точке Cₖ"),
    "divide pivot": ("from A₀ divide the pivot circle {opposite} at the divisions' angles {d}ₖ: A₁ … A{last}, the "
                     "pivot in position k", "自A₀沿−ω方向（{opposite}）按各分点的{d}ₖ等分转轴圆，得A₁ … A{last}，即反转后"
                     "摆杆转轴的位置k",
                     "от A₀ делим окружность центров качания {opposite} на углы {d}ₖ: A₁ … A{last} — ось коромысла "
                     "в положении k"),
    "lay off": ("position {k} ({d} = {deg}°): on axis {k} lay off from the base circle C{k}B{k} = {sk}/μl = {v}/{scale} = "
                "{mm} mm: B{k} (OB{k} = {r} mm)",
                "位置{k}（{d} = {deg}°）：在导路{k}上自基圆量取C{k}B{k} = {sk}/μl = {v}/{scale} = {mm} mm，得B{k}"
                "（OB{k} = {r} mm）",
                "положение {k} ({d} = {deg}°): на оси {k} откладываем от основной окружности C{k}B{k} = {sk}/μl = "
                "{v}/{scale} = {mm} mm: B{k} (OB{k} = {r} mm)"),
    "face here": ("; through B{k} draw the face ⟂ axis {k}", "；过B{k}作导路{k}的垂线，即平底", "; через B{k} проводим тарелку ⟂ оси {k}"),
    "swing arm": ("position {k} ({d} = {deg}°): at A{k} lay off ∠OA{k}B{k} = ψ₀ + {sk} = {psi0} + {v} = {angle}° "
                  "({turn} from A{k}O) and A{k}B{k} = {mm} mm: B{k} (OB{k} = {r} mm)",
                  "位置{k}（{d} = {deg}°）：在A{k}处自A{k}O{turn}量取∠OA{k}B{k} = ψ₀ + {sk} = {psi0} + {v} = {angle}°，"
                  "A{k}B{k} = {mm} mm，得B{k}（OB{k} = {r} mm）",
                  "положение {k} ({d} = {deg}°): в A{k} откладываем ∠OA{k}B{k} = ψ₀ + {sk} = {psi0} + {v} = {angle}° "
                  "({turn} от A{k}O) и A{k}B{k} = {mm} mm: B{k} (OB{k} = {r} mm)"),
    "swing face": ("position {k} ({d} = {deg}°): through A{k} draw the face at ψ₀ + {sk} = {psi0} + {v} = {angle}° "
                   "({turn} from A{k}O); B{k} = the foot of the perpendicular from O on it (OB{k} = {r} mm)",
                   "位置{k}（{d} = {deg}°）：过A{k}自A{k}O{turn}转ψ₀ + {sk} = {psi0} + {v} = {angle}°作平底，"
                   "自O作其垂线，垂足为B{k}（OB{k} = {r} mm）",
                   "положение {k} ({d} = {deg}°): через A{k} проводим тарелку под углом ψ₀ + {sk} = {psi0} + {v} = "
                   "{angle}° ({turn} от A{k}O); B{k} — основание перпендикуляра из O (OB{k} = {r} mm)"),
    "profile knife": ("join B₀, B₁ … B{last} with a smooth curve: the cam's profile",
                      "将B₀、B₁ … B{last}连成光滑曲线，即得凸轮廓线",
                      "соединяем B₀, B₁ … B{last} плавной кривой: профиль кулачка"),
    "profile pitch": ("join B₀, B₁ … B{last} with a smooth curve: the pitch curve (theoretical profile)",
                      "将B₀、B₁ … B{last}连成光滑曲线，即得理论廓线",
                      "соединяем B₀, B₁ … B{last} плавной кривой: центровой (теоретический) профиль"),
    "rollers": ("about each Bₖ draw the roller circle r_r/μl = {r}/{scale} = {mm} mm; the curve touching them all "
                "inside (their envelope) is the actual profile",
                "以理论廓线上各点Bₖ为圆心、r_r/μl = {r}/{scale} = {mm} mm为半径作一系列滚子圆，其内包络线即为凸轮的实际廓线",
                "из точек Bₖ проводим окружности ролика r_r/μl = {r}/{scale} = {mm} mm; их внутренняя огибающая — "
                "действительный (рабочий) профиль"),
    "faces envelope": ("the curve touching all the faces (their envelope) is the actual profile",
                       "作各平底位置的包络线，即得凸轮的实际廓线",
                       "огибающая всех положений тарелки — действительный (рабочий) профиль"),
    # what is read off the profile
    "pressure angles": ("at each Bₖ draw the normal to the pitch curve (⟂ the chord Bₖ₋₁Bₖ₊₁) and the direction of "
                        "Bₖ's motion ({along}); the pressure angle αₖ is the acute angle between them",
                        "在各点Bₖ作理论廓线的法线（⟂ 弦Bₖ₋₁Bₖ₊₁）及Bₖ的运动方向（{along}），两者所夹锐角即压力角αₖ",
                        "в каждой точке Bₖ проводим нормаль к центровому профилю (⟂ хорде Bₖ₋₁Bₖ₊₁) и направление "
                        "движения Bₖ ({along}); угол давления αₖ — острый угол между ними"),
    "along axis": ("along axis k", "沿导路k", "по оси k"),
    "along arc": ("⟂ AₖBₖ", "⟂ AₖBₖ", "⟂ AₖBₖ"),
    "alpha k": ("position {k} ({d} = {deg}°): measure {ak} = {value}°", "位置{k}（{d} = {deg}°）：量得{ak} = {value}°",
                "положение {k} ({d} = {deg}°): измеряем {ak} = {value}°"),
    "alpha flat": ("a flat face's normal is the direction of the follower's motion: α = 0 in every position",
                   "平底推杆的平底法线即推杆运动方向：各位置压力角α = 0",
                   "нормаль к тарелке совпадает с направлением движения толкателя: α = 0 во всех положениях"),
    "alpha max": ("the largest: α_max = {value}° in position {k} ({d} = {deg}°){basis}",
                  "最大压力角α_max = {value}°，在位置{k}（{d} = {deg}°）{basis}",
                  "наибольший: α_max = {value}° в положении {k} ({d} = {deg}°){basis}"),
    "alpha permissible": ("α_max = {value}° {cmp} [α] = {perm}°", "α_max = {value}° {cmp} [α] = {perm}°",
                          "α_max = {value}° {cmp} [α] = {perm}°"),
    "rho min": ("the circle through B{j0}, B{j}, B{j1} is the pitch curve's smallest convex one (its corners left out): "
                "measure its radius {mm} mm: ρ_min = {mm} × {scale} = {value} m, at {d} = {deg}°{basis}",
                "过B{j0}、B{j}、B{j1}三点的圆是理论廓线上最小的外凸曲率圆（尖点除外）：量得其半径{mm} mm，"
                "ρ_min = {mm} × {scale} = {value} m，在{d} = {deg}°处{basis}",
                "окружность через B{j0}, B{j}, B{j1} — наименьшая выпуклая окружность кривизны центрового профиля "
                "(без изломов): измеряем её радиус {mm} mm: ρ_min = {mm} × {scale} = {value} m, при {d} = {deg}°{basis}"),
    "rho min flat": ("the circle through three consecutive corners of the envelope at {d} = {deg}° is its smallest: "
                     "measure its radius {mm} mm: ρ_a,min = {mm} × {scale} = {value} m{basis}",
                     "包络线上{d} = {deg}°处相邻三角点所作的圆最小：量得其半径{mm} mm，ρ_a,min = {mm} × {scale} = {value} m{basis}",
                     "окружность через три соседние вершины огибающей при {d} = {deg}° — наименьшая: измеряем её "
                     "радиус {mm} mm: ρ_a,min = {mm} × {scale} = {value} m{basis}"),
    "rho actual": ("the actual profile's smallest radius: ρ_min − r_r = {mm} mm: ρ_a,min = {mm} × {scale} = {value} m{basis}",
                   "实际廓线的最小曲率半径：ρ_min − r_r = {mm} mm，ρ_a,min = {mm} × {scale} = {value} m{basis}",
                   "наименьший радиус рабочего профиля: ρ_min − r_r = {mm} mm: ρ_a,min = {mm} × {scale} = {value} m{basis}"),
    "undercut": ("r_r = {rr} mm ≥ ρ_min = {rho} mm: the actual profile undercuts (the follower's motion is distorted)",
                 "r_r = {rr} mm ≥ ρ_min = {rho} mm：实际廓线出现运动失真",
                 "r_r = {rr} mm ≥ ρ_min = {rho} mm: рабочий профиль подрезан (движение толкателя искажается)"),
    "deviation": ("laid over the exact profile, the drawn one departs from it by at most {mm} mm: {mm} × {scale} = "
                  "{value} m{basis}",
                  "与精确廓线相比，所作廓线的最大偏差为{mm} mm：{mm} × {scale} = {value} m{basis}",
                  "наложенный на точный профиль, построенный отходит от него не более чем на {mm} mm: {mm} × {scale} = "
                  "{value} m{basis}"),
    "r0 min": ("redraw with trial base radii until α_max = [α] = {perm}°: r₀ = {mm} mm: r₀,min = {mm} × {scale} = "
               "{value} m{basis}",
               "试取不同的基圆半径重新作图，直至α_max = [α] = {perm}°：r₀ = {mm} mm，r₀,min = {mm} × {scale} = {value} m{basis}",
               "перестраиваем при пробных радиусах основной окружности, пока α_max = [α] = {perm}°: r₀ = {mm} mm: "
               "r₀,min = {mm} × {scale} = {value} m{basis}"),
    # the laws' names (孙桓; the Russian books' законы движения)
    "uniform": ("uniform motion", "等速运动规律", "закон постоянной скорости"),
    "parabolic": ("constant acceleration and deceleration", "等加速等减速运动规律", "параболический закон"),
    "cosine": ("cosine acceleration", "余弦加速度运动规律", "косинусоидальный закон"),
    "sine": ("sine acceleration", "正弦加速度运动规律", "синусоидальный закон"),
    # the working profile's coordinates as handed in, and the follower's forces with friction (000 力 3)
    "coordinates": ("tabulate the working profile's point at each of the {n} divisions in the cam frame (O at the "
                    "origin, {frame}): x, y and the polar r = √(x² + y²), θ from +x counter-clockwise; division 0: "
                    "x = {x} mm, y = {y} mm, r = {r} mm, θ = {t}°",
                    "列出实际廓线在{n}个分点处的坐标（凸轮坐标系，O为原点，{frame}）：x、y及极坐标r = √(x² + y²)、θ"
                    "（自+x逆时针量）；分点0：x = {x} mm，y = {y} mm，r = {r} mm，θ = {t}°",
                    "составляем таблицу координат действительного профиля в {n} точках деления в системе кулачка "
                    "(O — начало, {frame}): x, y и полярные r = √(x² + y²), θ от +x против часовой; точка 0: "
                    "x = {x} mm, y = {y} mm, r = {r} mm, θ = {t}°"),
    "frame follower": ("the follower along +y at δ = 0", "δ = 0时推杆沿+y", "толкатель по +y при δ = 0"),
    "frame rocker": ("the rocker's pivot A on +x", "摆杆转轴A在+x上", "ось коромысла A на +x"),
    "forces": ("turn the cam to δ = {deg}° and draw the follower's free body: Q = {Q} N down its axis; R₁₂ at K along "
               "the common normal n–n leant by φ = {phi}° against the sliding; the guide's R′₃₂ at B₁ and R″₃₂ at B₂ "
               "leant from its normal by φ′ = atan f = {phi2}°; Culmann: Q and R₁₂ meet at P, R′₃₂ and R″₃₂ at {S}; "
               "choose {mu}, lay off Q = {q} mm, draw R₁₂ from its end and the resultant ∥ {PS} from its start, "
               "split that along R′₃₂ and R″₃₂: the force polygon; measure R₁₂ = {r} mm = {R} N, "
               "R′₃₂ = {r1} mm = {R1} N, R″₃₂ = {r2} mm = {R2} N; M₁ = R₁₂ × the lever of R₁₂ about O = {M} N·m",
               "将凸轮转至δ = {deg}°，作推杆的受力图：载荷Q = {Q} N沿其轴线向下；凸轮反力R₁₂作用于K，沿公法线n–n"
               "逆滑动方向偏摩擦角φ = {phi}°；导路反力R′₃₂作用于B₁、R″₃₂作用于B₂，自导路法线偏φ′ = arctan f = {phi2}°；"
               "Culmann法：Q与R₁₂交于P，R′₃₂与R″₃₂交于{S}；取{mu}，截取Q = {q} mm，自其末端作R₁₂，自其始端作∥ {PS}的"
               "合力，再沿R′₃₂、R″₃₂分解：即力多边形；量得R₁₂ = {r} mm = {R} N，R′₃₂ = {r1} mm = {R1} N，"
               "R″₃₂ = {r2} mm = {R2} N；M₁ = R₁₂ × 其对O的力臂 = {M} N·m",
               "поворачиваем кулачок на δ = {deg}° и изображаем силы, действующие на толкатель: Q = {Q} N вдоль его "
               "оси вниз; R₁₂ в точке K по общей нормали n–n, отклонённая на угол трения φ = {phi}° против "
               "скольжения; реакции направляющей R′₃₂ в B₁ и R″₃₂ в B₂, отклонённые от её нормали на φ′ = arctg f = "
               "{phi2}°; по Кульману Q и R₁₂ пересекаются в P, R′₃₂ и R″₃₂ — в {S}; выбираем {mu}, откладываем "
               "Q = {q} mm, из его конца проводим R₁₂, из начала — равнодействующую ∥ {PS} и раскладываем её по "
               "R′₃₂ и R″₃₂: многоугольник сил; измеряем R₁₂ = {r} mm = {R} N, R′₃₂ = {r1} mm = {R1} N, "
               "R″₃₂ = {r2} mm = {R2} N; M₁ = R₁₂ × плечо R₁₂ относительно O = {M} N·m"),
    "parallel": ("(parallel: split by the lever rule)", "（二者平行：按杠杆原理分解）", "(параллельны: делим по правилу рычага)"),
    "poly345": ("3-4-5 polynomial", "3-4-5多项式运动规律", "полиномиальный закон 3-4-5"),
    "table": ("the given table", "给定表格", "заданная таблица"),
}


def cam_steps(scene: Scene[CamScene]) -> list[str]:
    """The protocol of a cam scene, one line per step (not numbered)."""
    return protocol(analyse_cam(scene, ()))


def protocol(an: CamAnalysis) -> list[str]:
    """The protocol of an analysed cam scene: the diagrams it draws, then the profile by inversion
    and what is read off it."""
    w = _Words(an)
    out = w.displacement() if w.wants("displacement") else []
    for q in ("v", "a", "j"):
        out += w.derivative(q)
    if an.drawn is not None:
        out += w.inversion() + w.readings()
    if an.scene.problem.coordinates and an.drawn is not None:
        out.append(w.coordinates())
    if an.scene.problem.forces is not None:
        out.append(w.forces())
    return out


class _Words:
    """The words of a cam's steps, with the numbers of its analysis."""

    def __init__(self, an: CamAnalysis) -> None:
        self.an, self.cam = an, an.cam
        self.notation = getattr(an.scene.page, "notation", "en")
        self.rows: dict[str, Row] = {r.name: r for r in an.rows}
        self.angular = isinstance(an.cam.follower, OscillatingFollower)
        self.d = word("cam angle", self.notation, WORDS)
        self.n = round(math.tau / an.step)
        self.last = len(an.delta) - 1

    # ------------------------------------------------------------------ helpers
    def say(self, key: str, **fields: str) -> str:
        return phrase(key, self.notation, PHRASES, **fields)

    def wants(self, panel: str) -> bool:
        """Whether the s–δ (or v–δ, a–δ) diagram is drawn: shown, or needed by what is asked."""
        find = [n.split("@")[0] for n in self.an.scene.find]
        if panel == "displacement":
            return panel in self.an.scene.show or self.an.drawn is not None or "s" in find or "h" in find
        q = {"velocity": "v", "acceleration": "a"}[panel]
        return panel in self.an.scene.show or any(n.startswith(f"{q}_max") for n in find)

    def mu(self, key: str) -> str:
        """A scale as chosen: ``μs = 0.0005 m/mm (as the scene gives it)``; an oscillating
        follower's ordinates are angles (μψ, μω, με)."""
        sym = DRAWN_SCALE[key][int(self.angular)] if key in DRAWN_SCALE else key
        return scale_choice(sym, self.an.scales[key], key in self.an.stated, self.notation)

    def mu_value(self, key: str) -> str:
        """A scale's value as a factor, ``0.0005`` (degrees per mm for an angle)."""
        v = self.an.scales[key]
        return num(math.degrees(v) if key == "phi" or (key == "s" and self.angular) else v)

    def sym(self, panel: str) -> str:
        return text(SYMBOLS[panel][int(self.angular)])

    def basis(self, name: str) -> str:
        """Where the check says a row is read at N divisions, so does the protocol."""
        row = self.rows.get(name)
        if row is None or not row.basis:
            return ""
        return self.say("at divisions", n=str(self.n), step=num(math.degrees(self.an.step)))

    def at(self, k: int) -> str:
        """The displacement at division ``k``: s₃, or ψ(3) for a rocker (whose ψ₀ is its start angle)."""
        return f"ψ({k})" if self.angular else text(f"s_{{{k}}}")

    def deg(self, k: int) -> str:
        return num(math.degrees(float(self.an.delta[k])))

    def segment_of(self, k: int) -> int:
        """The segment of the program division ``k`` lies in (the one starting at a joint)."""
        starts = np.concatenate(([0.0], np.cumsum([s.angle for s in self.cam.program.segments])))
        return int(np.searchsorted(starts, float(self.an.delta[k]) + 1e-12, side="right") - 1)

    def what(self, k: int) -> str:
        i = self.segment_of(k)
        seg = self.cam.program.segments[i]
        name = word(kind_word(self.cam, i), self.notation, WORDS)
        if seg.law is None:
            return name
        law = self.say(seg.law)
        return f"{name}，{law}" if self.notation == "zh" else f"{name}, {law}"

    # ------------------------------------------------------------------ the diagrams
    def displacement(self) -> list[str]:
        an, cam = self.an, self.cam
        mu_phi = an.scales["phi"]
        s = self.sym("displacement")
        out = [self.say("diagram axes", mus=self.mu("s"), muphi=self.mu("phi"), s=s, d=self.d)]
        parts = [self.say("segment", name=word(kind_word(cam, i), self.notation, WORDS),
                          deg=num(math.degrees(seg.angle)), mm=num(seg.angle / mu_phi))
                 for i, seg in enumerate(cam.program.segments)]
        out.append(self.say("segments", d=self.d, parts=("、" if self.notation == "zh" else ", ").join(parts)))
        out.append(self.say("divide", d=self.d, step=num(math.degrees(an.step)), mm=num(an.step / mu_phi),
                            n=str(len(an.delta)), last=str(self.last)))
        mu_s = an.scales["s"]
        for k, d in enumerate(an.delta):
            v = math.degrees(float(an.s[k])) if self.angular else float(an.s[k])
            out.append(self.say("ordinate", k=str(k), d=self.d, deg=self.deg(k), mmx=num(float(d) / mu_phi), sk=self.at(k),
                                mu=scale(DRAWN_SCALE["s"][int(self.angular)], mu_s).split(" = ")[0], v=num(v),
                                scale=self.mu_value("s"), mm=num(float(an.s[k]) / mu_s), what=self.what(k)))
        out.append(self.say("curve s", last=str(self.last), s=s, d=self.d))
        for i in an.impacts:
            out.append(self.say(f"impact {i['kind']}", d=self.d, deg=num(i["angle_deg"])))
        if "h" in self.rows:
            r = self.rows["h"]
            if self.angular:  # drawn at μψ in degrees per mm, the check's value in degrees: said in rad too
                out.append(self.say("stroke", mm=num(r.drawn_mm or 0.0), sym="ψ_max", scale=num(r.scale),
                                    value=f"{num(r.graphical)}° = {num(math.radians(r.graphical))}", unit="rad"))
            else:
                out.append(self.say("stroke", mm=num(r.drawn_mm or 0.0), sym="h", scale=num(r.scale),
                                    value=num(r.graphical), unit=r.unit))
        return out

    def derivative(self, q: str) -> list[str]:
        """The v–δ or a–δ diagram (drawn when shown or asked for) and its maximum read off it;
        the jerk has no diagram: its maximum is read off the law at the divisions."""
        panel = {"v": "velocity", "a": "acceleration", "j": ""}[q]
        out: list[str] = []
        if q != "j" and self.wants(panel):
            fields = {"mu": self.mu(q), "d": self.d, "s": self.sym("displacement"), "w": num(self.cam.omega)}
            fields["v" if q == "v" else "a"] = self.sym(panel)
            out.append(self.say(f"diagram {q}", **fields))
        row = self.rows.get(f"{q}_max")
        if row is not None:
            k = self._division_of_max(q)
            sym = f"{q}_max"
            if q != "j" and row.drawn_mm is not None:
                out.append(self.say("largest ordinate", v=self.sym(panel), d=self.d, k=str(k), mm=num(row.drawn_mm),
                                    sym=sym, scale=num(row.scale), value=num(row.graphical), unit=row.unit,
                                    basis=self.basis(row.name)))
            else:
                out.append(self.say("largest value", v=q, k=str(k), sym=sym, value=num(row.graphical), unit=row.unit,
                                    basis=self.basis(row.name)))
        at = self.rows.get(f"{q}_max_at")
        if at is not None:
            out.append(self.say("where", sym=f"{q}_max", d=self.d, value=num(at.graphical), basis=self.basis(at.name)))
        return out

    def _division_of_max(self, q: str) -> int:
        """The division the check reads the maximum at (the first where it is reached)."""
        from graphmech.mechanisms.motion import displacement

        order = {"v": 1, "a": 2, "j": 3}[q]
        vals = np.abs(displacement(self.cam.program, self.an.delta, order))
        return int(np.flatnonzero(vals >= vals.max() * (1 - 1e-9))[0])

    # ------------------------------------------------------------------ the profile
    def inversion(self) -> list[str]:
        an, cam, f = self.an, self.cam, self.cam.follower
        drawn = an.profile
        mu = an.scales["l"]
        sc = num(mu)
        out = [self.say("base circle", mu=self.mu("l"), r=num(cam.base_radius), scale=sc, mm=num(cam.base_radius / mu))]
        opposite = sense(-float(cam.rotation), self.notation)
        radius = np.hypot(*drawn.pitch.T) / mu
        if isinstance(f, TranslatingFollower):
            e = f.offset
            if e:
                out.append(self.say("offset circle", e=num(abs(e)), scale=sc, mm=num(abs(e) / mu),
                                    side=self.say("right" if e > 0 else "left"),
                                    mmy=num(math.sqrt(cam.base_radius ** 2 - e * e) / mu)))
            else:
                out.append(self.say("centred axis"))
            out.append(self.say("invert", sense=sense(float(cam.rotation), self.notation), opposite=opposite))
            out.append(self.say("divide offset" if e else "divide rays", opposite=opposite, d=self.d,
                                last=text(f"_{{{self.last}}}")))
            for k in range(len(an.delta)):
                line = self.say("lay off", k=str(k), d=self.d, deg=self.deg(k),
                                sk=self.at(k), v=num(float(an.s[k])), scale=sc,
                                mm=num(float(an.s[k]) / mu), r=num(float(radius[k])))
                out.append(self._subscripted(line, k) + (self._subscripted(self.say("face here", k=str(k)), k)
                                                          if f.contact == "flat" else ""))
        else:
            a = f.pivot_distance
            out.append(self.say("pivot circle", a=num(a), scale=sc, mm=num(a / mu)))
            if f.contact == "flat":
                psi0 = math.degrees(math.asin(cam.base_radius / a))
                out.append(self.say("start face", psi0=num(psi0)))
            else:
                psi0 = math.degrees(math.acos((a * a + f.arm ** 2 - cam.base_radius ** 2) / (2.0 * a * f.arm)))
                out.append(self.say("start arm", l=num(f.arm), scale=sc, mm=num(f.arm / mu), psi0=num(psi0)))
            out.append(self.say("invert", sense=sense(float(cam.rotation), self.notation), opposite=opposite))
            out.append(self.say("divide pivot", opposite=opposite, d=self.d, last=text(f"_{{{self.last}}}")))
            turn = sense(-float(cam.rotation) if f.sense == "opposite" else float(cam.rotation), self.notation)
            for k in range(len(an.delta)):
                v = math.degrees(float(an.s[k]))
                line = self.say("swing face" if f.contact == "flat" else "swing arm", k=str(k), d=self.d, deg=self.deg(k),
                                sk=self.at(k), psi0=num(psi0), v=num(v), angle=num(psi0 + v), turn=turn,
                                mm=num(f.arm / mu), r=num(float(radius[k])))
                out.append(self._subscripted(line, k))
        last = str(self.last)
        if f.contact == "knife":
            out.append(self.say("profile knife", last=text(f"_{{{last}}}")))
        else:
            out.append(self.say("profile pitch", last=text(f"_{{{last}}}")))
            if f.contact == "roller":
                out.append(self.say("rollers", r=num(f.roller_radius), scale=sc, mm=num(f.roller_radius / mu)))
            else:
                out.append(self.say("faces envelope"))
        return out

    @staticmethod
    def _subscripted(line: str, k: int) -> str:
        """Point letters with their division as a subscript, as the drawing writes them: B12 → B₁₂."""
        sub = text(f"_{{{k}}}")
        for letter in ("B", "C", "A"):
            line = line.replace(f"{letter}{k}", f"{letter}{sub}")
        return line

    def coordinates(self) -> str:
        """The working profile's table as handed in: one line, with its first row."""
        rows = self.an.divisions
        first = rows[0]
        mm = ["—" if first[k] is None else num(first[k] * 1e3) for k in ("x", "y", "r")]
        return self.say("coordinates", n=str(len(rows)), x=mm[0], y=mm[1], r=mm[2],
                        t="—" if first["theta_deg"] is None else num(first["theta_deg"]),
                        frame=self.say("frame rocker" if self.angular else "frame follower"))

    def forces(self) -> str:
        """The follower's free body and its force polygon with friction, one line with the lengths drawn."""
        from graphmech.problems.cam.forces import force_polygon, force_rows

        data = self.an.scene.problem.forces
        assert data is not None
        mu = self.an.scales["F"]
        poly = force_polygon(self.cam, data, mu)
        rows = force_rows(self.cam, data, mu, ["R_K", "R_B1", "R_B2", "M_1"])
        crossing = poly["S"] is not None
        return self.say("forces", deg=num(math.degrees(data.at)), Q=num(data.load), phi=num(math.degrees(data.phi)),
                        phi2=num(math.degrees(math.atan(data.f))), S="S" if crossing else self.say("parallel"),
                        PS="PS" if crossing else "R′₃₂", mu=self.mu("F"), q=num(data.load / mu),
                        r=num(rows["R_K"].drawn_mm or 0.0), R=num(rows["R_K"].graphical),
                        r1=num(rows["R_B1"].drawn_mm or 0.0), R1=num(rows["R_B1"].graphical),
                        r2=num(rows["R_B2"].drawn_mm or 0.0), R2=num(rows["R_B2"].graphical),
                        M=num(rows["M_1"].graphical))

    def readings(self) -> list[str]:
        an, cam, f = self.an, self.cam, self.cam.follower
        drawn, rows = an.profile, self.rows
        mu = an.scales["l"]
        out: list[str] = []
        asks_alpha = any(n in rows for n in ("alpha_max", "alpha_max_at")) or any(n.startswith("alpha@") for n in rows)
        if asks_alpha:
            if f.contact == "flat":
                out.append(self.say("alpha flat"))
            else:
                along = self.say("along arc" if self.angular else "along axis")
                out.append(self.say("pressure angles", along=along))
                for k in range(len(an.delta)):
                    out.append(self.say("alpha k", k=str(k), ak=text(f"α_{{{k}}}"), d=self.d, deg=self.deg(k),
                                        value=num(math.degrees(float(drawn.pressure_angle[k])))))
            if "alpha_max" in rows or "alpha_max_at" in rows:
                rd = an.reading
                k = int(np.argmin(np.abs((an.delta - rd.alpha_max_at + math.pi) % math.tau - math.pi)))
                name = "alpha_max" if "alpha_max" in rows else "alpha_max_at"
                out.append(self.say("alpha max", value=num(math.degrees(rd.alpha_max)), k=str(k), d=self.d,
                                    deg=num(math.degrees(rd.alpha_max_at)), basis=self.basis(name)))
                if cam.alpha_permissible is not None and f.contact != "flat":
                    perm = math.degrees(cam.alpha_permissible)
                    amax = math.degrees(rd.alpha_max)
                    out.append(self.say("alpha permissible", value=num(amax), perm=num(perm),
                                        cmp="≤" if amax <= perm else ">"))
        if "rho_min_pitch" in rows or "rho_min_pitch_at" in rows or "rho_min_actual" in rows:
            rd = an.reading
            j = int(np.argmin(np.abs((an.delta - rd.rho_min_at + math.pi) % math.tau - math.pi)))
            n = len(an.delta)
            if f.contact == "flat":
                r = rows.get("rho_min_actual")
                if r is not None:
                    out.append(self.say("rho min flat", d=self.d, deg=num(math.degrees(rd.rho_min_at)),
                                        mm=num(r.drawn_mm or 0.0), scale=num(r.scale), value=num(r.graphical),
                                        basis=self.basis(r.name)))
            else:
                name = "rho_min_pitch" if "rho_min_pitch" in rows else next(
                    x for x in ("rho_min_pitch_at", "rho_min_actual") if x in rows)
                line = self.say("rho min", j0=str((j - 1) % n), j=str(j), j1=str((j + 1) % n), mm=num(rd.rho_min / mu),
                                scale=num(mu), value=num(rd.rho_min), d=self.d, deg=num(math.degrees(rd.rho_min_at)),
                                basis=self.basis(name))
                for i in ((j - 1) % n, j, (j + 1) % n):
                    line = self._subscripted(line, i)
                out.append(line)
                r = rows.get("rho_min_actual")
                if r is not None and f.contact == "roller":
                    out.append(self.say("rho actual", mm=num(r.drawn_mm or 0.0), scale=num(r.scale), value=num(r.graphical),
                                        basis=self.basis(r.name)))
                if rd.undercut:
                    out.append(self.say("undercut", rr=num(f.roller_radius / mu), rho=num(rd.rho_min / mu)))
        r = rows.get("profile_deviation")
        if r is not None:
            out.append(self.say("deviation", mm=num(r.drawn_mm or 0.0), scale=num(r.scale), value=num(r.graphical),
                                basis=self.basis(r.name)))
        r = rows.get("r0_min")
        if r is not None and cam.alpha_permissible is not None:
            out.append(self.say("r0 min", perm=num(math.degrees(cam.alpha_permissible)), mm=num(r.drawn_mm or 0.0),
                                scale=num(r.scale), value=num(r.graphical), basis=self.basis(r.name)))
        return out


__all__ = ["PHRASES", "cam_steps", "protocol"]
