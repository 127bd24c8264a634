# SPDX-License-Identifier: MIT
"""Shapes (rb/shape.h): the geometry and material attached to a body,
made by ``Body.add_circle``, ``add_box``, ``add_polygon``, ``add_segment``
and ``add_chain``. Friction mixes as the geometric mean, restitution as
the larger of two touching shapes'."""
import ctypes

from . import _api, errors, records
from ._handle import Handle
from ._lib import rb
from .errors import bits, boolean, check, integer, pair, real

#: rb_shape_type names, in the enum's order.
SHAPE_TYPES = ("circle", "polygon", "segment", "chain_segment")


def _shape_def(material):
    definition = rb.rb_default_shape_def()
    for name, value in material.items():
        if name == "filter":
            definition.filter = _filter(value)
        elif name in ("friction", "restitution", "density"):
            setattr(definition, name, real(name, value))
        elif name == "is_sensor":
            definition.is_sensor = boolean(name, value)
        else:
            raise TypeError(f"unknown shape material {name!r} (friction, restitution, density, is_sensor, filter)")
    return definition


def _filter(value):
    try:
        category, mask, group = value
    except (TypeError, ValueError):
        raise TypeError(f"filter must be (category_bits, mask_bits, group_index), got {value!r}") from None
    return _api.Filter(bits("category_bits", category), bits("mask_bits", mask), integer("group_index", group))


def create(body, function, geometry, material):
    definition = _shape_def(material)
    out = _api.ShapeId()
    check(function(body._world._w, body._id, ctypes.byref(definition), geometry, ctypes.byref(out)))
    return Shape(body._world, out)


def create_chain(body, points, loop, material):
    definition = _shape_def(material)
    points = [_api.Vec2(*pair(f"points[{k}]", p)) for k, p in enumerate(points)]
    array = (_api.Vec2 * max(len(points), 1))(*points)
    count = len(points) if loop else max(len(points) - 1, 0)
    out = (_api.ShapeId * max(count, 1))()
    check(
        rb.rb_shape_create_chain(
            body._world._w, body._id, ctypes.byref(definition), array, len(points), boolean("loop", loop), out, count
        )
    )
    return [Shape(body._world, out[k]) for k in range(count)]


def make_polygon_box(hx, hy, center, angle):
    polygon = _api.Polygon()
    if center is None and angle == 0.0:
        check(rb.rb_make_box(real("hx", hx), real("hy", hy), ctypes.byref(polygon)))
    else:
        center = (0.0, 0.0) if center is None else center
        check(
            rb.rb_make_offset_box(
                real("hx", hx), real("hy", hy), _api.Vec2(*pair("center", center)), real("angle", angle),
                ctypes.byref(polygon),
            )
        )
    return polygon


def make_polygon(points, hull):
    points = [_api.Vec2(*pair(f"points[{k}]", p)) for k, p in enumerate(points)]
    array = (_api.Vec2 * max(len(points), 1))(*points)
    polygon = _api.Polygon()
    function = rb.rb_make_polygon_hull if hull else rb.rb_make_polygon
    check(function(array, len(points), ctypes.byref(polygon)))
    return polygon


class Shape(Handle):
    """A shape of a body. Equal handles compare equal."""

    __slots__ = ()
    _FAMILY, _ID, _IS_VALID, _DESTROY = "Shape", _api.ShapeId, "rb_shape_is_valid", "rb_shape_destroy"

    @property
    def type(self):
        """"circle", "polygon", "segment" or "chain_segment"."""
        return SHAPE_TYPES[self._get(rb.rb_shape_type_of)]

    @property
    def body(self):
        from .body import Body

        return Body(self._world, self._get(rb.rb_shape_body))

    @property
    def geometry(self):
        """In the body frame (m): a circle's (center, radius); a polygon's
        vertices; a segment's (point1, point2)."""
        kind = self.type
        if kind == "circle":
            c = self._get(rb.rb_shape_circle)
            return records.vec2(c.center), c.radius
        if kind == "polygon":
            p = self._get(rb.rb_shape_polygon)
            return [records.vec2(v) for v in p.vertices[: p.count]]
        s = self._get(rb.rb_shape_segment)
        return records.vec2(s.point1), records.vec2(s.point2)

    @property
    def aabb(self):
        """The tight bounding box at the body's present pose (m, world)."""
        box = self._get(rb.rb_shape_aabb)
        return records.AABB(records.vec2(box.lower), records.vec2(box.upper))

    @property
    def friction(self):
        """Coulomb coefficient, 0 .. 1e3."""
        return self._get(rb.rb_shape_friction)

    @friction.setter
    def friction(self, value):
        self._set(rb.rb_shape_set_friction, real("friction", value))

    @property
    def restitution(self):
        """0 .. 1."""
        return self._get(rb.rb_shape_restitution)

    @restitution.setter
    def restitution(self, value):
        self._set(rb.rb_shape_set_restitution, real("restitution", value))

    @property
    def density(self):
        """kg/m²; changing it recomputes the body's mass."""
        return self._get(rb.rb_shape_density)

    @density.setter
    def density(self, value):
        self._set(rb.rb_shape_set_density, real("density", value))

    @property
    def is_sensor(self):
        return bool(self._get(rb.rb_shape_is_sensor))

    @property
    def filter(self):
        """Filter(category_bits, mask_bits, group_index)."""
        f = self._get(rb.rb_shape_filter)
        return records.Filter(f.category_bits, f.mask_bits, f.group_index)

    @filter.setter
    def filter(self, value):
        self._set(rb.rb_shape_set_filter, _filter(value))

    @property
    def sensor_overlaps(self):
        """For a sensor: the non-sensor shapes overlapping it after the last step."""
        count = rb.rb_shape_sensor_overlaps(self._world._w, self._id, None, 0)
        if count < 0:
            errors.raise_status(rb.rb_last_status())
        out = (_api.ShapeId * max(count, 1))()
        count = rb.rb_shape_sensor_overlaps(self._world._w, self._id, out, count)
        return [Shape(self._world, out[k]) for k in range(count)]
