"""The sheet of a given cam: the inversion panel and the s–δ diagram are drawn."""
from __future__ import annotations

from pathlib import Path

from tests.conftest import ROOT, run_cli


def test_render_draws_both_panels(tmp_path: Path) -> None:
    out = tmp_path / "c.svg"
    code, _, err = run_cli("render", str(ROOT / "figures/scenes/cam.eccentric_disc_oscillating.toml"), "-o", str(out))
    assert code == 0, err
    svg = out.read_text()
    assert "Cam profile by inversion" in svg and "ψ–δ" in svg
    assert ">rise " in svg and ">return " in svg  # the rise and the return named under the δ axis
