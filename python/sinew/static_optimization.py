# SPDX-License-Identifier: MIT
"""Static optimization (mu/static_optimization.h): the activations that
produce a frame's inverse-dynamics torques at least cost.

    with sinew.Model("arm", weight=1) as arm, arm.static_optimizer(exponent=3) as optimizer:
        frame = optimizer.solve(angles_deg, rates, accelerations)
        frame.activations, frame.reserves, frame.solved

Per frame it minimises the sum of activation^p plus (reserve/R)² over the
hinges, subject to every hinge's torque, with NLopt's SLSQP (docs/inverse.md).
The actuators are the model's muscles, then its torque muscles (whose
"activation" is the exertion, 0 to 1).
"""

import ctypes
from collections import namedtuple

import numpy as np

from . import _api, errors
from ._lib import mu
from .errors import check, integer, real
from .model import LOAD_DTYPE

#: One frame's solution. activations: per actuator, 0 to 1; forces: per
#: actuator, a muscle's tension (N) or a torque muscle's torque (N·m);
#: net_torques, actuator_torques, reserves: per hinge, N·m on body B (the
#: torque inverse dynamics asks, what the actuators give, what the reserve
#: gives); loads: per hinge, the joint's reaction (LOAD_DTYPE); solver_result:
#: NLopt's code; solved: the point meets the constraints and the optimality
#: conditions (checked by libmu, not taken from SLSQP).
StaticFrame = namedtuple(
    "StaticFrame", "activations forces net_torques actuator_torques reserves loads solver_result solved"
)

_DOUBLES = ctypes.POINTER(ctypes.c_double)


class StaticOptimizer:
    """A model's static optimizer; made by Model.static_optimizer. It is
    closed with its model, or by close() or a with block."""

    def __init__(self, model, exponent=2.0, reserve_scale=0.1, tolerance=None, max_evaluations=None):
        self._model = model
        self._optimizer = None
        settings = mu.mu_default_static_optimization_settings()
        settings.exponent = real("exponent", exponent)
        settings.reserve_scale = real("reserve_scale", reserve_scale)
        if tolerance is not None:
            settings.tolerance = real("tolerance", tolerance)
        if max_evaluations is not None:
            settings.max_evaluations = integer("max_evaluations", max_evaluations)
        optimizer = ctypes.c_void_p()
        check(mu.mu_static_optimizer_create(model._m, ctypes.byref(settings), ctypes.byref(optimizer)))
        self._optimizer = optimizer.value
        self.actuator_count = mu.mu_static_optimizer_actuator_count(self._optimizer)
        self.hinge_count = mu.mu_model_hinge_count(model._m)
        model._optimizers.add(self)

    @property
    def _o(self):
        if self._optimizer is None or self._model.closed:
            raise errors.Closed("the static optimizer is closed (or its model is)")
        return self._optimizer

    @property
    def actuator_names(self):
        """The actuators' names: the muscles', then the torque muscles'."""
        return self._model.muscle_names + self._model.torque_muscle_names

    def solve(self, angles_deg, rates, accelerations):
        """The frame at these hinge angles (deg), rates (rad/s) and
        accelerations (rad/s²), one per hinge (hinge_names order; a hinge not
        built takes 0): a StaticFrame. Frames solved one after another start
        from the one before. Raises, with the C message, for a pose the model
        cannot take."""
        o = self._o
        inputs = []
        for name, values in (("angles_deg", angles_deg), ("rates", rates), ("accelerations", accelerations)):
            array = np.ascontiguousarray(values, dtype=np.float64).reshape(-1)
            if array.shape[0] != self.hinge_count:
                raise errors.InvalidArgument(f"solve: {name} must have {self.hinge_count} values (one per hinge)")
            inputs.append(array)
        actuators, hinges = max(self.actuator_count, 1), max(self.hinge_count, 1)
        activations, forces = np.empty(actuators), np.empty(actuators)
        net, given, reserves = np.empty(hinges), np.empty(hinges), np.empty(hinges)
        loads = (_api.JointLoad * hinges)()
        frame = _api.StaticFrame(
            activations.ctypes.data_as(_DOUBLES),
            forces.ctypes.data_as(_DOUBLES),
            net.ctypes.data_as(_DOUBLES),
            given.ctypes.data_as(_DOUBLES),
            reserves.ctypes.data_as(_DOUBLES),
            loads,
            0,
            False,
        )
        check(mu.mu_static_optimizer_solve(o, *(a.ctypes.data_as(_DOUBLES) for a in inputs), ctypes.byref(frame)))
        load_rows = [
            (x.force.x, x.force.y, x.along, x.across, x.torque, x.muscle_torque) for x in loads[: self.hinge_count]
        ]
        return StaticFrame(
            activations[: self.actuator_count],
            forces[: self.actuator_count],
            net[: self.hinge_count],
            given[: self.hinge_count],
            reserves[: self.hinge_count],
            np.array(load_rows, LOAD_DTYPE),
            frame.solver_result,
            bool(frame.solved),
        )

    @staticmethod
    def result_name(solver_result):
        """NLopt's name of a solver_result ("NLOPT_XTOL_REACHED"), or None."""
        name = mu.mu_static_optimizer_result_name(integer("solver_result", solver_result))
        return name.decode() if name is not None else None

    def close(self):
        """Frees the optimizer. Twice does nothing."""
        if self._optimizer is not None:
            mu.mu_static_optimizer_destroy(self._optimizer)
            self._optimizer = None
            self._model._optimizers.discard(self)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        if getattr(self, "_optimizer", None) is not None:
            self.close()
