# SPDX-License-Identifier: MIT
"""sinew from Python: the rigid-body engine (librb) and the muscle layer
(libmu) through ctypes, with numpy arrays for the readouts.

    import sinew
    with sinew.World(gravity=(0, -9.8)) as world:
        ball = world.create_body("dynamic", position=(0, 2))
        ball.add_circle(0.1, density=1000)
        world.step(1 / 60)

    result = sinew.run("arm", duration=1, activations={"Biceps Short": 0.5})
    result.table["Elbow.angle_deg"]

docs/python.md maps the C API to this package. Every C error raises a
:class:`sinew.Error` subclass carrying the C message.
"""
from . import _lib
from ._program import ProgramError
from .body import BODY_TYPES, Body
from .cable import Cable
from .controls import Schedule
from .experiment import ExperimentResult, experiment, experiments
from .errors import (
    Closed,
    DegenerateShape,
    Error,
    ForeignId,
    InvalidArgument,
    Locked,
    NoMass,
    NotConvex,
    NotFinite,
    OutOfMemory,
    StaleId,
)
from .joint import (
    DistanceJoint,
    Joint,
    MouseJoint,
    PrismaticJoint,
    PulleyJoint,
    RevoluteJoint,
    WeldJoint,
)
from .model import Model, Muscle, builtin_models
from .records import AABB, Contact, Filter, MassData, RayHit, Vec2
from .run import RunResult, run
from .shape import Shape
from .sweep import SweepError, sweep
from .world import SolverSettings, World, bytes_in_use

__all__ = [
    "AABB", "BODY_TYPES", "Body", "Cable", "Closed", "Contact", "DegenerateShape", "DistanceJoint", "Error",
    "ExperimentResult", "Filter", "ForeignId", "InvalidArgument", "Joint", "Locked", "MassData", "Model",
    "MouseJoint", "Muscle", "NoMass", "NotConvex", "NotFinite", "OutOfMemory", "PrismaticJoint",
    "ProgramError", "PulleyJoint", "RayHit", "RevoluteJoint", "RunResult", "Schedule", "Shape",
    "SolverSettings", "StaleId", "SweepError", "Vec2", "WeldJoint", "World", "builtin_models", "bytes_in_use",
    "experiment", "experiments", "run", "sweep",
]

#: The version of the libraries loaded ("0.2.0").
__version__ = _lib.rb.rb_version().decode()
#: Where the libraries were loaded from.
library_paths = (_lib.rb._name, _lib.mu._name)
