"""A range A..B where one value is read (#48, found by a new user): 0.5..4kg was read as 0.5 × .4 kg
= 0.2 kg with exit 0 in convert, in a spec's key and in --want. The screen every quantity passes
refuses any text with "..": an option's sweep is split before any of its values is read."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli
from taucli.quantities.kinds import KINDS
from taucli.quantities.units import parse

KINDED = [(kind.name, unit) for kind in KINDS.values() for unit in kind.common_units[:2]]


@settings(max_examples=200, deadline=None)
@given(st.sampled_from(KINDED), st.decimals(0, 100, places=2), st.decimals(0, 100, places=2), st.sampled_from(["", " "]))
def test_any_range_is_refused_where_one_value_is_read(pair, low, high, space):
    kind, unit = pair
    with pytest.raises(taucli.InputError, match="a range FROM..TO"):
        parse(f"{low}..{high}{space}{unit}", "x", kind, sign="any")


@pytest.mark.parametrize("args", [
    ("convert", "0.5..4kg"),
    ("inertia", "point", "--mass", "1kg", "--radius", "1m", "--part", "point mass=0.5..4kg offset=1m", "--get", "I"),
    ("atwood", "--m2", "1kg", "--find", "m1", "--want", "a=0.5..4m/s^2", "--get", "m1"),
])
def test_the_new_user_s_three(args):
    assert_usage_error(run_taucli(*args), "a range FROM..TO")


def test_an_option_s_sweep_still_reads_its_range():
    run = run_taucli("atwood", "--m1", "0.5..4kg", "--m2", "1kg", "--points", "3", "--get", "a")
    assert run.code == 0 and len(run.out.splitlines()) == 3, run
