# SPDX-License-Identifier: MIT
"""A musculoskeletal model (mu/model.h): a model file or a built-in model,
built at a level, variant and weight, its muscles driven by activations,
tension targets and recruitment, stepped frame by frame or substep by
substep, and read out as numpy arrays: the muscles' states, the hinges'
angles, the parts' poses, the joints' loads (mu/joint_loads.h), the moment
arms (mu/moment_arms.h), the bones' stress (mu/bone_stress.h), inverse
dynamics (mu/inverse_dynamics.h) and static optimization
(mu/static_optimization.h).

A :class:`Model` owns its description, its C model and the world inside
it: ``close()`` (or leaving a ``with`` block) frees all three, after
which every call raises :class:`sinew.Closed`.
"""
import ctypes
import os
import weakref
from collections import namedtuple

import numpy as np

from . import _api, errors
from ._lib import mu
from .errors import check, checked, integer, real, text

#: Levels of a build: what exists (mu/model.h).
LEVELS = ("nothing", "bones and nails", "bones, joints", "bones, joints, muscles", "bones, joints, muscles, weight")

#: The readout of a muscle (mu_muscle_readout), one numpy field each: the
#: activation and excitation (0..1), target_tension (N, < 0 under activation
#: control), lengths (m), velocity (m/s, < 0 shortening), forces (N),
#: pennation_angle (rad), calcium (0..1) and the normalized ones.
READOUT_DTYPE = np.dtype([(name, np.float64) for name in _api.READOUT_FIELDS])
#: A joint's load (mu_joint_load): reaction on body B (N, world frame), along
#: and across the proximal bone (N), torque (N·m) and the muscles' torque (N·m).
LOAD_DTYPE = np.dtype(
    [(name, np.float64) for name in ("force_x", "force_y", "along", "across", "torque", "muscle_torque")]
)
#: A bone's worst section (mu_bone_stress): stress (Pa, signed), strain,
#: safety factor, s (m along the axis), axial force (N), bending moment (N·m).
STRESS_DTYPE = np.dtype(
    [
        (name, np.float64)
        for name in ("stress", "strain", "safety_factor", "s", "axial_force", "bending_moment", "shear_force")
    ]
)
#: A torque muscle: neurons recruited, exertion (0..1), torque (N·m).
TORQUE_MUSCLE_DTYPE = np.dtype([("recruited", np.int64), ("exertion", np.float64), ("torque", np.float64)])

#: The energy account (J): mu_model_energy.
Energy = namedtuple("Energy", "mechanical at_start muscle_work muscle_work_gross created")
#: A bone as a beam (mu_bone_beam): m, m², m⁴, Pa.
BoneBeam = namedtuple(
    "BoneBeam",
    "length outer_diameter wall_thickness area second_moment youngs_modulus tensile_strength compressive_strength",
)


def _decode(value):
    return None if value is None else value.decode("utf-8")


def builtin_models():
    """The names of the built-in models ("sample", "arm", ...)."""
    return [_decode(mu.mu_builtin_model_name(k)) for k in range(mu.mu_builtin_model_count())]


def is_builtin(source):
    return isinstance(source, str) and source in builtin_models()


