"""#42 items 5 and 13: atwood's --distance past the point where the masses turn back, and m2's
surface given with no m2.

References are written from the physics: under a constant acceleration a (m1 downward positive)
from a velocity v0, m1's displacement is s(t) = v0 t + a t²/2; where v0 and a have opposite signs
the masses stop at s* = −v0²/(2a), and a displacement beyond s* on that side is never reached.
"""

from __future__ import annotations

import json

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli
from taucli.core.errors import InputError


# Item 13: a surface for m2 with no m2 ------------------------------------------------------------

@pytest.mark.parametrize("surface", [{"incline": "30deg"}, {"incline": "30deg", "mu_k": 0.2}, {"mu_k": 0.2}, {"mu_s": 0.3}])
def test_a_surface_for_m2_without_m2_is_refused_in_python(surface):
    with pytest.raises(InputError):
        taucli.atwood(m1="2 kg", **surface)


@pytest.mark.parametrize("args, option", [(["--incline", "30deg", "--mu-k", "0.2"], "--incline"), (["--mu-k", "0.2"], "--mu-k"),
                                          (["--mu-s", "0.3"], "--mu-s")])
def test_a_surface_for_m2_without_m2_is_refused_naming_the_fix(args, option):
    assert_usage_error(run_taucli("atwood", "--m1", "2kg", *args), option, "--m2")
