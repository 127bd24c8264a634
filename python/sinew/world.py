# SPDX-License-Identifier: MIT
"""The world (rb/world.h): bodies, shapes, joints and cables, the step that
advances them, the solver's settings, statistics and profile, the state
hash, queries (rb/query.h) and events (rb/events.h).

A :class:`World` owns its C world: ``close()`` (or leaving a ``with``
block, or the garbage collector) frees it, after which every call on it
or on one of its objects raises :class:`sinew.Closed`. The objects
(:class:`~sinew.Body`, :class:`~sinew.Shape`, :class:`~sinew.Joint`,
:class:`~sinew.Cable`) keep a reference to their world, so the world lives
as long as any of them is reachable.
"""
import ctypes
from dataclasses import dataclass, fields

from . import _api, errors, records
from ._lib import rb
from .errors import boolean, check, checked, integer, pair, real

#: rb_solver_type names, in the enum's order.
SOLVER_TYPES = ("baumgarte", "ngs", "soft_step")


@dataclass
class SolverSettings:
    """The solver of a world (rb_solver_settings; ranges in rb/world.h).

    type: "baumgarte", "ngs" or "soft_step"; iterations and substeps per
    step; baumgarte (fraction per substep), linear_slop (m),
    max_linear_correction (m), restitution_threshold (m/s), contact_hertz
    and joint_hertz (Hz), damping ratios, max_push_speed (m/s)."""

    type: str = "ngs"
    velocity_iterations: int = 2
    position_iterations: int = 1
    relax_iterations: int = 1
    substeps: int = 6
    warm_starting: bool = True
    block_solver: bool = True
    tree_pins: bool = True
    baumgarte: float = 0.2
    linear_slop: float = 0.005
    max_linear_correction: float = 0.2
    restitution_threshold: float = 1.0
    contact_hertz: float = 30.0
    contact_damping_ratio: float = 10.0
    joint_hertz: float = 60.0
    joint_damping_ratio: float = 2.0
    max_push_speed: float = 3.0

    @classmethod
    def _from_c(cls, c):
        values = {f.name: getattr(c, f.name) for f in fields(cls) if f.name != "type"}
        return cls(type=SOLVER_TYPES[c.type] if 0 <= c.type < len(SOLVER_TYPES) else str(c.type), **values)

    def _to_c(self):
        c = rb.rb_default_solver_settings()
        if self.type not in SOLVER_TYPES:
            raise errors.InvalidArgument(
                f"SolverSettings.type: expected one of {', '.join(SOLVER_TYPES)}, got {self.type!r}"
            )
        c.type = SOLVER_TYPES.index(self.type)
        for f in fields(self):
            if f.name == "type":
                continue
            value = getattr(self, f.name)
            if f.type is int or f.type == "int":
                setattr(c, f.name, integer(f"SolverSettings.{f.name}", value))
            elif f.type is bool or f.type == "bool":
                setattr(c, f.name, boolean(f"SolverSettings.{f.name}", value))
            else:
                setattr(c, f.name, real(f"SolverSettings.{f.name}", value))
        return c


def set_fields(structure, what, values):
    """Sets fields of a C definition from keyword arguments, converting each
    to its C type; an unknown name is a TypeError listing the known ones."""
    known = {name: kind for name, kind in structure._fields_}
    for name, value in values.items():
        if name in ("internal_value", "user_data") or name not in known:
            choices = ", ".join(n for n in known if n not in ("internal_value", "user_data"))
            raise TypeError(f"{what}: unknown field {name!r} (fields: {choices})")
        kind = known[name]
        if kind is _api.Vec2:
            setattr(structure, name, _api.Vec2(*pair(name, value)))
        elif kind is ctypes.c_bool:
            setattr(structure, name, boolean(name, value))
        elif kind is ctypes.c_double:
            setattr(structure, name, real(name, value))
        elif kind is ctypes.c_uint32:
            setattr(structure, name, errors.bits(name, value))
        elif kind in (ctypes.c_int, ctypes.c_int32):
            setattr(structure, name, integer(name, value))
        else:
            raise TypeError(f"{what}: field {name!r} is set by the function's own arguments")