class Model:
    """A model built from ``source``: a built-in model's name ("arm"), or a
    model file's path (containing '/' or ending in .json, as ``sinew run``
    tells them apart).

    ``variant``: index or name (default 0); ``weight``: the weight choice
    of that mass in kg, or ``weight_index``; ``level``: 0 .. 4 (default 4);
    ``weld_glues``: keep glues as weld joints instead of merged bodies.
    """

    def __init__(self, source, variant=0, weight=None, weight_index=None, level=4, weld_glues=False):
        self._model = None
        self._desc = None
        self._optimizers = weakref.WeakSet()  # closed before the model
        self.source = source
        pointer = ctypes.c_void_p()
        if not isinstance(source, (str, os.PathLike)):
            raise TypeError(f"source must be a model name or a path, got {type(source).__name__}")
        source = os.fspath(source)
        if is_builtin(source):
            check(mu.mu_model_desc_load_builtin(text("source", source), ctypes.byref(pointer)))
        elif "/" in source or source.endswith(".json"):
            check(mu.mu_model_desc_load(text("source", source), ctypes.byref(pointer)))
        else:
            raise errors.InvalidArgument(
                f"unknown model {source!r} (built-in: {', '.join(builtin_models())}; "
                "a model file is a path containing '/' or ending in .json)"
            )
        self._desc = pointer.value
        self._d = _api.ModelDesc.from_address(self._desc)
        options = mu.mu_default_model_options()
        options.level = integer("level", level)
        options.variant = self._choose_variant(variant)
        options.weight_index = self._choose_weight(weight, weight_index)
        options.weld_glues = errors.boolean("weld_glues", weld_glues)
        self.options = options
        model = ctypes.c_void_p()
        try:
            check(mu.mu_model_create(self._desc, ctypes.byref(options), ctypes.byref(model)))
        except errors.Error:
            mu.mu_model_desc_destroy(self._desc)
            self._desc = None
            raise
        self._model = model.value
        from .world import World

        self._world = World._borrowed(mu.mu_model_world(self._model), self)

    # ------------------------------------------------------------ choices

    def _choose_variant(self, variant):
        d = self._d
        names = [_decode(d.variants[v].name) for v in range(d.variant_count)]
        if isinstance(variant, str):
            index = mu.mu_model_desc_find_variant(self._desc, variant.encode())
            if index >= 0:
                return index
            if variant.strip().isdigit():
                variant = int(variant)
            else:
                raise errors.InvalidArgument(
                    f"unknown variant {variant!r} of model {_decode(d.name)}; the variants are "
                    + ", ".join(f'{k} "{n}"' for k, n in enumerate(names))
                )
        variant = integer("variant", variant)
        if not 0 <= variant < d.variant_count:
            raise errors.InvalidArgument(
                f"variant {variant} of model {_decode(d.name)}: expected 0 .. {d.variant_count - 1} ("
                + ", ".join(f'{k} "{n}"' for k, n in enumerate(names))
                + ")"
            )
        return variant

    def _choose_weight(self, weight, weight_index):
        d = self._d
        masses = self.weights
        if weight is not None and weight_index is not None:
            raise errors.InvalidArgument("give weight or weight_index, not both")
        if (weight is not None or weight_index is not None) and not d.has_weight:
            raise errors.InvalidArgument(f"model {_decode(d.name)} has no weight")
        if weight_index is not None:
            weight_index = integer("weight_index", weight_index)
            if not 0 <= weight_index < len(masses):
                raise errors.InvalidArgument(
                    f"weight_index {weight_index}: model {_decode(d.name)} has weight choices 0 .. {len(masses) - 1}"
                )
            return weight_index
        if weight is None:
            return 0
        kilograms = real("weight", weight)
        # As `sinew run --weight` matches a choice: within 1e-9 relative.
        for index, mass in enumerate(masses):
            if abs(mass - kilograms) <= 1e-9 * max(1.0, mass):
                return index
        raise errors.InvalidArgument(
            f"weight {kilograms:g} kg: model {_decode(d.name)} has no such weight choice; its choices are "
            + ", ".join(f"{m:g}" for m in masses)
            + " kg"
        )

    # ----------------------------------------------------------- lifetime

    @property
    def _m(self):
        if self._model is None:
            raise errors.Closed("the model is closed: its world, bodies and muscles are gone")
        return self._model

    @property
    def closed(self):
        return self._model is None

    def close(self):
        """Frees the model, its world and its description, and closes its
        static optimizers. Twice does nothing."""
        for optimizer in list(getattr(self, "_optimizers", ())):
            optimizer.close()
        if self._model is not None:
            mu.mu_model_destroy(self._model)
            self._model = None
        if self._desc is not None:
            mu.mu_model_desc_destroy(self._desc)
            self._desc = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        if getattr(self, "_model", None) is not None or getattr(self, "_desc", None) is not None:
            self.close()

    def __repr__(self):
        if self.closed:
            return "<sinew.Model closed>"
        return f"<sinew.Model {self.name} variant {self.variant_name!r} level {self.options.level}>"

    # -------------------------------------------------------- description

    @property
    def name(self):
        self._m
        return _decode(self._d.name)

    @property
    def variants(self):
        """The variants' names, by index."""
        self._m
        return [_decode(self._d.variants[v].name) for v in range(self._d.variant_count)]

    @property
    def variant(self):
        return self.options.variant

    @property
    def variant_name(self):
        return self.variants[self.options.variant]

    @property
    def weights(self):
        """The weight choices, kg (empty without a weight)."""
        d = self._d
        return [d.weight.masses[k] for k in range(d.weight.mass_count)] if d.has_weight else []

    @property
    def weight_index(self):
        return self.options.weight_index

    @property
    def frame_rate(self):
        """Hz: frames per simulated second."""
        self._m
        return self._d.frame_rate

    @property
    def substeps(self):
        """Engine substeps per frame."""
        self._m
        return self._d.substeps

    @property
    def frame_duration(self):
        """s."""
        return mu.mu_model_frame_duration(self._m)

    @property
    def substep_duration(self):
        """s."""
        return mu.mu_model_substep_duration(self._m)

    @property
    def time(self):
        """s simulated since the build."""
        return mu.mu_model_time(self._m)

    @property
    def world(self):
        """The model's engine world (a World that closes with the model)."""
        self._m
        return self._world

    @property
    def warnings(self):
        """The build's warnings, one per line ('' when none)."""
        return _decode(mu.mu_model_warnings(self._m)) or ""

    @property
    def failure(self):
        """None while the run looks physical; else the first failure's line
        (a hinge torn open, a runaway speed, energy created)."""
        return _decode(mu.mu_model_failure(self._m))

    @property
    def energy(self):
        """The mechanical energy account (J), an Energy tuple."""
        e = mu.mu_model_energy_account(self._m)
        return Energy(e.mechanical, e.at_start, e.muscle_work, e.muscle_work_gross, e.created)

    def _desc_name(self, kind, index):
        """The description's name of object ``index`` of ``kind`` (mu_model_kind)."""
        return _decode(mu.mu_model_desc_name_of(self._desc, _api.ModelRef(kind, index)))

    def _names(self, count, name):
        m = self._m
        return [_decode(name(m, k)) for k in range(count(m))]

    @property
    def muscle_names(self):
        """The built muscles, in the description's order."""
        return self._names(mu.mu_model_muscle_count, mu.mu_model_muscle_name)

    @property
    def hinge_names(self):
        return self._names(mu.mu_model_hinge_count, mu.mu_model_hinge_name)

    @property
    def part_names(self):
        """Nails first, then bones."""
        return self._names(mu.mu_model_part_count, mu.mu_model_part_name)

    @property
    def glue_names(self):
        return self._names(mu.mu_model_glue_count, mu.mu_model_glue_name)

    @property
    def torque_muscle_names(self):
        return self._names(mu.mu_model_torque_muscle_count, mu.mu_model_torque_muscle_name)

    @property
    def bone_names(self):
        """The description's bones (built or not), as bone_stress indexes them."""
        self._m
        return [_decode(self._d.bones[b].name) for b in range(self._d.bone_count)]

    @property
    def body_count(self):
        return mu.mu_model_body_count(self._m)

    @property
    def joint_count(self):
        return mu.mu_model_joint_count(self._m)

    # ------------------------------------------------------------ objects

    def muscle(self, which):
        """The built muscle by name or index, a :class:`Muscle`."""
        return Muscle(self, self._muscle_index(which))

    @property
    def muscles(self):
        """Every built muscle, a list of :class:`Muscle`."""
        return [Muscle(self, k) for k in range(mu.mu_model_muscle_count(self._m))]

    def _index(self, which, names, what):
        if isinstance(which, str):
            if which in names:
                return names.index(which)
            raise errors.InvalidArgument(f"no {what} named {which!r}; the built ones: {', '.join(names) or 'none'}")
        index = integer(what, which)
        if not 0 <= index < len(names):
            raise errors.InvalidArgument(f"{what} {index}: expected 0 .. {len(names) - 1}")
        return index

    def _muscle_index(self, which):
        return self._index(which, self.muscle_names, "muscle")

    def _hinge_index(self, which):
        return self._index(which, self.hinge_names, "hinge")

    def hinge_joint(self, which):
        """The hinge's engine joint (a RevoluteJoint), or None when not built."""
        from .joint import joint_of

        return joint_of(self._world, checked(mu.mu_model_hinge_joint, self._m, self._hinge_index(which)))

    def body(self, index):
        """Engine body ``index`` (0 .. body_count - 1)."""
        from .body import Body

        return Body(self._world, checked(mu.mu_model_body, self._m, integer("index", index)))

    def part_body(self, which):
        """The engine body a part (nail or bone, by name or index) became part of, or None."""
        index = self._index(which, self.part_names, "part")
        body = mu.mu_model_part_body(self._m, index)
        return None if body < 0 else self.body(body)

    # ----------------------------------------------------------- controls

    def set_activation(self, which, activation):
        """Activation 0 .. 1 (clamped) of a muscle or group, by name, or of
        a built muscle by index; switches tension control off."""
        if isinstance(which, str):
            check(mu.mu_model_set_activation(self._m, which.encode(), real("activation", activation)))
        else:
            check(mu.mu_model_set_activation_at(self._m, integer("muscle", which), real("activation", activation)))

    def set_tension(self, which, newtons):
        """A tension target (N) for a muscle or group by name, or a muscle by index."""
        if isinstance(which, str):
            check(mu.mu_model_set_tension(self._m, which.encode(), real("newtons", newtons)))
        else:
            check(mu.mu_model_set_tension_at(self._m, integer("muscle", which), real("newtons", newtons)))

    def recruit(self, which, neurons):
        """Recruits the first ``neurons`` of a torque muscle's pool (by name or index)."""
        if isinstance(which, str):
            check(mu.mu_model_recruit(self._m, which.encode(), integer("neurons", neurons)))
        else:
            check(mu.mu_model_recruit_at(self._m, integer("torque muscle", which), integer("neurons", neurons)))

    def group_activation(self, name):
        """Mean activation of a group's (or muscle's) built muscles."""
        return checked(mu.mu_model_group_activation, self._m, text("name", name))

    def set_gravity(self, gravity):
        """m/s² (restarts the energy account)."""
        check(mu.mu_model_set_gravity(self._m, _api.Vec2(*errors.pair("gravity", gravity))))

    # ----------------------------------------------------------- stepping

    def step(self, frames=1):
        """Advances ``frames`` frames (each 1/frame_rate s in substeps)."""
        for _ in range(integer("frames", frames)):
            check(mu.mu_model_step(self._m))

    def substep(self, count=1):
        """Advances ``count`` substeps (1/(frame_rate · substeps) s each)."""
        for _ in range(integer("count", count)):
            check(mu.mu_model_substep(self._m))

    # ----------------------------------------------------------- readouts

    def readouts(self):
        """Every built muscle's readout now: a structured array of READOUT_DTYPE, one record a muscle."""
        m = self._m
        count = mu.mu_model_muscle_count(m)
        out = np.empty(count, READOUT_DTYPE)
        for k in range(count):
            r = mu.mu_model_muscle_readout(m, k)
            out[k] = tuple(getattr(r, name) for name in _api.READOUT_FIELDS)
        return out

    def hinge_angles(self):
        """deg, angle(B) - angle(A) of every hinge (NaN for one not built)."""
        m = self._m
        return np.array([mu.mu_model_hinge_angle(m, h) for h in range(mu.mu_model_hinge_count(m))])

    def part_centres(self):
        """m, (parts, 2): each part's centre (NaN for one not built)."""
        m = self._m
        out = np.empty((mu.mu_model_part_count(m), 2))
        for p in range(out.shape[0]):
            c = mu.mu_model_part_centre(m, p)
            out[p] = (c.x, c.y)
        return out

    def part_angles(self):
        """deg, each part's angle (NaN for one not built)."""
        m = self._m
        return np.array([mu.mu_model_part_angle(m, p) for p in range(mu.mu_model_part_count(m))])

    def torque_muscles(self):
        """Each torque muscle's recruitment, exertion and torque (TORQUE_MUSCLE_DTYPE)."""
        m = self._m
        count = mu.mu_model_torque_muscle_count(m)
        out = np.empty(count, TORQUE_MUSCLE_DTYPE)
        for t in range(count):
            pool, actuator = mu.mu_model_motor_pool(m, t), mu.mu_model_torque_actuator(m, t)
            out[t] = (
                mu.mu_motor_pool_recruited(pool),
                mu.mu_motor_pool_exertion(pool),
                mu.mu_torque_actuator_torque(actuator),
            )
        return out

    @staticmethod
    def _load(load):
        return (load.force.x, load.force.y, load.along, load.across, load.torque, load.muscle_torque)

    def hinge_loads(self):
        """Every hinge's load (LOAD_DTYPE; NaN fields for a hinge not built)."""
        m = self._m
        count = mu.mu_model_hinge_count(m)
        return np.array([self._load(mu.mu_model_hinge_load(m, h)) for h in range(count)], LOAD_DTYPE)

    def glue_loads(self):
        """Every glue's load (LOAD_DTYPE; NaN for a glue merged, i.e. without weld_glues)."""
        m = self._m
        count = mu.mu_model_glue_count(m)
        return np.array([self._load(mu.mu_model_glue_load(m, g)) for g in range(count)], LOAD_DTYPE)

    def moment_arms(self, hinge):
        """m, r = -dL/dθ of every built muscle about the hinge (by name or index)."""
        m = self._m
        arms = np.zeros(max(mu.mu_model_muscle_count(m), 1))
        pointer = arms.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
        check(mu.mu_model_moment_arms(m, self._hinge_index(hinge), pointer))
        return arms[: mu.mu_model_muscle_count(m)]

    def crosses(self, muscle, hinge):
        """Whether the muscle's path has points on both sides of the hinge."""
        return bool(
            checked(mu.mu_model_muscle_crosses, self._m, self._muscle_index(muscle), self._hinge_index(hinge))
        )

    def muscle_torques(self, hinge):
        """N·m, each muscle's tension times its moment arm about the hinge."""
        return self.readouts()["total_force"] * self.moment_arms(hinge)

    def pose_hinge(self, hinge, degrees):
        """Turns one side of the hinge to ``degrees`` without simulating."""
        check(mu.mu_model_pose_hinge(self._m, self._hinge_index(hinge), real("degrees", degrees)))

    def bone_beam(self, bone):
        """The bone's beam (by description name or index): a BoneBeam."""
        b = checked(mu.mu_model_bone_beam, self._m, self._index(bone, self.bone_names, "bone"))
        return BoneBeam(*(getattr(b, name) for name in BoneBeam._fields))

    def bone_stress(self):
        """Each description bone's worst section now (STRESS_DTYPE); NaN for
        a bone not built or fixed to the ground."""
        count = self._d.bone_count
        stresses = (_api.BoneStress * max(count, 1))()
        check(mu.mu_model_bone_stresses(self._m, stresses))
        out = np.empty(count, STRESS_DTYPE)
        for b, s in enumerate(stresses[:count]):
            w = s.worst
            out[b] = (w.stress, s.strain, w.safety_factor, w.s, w.axial_force, w.bending_moment, w.shear_force)
        return out

    def bone_sections(self, bone, count=65):
        """``count`` sections at the middles of equal pieces of the bone: a
        structured array of s (m), axial_force (N), shear_force (N),
        bending_moment (N·m), stress (Pa) and safety_factor."""
        index = self._index(bone, self.bone_names, "bone")
        count = integer("count", count)
        out = (_api.BoneSection * max(count, 1))()
        check(mu.mu_model_bone_sections(self._m, index, count, out))
        dtype = np.dtype([(name, np.float64) for name, _ in _api.BoneSection._fields_])
        return np.array([tuple(getattr(x, n) for n in dtype.names) for x in out[:count]], dtype)

    # ---------------------------------------------------- inverse dynamics

    def check_tree(self):
        """Raises, with the C message, when inverse dynamics cannot be done
        (a closed loop of joints, a floating body)."""
        check(mu.mu_model_check_tree(self._m))

    def inverse_dynamics(self, angles_deg, rates, accelerations):
        """Net torques (N·m on body B) about every hinge that make the bones
        move as prescribed: angles in deg, rates in rad/s, accelerations in
        rad/s², one per hinge (hinge_names order). NaN for a hinge not built."""
        m = self._m
        count = mu.mu_model_hinge_count(m)
        arrays = []
        for name, values in (("angles_deg", angles_deg), ("rates", rates), ("accelerations", accelerations)):
            array = np.ascontiguousarray(values, dtype=np.float64).reshape(-1)
            if array.shape[0] != count:
                raise errors.InvalidArgument(f"inverse_dynamics: {name} must have {count} values (one per hinge)")
            arrays.append(array)
        torques = np.empty(max(count, 1))
        pointer = ctypes.POINTER(ctypes.c_double)
        inputs = (a.ctypes.data_as(pointer) for a in arrays)
        check(mu.mu_model_inverse_dynamics(m, *inputs, torques.ctypes.data_as(pointer)))
        return torques[:count]

    def static_optimizer(self, exponent=2.0, reserve_scale=0.1, tolerance=None, max_evaluations=None):
        """A StaticOptimizer (sinew.static_optimization) of this model: the
        cost is the sum of activation^exponent (2; 3 as Crowninshield and
        Brand 1981) plus (reserve / reserve_scale)² (N·m) per hinge;
        tolerance and max_evaluations bound SLSQP (the C defaults when None).
        Raises, with the C message, for a model without muscles or hinges or
        whose joints close a loop."""
        from .static_optimization import StaticOptimizer  # it imports this module

        return StaticOptimizer(self, exponent, reserve_scale, tolerance, max_evaluations)


