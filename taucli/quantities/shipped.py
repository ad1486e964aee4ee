"""Build the table of pint's SI factors shipped in the package (taucli/quantities/units-shipped.json).

    python -m taucli.quantities.shipped

Run after a change to the reading rules (units, registry, screen, spellings, kinds), to pint, or
to the units the docs' examples type: tests/quantities/test_first_run.py says when. taucli.quantities.cache reads the
table; this module, which asks pint for each factor, is imported only to build it.
"""

from __future__ import annotations

import glob
import json
import os
import re
import shlex

from taucli.quantities import cache
from taucli.quantities import units
from taucli.quantities.kinds import KINDS


def build_shipped(texts: dict[str, list[str]]) -> dict:
    """The shipped table: pint's answer, under taucli's rules, for each unit text of each kind
    in ``texts`` (kind name -> unit texts) that reads as that kind; texts that do not are left out."""
    entries: dict[str, object] = {}
    for kind_name, unit_texts in texts.items():
        for text in unit_texts:
            key_and_factor = units.factor_entry(f"1 {text}", kind_name)
            if key_and_factor is not None:
                entries[key_and_factor[0]] = key_and_factor[1]
    return {"stamp": cache.rules_stamp(), "entries": dict(sorted(entries.items()))}


# Unit texts the shipped table holds for every kind they read as: each kind's common units, these,
# and every unit in README's and docs/'s examples (when built from a checkout).
COMMON_TEXTS = (
    "kg g mg lb lbs oz tonne t slug m cm mm km um µm in ft yd mi inch deg rad rev ° degree degrees turn "
    "s ms us min h hr sec rad/s rpm RPM rev/s rev/min rps deg/s Hz min^-1 1/min rad/s^2 rad/s**2 rpm/s "
    "rev/s^2 rev/min^2 deg/s^2 N*m N·m Nm N.m N-m mN*m mNm kN*m kNm lbf*ft lbf*in ft*lbf ft-lb ft-lbf lb-ft "
    "in-lb lb*ft lb*in in*lbf oz*in ozf*in kg*m^2 kg*m**2 kg·m² kgm^2 kgm2 g*cm^2 kg*cm^2 g*mm^2 lb*ft^2 lb*in^2 "
    "slug*ft^2 lb*in*s^2 lbf*in*s^2 oz*in^2 N kN mN lbf kgf lb-f m/s^2 m/s**2 m/s² cm/s^2 ft/s^2 g0 gravity m/s km/h "
    "kph ft/s mph cm/s mm/s N*m*s N*m*s^2 N*m*s**2 N*m/(rad/s) W kW MW mW hp J kJ MJ mJ kW*h kWh Wh cal kcal "
    "kg/m^3 g/cm^3 lb/ft^3 lb/in^3 kg/m^2 kg/m g/cm^2 N*m/rad N*m/deg mN*m/rad Nm/rad mm/rev in/rev"
).split()


def _document_units(root: str) -> set[str]:
    """The unit of every value typed in README's and docs/'s commands (a checkout's, if there)."""
    found: set[str] = set()
    for path in [os.path.join(root, "README.md"), *glob.glob(os.path.join(root, "docs", "*.md"))]:
        try:
            with open(path, encoding="utf-8") as handle:
                text = handle.read()
        except OSError:
            continue
        for line in re.findall(r"^\$ (taucli .*)$", text, re.M):
            try:
                words = shlex.split(line)
            except ValueError:
                continue
            for word in words:
                for piece in re.split(r"\.\.|,|\s+|=|\+/-", word):
                    unit = re.sub(r"^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?", "", piece.strip())
                    if unit and unit != piece.strip() and len(unit) < 20:
                        found.add(unit)
    return found


def main() -> None:
    """Rebuild the shipped table (taucli/quantities/units-shipped.json) from pint, in a checkout."""
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    texts = sorted({*COMMON_TEXTS, *_document_units(root), *(unit for kind in KINDS.values() for unit in kind.common_units)})
    table = build_shipped({name: texts for name in KINDS})
    with open(cache.own_file(cache.SHIPPED), "w", encoding="utf-8") as handle:
        entries = ",\n".join(f"{json.dumps(key, ensure_ascii=False)}: {json.dumps(value)}" for key, value in table["entries"].items())
        handle.write(f'{{"stamp": {json.dumps(table["stamp"])},\n"entries": {{\n{entries}\n}}}}\n')
    print(f"{cache.own_file(cache.SHIPPED)}: {len(table['entries'])} unit factors for {table['stamp']}")


if __name__ == "__main__":
    main()
