"""#42 item 23: what a new user met in two hours, each small."""

from __future__ import annotations

from pathlib import Path

import pytest

from conftest import assert_usage_error, run_taucli

ROOT = Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]


@pytest.mark.parametrize("page", PAGES, ids=[page.name for page in PAGES])
def test_every_code_fence_of_the_docs_is_closed_before_the_next_opens(page):
    """A fence opened with a language (```console) inside an open block is a broken page: the
    spin-down page's --work example sat inside the band brake's block."""
    opened = None
    for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), start=1):
        if not line.startswith("```"):
            continue
        if opened is None:
            opened = number
        else:
            assert line.strip() == "```", f"{page.name}:{number}: {line!r} opens a block inside the one opened on line {opened}"
            opened = None
    assert opened is None, f"{page.name}: the block opened on line {opened} is never closed"
