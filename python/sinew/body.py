# SPDX-License-Identifier: MIT
"""A rigid body (rb/body.h), addressed by its id in its world.

Positions are of the body's origin unless a name says "center" (the
centre of mass). A destroyed body's handle raises :class:`sinew.StaleId`
with the C message; a body of a closed world raises :class:`sinew.Closed`.
"""
import ctypes

from . import _api, errors, records
from ._handle import Handle
from ._lib import rb
from .errors import boolean, pair, real

#: rb_body_type names, in the enum's order.
BODY_TYPES = ("static", "kinematic", "dynamic")


def _v(name, value):
    return _api.Vec2(*pair(name, value))


class Body(Handle):
    """A body of a :class:`~sinew.World`; made by ``World.create_body``.
    ``destroy()`` destroys its shapes and contacts too."""

    __slots__ = ()
    _FAMILY, _ID, _IS_VALID, _DESTROY = "Body", _api.BodyId, "rb_body_is_valid", "rb_body_destroy"

    # ---------------------------------------------------------------- type

    @property
    def type(self):
        """"static", "kinematic" or "dynamic" (write to change)."""
        return BODY_TYPES[self._get(rb.rb_body_type_of)]

    @type.setter
    def type(self, value):
        if value not in BODY_TYPES:
            raise errors.InvalidArgument(f"Body.type must be one of {', '.join(BODY_TYPES)}, got {value!r}")
        self._set(rb.rb_body_set_type, BODY_TYPES.index(value))

    # ---------------------------------------------------------------- pose

    @property
    def position(self):
        """m, the origin's world position (write to move the body; see set_transform)."""
        return records.vec2(self._get(rb.rb_body_position))

    @position.setter
    def position(self, value):
        self.set_transform(value, self.angle)

    @property
    def angle(self):
        """rad, continuous (not wrapped)."""
        return self._get(rb.rb_body_angle)

    @angle.setter
    def angle(self, value):
        self.set_transform(self.position, value)

    @property
    def transform(self):
        """Transform(position (m), angle (rad))."""
        return records.Transform(self.position, self.angle)

    def set_transform(self, position, angle):
        """Puts the origin at ``position`` (m) turned by ``angle`` (rad)."""
        self._set(rb.rb_body_set_transform, _v("position", position), real("angle", angle))

    @property
    def world_center(self):
        """m, the centre of mass in the world."""
        return records.vec2(self._get(rb.rb_body_world_center))

    @property
    def local_center(self):
        """m, the centre of mass in the body frame."""
        return records.vec2(self._get(rb.rb_body_local_center))

    # ---------------------------------------------------------- velocities

    @property
    def linear_velocity(self):
        """m/s, of the centre of mass."""
        return records.vec2(self._get(rb.rb_body_linear_velocity))

    @linear_velocity.setter
    def linear_velocity(self, value):
        self._set(rb.rb_body_set_linear_velocity, _v("linear_velocity", value))

    @property
    def angular_velocity(self):
        """rad/s, counter-clockwise."""
        return self._get(rb.rb_body_angular_velocity)

    @angular_velocity.setter
    def angular_velocity(self, value):
        self._set(rb.rb_body_set_angular_velocity, real("angular_velocity", value))

    def point_velocity(self, world_point):
        """m/s of the material point now at ``world_point`` (m): v + ω × r."""
        return records.vec2(self._get(rb.rb_body_point_velocity, _v("world_point", world_point)))

    # ------------------------------------------------------------- frames

    def world_point(self, local_point):
        return records.vec2(self._get(rb.rb_body_world_point, _v("local_point", local_point)))

    def local_point(self, world_point):
        return records.vec2(self._get(rb.rb_body_local_point, _v("world_point", world_point)))

    def world_vector(self, local_vector):
        return records.vec2(self._get(rb.rb_body_world_vector, _v("local_vector", local_vector)))

    def local_vector(self, world_vector):
        return records.vec2(self._get(rb.rb_body_local_vector, _v("world_vector", world_vector)))

    # ---------------------------------------------------- forces, impulses

    def apply_force(self, force, point=None):
        """A force (N) for the next step, at a world point (m), or at the
        centre of mass when ``point`` is None. Wakes the body."""
        if point is None:
            self._set(rb.rb_body_apply_force_to_center, _v("force", force))
        else:
            self._set(rb.rb_body_apply_force, _v("force", force), _v("point", point))

    def apply_torque(self, torque):
        """A torque (N·m) for the next step."""
        self._set(rb.rb_body_apply_torque, real("torque", torque))

    def apply_impulse(self, impulse, point=None):
        """An impulse (N·s) now, at a world point (m) or the centre of mass."""
        if point is None:
            self._set(rb.rb_body_apply_linear_impulse_to_center, _v("impulse", impulse))
        else:
            self._set(rb.rb_body_apply_linear_impulse, _v("impulse", impulse), _v("point", point))

    def apply_angular_impulse(self, impulse):
        """An angular impulse (N·m·s) now."""
        self._set(rb.rb_body_apply_angular_impulse, real("impulse", impulse))

    @property
    def force(self):
        """N, accumulated for the next step."""
        return records.vec2(self._get(rb.rb_body_force))

    @property
    def torque(self):
        """N·m, accumulated for the next step."""
        return self._get(rb.rb_body_torque)

    # ---------------------------------------------------------------- mass

    @property
    def mass(self):
        """kg (0 for static and kinematic bodies)."""
        return self._get(rb.rb_body_mass)

    @property
    def rotational_inertia(self):
        """kg·m², about the centre of mass."""
        return self._get(rb.rb_body_rotational_inertia)

    @property
    def mass_data(self):
        """MassData(mass kg, center m in the body frame, rotational_inertia kg·m²);
        write one to override the shapes' mass, None to go back to them."""
        return records.mass_data(self._get(rb.rb_body_mass_data))

    @mass_data.setter
    def mass_data(self, value):
        if value is None:
            self._set(rb.rb_body_reset_mass_data)
            return
        mass, center, inertia = value
        data = _api.MassData(real("mass", mass), _v("center", center), real("rotational_inertia", inertia))
        self._set(rb.rb_body_set_mass_data, ctypes.byref(data))

    # ---------------------------------------------------- damping and flags

    @property
    def linear_damping(self):
        """1/s, 0 .. 1e6."""
        return self._get(rb.rb_body_linear_damping)

    @linear_damping.setter
    def linear_damping(self, value):
        self._set(rb.rb_body_set_linear_damping, real("linear_damping", value))

    @property
    def angular_damping(self):
        """1/s, 0 .. 1e6."""
        return self._get(rb.rb_body_angular_damping)

    @angular_damping.setter
    def angular_damping(self, value):
        self._set(rb.rb_body_set_angular_damping, real("angular_damping", value))

    @property
    def gravity_scale(self):
        """Multiplies the world's gravity, within ±1e6."""
        return self._get(rb.rb_body_gravity_scale)

    @gravity_scale.setter
    def gravity_scale(self, value):
        self._set(rb.rb_body_set_gravity_scale, real("gravity_scale", value))

    @property
    def fixed_rotation(self):
        return bool(self._get(rb.rb_body_is_fixed_rotation))

    @fixed_rotation.setter
    def fixed_rotation(self, value):
        self._set(rb.rb_body_set_fixed_rotation, boolean("fixed_rotation", value))

    @property
    def awake(self):
        return bool(self._get(rb.rb_body_is_awake))

    @awake.setter
    def awake(self, value):
        self._set(rb.rb_body_set_awake, boolean("awake", value))

    @property
    def sleep_enabled(self):
        return bool(self._get(rb.rb_body_is_sleep_enabled))

    @sleep_enabled.setter
    def sleep_enabled(self, value):
        self._set(rb.rb_body_enable_sleep, boolean("sleep_enabled", value))

    @property
    def bullet(self):
        return bool(self._get(rb.rb_body_is_bullet))

    @bullet.setter
    def bullet(self, value):
        self._set(rb.rb_body_set_bullet, boolean("bullet", value))

    # -------------------------------------------------------------- shapes

    @property
    def shapes(self):
        """The body's shapes, in creation order."""
        from .shape import Shape

        count = self._get(rb.rb_body_shape_count)
        out = (_api.ShapeId * max(count, 1))()
        count = self._get(rb.rb_body_shapes, out, count)
        return [Shape(self._world, out[k]) for k in range(count)]

    def add_circle(self, radius, center=(0.0, 0.0), **material):
        """A circle of ``radius`` m centred at ``center`` (m, body frame).
        Material by name: friction, restitution, density (kg/m², default 1),
        is_sensor, filter (a Filter or (category, mask, group))."""
        from .shape import create

        circle = _api.Circle(_v("center", center), real("radius", radius))
        return create(self, rb.rb_shape_create_circle, ctypes.byref(circle), material)

    def add_box(self, hx, hy, center=None, angle=0.0, **material):
        """A box of half-extents ``hx``, ``hy`` (m), centred on the origin
        or at ``center`` (m) turned by ``angle`` (rad)."""
        from .shape import create, make_polygon_box

        polygon = make_polygon_box(hx, hy, center, angle)
        return create(self, rb.rb_shape_create_polygon, ctypes.byref(polygon), material)

    def add_polygon(self, points, hull=False, **material):
        """A convex polygon with exactly these 3 .. 8 vertices (m, body frame;
        NotConvex otherwise), or with ``hull`` their convex hull."""
        from .shape import create, make_polygon

        polygon = make_polygon(points, hull)
        return create(self, rb.rb_shape_create_polygon, ctypes.byref(polygon), material)

    def add_segment(self, point1, point2, **material):
        """A two-sided segment between two points (m, body frame); no mass."""
        from .shape import create

        segment = _api.Segment(_v("point1", point1), _v("point2", point2))
        return create(self, rb.rb_shape_create_segment, ctypes.byref(segment), material)

    def add_chain(self, points, loop=False, **material):
        """A chain of one-sided segments through ``points`` (m, body frame),
        facing left of their order; closed when ``loop``. Returns its shapes."""
        from .shape import create_chain

        return create_chain(self, points, loop, material)
