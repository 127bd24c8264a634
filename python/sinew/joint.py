# SPDX-License-Identifier: MIT
"""Joints (rb/joint.h): revolute, weld, distance, mouse, prismatic and
pulley, made by the ``World.create_*_joint`` methods, which take the
definition's fields by name (rb/joint.h gives each one's range).

Angles are in radians, lengths in metres, forces in newtons, torques in
N·m; a joint's reaction is what it applied to body B over the last
substep of the last step.
"""
import ctypes

from . import _api, records
from ._handle import Handle
from ._lib import rb
from .errors import boolean, check, checked, pair, real
from .world import set_fields

#: rb_joint_type names, in the enum's order.
JOINT_TYPES = ("revolute", "weld", "distance", "mouse", "prismatic", "pulley")

_CREATE = {
    "revolute": "rb_revolute_joint_create",
    "weld": "rb_weld_joint_create",
    "distance": "rb_distance_joint_create",
    "mouse": "rb_mouse_joint_create",
    "prismatic": "rb_prismatic_joint_create",
    "pulley": "rb_pulley_joint_create",
}


def make_joint(world, kind, definition, fields):
    set_fields(definition, f"create_{kind}_joint", fields)
    out = _api.JointId()
    check(getattr(rb, _CREATE[kind])(world._w, ctypes.byref(definition), ctypes.byref(out)))
    return _CLASSES[kind](world, out)


class Joint(Handle):
    """What every joint has: its bodies, anchors and reaction."""

    __slots__ = ()
    _FAMILY, _ID, _IS_VALID, _DESTROY = "Joint", _api.JointId, "rb_joint_is_valid", "rb_joint_destroy"

    @property
    def type(self):
        """"revolute", "weld", "distance", "mouse", "prismatic" or "pulley"."""
        return JOINT_TYPES[self._get(rb.rb_joint_type_of)]

    @property
    def body_a(self):
        """Body A, or None for a mouse joint."""
        from .body import Body

        body = self._get(rb.rb_joint_body_a)
        return None if body.generation == 0 else Body(self._world, body)

    @property
    def body_b(self):
        from .body import Body

        return Body(self._world, self._get(rb.rb_joint_body_b))

    @property
    def anchor_a(self):
        """m, world; the target of a mouse joint."""
        return records.vec2(self._get(rb.rb_joint_world_anchor_a))

    @property
    def anchor_b(self):
        """m, world."""
        return records.vec2(self._get(rb.rb_joint_world_anchor_b))

    @property
    def reaction_force(self):
        """N, world frame: what the joint applied to body B in the last substep."""
        return records.vec2(self._get(rb.rb_joint_reaction_force))

    @property
    def reaction_torque(self):
        """N·m, counter-clockwise, on body B."""
        return self._get(rb.rb_joint_reaction_torque)


class RevoluteJoint(Joint):
    """A pin; its angle is angle(B) - angle(A) - reference angle (rad)."""

    __slots__ = ()

    @property
    def angle(self):
        """rad, continuous."""
        return self._get(rb.rb_revolute_joint_angle)

    @property
    def speed(self):
        """rad/s, ωB - ωA."""
        return self._get(rb.rb_revolute_joint_speed)

    @property
    def motor_torque(self):
        """N·m the motor applied in the last step."""
        return self._get(rb.rb_revolute_joint_motor_torque)

    def set_motor(self, enable, speed=0.0, max_torque=0.0):
        """Drives the speed (rad/s) with at most max_torque (N·m)."""
        self._set(
            rb.rb_revolute_joint_set_motor, boolean("enable", enable), real("speed", speed),
            real("max_torque", max_torque),
        )

    def set_limits(self, lower=None, upper=None):
        """Angle limits (rad); None leaves that side free."""
        self._set(
            rb.rb_revolute_joint_set_limits,
            lower is not None, real("lower", 0.0 if lower is None else lower),
            upper is not None, real("upper", 0.0 if upper is None else upper),
        )

    def set_spring(self, enable, hertz=0.0, damping_ratio=0.0):
        """A spring towards angle 0 of ``hertz`` Hz."""
        self._set(
            rb.rb_revolute_joint_set_spring, boolean("enable", enable), real("hertz", hertz),
            real("damping_ratio", damping_ratio),
        )


class WeldJoint(Joint):
    """Freezes the relative pose (softened by its hertz fields)."""

    __slots__ = ()


class DistanceJoint(Joint):
    """A bar, spring or rope between the anchors."""

    __slots__ = ()

    @property
    def length(self):
        """m, the anchors' distance now."""
        return self._get(rb.rb_distance_joint_current_length)


class MouseJoint(Joint):
    """Pulls a body point towards a target with a bounded force."""

    __slots__ = ()

    @property
    def target(self):
        """m, world (write to move it)."""
        return self.anchor_a

    @target.setter
    def target(self, value):
        self._set(rb.rb_mouse_joint_set_target, _api.Vec2(*pair("target", value)))


class PrismaticJoint(Joint):
    """Body B slides along an axis fixed in body A."""

    __slots__ = ()

    @property
    def translation(self):
        """m along the axis."""
        return self._get(rb.rb_prismatic_joint_translation)

    @property
    def speed(self):
        """m/s, the translation's rate."""
        return self._get(rb.rb_prismatic_joint_speed)

    @property
    def motor_force(self):
        """N the motor applied along the axis in the last step."""
        return self._get(rb.rb_prismatic_joint_motor_force)

    def set_motor(self, enable, speed=0.0, max_force=0.0):
        self._set(
            rb.rb_prismatic_joint_set_motor, boolean("enable", enable), real("speed", speed),
            real("max_force", max_force),
        )

    def set_limits(self, lower=None, upper=None):
        """Translation limits (m); None leaves that side free."""
        self._set(
            rb.rb_prismatic_joint_set_limits,
            lower is not None, real("lower", 0.0 if lower is None else lower),
            upper is not None, real("upper", 0.0 if upper is None else upper),
        )

    def set_spring(self, enable, hertz=0.0, damping_ratio=0.0):
        self._set(
            rb.rb_prismatic_joint_set_spring, boolean("enable", enable), real("hertz", hertz),
            real("damping_ratio", damping_ratio),
        )


class PulleyJoint(Joint):
    """A rope over two fixed pulleys."""

    __slots__ = ()

    @property
    def length_a(self):
        """m, |anchor A - ground A| now."""
        return self._get(rb.rb_pulley_joint_length_a)

    @property
    def length_b(self):
        return self._get(rb.rb_pulley_joint_length_b)


_CLASSES = {
    "revolute": RevoluteJoint,
    "weld": WeldJoint,
    "distance": DistanceJoint,
    "mouse": MouseJoint,
    "prismatic": PrismaticJoint,
    "pulley": PulleyJoint,
}


def joint_of(world, joint_id):
    """The Joint of the right class for an id (None for the null id)."""
    if joint_id.generation == 0:
        return None
    kind = JOINT_TYPES[checked(rb.rb_joint_type_of, world._w, joint_id)]
    return _CLASSES[kind](world, joint_id)
