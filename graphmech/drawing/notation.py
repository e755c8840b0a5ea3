"""Whose words and symbols a drawing is lettered in: English, Chinese (孙桓《机械原理》) or Russian
(the course-project page). Drawn text only — the names in a scene's ``find`` and in ``check``
never change.

A figure asks for a caption or symbol by its English key; :func:`word` gives it in the scene's
notation (``[page] notation``). A kind with words of its own passes its own table, laid out as
:data:`WORDS` is; a key missing from a table is a programming error, found by the tests that
draw every reference scene in every notation.

>>> word("velocity polygon", "zh"), word("velocity polygon", "ru"), word("M_red", "zh")
('速度多边形', 'план скоростей', 'M_{e}')
"""
from __future__ import annotations

from typing import Literal, Mapping

Notation = Literal["en", "zh", "ru"]

#: Key → (English, 中文, русский). Symbols use the lettering marks (``_{…}`` subscripts).
WORDS: Mapping[str, tuple[str, str, str]] = {
    # panels
    "kinematic diagram": ("Kinematic diagram", "机构运动简图", "кинематическая схема"),
    "mechanism": ("Mechanism", "机构运动简图", "кинематическая схема"),
    "velocity polygon": ("Velocity polygon", "速度多边形", "план скоростей"),
    "acceleration polygon": ("Acceleration polygon", "加速度多边形", "план ускорений"),
    "force polygon": ("Force polygon", "力多边形", "план сил"),
    "instant centres": ("Instant centres", "速度瞬心", "мгновенные центры скоростей"),
    "cam profile": ("Cam profile by inversion", "凸轮轮廓（反转法）", "профиль кулачка (метод обращения движения)"),
    "displacement diagram": ("Displacement diagram", "位移线图", "график перемещений"),
    "Wittenbauer diagram": ("Wittenbauer diagram", "能量指示图", "диаграмма Виттенбауэра"),
    "balancing polygon": ("Balancing polygon", "平衡矢量多边形", "план уравновешивания"),
    "structure": ("Kinematic diagram and Assur groups", "机构运动简图与杆组", "структурная схема и группы Ассура"),
    "not to scale": ("not to scale", "未按比例", "не в масштабе"),
    # symbols (FIGURES.md, notation by language)
    "M_red": ("M_{red}", "M_{e}", "M_{п}"),
    "J_red": ("J_{red}", "J_{e}", "J_{п}"),
    "M_d": ("M_{d}", "M_{ed}", "M_{д}"),
    "M_r": ("M_{r}", "M_{er}", "M_{с}"),
    "J_F": ("J_{F}", "J_{F}", "J_{м}"),
    "flywheel": ("flywheel", "飞轮", "маховик"),
    "pressure angle": ("pressure angle", "压力角", "угол давления"),
    "transmission angle": ("transmission angle", "传动角", "угол передачи"),
}

_INDEX = {"en": 0, "zh": 1, "ru": 2}


def word(key: str, notation: str = "en", table: Mapping[str, tuple[str, str, str]] = WORDS) -> str:
    """``key``'s caption or symbol in ``notation`` (``"en"``, ``"zh"``, ``"ru"``).

    Raises
    ------
    KeyError
        For a key the table lacks, or an unknown notation.
    """
    return table[key][_INDEX[notation]]
