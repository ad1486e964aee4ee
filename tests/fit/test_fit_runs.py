"""Several runs of one fit (#44 items 9 and 11): runs side by side split into tables of their
own, inputs fitted for each run (--per-run), an encoder's counts (--counts-per-rev), and each
misuse refused in one line."""

from __future__ import annotations

import io

import pytest

from taucli.core.errors import InputError
from taucli.fit import columns, data, encoder

from conftest import assert_usage_error, run_taucli


def table(text: str) -> data.DataTable:
    return data.read("-", io.StringIO(text))


@pytest.mark.parametrize("text", [
    "Run 1: Time (s),Run 1: Angle (rad),Run 2: Time (s),Run 2: Angle (rad)\n0,1,0,2\n1,3,1,4\n2,5,,\n",  # Vernier, run 2 shorter
    "Time (s) Run #1,Angle (rad) Run #1,Time (s) Run #2,Angle (rad) Run #2\n0,1,0,2\n1,3,1,4\n2,5,,\n",  # PASCO
])  # fmt: skip
def test_runs_side_by_side_are_split_into_a_table_each_the_padding_left_out(text):
    first, second = columns.split_runs(table(text))
    assert [c.header for c in first.columns] == ["Time (s)", "Angle (rad)"] == [c.header for c in second.columns]
    assert list(first.column("Angle (rad)").values) == [1, 3, 5] and list(second.column("Angle (rad)").values) == [2, 4]
    assert list(second.lines) == [2, 3] and "run 2" in second.source


def test_a_shared_time_column_goes_to_every_run():
    first, second = columns.split_runs(table("t (s),Run 1: omega (rad/s),Run 2: omega (rad/s)\n0,1,2\n1,3,4\n"))
    assert list(second.column("t (s)").values) == [0, 1] and list(second.column("omega (rad/s)").values) == [2, 4]


def test_runs_with_other_columns_are_refused():
    with pytest.raises(InputError, match="every run of one fit has the same columns"):
        columns.split_runs(table("Run 1: t (s),Run 1: omega (rad/s),Run 2: t (s),Run 2: w (rad/s)\n0,1,0,2\n"))


def test_x_naming_a_run_as_written_fits_that_run_alone():
    (only,) = columns.split_runs(table("Run 1: t (s),Run 1: omega (rad/s),Run 2: t (s),Run 2: omega (rad/s)\n0,1,0,2\n"), {"Run 2: t (s)"})
    assert [c.header for c in only.columns] == ["Run 2: t (s)", "Run 2: omega (rad/s)"]


TWO_RUNS = "Run 1: t (s),Run 1: omega (rad/s),Run 2: t (s),Run 2: omega (rad/s)\n" + "".join(
    f"{t},{12 - 0.4 * t:.3f},{t},{9 - 0.4 * t:.3f}\n" for t in range(8))


@pytest.mark.parametrize("args,said", [
    (("--fit", "friction", "--per-run", "omega0"), "--per-run: names omega0, which --fit does not fit"),
    (("--fit", "friction,omega0", "--per-run", "omega0", "--range", "t=..0.5s"), "more samples than inputs"),
    (("--fit", "friction,omega0", "--per-run", ""), "--per-run: expected the inputs of --fit to fit for each run"),
    (("--fit", "friction,omega0", "--counts-per-rev", "360"), "--counts: expected cumulative"),
    (("--fit", "friction,omega0", "--counts", "interval"), "--counts: says what an encoder's counts are, and goes with --counts-per-rev"),
    (("--fit", "friction,omega0", "--counts-per-rev", "0", "--counts", "interval"), "--counts-per-rev: expected the encoder's counts in one revolution"),
    (("--fit", "friction,omega0", "--counts-per-rev", "360", "--counts", "interval", "--y", "omega (rad/s)=theta"), "holds counts, read as omega"),
])  # fmt: skip
def test_a_misuse_of_runs_or_counts_is_refused_in_one_line(tmp_path, args, said):
    path = tmp_path / "runs.csv"
    path.write_text(TWO_RUNS)
    assert_usage_error(run_taucli("fit", "spin-down", str(path), "--inertia", "0.1kg*m^2", *args), said)


def test_per_run_on_one_run_is_refused(tmp_path):
    path = tmp_path / "one.csv"
    path.write_text("t (s),omega (rad/s)\n" + "".join(f"{t},{12 - 0.4 * t:.3f}\n" for t in range(8)))
    assert_usage_error(run_taucli("fit", "spin-down", str(path), "--inertia", "0.1kg*m^2", "--fit", "friction,omega0", "--per-run", "omega0"),
                       "--per-run: fits omega0 for each run, and the samples are one run")


