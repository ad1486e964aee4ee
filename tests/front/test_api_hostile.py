"""The Python API raises taucli.InputError for every bad argument, and nothing else (#33 item 13).

numpy scalars and 0-d arrays are numbers, and a 1-d array of three a vector; every other value of
any Python type given to any keyword of any scene is answered or refused with an InputError that
names the parameter.
"""

from __future__ import annotations

import decimal
import os
import fractions
import shlex

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import taucli
from taucli.options import SCENES
from taucli.writing.report import Report

try:
    import numpy
except ImportError:  # numpy is not a dependency of taucli: its cases run where it is installed
    numpy = None


def _example(command) -> dict:
    """The keywords of the scene's example line (``taucli atwood --m1 4kg ...``)."""
    words = shlex.split(command.example)[2:]
    given, positional = {}, [option.name for option in command.options if option.positional]
    while words:
        word = words.pop(0)
        if word.startswith("--"):
            given[word[2:].replace("-", "_")] = words.pop(0)
        else:
            given[positional.pop(0)] = word
    return given


TEXTS = ["4kg", "0.1 kg*m^2", "30deg", "300 rpm", "2 s", "disc", "rod", "end", "rim", "point mass=1kg offset=1m", "0.3,0.4,0 m",
         "force=6N mu=0.4 radius=0.1m", "mu=0.3 force=10N", "hang", "incline angle=30deg", "a=2m/s^2", "m1", "rk4", "",
         "4.0+/-0.1 kg", "1..2kg", "1kg,2kg", "-1", "1e400", "nan"]


def values() -> st.SearchStrategy:
    plain = st.one_of(
        st.none(), st.booleans(), st.integers(), st.sampled_from([400, -400, 5000, 309]).map(lambda e: 10 ** abs(e) * (1 if e > 0 else -1)),
        st.floats(), st.complex_numbers(allow_nan=True), st.sampled_from(TEXTS), st.text(max_size=20), st.binary(max_size=8),
        st.fractions(), st.decimals(), st.just(object()), st.just(Ellipsis), st.just(float), st.just(decimal.Decimal("NaN")),
        st.just(fractions.Fraction(1, 3)),
    )
    numpy_values = st.nothing()
    if numpy is not None:
        numpy_values = st.one_of(
            st.floats(width=64).map(numpy.float64), st.integers(-(2**63), 2**63 - 1).map(numpy.int64), st.floats(width=32).map(numpy.float32),
            st.floats().map(numpy.array), st.lists(st.floats(), min_size=0, max_size=4).map(numpy.array), st.sampled_from(TEXTS).map(numpy.str_),
            st.booleans().map(numpy.bool_), st.just(numpy.zeros((2, 3))), st.just(numpy.array([[1.0, 2.0, 3.0]])), st.just(numpy.array(["4kg"])),
            st.sampled_from(["4", "0", "-1", "1e-4000", "1e4000", "nan", "inf"]).map(numpy.longdouble),
            st.sampled_from(["4", "4+1j", "1e4000"]).map(numpy.clongdouble), st.sampled_from(["4", "1e-4000"]).map(lambda t: numpy.array(numpy.longdouble(t))),
            st.just(numpy.array(numpy.clongdouble(4))), st.just(numpy.array([numpy.longdouble(1), 2, 3], dtype=numpy.longdouble)),
        )
    containers = st.recursive(st.one_of(plain, numpy_values), lambda inner: st.one_of(
        st.lists(inner, max_size=4), st.tuples(inner, inner, inner), st.dictionaries(st.text(max_size=5), inner, max_size=2),
        st.frozensets(st.integers(), max_size=3)), max_leaves=6)
    return st.one_of(plain, numpy_values, containers)


@pytest.mark.parametrize("scene", sorted(SCENES))
def test_every_keyword_of_every_scene_raises_only_input_error(scene):
    command = SCENES[scene]
    function = getattr(taucli, command.function_name)
    base = _example(command)
    keywords = [option.name for option in command.options] + ["find", "want"]

    @settings(max_examples=int(os.environ.get("TAUCLI_API_EXAMPLES", "60")), deadline=None, database=None, suppress_health_check=list(HealthCheck))
    @given(st.lists(st.tuples(st.sampled_from(keywords), values()), min_size=1, max_size=3), st.booleans())
    def check(changes, keep_base):
        arguments = dict(base) if keep_base else {}
        arguments.update(changes)
        try:
            report = function(**arguments)
        except taucli.InputError as err:
            assert str(err)  # a message, naming what is wrong
        else:  # a list for one keyword that takes one quantity: a sweep of reports (#46 item 10)
            assert isinstance(report, Report) or (isinstance(report, taucli.Sweep) and all(isinstance(row, Report) for row in report))

    check()


def test_the_issues_examples():
    with pytest.raises(taucli.InputError, match=r"^m1: expected a number a double holds .*about 401 digits"):
        taucli.atwood(m1=10**400, m2=1)
    with pytest.raises(taucli.InputError, match=r"^r: expected a number a double holds .*about 5001 digits"):
        taucli.torque(r=[1, 10**5000, 0], force=[1, 0, 0])
    for keyword, scene in (("part", taucli.atwood), ("brake", taucli.impulse), ("particle", taucli.impulse)):
        with pytest.raises(taucli.InputError, match=rf"^{keyword}: expected a text, got 5 \(int\)"):
            scene(**{keyword: 5, "inertia" if scene is taucli.impulse else "m1": 1})


