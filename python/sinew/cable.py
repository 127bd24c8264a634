# SPDX-License-Identifier: MIT
"""Cables (rb/cable.h): a path of body points carrying a tension
T = base_tension + damping·L' (never below 0), solved implicitly; made by
``World.create_cable``. The muscles of a model pull through cables."""
import ctypes

from . import _api, records
from ._handle import Handle
from ._lib import rb
from .errors import check, checked, real


class Cable(Handle):
    """A cable of a world. Equal handles compare equal."""

    __slots__ = ()
    _FAMILY, _ID, _IS_VALID, _DESTROY = "Cable", _api.CableId, "rb_cable_is_valid", "rb_cable_destroy"

    def set_tension_law(self, base_tension, damping=0.0):
        """T = base_tension (N) + damping (N·s/m) · lengthening speed, from the next step."""
        check(
            rb.rb_cable_set_tension_law(
                self._world._w, self._id, real("base_tension", base_tension), real("damping", damping)
            )
        )

    @property
    def length(self):
        """m, the path's length now."""
        return self.state[0]

    @property
    def lengthening_speed(self):
        """m/s, < 0 while shortening."""
        return self.state[1]

    @property
    def state(self):
        """(length m, lengthening speed m/s) in one pass over the path."""
        length, speed = ctypes.c_double(), ctypes.c_double()
        check(rb.rb_cable_state(self._world._w, self._id, ctypes.byref(length), ctypes.byref(speed)))
        return length.value, speed.value

    @property
    def tension(self):
        """N, >= 0, carried in the last substep."""
        return checked(rb.rb_cable_tension, self._world._w, self._id)

    @property
    def points(self):
        """The path's world points now (m)."""
        out = (_api.Vec2 * _api.MAX_CABLE_POINTS)()
        count = checked(rb.rb_cable_points, self._world._w, self._id, out, _api.MAX_CABLE_POINTS)
        return [records.vec2(out[k]) for k in range(count)]
