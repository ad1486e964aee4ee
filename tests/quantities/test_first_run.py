"""A first run (an empty cache folder) costs no more than a warm one (#36 item 8).

pint's SI factor for each common unit text is shipped in the package (taucli/units-shipped.json,
built by ``python -m taucli.quantities.shipped``), so a first run reads "4 kg" without importing pint and
building its registry, as a warm run does. The table is used only for the rules and the pint it
was built with; these tests check that it is current, that each factor is pint's, and that a
first run of README's examples never imports pint. (Timings: docs/running.md, measured by hand.)
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys

import pytest

from taucli.quantities import cache
from taucli.quantities import shipped
from taucli.quantities import units
from taucli.quantities.kinds import KINDS

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def _shipped() -> dict:
    with open(cache.own_file(cache.SHIPPED), encoding="utf-8") as handle:
        return json.load(handle)


def test_the_shipped_table_is_current():
    if cache.pint_version() is None:
        pytest.skip("pint's version cannot be found from its dist-info folder here: the table is not used")
    assert _shipped()["stamp"] == cache.rules_stamp(), "the reading rules or pint changed: run `python -m taucli.quantities.shipped`"
    assert cache.shipped_unit_factors() == _shipped()["entries"]


def test_each_shipped_factor_is_pints():
    entries = _shipped()["entries"]
    assert len(entries) > 150
    for key, (factor, how) in entries.items():
        si_unit, kind_name, unit = key.split("|", 2)
        assert KINDS[kind_name].si_unit == si_unit
        asked = units.factor_entry(f"1 {unit}", kind_name)
        assert asked is not None and asked[0] == key, key
        # pint's own answer may differ in the last bit from one registry state to another (the
        # order its conversions were cached in): within two ulp
        assert asked[1][1] == how and asked[1][0] == pytest.approx(factor, rel=5e-16, abs=0), key
        assert math.isfinite(factor) and factor != 0


def test_every_unit_of_the_docs_examples_is_shipped():
    """A unit a page's example types reads from the table on a first run."""
    entries = cache.shipped_unit_factors() or pytest.skip("the table is not used with this pint")
    missing = []
    for text in sorted(shipped._document_units(ROOT)):
        for kind in KINDS:
            found = units.factor_entry(f"1 {text}", kind)
            if found is not None and found[0] not in entries:
                missing.append(found[0])
    assert not missing, f"run `python -m taucli.quantities.shipped`: {missing}"


def test_a_stale_table_is_not_used(monkeypatch):
    """A table built for other rules or another pint is passed over: pint answers, as before."""
    monkeypatch.setattr(cache, "rules_stamp", lambda: "other rules|pint 0.0")
    cache.shipped_unit_factors.cache_clear()
    try:
        assert cache.shipped_unit_factors() == {}
    finally:
        monkeypatch.undo()
        cache.shipped_unit_factors.cache_clear()


def _first_run(tmp_path, *args: str) -> subprocess.CompletedProcess:
    folder = tmp_path / "empty-cache"
    folder.mkdir(exist_ok=True)
    env = {**os.environ, "TAUCLI_CACHE_DIR": str(folder), "PYTHONIOENCODING": "utf-8"}
    env.pop("TAUCLI_DEBUG", None)
    return subprocess.run([sys.executable, "-X", "importtime", "-m", "taucli", *args], capture_output=True, text=True, env=env, timeout=120)


@pytest.mark.parametrize("args", [
    ("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--pulley-radius", "0.1m"),
    ("spin-down", "--shape", "disc", "--mass", "5kg", "--radius", "0.2m", "--omega0", "30rad/s", "--friction", "0.3N*m", "--get", "t_stop"),
    ("impulse", "--inertia", "0.1kg*m^2", "--omega0", "300rpm", "--torque", "2N*m", "--duration", "0.5s", "--json"),
    ("inertia", "disc", "--mass", "5kg", "--radius", "0.2m", "--to", "I=g*cm^2"),
])
def test_a_first_run_does_not_import_pint(tmp_path, args):
    done = _first_run(tmp_path, *args)
    assert done.returncode == 0, done.stderr[-2000:]
    imported = [line.rsplit("|", 1)[-1].strip() for line in done.stderr.splitlines() if line.startswith("import time:")]
    assert not [name for name in imported if name.split(".")[0] == "pint"]


def test_the_shipped_table_and_pint_give_the_same_answers(tmp_path, monkeypatch):
    args = ("spin-down", "--shape", "disc", "--mass", "5kg", "--radius", "20cm", "--omega0", "300rpm", "--friction", "0.3N*m", "--time", "1s", "--json")
    shipped = _first_run(tmp_path, *args)
    env = {**os.environ, "TAUCLI_CACHE_DIR": ""}
    with_pint = subprocess.run([sys.executable, "-c", "import sys; from taucli.quantities import cache; cache.shipped_unit_factors = dict;"
                                "from taucli.front.cli import main; sys.exit(main(sys.argv[1:]))", *args], capture_output=True, text=True, env=env, timeout=120)
    assert shipped.returncode == with_pint.returncode == 0, with_pint.stderr
    assert json.loads(shipped.stdout) == json.loads(with_pint.stdout)
