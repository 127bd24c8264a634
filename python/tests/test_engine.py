# SPDX-License-Identifier: MIT
"""The engine from Python against closed forms: free fall under
semi-implicit Euler, a ray's hit on a circle, a pin's static reaction; and
the queries, events, settings, statistics and state hash."""
import math

import pytest

import sinew

G = 9.8


def test_free_fall_follows_semi_implicit_euler_exactly(world):
    """N substeps of h from rest: v_N = -g·N·h, y_N = y0 - g·h²·N(N+1)/2."""
    body = world.create_body("dynamic", position=(0.0, 10.0))
    body.add_circle(0.1, density=2.0)
    substeps = world.solver.substeps
    for _ in range(60):
        world.step(1.0 / 60.0)
    n, h = 60 * substeps, 1.0 / (60.0 * substeps)
    assert body.linear_velocity.y == pytest.approx(-G * n * h, rel=1e-12)
    assert body.position.y == pytest.approx(10.0 - G * h * h * n * (n + 1) / 2.0, rel=1e-12)
    assert body.mass == pytest.approx(2.0 * math.pi * 0.01, rel=1e-14)


def test_ray_cast_hits_a_circle_where_geometry_says(world):
    ball = world.create_body(position=(3.0, 0.0))
    shape = ball.add_circle(0.5)
    hit = world.ray_cast((0.0, 0.0), (10.0, 0.0))
    assert hit.shape == shape and hit.body == ball
    assert hit.fraction == pytest.approx(0.25, abs=1e-14)
    assert hit.point.x == pytest.approx(2.5, abs=1e-14) and hit.point.y == pytest.approx(0.0, abs=1e-14)
    assert tuple(hit.normal) == pytest.approx((-1.0, 0.0), abs=1e-14)
    assert world.ray_cast((0.0, 5.0), (10.0, 0.0)) is None
    second = world.create_body(position=(6.0, 0.0)).add_circle(0.5)
    assert [h.shape for h in world.ray_cast_all((0.0, 0.0), (10.0, 0.0))] == [shape, second]
    assert world.overlap_point((3.2, 0.1)) == [shape]
    assert world.overlap_aabb((5.0, -1.0), (7.0, 1.0)) == [second]


def test_a_pin_at_rest_carries_the_weight(world):
    """A body hanging still under a pin: the reaction on it is m·g up."""
    ground = world.create_body()
    bob = world.create_body("dynamic", position=(0.0, -1.0))
    bob.add_circle(0.1, density=50.0)
    pin = world.create_revolute_joint(ground, bob, (0.0, 0.0))
    for _ in range(30):
        world.step(1.0 / 60.0)
    assert pin.reaction_force.y == pytest.approx(bob.mass * G, rel=1e-9)
    assert pin.reaction_force.x == pytest.approx(0.0, abs=1e-9)
    assert pin.angle == pytest.approx(0.0, abs=1e-12)
    assert pin.body_a == ground and pin.body_b == bob
    assert isinstance(pin, sinew.RevoluteJoint) and pin.type == "revolute"


def test_contact_and_sensor_events(world):
    floor = world.create_body()
    floor_shape = floor.add_box(5.0, 0.5)
    sensor = floor.add_circle(0.3, center=(0.0, 1.5), is_sensor=True)
    ball = world.create_body("dynamic", position=(0.0, 3.0))
    ball_shape = ball.add_circle(0.25, restitution=0.0)
    began, entered = [], []
    for _ in range(120):
        world.step(1.0 / 60.0)
        began += world.contact_events.begin
        entered += world.sensor_events.begin
    assert [(a, b) for a, b, _ in began] in ([(floor_shape, ball_shape)], [(ball_shape, floor_shape)])
    assert entered == [(sensor, ball_shape)]
    contacts = world.contacts
    assert len(contacts) == 1 and contacts[0].touching
    assert contacts[0].manifold.points[0].normal_impulse > 0.0
    # Resting on the floor: the top face is at y = 0.5, the ball's centre a radius above.
    assert ball.position.y == pytest.approx(0.75, abs=0.01)
    stats = world.statistics
    assert stats.body_count == 2 and stats.shape_count == 3 and stats.contact_count == 1
    assert all(value >= 0.0 for value in world.profile)


def test_pre_solve_can_disable_a_contact(world):
    floor = world.create_body().add_box(5.0, 0.5)
    ball = world.create_body("dynamic", position=(0.0, 2.0))
    ball_shape = ball.add_circle(0.25)
    asked = set()

    def refuse(a, b, manifold):
        asked.add(frozenset((a, b)))
        assert manifold.points
        return False

    world.set_pre_solve(refuse)
    for _ in range(60):
        world.step(1.0 / 60.0)
    assert asked == {frozenset((floor, ball_shape))}
    assert ball.position.y < 0.0  # fell through


