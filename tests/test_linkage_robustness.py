"""Robustness of the linkage methods (issue 12): names, degenerate and extreme geometry, bounded
work, and how accurate the discretised cycle values say they are."""
from __future__ import annotations

import json
import re

import pytest

from tests.conftest import SCENES, assert_refused, run_cli

BLOCK = (SCENES / "kin.oscillating_block.toml").read_text()


def _rename(text: str, names: dict[str, str]) -> str:
    """The scene with its points renamed (whole names only, in strings and quantity names)."""
    pattern = re.compile(r"(?<![A-Za-z0-9])(" + "|".join(map(re.escape, names)) + r")(?![a-z0-9'])")
    return pattern.sub(lambda m: names[m.group(1)], text)


def _rows(path) -> dict[str, dict]:
    code, out, err = run_cli("check", "--json", str(path))
    assert code == 0 and err == "", err
    return {r["name"]: r for r in json.loads(out)["quantities"]}


# The construction's own points are the poles p and p′, the normal-component points n₁′, n₂′ … and
# the Coriolis points k′, k″: a point named after any of them must not meet them.
@pytest.mark.parametrize("names", [
    {"B": "P", "D": "N2", "E": "K"},
    {"B": "N1", "D": "K", "E": "P"},
    {"D": "N2'", "E": "K'"},
    {"B": "N2", "D": "N3", "E": "N1'"},
])
def test_point_names_of_the_construction_s_own_points(tmp_path, names):
    original = tmp_path / "block.toml"
    original.write_text(BLOCK)
    renamed = tmp_path / "renamed.toml"
    renamed.write_text(_rename(BLOCK, names))
    want = _rows(original)
    got = _rows(renamed)
    assert len(got) == len(want)
    for name, row in want.items():
        other = got[_rename(name, names)]
        assert other["graphical"] == row["graphical"] and other["exact"] == row["exact"]
    code, out, err = run_cli("render", str(renamed), "-o", str(tmp_path / "renamed.svg"))
    assert code == 0 and err == "", err


def test_a_segment_the_letters_name_twice_is_refused(tmp_path):
    """With a point P, 'pd' is both the pole p → d (v_D) and the image p → d (v_DP)."""
    scene = tmp_path / "p.toml"
    scene.write_text(_rename(BLOCK, {"E": "P"}))
    assert_refused(run_cli("check", str(scene), "--measured", "pd=45"), "p.toml", "v_D", "v_DP")
