"""The README's figure shows what wtvib draws today (it no longer matched `make
demo`'s output). `make docs-images` redraws it; this test fails when it is stale."""

import io

import numpy as np
from PIL import Image

from tests.conftest import ROOT, TURBINES
from wtvib import audit, spec
from wtvib.outputs.plots import png_bytes
from wtvib.outputs.plots.campbell import campbell_plot


def _pixels(data: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(data)).convert("RGB"), dtype=np.int16)


def test_the_readme_figure_is_what_check_draws_today():
    committed = _pixels((ROOT / "docs" / "wka-60.campbell.png").read_bytes())
    report = audit.run(spec.load(TURBINES / "wka-60.yaml"))
    fresh = _pixels(png_bytes(campbell_plot(report)))
    assert committed.shape == fresh.shape, "docs/wka-60.campbell.png is stale: make docs-images"
    # the same picture, up to the last bit of anti-aliasing a font library may differ by
    differ = np.mean(np.abs(committed - fresh).max(axis=2) > 32)
    assert differ < 0.002, f"{differ:.2%} of the pixels differ: make docs-images"
