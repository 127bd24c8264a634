# SPDX-License-Identifier: MIT
"""A whole scheduled run, as ``sinew run MODEL`` makes it: build the model,
recruit, apply the controls before every substep they change, step frame
by frame, and record after every frame the row ``sinew run`` writes to its
CSV, with the same columns (docs/cli.md, "The CSV"), as a numpy structured
array whose field names are the CSV's header (and a pandas DataFrame when
pandas is installed).

The columns are fixed when the run starts, as the program's recorder fixes
them: hinges and parts the level or variant leaves out, joints merged away
and bones that cannot be read (fixed to the ground) have no columns.
"""
import ctypes
import math
from dataclasses import dataclass, field

import numpy as np

from . import _api, control_file, errors
from ._lib import mu
from .controls import Schedule
from .model import Model

MUSCLE_COLUMNS = (
    "activation",
    "target_tension_N",
    "length_m",
    "normalized_length",
    "velocity_m_s",
    "normalized_velocity",
    "contraction_m",
    "normalized_contraction",
    "active_force_N",
    "passive_force_N",
    "total_force_N",
    "excitation",
    "fibre_length_m",
    "tendon_length_m",
    "pennation_angle_deg",
)
TORQUE_COLUMNS = ("recruited_neurons", "exertion", "torque_N_m")
PART_COLUMNS = ("x_m", "y_m", "angle_deg")
LOAD_COLUMNS = (
    "reaction_x_N",
    "reaction_y_N",
    "reaction_along_N",
    "reaction_across_N",
    "reaction_torque_N_m",
    "muscle_torque_N_m",
)
STRESS_COLUMNS = (
    "max_stress_Pa",
    "max_strain",
    "safety_factor",
    "worst_section_m",
    "axial_force_N",
    "bending_moment_N_m",
)

#: Most frames a run may have (as `sinew run`): one row each.
MAX_FRAMES = 1e7


class Recorder:
    """The row of every frame, in the CSV's column order."""

    def __init__(self, model):
        m = model._m
        self.model = model
        self.muscles = mu.mu_model_muscle_count(m)
        self.torque_muscles = mu.mu_model_torque_muscle_count(m)
        self.hinges = [h for h in range(mu.mu_model_hinge_count(m)) if math.isfinite(mu.mu_model_hinge_angle(m, h))]
        self.parts = [
            p for p in range(mu.mu_model_part_count(m)) if math.isfinite(mu.mu_model_part_centre(m, p).x)
        ]
        self.load_hinges = [
            h for h in range(mu.mu_model_hinge_count(m)) if mu.mu_model_hinge_joint(m, h).generation != 0
        ]
        self.load_glues = [g for g in range(mu.mu_model_glue_count(m)) if mu.mu_model_glue_joint(m, g).generation != 0]
        self.crossing = [
            [mu.mu_model_muscle_crosses(m, k, h) for k in range(self.muscles)] for h in self.load_hinges
        ]
        self.bones = [
            b for b in range(model._d.bone_count) if not math.isnan(mu.mu_model_bone_stress(m, b).worst.stress)
        ]
        self.arms = np.zeros(max(self.muscles, 1))
        self.arms_pointer = self.arms.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
        self.stresses = (_api.BoneStress * max(model._d.bone_count, 1))()

    def columns(self):
        """The CSV header's names, in order."""
        model = self.model
        muscles, torques = model.muscle_names, model.torque_muscle_names
        hinges, parts, glues = model.hinge_names, model.part_names, model.glue_names
        names = ["time_s"]
        names += [f"{n}.{c}" for n in muscles for c in MUSCLE_COLUMNS]
        names += [f"{n}.{c}" for n in torques for c in TORQUE_COLUMNS]
        names += [f"{hinges[h]}.angle_deg" for h in self.hinges]
        names += [f"{parts[p]}.{c}" for p in self.parts for c in PART_COLUMNS]
        names += [f"{hinges[h]}.{c}" for h in self.load_hinges for c in LOAD_COLUMNS]
        names += [f"{glues[g]}.{c}" for g in self.load_glues for c in LOAD_COLUMNS]
        for slot, h in enumerate(self.load_hinges):
            for k in range(self.muscles):
                if self.crossing[slot][k]:
                    names += [f"{muscles[k]}.{hinges[h]}.moment_arm_m", f"{muscles[k]}.{hinges[h]}.torque_N_m"]
        bones = model.bone_names
        names += [f"{bones[b]}.{c}" for b in self.bones for c in STRESS_COLUMNS]
        return names

    def row(self, time):
        """The values of the row at ``time`` s, as recorder.c computes them."""
        m = self.model._m
        row = [time]
        readouts = [mu.mu_model_muscle_readout(m, k) for k in range(self.muscles)]
        for r in readouts:
            row += [
                r.activation,
                r.target_tension,
                r.length,
                r.normalized_length,
                r.velocity,
                r.normalized_velocity,
                r.contraction,
                r.normalized_contraction,
                r.active_force,
                r.passive_force,
                r.total_force,
                r.excitation,
                r.fibre_length,
                r.tendon_length,
                r.pennation_angle * 180.0 / math.pi,
            ]
        for t in range(self.torque_muscles):
            pool, actuator = mu.mu_model_motor_pool(m, t), mu.mu_model_torque_actuator(m, t)
            row += [
                mu.mu_motor_pool_recruited(pool),
                mu.mu_motor_pool_exertion(pool),
                mu.mu_torque_actuator_torque(actuator),
            ]
        row += [mu.mu_model_hinge_angle(m, h) for h in self.hinges]
        for p in self.parts:
            centre = mu.mu_model_part_centre(m, p)
            row += [centre.x, centre.y, mu.mu_model_part_angle(m, p)]
        for load in [mu.mu_model_hinge_load(m, h) for h in self.load_hinges] + [
            mu.mu_model_glue_load(m, g) for g in self.load_glues
        ]:
            row += [load.force.x, load.force.y, load.along, load.across, load.torque, load.muscle_torque]
        for slot, h in enumerate(self.load_hinges):
            errors.check(mu.mu_model_moment_arms(m, h, self.arms_pointer))
            for k in range(self.muscles):
                if self.crossing[slot][k]:
                    row += [self.arms[k], readouts[k].total_force * self.arms[k]]
        if self.bones:
            errors.check(mu.mu_model_bone_stresses(m, self.stresses))
        for b in self.bones:
            s = self.stresses[b]
            w = s.worst
            row += [w.stress, s.strain, w.safety_factor, w.s, w.axial_force, w.bending_moment]
        return row


