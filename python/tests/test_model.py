# SPDX-License-Identifier: MIT
"""Models from Python: stepping, readouts as numpy arrays, moment arms,
joint loads, bone stress, and inverse dynamics against a static balance
computed here from the bodies' masses and centres."""
import numpy as np
import pytest

import sinew


def test_builtins_and_description():
    assert {"sample", "arm", "leg", "worm"} <= set(sinew.builtin_models())
    with sinew.Model("arm", variant="All Biceps", weight=10) as arm:
        assert arm.frame_rate == 60 and arm.substeps == 10
        assert arm.variant == 2 and arm.weights[arm.weight_index] == 10
        assert arm.muscle_names == ["Biceps Short", "Biceps Long"]
        assert arm.hinge_names == ["Shoulder", "Elbow"]
        assert arm.variants[0] == "All Muscles"


def test_frames_and_substeps_advance_time_exactly():
    with sinew.Model("sample") as model:
        model.step(3)
        model.substep(4)
        assert model.time == (3 * 10 + 4) / 600.0
        assert model.frame_duration == 1.0 / 60.0 and model.substep_duration == 1.0 / 600.0


def test_readouts_are_numpy_records():
    with sinew.Model("arm") as arm:
        arm.set_activation("Biceps Short + Biceps Long", 0.8)
        arm.set_tension("Triceps Long", 30.0)
        arm.step(30)
        readouts = arm.readouts()
        assert readouts.dtype.names[:3] == ("activation", "target_tension", "length")
        assert readouts["activation"][0] == 0.8 and readouts["activation"][1] == 0.8
        assert readouts["target_tension"][3] == 30.0
        np.testing.assert_array_equal(
            readouts["total_force"], readouts["active_force"] + readouts["passive_force"]
        )
        assert arm.muscle("Biceps Short").activation == 0.8
        assert arm.group_activation("Biceps Short + Biceps Long") == 0.8
        assert arm.hinge_angles().shape == (2,)
        assert arm.part_centres().shape == (len(arm.part_names), 2)


def test_moment_arms_and_hinge_torque():
    """Flexors have positive arms about the elbow, extensors negative; the
    hinge's muscle torque is Σ tension × arm."""
    with sinew.Model("arm") as arm:
        arm.set_activation(0, 1.0)
        arm.set_activation(2, 0.5)
        arm.step(10)
        arms = arm.moment_arms("Elbow")
        assert arms[0] > 0.0 and arms[1] > 0.0 and (arms[2:] < 0.0).all()
        load = arm.hinge_loads()[1]
        torques = arm.muscle_torques("Elbow")
        assert load["muscle_torque"] == pytest.approx(torques.sum(), rel=1e-12)
        assert arm.crosses("Biceps Long", "Shoulder") and not arm.crosses("Triceps Medial", "Shoulder")
        assert arm.muscle("Biceps Short").moment_arm("Elbow") == arms[0]


def test_bone_stress_and_glue_loads():
    with sinew.Model("arm", weight=5, weld_glues=True) as arm:
        arm.set_activation("Biceps Short", 0.6)
        arm.step(20)
        stress = arm.bone_stress()
        humerus = arm.bone_names.index("Humerus")
        assert stress["safety_factor"][humerus] > 1.0
        assert stress["strain"][humerus] == pytest.approx(
            stress["stress"][humerus] / arm.bone_beam("Humerus").youngs_modulus, rel=1e-12
        )
        assert np.isfinite(arm.glue_loads()["force_x"]).all()
        sections = arm.bone_sections("Humerus", 8)
        assert sections.shape == (8,) and np.all(np.diff(sections["s"]) > 0)


def test_inverse_dynamics_at_rest_is_the_weight_moment():
    """With every rate and acceleration 0 the net torque about the elbow
    balances the weight of what hangs beyond it:
    τ = Σ m·g·(c.x - p.x) over the bodies on the forearm's side, c their
    centres of mass, p the elbow's pivot (the elbow is the arm's last
    hinge, and the forearm, hand and weight are one merged body)."""
    with sinew.Model("arm", weight=10) as arm:
        arm.check_tree()
        angles = arm.hinge_angles()
        torques = arm.inverse_dynamics(angles, np.zeros(2), np.zeros(2))
        elbow = arm.hinge_joint("Elbow")
        forearm = elbow.body_b
        pivot = elbow.anchor_b
        expected = forearm.mass * 9.8 * (forearm.world_center.x - pivot.x)
        assert torques[1] == pytest.approx(expected, rel=1e-6)
        with pytest.raises(sinew.InvalidArgument, match="2 values"):
            arm.inverse_dynamics([0.0], [0.0], [0.0])
    with sinew.Model("leg") as leg:  # a chain closed between two nails
        with pytest.raises(sinew.InvalidArgument, match="loop"):
            leg.check_tree()


def test_energy_and_failure():
    with sinew.Model("arm") as arm:
        arm.set_activation("Biceps Short", 1.0)
        arm.step(60)
        energy = arm.energy
        assert energy.created == energy.mechanical - energy.at_start - energy.muscle_work
        assert energy.created < 1.0  # MU_MODEL_MAX_CREATED_ENERGY
        assert energy.muscle_work > 0.0
        assert arm.failure is None
