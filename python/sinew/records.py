# SPDX-License-Identifier: MIT
"""Plain values the API returns: vectors, mass data, statistics, profiles,
contacts, events and ray hits, as named tuples (immutable, unpackable,
``._asdict()`` for a dict). Units are those of the C headers: metres,
radians, seconds, kilograms, newtons."""
from collections import namedtuple

from . import _api

#: A vector in the plane: x right, y up (m, m/s, N, ... as the call says).
Vec2 = namedtuple("Vec2", "x y")
#: A rigid transform: the origin's position p (m) and the angle (rad).
Transform = namedtuple("Transform", "position angle")
#: An axis-aligned box (m, world).
AABB = namedtuple("AABB", "lower upper")
#: Mass (kg), centre of mass in the body frame (m), inertia about it (kg·m²).
MassData = namedtuple("MassData", "mass center rotational_inertia")
#: One contact point: world point (m), separation (m, < 0 overlapping), feature
#: id, and the last step's normal and friction impulses (N·s).
ManifoldPoint = namedtuple("ManifoldPoint", "point separation id normal_impulse tangent_impulse")
#: A contact manifold: unit normal from shape A to B, and its points.
Manifold = namedtuple("Manifold", "normal points reference_on_b")
#: A contact of the world: its shapes and bodies, touching, sensor, manifold.
Contact = namedtuple("Contact", "shape_a shape_b body_a body_b touching sensor manifold")
#: A ray hit: shape, body, world point (m), outward unit normal, fraction 0..1.
RayHit = namedtuple("RayHit", "shape body point normal fraction")
#: The events of the last step: lists of (shape_a, shape_b[, manifold]).
ContactEvents = namedtuple("ContactEvents", "begin end")
#: Sensor events of the last step: lists of (sensor, visitor) shape pairs.
SensorEvents = namedtuple("SensorEvents", "begin end")
#: Counters of the last step (rb_statistics; energy in J, lengths in m, angles in rad).
Statistics = namedtuple("Statistics", [name for name, _ in _api.Statistics._fields_])
#: Milliseconds spent in each phase of the last step (rb_profile).
Profile = namedtuple("Profile", _api.PROFILE_FIELDS)
#: Collision filter: category bits, mask bits, group index (rb/shape.h).
Filter = namedtuple("Filter", "category_bits mask_bits group_index")


def vec2(v):
    return Vec2(v.x, v.y)


def mass_data(m):
    return MassData(m.mass, vec2(m.center), m.rotational_inertia)


def manifold(m):
    points = tuple(
        ManifoldPoint(vec2(p.point), p.separation, p.id, p.normal_impulse, p.tangent_impulse)
        for p in m.points[: m.point_count]
    )
    return Manifold(vec2(m.normal), points, bool(m.reference_on_b))


def structure(cls, value):
    """A named tuple of the fields of a ctypes structure of numbers."""
    return cls(*(getattr(value, name) for name in cls._fields))
