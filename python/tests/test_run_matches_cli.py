# SPDX-License-Identifier: MIT
"""A run from Python gives the numbers of ``sinew run`` with the same
options, bit for bit.

Both drive the same libmu: the Python package reproduces the program's
schedule (controls before every substep they change, a frame stepped
whole when nothing changes within it) and its CSV's columns. The program
runs with ``--digits 17``, which gives every double back exactly, so every
cell of its CSV, read back as a double, must equal the Python value
exactly (NaN where Python has NaN).
"""
import csv
import math
import os
import subprocess

import pytest

import sinew


def cli_table(program, folder, model, arguments):
    environment = {k: v for k, v in os.environ.items() if k != "SINEW_DATA_DIR"}
    subprocess.run(
        [program, "run", model, "--out", str(folder), "--digits", "17"] + arguments,
        check=True,
        stdout=subprocess.DEVNULL,
        env=environment,
    )
    stem = os.path.basename(model).removesuffix(".json")
    with open(os.path.join(folder, stem + ".csv"), newline="") as stream:
        rows = list(csv.reader(stream))
    return rows[0], rows[1:]


def assert_same(result, header, rows):
    assert result.columns == header
    assert len(result.table) == len(rows)
    differences, seventeen = [], False
    for index, row in enumerate(rows):
        for name, cell in zip(header, row):
            value = result.table[name][index]
            if name.endswith(".recruited_neurons"):
                same = cell == "%d" % value
            else:
                number = float(cell)
                same = number == value or (math.isnan(number) and math.isnan(value))
                seventeen = seventeen or len(cell.lstrip("-").replace(".", "").split("e")[0].lstrip("0")) > 10
            if not same:
                differences.append(f"row {index} {name}: sinew run {cell}, Python {value!r}")
    assert not differences, "\n".join(differences[:20])
    # --digits took effect: some value was written with more than 10 digits.
    assert seventeen


@pytest.fixture
def compare(sinew_program, tmp_path):
    """compare(model, cli_arguments, **run_arguments): the program's CSV against sinew.run's table."""

    def check(model, arguments, **options):
        header, rows = cli_table(sinew_program, tmp_path, model, arguments)
        result = sinew.run(model, **options)
        assert_same(result, header, rows)
        return header

    return check


def test_arm_with_activation_tension_and_weight(compare):
    header = compare(
        "arm",
        ["--duration", "3", "--weight", "5", "--activation", "Biceps Short=0.5", "--tension", "Triceps Long=40"],
        duration=3,
        weight=5,
        activations={"Biceps Short": 0.5},
        tensions={"Triceps Long": 40},
    )
    assert len(header) > 150  # muscles, hinges, parts, loads, moment arms, bone stress


def test_arm_with_control_file_shapes(compare, repository):
    """Ramps, sines and pulse trains drive the model substep by substep."""
    control = os.path.join(repository, "models", "controls", "biceps_shapes.txt")
    compare("arm", ["--duration", "8", "--control", control], duration=8, control=control)


def test_arm_variant_level_and_weld_glues(compare, repository):
    control = os.path.join(repository, "models", "controls", "biceps_pulse.txt")
    header = compare(
        "arm",
        ["--duration", "4", "--variant", "All Biceps", "--weight-index", "3", "--weld-glues", "--control", control],
        duration=4,
        variant="All Biceps",
        weight_index=3,
        weld_glues=True,
        control=control,
    )
    assert any(name.endswith(".reaction_along_N") for name in header)


def test_arm_below_level_4(compare):
    compare("arm", ["--duration", "1", "--level", "3", "--activation", "Biceps Long=1"],
            duration=1, level=3, activations={"Biceps Long": 1})


def test_worm_recruitment(compare, repository):
    control = os.path.join(repository, "models", "controls", "worm_recruit.txt")
    compare("worm", ["--duration", "6.5", "--control", control], duration=6.5, control=control)


def test_model_file_by_path(compare, repository):
    path = os.path.join(repository, "models", "leg.json")
    compare(path, ["--duration", "1", "--activation", "Soleus=0.6"], duration=1, activations={"Soleus": 0.6})


def test_a_run_is_deterministic_to_the_bit():
    """Two runs, and the same run stepped by hand, end in the same state hash."""
    first = sinew.run("arm", duration=1, activations={"Biceps Long": 0.7})
    second = sinew.run("arm", duration=1, activations={"Biceps Long": 0.7})
    assert first.table.tobytes() == second.table.tobytes()
    with sinew.Model("arm") as a, sinew.Model("arm") as b:
        a.set_activation("Biceps Long", 0.7)
        b.set_activation("Biceps Long", 0.7)
        a.step(60)
        for _ in range(60):
            b.step()
        assert a.world.state_hash == b.world.state_hash
        assert a.readouts().tobytes() == b.readouts().tobytes()
        assert a.time == pytest.approx(1.0, abs=1e-12)


def test_dataframe():
    pandas = pytest.importorskip("pandas")
    result = sinew.run("sample", duration=0.5, activations={"Muscle": 1.0})
    frame = result.dataframe()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns) == result.columns
    assert len(frame) == 30
    assert frame["Muscle.total_force_N"].iloc[-1] == result.table["Muscle.total_force_N"][-1]


def test_controls_given_in_python_equal_the_control_file(repository):
    """biceps_shapes.txt's lines as Schedule.add arguments give the same bits."""
    control = os.path.join(repository, "models", "controls", "biceps_shapes.txt")
    both = "Biceps Short + Biceps Long"
    controls = [
        dict(time=0.5, kind="activation", name=both, shape="ramp", start_value=0, end_value=0.4, duration=1.5),
        dict(time=3.0, kind="activation", name=both, shape="sine", mean=0.25, amplitude=0.15, frequency=0.5,
             duration=2),
        dict(time=5.0, kind="activation", name="Biceps Long", shape="pulses", level=1, frequency=10, width=0.02,
             duration=1),
        (5.0, "activation", "Biceps Short", 0),
        dict(time=6.5, kind="tension", name="Biceps Short", shape="ramp", start_value=0, end_value=60, duration=1),
    ]
    from_file = sinew.run("arm", duration=8, control=control)
    from_python = sinew.run("arm", duration=8, controls=controls)
    assert from_file.table.tobytes() == from_python.table.tobytes()
    with pytest.raises(sinew.InvalidArgument, match="is no muscle or group"):
        sinew.run("arm", duration=1, controls=[(0.0, "activation", "Biceps", 0.5)])
    with pytest.raises(sinew.InvalidArgument, match="before the previous control"):
        sinew.run("arm", duration=1, controls=[(0.5, "activation", both, 0.5), (0.2, "activation", both, 0)])
