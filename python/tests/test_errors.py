# SPDX-License-Identifier: MIT
"""Every C error raises a sinew.Error carrying the C message; misuse (a
destroyed object, a closed world or model, a wrong type, NaN) raises and
never crashes the interpreter."""
import math

import pytest

import sinew


def test_a_c_error_raises_with_the_c_message(world):
    with pytest.raises(sinew.InvalidArgument) as caught:
        world.step(math.nan)
    assert str(caught.value) == "rb_world_step: dt is nan, expected a value in [1e-06, 10]"
    assert caught.value.status == "RB_ERR_INVALID_ARGUMENT"
    assert isinstance(caught.value, ValueError)  # and a sinew.Error
    with pytest.raises(sinew.InvalidArgument, match=r"^rb_world_step: dt is 20, expected a value in \[1e-06, 10\]$"):
        world.step(20.0)


def test_a_destroyed_body_raises_stale_id(world):
    body = world.create_body("dynamic", position=(0, 1))
    body.add_circle(0.1)
    body.destroy()
    assert not body.valid
    with pytest.raises(sinew.StaleId, match="rb_body_position: .* refers to a destroyed body"):
        body.position
    with pytest.raises(sinew.StaleId):
        body.apply_force((1.0, 0.0))
    with pytest.raises(sinew.StaleId):
        body.destroy()
    # A new body in the same slot is another body: the old handle stays stale.
    again = world.create_body("dynamic")
    assert again != body
    with pytest.raises(sinew.StaleId):
        body.linear_velocity


def test_destroyed_shapes_and_joints_raise(world):
    ground = world.create_body()
    bob = world.create_body("dynamic", position=(1, 0))
    shape = bob.add_circle(0.1)
    joint = world.create_revolute_joint(ground, bob, (0, 0))
    joint.destroy()
    with pytest.raises(sinew.StaleId, match="rb_revolute_joint_angle"):
        joint.angle
    bob.destroy()  # its shapes go with it
    with pytest.raises(sinew.StaleId):
        shape.friction


def test_a_body_of_another_world_raises_foreign_id(world):
    with sinew.World() as other:
        stranger = other.create_body("dynamic")
        local = world.create_body()
        with pytest.raises(sinew.ForeignId, match="belongs to another world"):
            world.create_revolute_joint(local, stranger, (0, 0))


def test_a_closed_world_raises_closed():
    world = sinew.World()
    body = world.create_body("dynamic")
    shape = body.add_circle(0.2)
    world.close()
    world.close()  # twice is fine
    for use in (lambda: world.step(0.01), lambda: body.position, lambda: shape.density, lambda: world.gravity):
        with pytest.raises(sinew.Closed):
            use()
    assert not body.valid


def test_the_world_lives_while_its_objects_do():
    """A body keeps its world: dropping every other reference frees nothing."""
    body = sinew.World().create_body("dynamic", position=(0, 3))
    body.add_circle(0.1)
    body.world.step(0.1)
    assert body.position.y < 3.0


def test_wrong_types_raise_type_error(world):
    body = world.create_body("dynamic")
    with pytest.raises(TypeError, match="dt must be a real number"):
        world.step("0.01")
    with pytest.raises(TypeError, match="position"):
        world.create_body("dynamic", position="ab")
    with pytest.raises(TypeError):
        body.apply_force(5.0)
    with pytest.raises(TypeError, match="expected a sinew.Body"):
        world.create_revolute_joint(body, "ground", (0, 0))
    with pytest.raises(TypeError, match="unknown field 'colour'"):
        world.create_body("dynamic", colour="red")
    with pytest.raises(TypeError):
        body.add_circle(None)
    with pytest.raises(TypeError):
        world.solver = {"substeps": 4}
    with sinew.Model("sample") as model:
        with pytest.raises(TypeError):
            model.set_activation("Muscle", "half")
        with pytest.raises(TypeError):
            model.step(1.5)
        with pytest.raises(sinew.InvalidArgument, match="32-bit"):
            model.set_activation(2**32, 0.5)


