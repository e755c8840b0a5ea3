"""Mutated efficiency and balancing scenes: a finite table and its figure, or a one-line refusal."""
from __future__ import annotations

import math
import tomllib

from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.problems.efficiency.check import efficiency_figure
from graphmech.scene import parse_scene
from tests.conftest import ROOT, SCENES
from tests.mutation import mutate


def _forces_blocks() -> list[str]:
    import re

    text = (ROOT / "docs" / "scene-format.md").read_text(encoding="utf-8")
    blocks = re.findall(r"^```toml\n(.*?)^```", text, re.S | re.M)
    return [b for b in blocks if "[efficiency]" in b or "[balancing]" in b] + [
        p.read_text(encoding="utf-8") for p in sorted(SCENES.glob("*.toml"))
        if p.stem.startswith(("force.", "eff.", "thread.", "bal."))]


_values_to_try = st.one_of(st.booleans(), st.integers(-5, 400), st.floats(allow_nan=True, allow_infinity=True),
                           st.sampled_from([0, 0.0, 1e-300, 89.999999, 90, 45, -1, "forward", "V", "x", [], [0, 0],
                                            [1, 1], {}]))


@settings(max_examples=150, deadline=None)
@given(st.data())
def test_any_mutation_checks_or_is_refused_in_one_line(data):
    """Whatever a mutated efficiency or balancing scene holds: a table without NaN and its figure, or
    a refusal in one line — never an internal error."""
    from graphmech.errors import GraphmechError
    from graphmech.problems.balancing.check import analyse_balancing
    from graphmech.problems.efficiency.check import analyse_efficiency

    base = tomllib.loads(data.draw(st.sampled_from(_forces_blocks())))
    mutated = mutate(data, base, _values_to_try)
    try:
        sc = parse_scene(mutated, "fuzz.toml")
        an = analyse_efficiency(sc) if sc.kind == "efficiency" else analyse_balancing(sc) \
            if sc.kind == "balancing" else None
    except GraphmechError as err:
        assert "\n" not in str(err)
        return
    if an is None:
        return
    for row in an.rows:
        assert math.isfinite(row.graphical) and math.isfinite(row.exact) and math.isfinite(row.rel_error), row
    from graphmech.problems.balancing.check import balancing_figure
    from graphmech.render.svg import render_svg

    try:  # and its figure draws, or a stated scale that cannot draw it is refused in one line
        sheet = efficiency_figure(an, (297.0, 210.0)) if sc.kind == "efficiency" else \
            balancing_figure(an, (297.0, 210.0))
    except GraphmechError as err:
        assert "\n" not in str(err)
        return
    svg = render_svg(sheet, "gfuzz", on_warning=lambda w: None)
    assert "nan" not in svg.lower().replace("nane", "") and "inf" not in svg.lower().replace("info", "")
