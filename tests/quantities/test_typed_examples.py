"""Every kind's example in a message is one word of a command line, as typed in bash, zsh and
fish: "--drum-mass: expected a positive mass (e.g. 4 kg)" offered two words, and `--drum-mass
4 kg` is refused (a new user's trial). A shell splits at spaces and globs * ? [ ] ^ ( ): the
example runs its number and a plain unit together, or is quoted."""

from __future__ import annotations

import re
import shlex

import pytest

from taucli.quantities.units import KINDS, read

GLOB = re.compile(r"[*?\[\]^()]")


@pytest.mark.parametrize("name", sorted(KINDS))
def test_each_kind_offers_one_word(name):
    typed = KINDS[name].typed
    words = shlex.split(typed)
    assert len(words) == 1, typed
    assert typed.startswith("'") or not GLOB.search(typed), typed  # a glob character only in quotes


@pytest.mark.parametrize("text", ["5 furlongs_per_fortnight_x", "1-5"])  # an unknown unit; the screen's refusals (a range with a dash)
@pytest.mark.parametrize("name", sorted(KINDS))
def test_a_refused_value_offers_the_one_word(name, text):
    from taucli.core.errors import InputError
    with pytest.raises(InputError) as refused:
        read(text, "option", KINDS[name])
    example = re.search(r"\(e\.g\. (.*?)\)(?:,|$)", str(refused.value))
    assert example is not None and len(shlex.split(example[1])) == 1, str(refused.value)
