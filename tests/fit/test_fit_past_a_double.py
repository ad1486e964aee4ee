"""A fit among numbers near a double's range (#43 item 18, found by the fuzz of every command): no
exit 1, no numpy or scipy RuntimeWarning on stderr, no LAPACK line on stdout; a refusal that says
why, or the answer.

Measured ω = (τ/I)·t up to 5e39 rad/s with τ = 1e40 N·m given: fitting I and τ together (only
their ratio shows) ended in numpy.linalg.LinAlgError (exit 1) after scipy warned "overflow
encountered in power" and LAPACK wrote "** On entry to DLASCL parameter number 4 had an illegal
value" six times on stdout.
"""

from __future__ import annotations

import io
import warnings

import pytest

from conftest import run_taucli
from taucli.front.cli import Environment, main

FAST = "t (s),omega (rad/s)\n1,1e39\n2,2e39\n3,3e39\n4,4.1e39\n5,5e39\n"


@pytest.fixture
def fast(tmp_path):
    path = tmp_path / "fast.csv"
    path.write_text(FAST)
    return str(path)


def test_fitting_inputs_at_a_double_range_is_refused_with_its_reason_not_a_bug(fast):
    done = run_taucli("fit", "spin-down", fast, "--torque", "1e40", "--omega0", "0rad/s", "--fit", "inertia,torque", "--get", "r2", timeout=120)
    assert done.code == 2, (done.code, done.err)
    assert done.out == "" and "DLASCL" not in done.err and "Warning" not in done.err
    # (either refusal says why: the samples cannot tell I and τ apart, or the scene has no ω just past τ's bound)
    assert done.err.startswith(("taucli: error: --fit: the samples cannot tell inertia and torque apart", "taucli: error: --fit: ends where the scene has no omega"))
    assert len(done.err.strip().splitlines()) == 1


@pytest.mark.parametrize("sigma", [[], ["--sigma", "1e-40rad/s"], ["--sigma", "1e-30rad/s"]])
@pytest.mark.parametrize("fitted", ["inertia", "inertia,torque", "inertia,friction", "torque,viscous"])
def test_no_warning_reaches_stderr_and_every_end_is_an_answer_or_a_refusal(fast, fitted, sigma):
    stdout, stderr = io.StringIO(), io.StringIO()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        status = main(["fit", "spin-down", fast, "--torque", "1e40", "--omega0", "0rad/s", "--fit", fitted, *sigma, "--get", "r2"],
                      Environment(stdin=None, stdout=stdout, stderr=stderr))
    assert status in (0, 2), stderr.getvalue()
    assert not [w for w in caught if issubclass(w.category, RuntimeWarning)], [str(w.message) for w in caught]
    if status == 0:
        assert 0.99 < float(stdout.getvalue()) <= 1  # ω = (τ/I)·t with one I fits the rows to 0.1 %