def test_solver_settings_round_trip(world):
    settings = world.solver
    assert settings == sinew.SolverSettings()
    settings.type, settings.substeps, settings.velocity_iterations = "soft_step", 4, 3
    world.solver = settings
    assert world.solver.type == "soft_step" and world.solver.substeps == 4
    with pytest.raises(sinew.InvalidArgument, match="baumgarte"):
        world.solver = sinew.SolverSettings(type="baumgarte", substeps=2, baumgarte=2.0)


def test_state_hash_tells_identical_states():
    def build():
        w = sinew.World()
        w.create_body().add_box(5.0, 0.5)
        for k in range(4):
            w.create_body("dynamic", position=(0.1 * k, 1.0 + 0.6 * k)).add_box(0.25, 0.25)
        return w

    with build() as a, build() as b:
        for _ in range(90):
            a.step(1.0 / 60.0)
            b.step(1.0 / 60.0)
        assert a.state_hash == b.state_hash
        b.step(1.0 / 60.0)
        assert a.state_hash != b.state_hash
        assert a.bytes_in_use > 0


def test_joints_and_cables(world):
    ground = world.create_body()
    slider = world.create_body("dynamic", position=(0.0, 0.0), gravity_scale=0.0)
    slider.add_box(0.1, 0.1)
    rail = world.create_prismatic_joint(ground, slider, (0.0, 0.0), (1.0, 0.0))
    rail.set_motor(True, speed=0.5, max_force=1000.0)
    for _ in range(60):
        world.step(1.0 / 60.0)
    assert rail.speed == pytest.approx(0.5, rel=1e-9)
    assert rail.translation == pytest.approx(0.5, rel=1e-2)
    assert slider.position.y == pytest.approx(0.0, abs=1e-9)

    a = world.create_body("dynamic", position=(-1.0, -1.0))
    a.add_circle(0.1)
    b = world.create_body("dynamic", position=(1.0, -1.0))
    b.add_circle(0.1)
    rope = world.create_pulley_joint(a, b, (-1.0, 1.0), (1.0, 1.0), (-1.0, -1.0), (1.0, -1.0))
    assert rope.length_a == pytest.approx(2.0) and rope.length_b == pytest.approx(2.0)
    bar = world.create_distance_joint(ground, a, (-1.0, 2.0), (-1.0, -1.0))
    assert bar.length == pytest.approx(3.0, rel=1e-12)

    anchor = world.create_body(position=(5.0, 0.0))
    weight = world.create_body("dynamic", position=(5.0, -1.0), gravity_scale=0.0)
    weight.add_circle(0.1)
    cable = world.create_cable([(anchor, (0.0, 0.0)), (weight, (0.0, 0.0))], tension=2.0)
    assert cable.length == pytest.approx(1.0, rel=1e-12)
    world.step(1.0 / 60.0)
    assert cable.tension == pytest.approx(2.0, rel=1e-12)
    assert weight.linear_velocity.y > 0.0  # pulled up towards the anchor
    assert [tuple(p) for p in cable.points][0] == pytest.approx((5.0, 0.0))
    # Handles of one object compare equal, of different families never.
    again = sinew.Cable(world, cable._id)
    assert again == cable and hash(again) == hash(cable) and again != weight
    cable.destroy()
    assert not again.valid
    with pytest.raises(sinew.StaleId):
        again.length


def test_mouse_weld_and_shapes(world):
    box = world.create_body("dynamic", position=(0.0, 0.0), gravity_scale=0.0)
    shape = box.add_box(0.5, 0.25, density=4.0, friction=0.3)
    assert shape.type == "polygon" and len(shape.geometry) == 4
    assert box.mass == pytest.approx(4.0 * 1.0 * 0.5, rel=1e-14)
    assert shape.friction == pytest.approx(0.3)
    shape.filter = (2, 0xFFFFFFFF, -1)
    assert shape.filter == sinew.Filter(2, 0xFFFFFFFF, -1)
    assert world.overlap_point((0.0, 0.0), category_bits=1, mask_bits=2) == [shape]
    assert world.overlap_point((0.0, 0.0), mask_bits=1) == []
    mouse = world.create_mouse_joint(box, (0.0, 0.0), max_force=1000.0)
    mouse.target = (1.0, 0.0)
    for _ in range(120):
        world.step(1.0 / 60.0)
    assert box.position.x == pytest.approx(1.0, abs=1e-2)
    other = world.create_body("dynamic", position=(1.0, 1.0), gravity_scale=0.0)
    other.add_circle(0.1)
    weld = world.create_weld_joint(box, other, (1.0, 0.5))
    assert weld.type == "weld" and weld.valid
    chain = world.create_body().add_chain([(0, -3), (1, -3), (2, -2.5)])
    assert [s.type for s in chain] == ["chain_segment", "chain_segment"]
