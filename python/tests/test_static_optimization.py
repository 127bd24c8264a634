# SPDX-License-Identifier: MIT
"""Model.static_optimizer: a lever held horizontal by two muscles at rest
needs m·g·d about its pivot (the lever's weight at its centre), which the
muscles' forces found give through their moment arms, each the geometry's
closed form; on the arm the muscles meet inverse dynamics' torques; a
closed model, a wrong length and a model without muscles raise."""

import json
import math

import numpy as np
import pytest

import sinew

G = 9.8
ORIGINS = ((0.02, 0.05), (0.0, 0.08))
INSERTIONS = (0.10, 0.05)  # m from the pivot along the lever
MAX_FORCES = (100.0, 300.0)


def lever_file(folder):
    muscles = [
        {
            "name": name,
            "rest_length": 0.08,
            "max_force": force,
            "path": [{"body": "Ground", "point": list(origin)}, {"body": "Lever", "point": [insertion - 0.15, 0]}],
        }
        for name, force, origin, insertion in zip(("One", "Two"), MAX_FORCES, ORIGINS, INSERTIONS)
    ]
    model = {
        "name": "agonists",
        "gravity": [0, -G],
        "nails": [{"name": "Ground", "position": [0, 0]}],
        "bones": [{"name": "Lever", "centre": [0.15, 0], "size": [0.3, 0.03], "density": 20000}],
        "hinges": [
            {
                "name": "Pivot",
                "body_a": "Ground",
                "anchor_a": [0, 0],
                "body_b": "Lever",
                "anchor_b": [-0.15, 0],
                "radius": 0.01,
                "lower": -80,
                "upper": 80,
            }
        ],
        "muscles": muscles,
        "groups": [],
        "variants": [{"name": "both", "muscles": ["One", "Two"]}],
    }
    path = folder / "agonists.json"
    path.write_text(json.dumps(model))
    return str(path)


def test_a_lever_at_rest_needs_its_weights_moment(tmp_path):
    with sinew.Model(lever_file(tmp_path)) as lever, lever.static_optimizer() as optimizer:
        assert optimizer.actuator_names == ["One", "Two"]
        frame = optimizer.solve([0.0], [0.0], [0.0])
        assert frame.solved, sinew.static_optimization.StaticOptimizer.result_name(frame.solver_result)
        mass = 20000 * 0.3 * 0.03 * 0.03  # density · size · depth (the smaller extent)
        assert frame.net_torques[0] == pytest.approx(mass * G * 0.15, rel=1e-9)
        assert abs(frame.reserves[0]) < 1e-3
        # r = y_o·x_i / |insertion − origin| for an origin above the pivot.
        arms = [oy * xi / math.hypot(xi - ox, oy) for (ox, oy), xi in zip(ORIGINS, INSERTIONS)]
        assert list(lever.moment_arms("Pivot")) == pytest.approx(arms, rel=1e-9)
        assert float(np.dot(arms, frame.forces)) == pytest.approx(frame.actuator_torques[0], rel=1e-9)
        assert frame.actuator_torques[0] + frame.reserves[0] == pytest.approx(frame.net_torques[0], rel=1e-9)
        assert np.all((frame.activations >= 0) & (frame.activations <= 1))


def test_the_arm_meets_inverse_dynamics():
    with sinew.Model("arm", weight=1) as arm, arm.static_optimizer(exponent=3) as optimizer:
        angles = [10.0, 80.0]
        frame = optimizer.solve(angles, [0.0, 0.0], [0.0, 0.0])
        assert frame.solved
        assert list(frame.net_torques) == pytest.approx(list(arm.inverse_dynamics(angles, [0, 0], [0, 0])), rel=1e-12)
        assert np.max(np.abs(frame.actuator_torques - frame.net_torques)) < 1e-3
        assert frame.loads.dtype == sinew.model.LOAD_DTYPE and frame.loads.shape == (2,)


def test_misuse_raises(tmp_path):
    arm = sinew.Model("arm")
    optimizer = arm.static_optimizer()
    with pytest.raises(sinew.InvalidArgument, match="2 values"):
        optimizer.solve([0.0], [0.0], [0.0])
    arm.close()
    with pytest.raises(sinew.Closed):
        optimizer.solve([0.0, 0.0], [0.0, 0.0], [0.0, 0.0])
    with sinew.Model("arm", level=2) as bones_only, pytest.raises(sinew.Error, match="muscle"):
        bones_only.static_optimizer()
    with sinew.Model("arm") as arm, pytest.raises(sinew.Error):
        arm.static_optimizer(exponent=0.5)