def test_nan_is_refused_by_the_c_side_with_its_message(world):
    body = world.create_body("dynamic")
    with pytest.raises(sinew.InvalidArgument, match="rb_body_set_linear_velocity"):
        body.linear_velocity = (math.nan, 0.0)
    with pytest.raises(sinew.InvalidArgument, match="rb_body_apply_torque"):
        body.apply_torque(math.inf)
    with pytest.raises(sinew.InvalidArgument, match="solver"):
        world.solver = sinew.SolverSettings(substeps=0)


def test_bad_geometry_raises_its_status(world):
    body = world.create_body("dynamic")
    with pytest.raises(sinew.DegenerateShape, match="rb_make_polygon: the points are collinear"):
        body.add_polygon([(0, 0), (1, 0), (2, 0)])
    with pytest.raises(sinew.NotConvex):
        body.add_polygon([(0, 0), (1, 0), (1, 1), (0, 1), (0.5, 0.5)])
    with pytest.raises(sinew.NoMass):
        body.add_segment((0, 0), (1, 0))


def test_model_errors_carry_the_c_message(tmp_path):
    with pytest.raises(sinew.InvalidArgument, match="/nonexistent/x.json: cannot open"):
        sinew.Model("/nonexistent/x.json")
    broken = tmp_path / "broken.json"
    broken.write_text('{\n  "name": "broken",\n  "bones": [ { "name": "B", "size": [0.1] } ]\n}\n')
    with pytest.raises(sinew.InvalidArgument, match=r"broken\.json:3:14: bones\[0\]: missing key \"centre\""):
        sinew.Model(str(broken))
    with pytest.raises(sinew.InvalidArgument, match="unknown model 'armm'"):
        sinew.Model("armm")
    with pytest.raises(sinew.InvalidArgument, match='unknown variant .* "All Muscles"'):
        sinew.Model("arm", variant="No Such")
    with pytest.raises(sinew.InvalidArgument, match="no such weight choice; its choices are 0, 1, 5, 10, 50, 100 kg"):
        sinew.Model("arm", weight=7)
    with sinew.Model("arm") as model:
        with pytest.raises(sinew.InvalidArgument, match="mu_model_set_activation: no muscle or group named 'Bicep'"):
            model.set_activation("Bicep", 0.5)
        with pytest.raises(sinew.InvalidArgument, match="mu_model_set_tension: .*nan"):
            model.set_tension("Biceps Short", math.nan)
        with pytest.raises(sinew.InvalidArgument, match="mu_model_recruit"):
            model.recruit("Torque Muscle", 3)


def test_a_closed_model_raises_closed():
    model = sinew.Model("arm")
    world = model.world
    body = model.body(1)
    muscle = model.muscle("Biceps Short")
    model.close()
    with pytest.raises(sinew.Closed):
        model.step()
    with pytest.raises(sinew.Closed):
        world.step(0.01)
    with pytest.raises(sinew.Closed):
        body.position
    with pytest.raises(sinew.Closed):
        muscle.activation
    with pytest.raises(sinew.Error, match="belongs to a Model"):
        world.close()


def test_a_control_file_error_names_file_and_line(tmp_path):
    control = tmp_path / "bad.txt"
    control.write_text('# comment\n0.5 activation "Biceps Short" 0.3\n1.0 ramp "Biceps Short" 0 0.4\n')
    with pytest.raises(sinew.InvalidArgument, match=r"bad\.txt:3: a ramp line takes 3 numbers"):
        sinew.run("arm", duration=1, control=str(control))
    control.write_text('0.5 activation "Biceps Short" 1.5\n')
    with pytest.raises(sinew.InvalidArgument, match=r"bad\.txt:1: .*from 0 to 1, got 1.5"):
        sinew.run("arm", duration=1, control=str(control))


def test_an_exception_in_a_callback_is_raised_by_the_step(world):
    body = world.create_body("dynamic")
    body.add_circle(0.1)

    def fails(_world, substep, _h):
        raise RuntimeError(f"substep {substep}")

    world.set_substep_callback(fails)
    with pytest.raises(RuntimeError, match="substep 0"):
        world.step(1 / 60)
    world.set_substep_callback(None)
    world.step(1 / 60)


def test_changing_the_world_inside_its_step_raises_locked(world):
    world.create_body("dynamic").add_circle(0.1)
    world.set_substep_callback(lambda w, substep, h: w.create_body("dynamic"))
    with pytest.raises(sinew.Locked, match="rb_body_create"):
        world.step(1 / 60)