@dataclass
class RunResult:
    """What a run gives: ``table`` (a structured array, one record a frame,
    fields named as the CSV's columns), the model's name, variant, weight
    and level, frames, warnings and failure (None when the run stayed
    physical), each muscle's peak force (N) and its time (s), each built
    hinge's final, least and greatest angle (deg), and controls not applied
    (after the end)."""

    table: np.ndarray
    model: str
    variant: str
    weight_kg: float
    level: int
    frames: int
    warnings: str
    failure: str
    peak_force: dict = field(default_factory=dict)
    peak_time: dict = field(default_factory=dict)
    angles: dict = field(default_factory=dict)
    pending_controls: int = 0

    @property
    def columns(self):
        """The table's column names (the CSV's header)."""
        return list(self.table.dtype.names)

    def dataframe(self):
        """The table as a pandas DataFrame (ImportError without pandas)."""
        try:
            import pandas
        except ImportError:
            raise ImportError("sinew: RunResult.dataframe() needs pandas (Debian: python3-pandas)") from None
        return pandas.DataFrame({name: self.table[name] for name in self.table.dtype.names})


def run(
    model,
    duration=10.0,
    variant=0,
    weight=None,
    weight_index=None,
    level=4,
    activations=None,
    tensions=None,
    recruits=None,
    controls=(),
    control=None,
    weld_glues=False,
    strict=False,
):
    """Runs ``model`` (a built-in name or a model file) for ``duration`` s as
    ``sinew run`` does with the same options:

    - ``activations``, ``tensions``: {muscle or group: value} from t = 0
      (``--activation``, ``--tension``), applied in that order;
    - ``recruits``: {torque muscle: neurons} (``--recruit``);
    - ``controls``: further events, each a tuple (time, kind, name, value)
      or a dict of Schedule.add's arguments;
    - ``control``: a control file's path (``--control``), read after them;
    - ``strict``: raise :class:`sinew.Error` when the run fails
      (``--strict``) instead of reporting it in ``failure``.

    Returns a :class:`RunResult`.
    """
    built = Model(model, variant=variant, weight=weight, weight_index=weight_index, level=level, weld_glues=weld_glues)
    with built as m:
        duration = errors.real("duration", duration)
        frames = round(duration * m.frame_rate)  # nearbyint: halves to even
        if not 0.0 < duration or frames < 1:
            raise errors.InvalidArgument(
                f"duration {duration:g} s is {frames:.0f} frames at {m.frame_rate:g} Hz, expected at least 1"
            )
        if frames > MAX_FRAMES:
            raise errors.InvalidArgument(f"duration {duration:g} s is {frames:.0f} frames, more than {MAX_FRAMES:.0f}")
        schedule = Schedule(m)
        for kind, values in (("activation", activations), ("tension", tensions)):
            for name, value in (values or {}).items():
                schedule.add(0.0, kind, name, value)
        for event in controls:
            if isinstance(event, dict):
                schedule.add(**event)
            else:
                schedule.add(*event)
        if control is not None:
            control_file.read(control, schedule)
        for name, neurons in (recruits or {}).items():
            m.recruit(name, neurons)
        recorder = Recorder(m)
        columns = recorder.columns()
        rows = np.empty((frames, len(columns)))
        muscles = m.muscle_names
        peak = np.zeros(len(muscles))
        peak_time = np.zeros(len(muscles))
        hinges = m.hinge_names
        low = np.full(len(hinges), np.nan)
        high = np.full(len(hinges), np.nan)
        for frame in range(frames):
            schedule.step_frame(frame)
            if strict and m.failure is not None:
                raise errors.Error(f"the run failed (strict): {m.failure}", "failure")
            time = (frame + 1) / m.frame_rate
            forces = m.readouts()["total_force"]
            better = forces > peak
            peak = np.where(better, forces, peak)
            peak_time = np.where(better, time, peak_time)
            angles = m.hinge_angles()
            low, high = np.fmin(low, angles), np.fmax(high, angles)
            rows[frame] = recorder.row(time)
        dtype = np.dtype(
            [(name, np.int64 if name.endswith(".recruited_neurons") else np.float64) for name in columns]
        )
        table = np.empty(frames, dtype)
        for k, name in enumerate(columns):
            table[name] = rows[:, k]
        final = m.hinge_angles()
        return RunResult(
            table=table,
            model=m.name,
            variant=m.variant_name,
            weight_kg=m.weights[m.weight_index] if m.weights else 0.0,
            level=m.options.level,
            frames=frames,
            warnings=m.warnings,
            failure=m.failure,
            peak_force=dict(zip(muscles, peak.tolist())),
            peak_time=dict(zip(muscles, peak_time.tolist())),
            angles={
                hinges[h]: (final[h], low[h], high[h]) for h in range(len(hinges)) if not math.isnan(final[h])
            },
            pending_controls=schedule.pending,
        )