class World:
    """A simulation world (rb_world).

    ``World(gravity=(0, -9.8), solver=SolverSettings(), enable_profile=True,
    enable_sleep=True)``; gravity in m/s². Use it as a context manager, or
    call :meth:`close`, to free the C world at a known time."""

    def __init__(self, gravity=(0.0, -9.8), solver=None, enable_profile=True, enable_sleep=True):
        definition = rb.rb_default_world_def()
        definition.gravity = _api.Vec2(*pair("gravity", gravity))
        if solver is not None:
            if not isinstance(solver, SolverSettings):
                raise TypeError(f"solver must be a SolverSettings, got {type(solver).__name__}")
            definition.solver = solver._to_c()
        definition.enable_profile = boolean("enable_profile", enable_profile)
        definition.enable_sleep = boolean("enable_sleep", enable_sleep)
        pointer = ctypes.c_void_p()
        check(rb.rb_world_create(ctypes.byref(definition), ctypes.byref(pointer)))
        self._pointer = pointer.value
        self._owner = None  # a Model, when the model owns the world
        self._callbacks = {}  # the ctypes function objects the C world calls
        self._callback_error = None

    @classmethod
    def _borrowed(cls, pointer, owner):
        """The world of a model: freed with the model, never by itself."""
        world = cls.__new__(cls)
        world._pointer = pointer
        world._owner = owner
        world._callbacks = {}
        world._callback_error = None
        return world

    # ------------------------------------------------------------ lifetime

    @property
    def _w(self):
        """The C pointer; raises Closed once the world (or its model) is freed."""
        if self._owner is not None:
            self._owner._m  # raises when the model is closed
        if self._pointer is None:
            raise errors.Closed("the world is closed: its bodies, shapes and joints are gone")
        return self._pointer

    @property
    def closed(self):
        return self._pointer is None or (self._owner is not None and self._owner.closed)

    def close(self):
        """Frees the C world and everything in it. Closing twice does nothing.
        A model's world closes with its model (Model.close)."""
        if self._owner is not None:
            raise errors.Error("this world belongs to a Model: close the model instead", "misuse")
        if self._pointer is not None:
            rb.rb_world_destroy(self._pointer)
            self._pointer = None
            self._callbacks.clear()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        if self._owner is None:
            self.close()

    def __del__(self):
        if getattr(self, "_owner", True) is None and getattr(self, "_pointer", None) is not None:
            rb.rb_world_destroy(self._pointer)
            self._pointer = None

    def __repr__(self):
        if self.closed:
            return "<sinew.World closed>"
        return f"<sinew.World gravity {tuple(self.gravity)}>"

    # ------------------------------------------------------------ stepping

    def step(self, dt):
        """Advances the world by ``dt`` s (1e-6 .. 10). Raises NotFinite,
        with the world put back, when the motion overflows."""
        self._callback_error = None
        status = rb.rb_world_step(self._w, real("dt", dt))
        self._raise_callback_error()
        check(status)

    def _raise_callback_error(self):
        if self._callback_error is not None:
            error, self._callback_error = self._callback_error, None
            raise error

    @property
    def gravity(self):
        """m/s², a Vec2; each component within ±1e6."""
        return records.vec2(checked(rb.rb_world_gravity, self._w))

    @gravity.setter
    def gravity(self, value):
        check(rb.rb_world_set_gravity(self._w, _api.Vec2(*pair("gravity", value))))

    @property
    def solver(self):
        """The solver settings (a copy: assign a changed one back)."""
        return SolverSettings._from_c(checked(rb.rb_world_solver_settings, self._w))

    @solver.setter
    def solver(self, settings):
        if not isinstance(settings, SolverSettings):
            raise TypeError(f"solver must be a SolverSettings, got {type(settings).__name__}")
        c = settings._to_c()
        check(rb.rb_world_set_solver_settings(self._w, ctypes.byref(c)))

    def set_substep_callback(self, function):
        """``function(world, substep, h)`` is called at the start of every
        substep (h in s); None removes it. The world is locked meanwhile:
        only cable tension laws may change. An exception it raises is
        raised again by the step."""
        if function is None:
            check(rb.rb_world_set_substep_callback(self._w, _api.SUBSTEP_FN(), None))
            self._callbacks.pop("substep", None)
            return
        if not callable(function):
            raise TypeError("the substep callback must be callable or None")

        def trampoline(_pointer, substep, h, _context):
            if self._callback_error is None:
                try:
                    function(self, substep, h)
                except BaseException as error:  # raised again after the step
                    self._callback_error = error

        c_function = _api.SUBSTEP_FN(trampoline)
        check(rb.rb_world_set_substep_callback(self._w, c_function, None))
        self._callbacks["substep"] = c_function

    def set_pre_solve(self, function):
        """``function(shape_a, shape_b, manifold) -> bool`` is asked about
        every contact with points before the solver; False disables it
        for this step. None removes it."""
        if function is None:
            check(rb.rb_world_set_pre_solve(self._w, _api.PRE_SOLVE_FN(), None))
            self._callbacks.pop("pre_solve", None)
            return
        if not callable(function):
            raise TypeError("the pre-solve function must be callable or None")
        from .shape import Shape

        def trampoline(a, b, manifold, _context):
            if self._callback_error is not None:
                return True
            try:
                return bool(function(Shape(self, a), Shape(self, b), records.manifold(manifold.contents)))
            except BaseException as error:
                self._callback_error = error
                return True

        c_function = _api.PRE_SOLVE_FN(trampoline)
        check(rb.rb_world_set_pre_solve(self._w, c_function, None))
        self._callbacks["pre_solve"] = c_function

    # ------------------------------------------------- statistics, profile

    @property
    def statistics(self):
        """Counters of the last step (a Statistics named tuple)."""
        return records.structure(records.Statistics, checked(rb.rb_world_statistics, self._w))

    @property
    def profile(self):
        """Milliseconds per phase of the last step (all 0 with profiling off)."""
        return records.structure(records.Profile, checked(rb.rb_world_profile, self._w))

    def enable_profile(self, enable=True):
        """Turns the timing of each step's phases on or off (it costs about
        0.3 µs a step)."""
        check(rb.rb_world_enable_profile(self._w, boolean("enable", enable)))

    @property
    def sleep_enabled(self):
        """Whether resting islands fall asleep; disabling wakes every body."""
        return bool(checked(rb.rb_world_is_sleep_enabled, self._w))

    @sleep_enabled.setter
    def sleep_enabled(self, enable):
        check(rb.rb_world_enable_sleep(self._w, boolean("enable", enable)))

    @property
    def bytes_in_use(self):
        """Bytes the C world holds now."""
        return int(checked(rb.rb_world_bytes_in_use, self._w))

    @property
    def state_hash(self):
        """64-bit FNV-1a hash of every body's pose and velocity bits: equal
        hashes mean bit-identical states."""
        return int(checked(rb.rb_world_state_hash, self._w))

    # ---------------------------------------------------- creating objects

    def create_body(self, type="static", position=(0.0, 0.0), angle=0.0, **fields):
        """A body (rb_body_def): type "static", "kinematic" or "dynamic";
        position (m) of its origin, angle (rad); further fields by name:
        linear_velocity (m/s), angular_velocity (rad/s), linear_damping and
        angular_damping (1/s), gravity_scale, fixed_rotation, awake,
        enable_sleep, bullet."""
        from .body import BODY_TYPES, Body

        definition = rb.rb_default_body_def()
        if type not in BODY_TYPES:
            raise errors.InvalidArgument(f"create_body: type must be one of {', '.join(BODY_TYPES)}, got {type!r}")
        definition.type = BODY_TYPES.index(type)
        set_fields(definition, "create_body", dict(position=position, angle=angle, **fields))
        out = _api.BodyId()
        check(rb.rb_body_create(self._w, ctypes.byref(definition), ctypes.byref(out)))
        return Body(self, out)

    def create_revolute_joint(self, body_a, body_b, anchor, **fields):
        """A pin at the world point ``anchor`` (m) in the bodies' present
        poses (rb_revolute_joint_def_at); further fields by name:
        enable_lower_limit, lower_angle (rad), enable_upper_limit,
        upper_angle, enable_motor, motor_speed (rad/s), max_motor_torque
        (N·m), enable_spring, spring_hertz (Hz), spring_damping_ratio,
        collide_connected, reference_angle (rad), local_anchor_a/b (m)."""
        from .joint import make_joint

        definition = _api.RevoluteJointDef()
        check(
            rb.rb_revolute_joint_def_at(
                ctypes.byref(definition),
                self._w,
                self._body_id(body_a),
                self._body_id(body_b),
                _api.Vec2(*pair("anchor", anchor)),
            )
        )
        return make_joint(self, "revolute", definition, fields)

    def create_weld_joint(self, body_a, body_b, anchor, **fields):
        """Freezes the bodies' present relative pose about ``anchor`` (m);
        linear_hertz, angular_hertz (Hz, 0 rigid) and their damping ratios
        soften it."""
        from .joint import make_joint

        definition = _api.WeldJointDef()
        check(
            rb.rb_weld_joint_def_at(
                ctypes.byref(definition),
                self._w,
                self._body_id(body_a),
                self._body_id(body_b),
                _api.Vec2(*pair("anchor", anchor)),
            )
        )
        return make_joint(self, "weld", definition, fields)

    def create_distance_joint(self, body_a, body_b, anchor_a, anchor_b, **fields):
        """A bar (or with enable_spring a spring, with enable_limit a rope)
        between two world points (m); length, min_length, max_length (m)
        default to their present distance."""
        from .joint import make_joint

        definition = _api.DistanceJointDef()
        check(
            rb.rb_distance_joint_def_between(
                ctypes.byref(definition),
                self._w,
                self._body_id(body_a),
                self._body_id(body_b),
                _api.Vec2(*pair("anchor_a", anchor_a)),
                _api.Vec2(*pair("anchor_b", anchor_b)),
            )
        )
        return make_joint(self, "distance", definition, fields)

    def create_prismatic_joint(self, body_a, body_b, anchor, axis, **fields):
        """Body B slides along the world ``axis`` through ``anchor`` (m);
        limits (m), motor (m/s, N) and spring as for revolute joints."""
        from .joint import make_joint

        definition = _api.PrismaticJointDef()
        check(
            rb.rb_prismatic_joint_def_at(
                ctypes.byref(definition),
                self._w,
                self._body_id(body_a),
                self._body_id(body_b),
                _api.Vec2(*pair("anchor", anchor)),
                _api.Vec2(*pair("axis", axis)),
            )
        )
        return make_joint(self, "prismatic", definition, fields)

    def create_pulley_joint(self, body_a, body_b, ground_a, ground_b, anchor_a, anchor_b, **fields):
        """A rope from ``anchor_a`` over fixed pulleys at ``ground_a`` and
        ``ground_b`` down to ``anchor_b`` (world points, m), taut now;
        ratio and min_length (m) by name."""
        from .joint import make_joint

        definition = _api.PulleyJointDef()
        names = ("ground_a", "ground_b", "anchor_a", "anchor_b")
        values = (ground_a, ground_b, anchor_a, anchor_b)
        points = [_api.Vec2(*pair(name, value)) for name, value in zip(names, values)]
        check(
            rb.rb_pulley_joint_def_between(
                ctypes.byref(definition), self._w, self._body_id(body_a), self._body_id(body_b), *points
            )
        )
        return make_joint(self, "pulley", definition, fields)

    def create_mouse_joint(self, body, target, max_force, **fields):
        """Pulls the body's point now at ``target`` (m, world) towards the
        target (set_target moves it) with at most ``max_force`` N; hertz
        (default 5) and damping_ratio (0.7) by name."""
        from .joint import make_joint

        definition = rb.rb_default_mouse_joint_def()
        definition.body = self._body_id(body)
        target = _api.Vec2(*pair("target", target))
        definition.local_anchor = checked(rb.rb_body_local_point, self._w, definition.body, target)
        definition.target = target
        definition.max_force = real("max_force", max_force)
        return make_joint(self, "mouse", definition, fields)

    def create_cable(self, points, tension=0.0, damping=0.0):
        """A cable along ``points``, a list of (body, (x, y)) with each point
        in its body's frame (m), 2 .. 8 of them; its tension law
        T = tension (N) + damping (N·s/m) · lengthening speed."""
        from .cable import Cable

        definition = rb.rb_default_cable_def()
        points = list(points)
        if not 2 <= len(points) <= _api.MAX_CABLE_POINTS:
            raise errors.InvalidArgument(
                f"create_cable: expected 2 to {_api.MAX_CABLE_POINTS} points (body, (x, y)), got {len(points)}"
            )
        definition.point_count = len(points)
        for k, point in enumerate(points):
            try:
                body, local = point
            except (TypeError, ValueError):
                raise TypeError(f"create_cable: point {k} must be (body, (x, y)), got {point!r}") from None
            definition.bodies[k] = self._body_id(body)
            definition.local_points[k] = _api.Vec2(*pair(f"points[{k}]", local))
        out = _api.CableId()
        check(rb.rb_cable_create(self._w, ctypes.byref(definition), ctypes.byref(out)))
        cable = Cable(self, out)
        if tension or damping:
            cable.set_tension_law(tension, damping)
        return cable

    def _body_id(self, body):
        from .body import Body

        if not isinstance(body, Body):
            raise TypeError(f"expected a sinew.Body, got {type(body).__name__}")
        return body._id

    # ------------------------------------------------------------- queries

    def _filter(self, category_bits, mask_bits):
        f = rb.rb_default_query_filter()
        if category_bits is not None:
            f.category_bits = errors.bits("category_bits", category_bits)
        if mask_bits is not None:
            f.mask_bits = errors.bits("mask_bits", mask_bits)
        return f

    def _overlap(self, function, where, category_bits, mask_bits, include_sensors):
        from .shape import Shape

        f = self._filter(category_bits, mask_bits)
        sensors = boolean("include_sensors", include_sensors)
        count = ctypes.c_int()
        check(function(self._w, where, f, sensors, None, 0, ctypes.byref(count)))
        out = (_api.ShapeId * max(count.value, 1))()
        check(function(self._w, where, f, sensors, out, count.value, ctypes.byref(count)))
        return [Shape(self, out[k]) for k in range(count.value)]

    def overlap_aabb(self, lower, upper, category_bits=None, mask_bits=None, include_sensors=False):
        """The shapes whose bounding box overlaps the box lower..upper (m), by shape index."""
        box = _api.AABB(_api.Vec2(*pair("lower", lower)), _api.Vec2(*pair("upper", upper)))
        return self._overlap(rb.rb_world_overlap_aabb, box, category_bits, mask_bits, include_sensors)

    def overlap_point(self, point, category_bits=None, mask_bits=None, include_sensors=False):
        """The shapes containing the world point (m)."""
        where = _api.Vec2(*pair("point", point))
        return self._overlap(rb.rb_world_overlap_point, where, category_bits, mask_bits, include_sensors)

    def _hit(self, hit):
        from .body import Body
        from .shape import Shape

        return records.RayHit(
            Shape(self, hit.shape),
            Body(self, hit.body),
            records.vec2(hit.point),
            records.vec2(hit.normal),
            hit.fraction,
        )

    def ray_cast(self, origin, translation, category_bits=None, mask_bits=None, include_sensors=False):
        """The nearest hit of the ray origin → origin + translation (m), a RayHit, or None."""
        hit, found = _api.RayHit(), ctypes.c_bool()
        check(
            rb.rb_world_ray_cast_closest(
                self._w,
                _api.Vec2(*pair("origin", origin)),
                _api.Vec2(*pair("translation", translation)),
                self._filter(category_bits, mask_bits),
                boolean("include_sensors", include_sensors),
                ctypes.byref(hit),
                ctypes.byref(found),
            )
        )
        return self._hit(hit) if found.value else None

    def ray_cast_all(self, origin, translation, category_bits=None, mask_bits=None, include_sensors=False):
        """Every hit of the ray, nearest first."""
        args = (
            self._w,
            _api.Vec2(*pair("origin", origin)),
            _api.Vec2(*pair("translation", translation)),
            self._filter(category_bits, mask_bits),
            boolean("include_sensors", include_sensors),
        )
        count = ctypes.c_int()
        check(rb.rb_world_ray_cast_all(*args, None, 0, ctypes.byref(count)))
        out = (_api.RayHit * max(count.value, 1))()
        check(rb.rb_world_ray_cast_all(*args, out, count.value, ctypes.byref(count)))
        return [self._hit(out[k]) for k in range(count.value)]

    # ---------------------------------------------------- contacts, events

    @property
    def contacts(self):
        """The contacts now, in the world's deterministic order (Contact tuples)."""
        from .body import Body
        from .shape import Shape

        count = checked(rb.rb_world_contact_count, self._w)
        out = (_api.ContactData * max(count, 1))()
        count = rb.rb_world_contacts(self._w, out, count)
        return [
            records.Contact(
                Shape(self, c.shape_a),
                Shape(self, c.shape_b),
                Body(self, c.body_a),
                Body(self, c.body_b),
                bool(c.touching),
                bool(c.sensor),
                records.manifold(c.manifold),
            )
            for c in out[:count]
        ]

    @property
    def contact_events(self):
        """The last step's contact events: begin, a list of (shape_a,
        shape_b, manifold); end, a list of (shape_a, shape_b). An ended
        contact's shapes may be destroyed: compare them, do not use them."""
        from .shape import Shape

        e = checked(rb.rb_world_contact_events, self._w)
        begin = [
            (Shape(self, x.shape_a), Shape(self, x.shape_b), records.manifold(x.manifold))
            for x in e.begin_events[: e.begin_count]
        ]
        end = [(Shape(self, x.shape_a), Shape(self, x.shape_b)) for x in e.end_events[: e.end_count]]
        return records.ContactEvents(begin, end)

    @property
    def sensor_events(self):
        """The last step's sensor events: begin and end lists of (sensor, visitor) shapes."""
        from .shape import Shape

        e = checked(rb.rb_world_sensor_events, self._w)
        begin = [
            (Shape(self, x.sensor_shape), Shape(self, x.visitor_shape)) for x in e.begin_events[: e.begin_count]
        ]
        end = [(Shape(self, x.sensor_shape), Shape(self, x.visitor_shape)) for x in e.end_events[: e.end_count]]
        return records.SensorEvents(begin, end)


def bytes_in_use():
    """Bytes the engine holds over all worlds of the process (0 once all are closed)."""
    return int(rb.rb_bytes_in_use())
