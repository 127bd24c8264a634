# SPDX-License-Identifier: MIT
"""What every handle to an engine object has (bodies, shapes, joints,
cables): its world and its id, C calls made through them, equality by id,
validity and destruction. The C side checks every id: a destroyed
object's raises StaleId with the C message, another world's ForeignId."""

from ._lib import rb
from .errors import check, checked


class Handle:
    """A handle to one object of a world. Subclasses name their family
    (_FAMILY: "Body", "Shape", ...), id struct (_ID), and the C functions
    that test and destroy one (_IS_VALID, _DESTROY: rb_ function names)."""

    __slots__ = ("_world", "_id")
    _FAMILY = _ID = _IS_VALID = _DESTROY = None

    def __init__(self, world, object_id):
        self._world = world
        self._id = self._ID(object_id.index, object_id.generation, object_id.world)

    def _get(self, function, *args):
        return checked(function, self._world._w, self._id, *args)

    def _set(self, function, *args):
        check(function(self._world._w, self._id, *args))

    @property
    def world(self):
        return self._world

    @property
    def key(self):
        """(index, generation, world serial): equal for handles of one object."""
        return (self._id.index, self._id.generation, self._id.world)

    def __eq__(self, other):
        return isinstance(other, Handle) and other._FAMILY == self._FAMILY and other.key == self.key

    def __hash__(self):
        return hash((self._FAMILY,) + self.key)

    def __repr__(self):
        return f"<sinew.{type(self).__name__} {self._id.index}.{self._id.generation}>"

    @property
    def valid(self):
        """False once the object is destroyed (or its world closed)."""
        return not self._world.closed and bool(getattr(rb, self._IS_VALID)(self._world._w, self._id))

    def destroy(self):
        self._set(getattr(rb, self._DESTROY))