class Muscle:
    """A built muscle of a model: its name, controls and readout."""

    __slots__ = ("_model", "index")

    def __init__(self, model, index):
        self._model = model
        self.index = index

    def __repr__(self):
        return f"<sinew.Muscle {self.name!r}>"

    @property
    def name(self):
        return _decode(checked(mu.mu_model_muscle_name, self._model._m, self.index))

    @property
    def readout(self):
        """The readout now: a dict of READOUT_DTYPE's fields (see there for units)."""
        r = mu.mu_model_muscle_readout(self._model._m, self.index)
        return {name: getattr(r, name) for name in _api.READOUT_FIELDS}

    def __getattr__(self, name):
        if name in _api.READOUT_FIELDS:
            return getattr(mu.mu_model_muscle_readout(self._model._m, self.index), name)
        raise AttributeError(name)

    @property
    def activation(self):
        """0 .. 1 (write to set it, switching tension control off)."""
        return mu.mu_model_muscle_readout(self._model._m, self.index).activation

    @activation.setter
    def activation(self, value):
        self._model.set_activation(self.index, value)

    def set_tension(self, newtons):
        """Tension control towards ``newtons`` N."""
        self._model.set_tension(self.index, newtons)

    def moment_arm(self, hinge):
        """m, about the hinge (name or index)."""
        model = self._model
        return checked(mu.mu_model_moment_arm, model._m, self.index, model._hinge_index(hinge))