@pytest.mark.skipif(numpy is None, reason="numpy is not installed")
def test_numpy_scalars_and_arrays_are_numbers_and_vectors():
    expected = taucli.atwood(m1=4, m2=1).results["a"].value
    for m1 in (numpy.int64(4), numpy.float32(4), numpy.float64(4), numpy.array(4.0), numpy.array(4)):
        assert taucli.atwood(m1=m1, m2=1).results["a"].value == expected
    tau = taucli.torque(r=numpy.array([0.3, 0.4, 0.0]), force=numpy.array([0, 0, 10])).results["tau"].value
    assert tau == pytest.approx(5.0, rel=1e-15)
    swept = taucli.atwood(m1=4, m2=1, g=numpy.array([1.0, 2.0, 3.0]))  # a 1-d array for one keyword: a sweep (#46 item 10)
    assert [row.results["a"].value for row in swept] == pytest.approx([0.6, 1.2, 1.8], rel=1e-15)
    with pytest.raises(taucli.InputError, match=r"^g: "):
        taucli.atwood(m1=4, m2=1, g=numpy.array([[1.0, 2.0, 3.0]]))


FRICTION = "t (s),omega (rad/s)\n0,29.928\n1,27.012\n2,23.986\n3,20.976\n4,18.048\n5,15.003\n6,11.986\n7,9.090\n8,5.975\n9,2.937\n"  # docs/fit.md
FIT_KEYWORDS = ["scene", "data", "fit", "x", "y", "sigma", "range", "every", "stdin", "inertia", "omega0", "friction", "viscous", "method", "g"]


@pytest.mark.skipif(numpy is None, reason="taucli fit needs numpy")
def test_every_keyword_of_fit_raises_only_input_error(tmp_path):
    """taucli.fit.fit (#43 item 10): a str, a pathlib.Path or an open file as data; every other bad
    value of any keyword raises InputError, as the scenes' functions do."""
    import io
    import pathlib

    import taucli.fit

    path = tmp_path / "friction.csv"
    path.write_text(FRICTION, encoding="utf-8")
    base = {"scene": "spin-down", "data": [str(path)], "fit": "friction,omega0", "inertia": "0.1 kg*m^2"}
    data = st.one_of(values(), st.sampled_from(["path", "Path", "text file", "byte file", "StringIO", "closed file"]).map(
        lambda kind: {"path": str(path), "Path": path, "StringIO": io.StringIO(FRICTION)}.get(kind) or _opened(path, kind)))

    @settings(max_examples=int(os.environ.get("TAUCLI_API_EXAMPLES", "60")), deadline=None, database=None, suppress_health_check=list(HealthCheck))
    @given(st.lists(st.tuples(st.sampled_from(FIT_KEYWORDS), values()), min_size=1, max_size=3), st.lists(data, max_size=2), st.booleans())
    def check(changes, sources, keep_base):
        arguments = dict(base) if keep_base else {}
        arguments.update(changes)
        if sources:
            arguments["data"] = sources
        scene, files = arguments.pop("scene", None), arguments.pop("data", [])
        files = files if isinstance(files, list) else [files]
        try:
            report = taucli.fit.fit(scene, *files, **arguments) if "fit" in arguments else taucli.fit.fit(scene, *files, fit=None, **arguments)
        except taucli.InputError as err:
            assert str(err)
        else:  # a list for one keyword that takes one quantity: a sweep of reports (#46 item 10)
            assert isinstance(report, Report) or (isinstance(report, taucli.Sweep) and all(isinstance(row, Report) for row in report))

    check()


def _opened(path, kind):
    handle = path.open("rb" if kind == "byte file" else "r", encoding=None if kind == "byte file" else "utf-8")
    if kind == "closed file":
        handle.close()
    return handle


@pytest.mark.skipif(numpy is None, reason="taucli fit needs numpy")
def test_fits_issue_examples(tmp_path):
    import io
    import pathlib

    import taucli.fit

    path = tmp_path / "friction.csv"
    path.write_text(FRICTION, encoding="utf-8")
    expected = taucli.fit.fit("spin-down", str(path), fit="friction,omega0", inertia="0.1 kg*m^2").results["friction"].value
    with path.open(encoding="utf-8") as handle:
        for data in (pathlib.Path(path), handle, io.StringIO(FRICTION)):
            assert taucli.fit.fit("spin-down", data, fit="friction,omega0", inertia=numpy.float64(0.1), friction=numpy.float64(0.3)).results["friction"].value \
                == pytest.approx(expected, rel=1e-9)
    for arguments, keyword in ((("spin-down", bytes(path)), "data"), (("spin-down",), "data"), ((5, str(path)), "scene")):
        with pytest.raises(taucli.InputError, match=f"^{keyword}: "):
            taucli.fit.fit(*arguments, fit="friction,omega0", inertia="0.1 kg*m^2")
    for keyword, value in (("sigma", 0.05), ("x", 5), ("range", 5), ("every", 10**5000), ("stdin", 5)):
        with pytest.raises(taucli.InputError, match=f"^{keyword}: "):
            taucli.fit.fit("spin-down", str(path), fit="friction,omega0", inertia="0.1 kg*m^2", **{keyword: value})
    for value in (numpy.longdouble(4), numpy.array(numpy.longdouble(4))):
        assert taucli.atwood(m1=value, m2=1).results["a"].value == taucli.atwood(m1=4, m2=1).results["a"].value
    for value in (numpy.clongdouble(4), numpy.array(numpy.clongdouble(4)), numpy.longdouble("1e-4000")):
        with pytest.raises(taucli.InputError, match="^m1: "):
            taucli.atwood(m1=value, m2=1)