def test_two_runs_fitted_together_give_each_its_own_omega0_exactly():
    # friction alone (0.04 N·m on 0.1 kg·m²: α = −0.4 rad/s²), no noise: linear, solved exactly
    found = run_taucli("fit", "spin-down", "-", "--inertia", "0.1kg*m^2", "--fit", "friction,omega0", "--per-run", "omega0",
                       "--get", "friction", "--get", "omega0_run1", "--get", "omega0_run2", stdin=TWO_RUNS)
    assert found.code == 0, found.err
    assert [round(float(x), 9) for x in found.out.split()] == [0.04, 12.0, 9.0]


def test_encoder_counts_that_are_not_whole_are_refused():
    counted = table("t (s),Counts\n0,0\n1,2.5\n")
    with pytest.raises(InputError, match="holds 2.5, not a whole number"):
        encoder.speeds(counted, "Counts", "t (s)", 360, "cumulative")


def test_encoder_counts_give_the_mean_speed_over_each_interval_at_its_middle():
    counted = encoder.speeds(table("t (ms),Counts\n0,0\n100,36\n300,108\n"), "Counts", "t (ms)", 360, "cumulative")
    assert list(counted.column("t (ms)").values) == [50, 200] and list(counted.column("Counts").values) == [0.001, 0.001]
    assert counted.column("Counts").unit == "rev/ms" and list(counted.lines) == [3, 4]


def test_the_python_api_takes_per_run_and_counts(tmp_path):
    import taucli.fit

    path = tmp_path / "runs.csv"
    path.write_text(TWO_RUNS)
    report = taucli.fit.fit("spin-down", str(path), fit="friction,omega0", per_run="omega0", inertia="0.1 kg*m^2")
    assert [round(report.results[name].value, 9) for name in ("friction", "omega0_run1", "omega0_run2")] == [0.04, 12.0, 9.0]
    assert "from each run fitted alone" in report.method or "linear least squares" in report.method
    counted = tmp_path / "counts.csv"
    # friction alone: α = −0.4 rad/s², ω₀ = 2π·10 rad/s; counts every 0.5 s of 100 a revolution, cumulative, exact where whole
    times = [0.5 * k for k in range(9)]
    import math

    revs = [(2 * math.pi * 10 * t - 0.2 * t * t) / (2 * math.pi) for t in times]
    counted.write_text("t (s),Counts\n" + "".join(f"{t},{round(r * 100)}\n" for t, r in zip(times, revs)))
    report = taucli.fit.fit("spin-down", str(counted), fit="friction,omega0", counts_per_rev=100, counts="cumulative", inertia="0.1 kg*m^2")
    assert abs(report.results["omega0"].value - 2 * math.pi * 10) < 3 * report.uncertainties["omega0"] + 1e-9


def test_the_chart_of_runs_draws_each_run_with_its_own_inputs():
    # two coasts (ω₀ 12 and 9 rad/s, noise 0.01 rad/s): each sample's fitted value is its own run's, so no residual is a run's offset
    found = run_taucli("fit", "spin-down", "docs/data/vernier-two-runs.csv", "--y", "Angular Velocity (rad/s)=omega", "--inertia", "0.05 kg*m^2",
                       "--fit", "friction,viscous,omega0", "--per-run", "omega0", "--json", "--plot", timeout=180)
    assert found.code == 0, found.err
    plot = found.json()["plot"]
    assert len(plot["samples"]) == 72 and plot["curve"] == []
    assert max(abs(sample["residual"]) for sample in plot["samples"]) < 0.05


def test_logger_pros_latest_run_is_one_run_named_as_the_scene_names():
    (only,) = columns.split_runs(table("Latest: t (s)\tLatest: omega (rad/s)\n0\t1\n1\t2\n"))
    assert [column.name for column in only.columns] == ["t", "omega"]
    first, latest = columns.split_runs(table("Run 1: t (s),Run 1: omega (rad/s),Latest: t (s),Latest: omega (rad/s)\n0,1,0,2\n"))
    assert "run Latest" in latest.source and list(latest.column("omega (rad/s)").values) == [2]


def test_the_runs_own_fits_are_within_the_fits_time_bound(tmp_path):
    # two swings of 1,000 samples each, solved by rk4 at 1 ms: each run's own fit alone would take many minutes
    import math
    import time

    paths = []
    for k in (1, 2):
        path = tmp_path / f"swing{k}.csv"
        path.write_text("t (s),theta (rad)\n" + "".join(f"{0.02 * i:.2f},{0.5 * math.cos(math.sqrt(9.81) * 0.02 * i):.5f}\n" for i in range(1000)))
        paths.append(str(path))
    started = time.monotonic()
    done = run_taucli("fit", "pendulum", *paths, "--shape", "point", "--mass", "1kg", "--radius", "1m", "--angle0", "0.5rad", "--fit", "g,angle0",
                      "--per-run", "angle0", "--method", "rk4", "--no-steps", timeout=90)
    assert time.monotonic() - started < 30
    assert_usage_error(done, "--fit is estimated to take about", "--no-limit runs it as asked")
