# SPDX-License-Identifier: MIT
"""The controls of a scheduled run, as ``sinew run`` applies them: events
that set a muscle's or group's activation or tension target, give it a
one-frame pulse, or set a torque muscle's recruitment, from a time on,
each a shape over time (a step, a ramp, a sine, a pulse train).

The rules are the command's (docs/cli.md, "Control files"), reproduced
here over the C API because they live in the sinew program, not in libmu:

- times resolve to substeps of 1/(frame_rate · substeps) s: an event at t
  acts from the first substep starting at or after t (within a millionth
  of a substep), before that substep is stepped; events of one substep act
  in the order added;
- each muscle keeps a command (initially activation 0, not driven), each
  torque muscle its recruitment; an event replaces the command of each of
  its muscles in the variant; a pulse holds the activation for one frame;
- a frame is stepped whole (mu_model_step) when nothing driven changes
  within it, else substep by substep (mu_model_substep), the controls
  applied before each: the two differ in where collision runs, so the
  same choice is made here to give the same bits.

The arithmetic is the C code's, operation for operation (Python floats
are C doubles; math.sin is the C library's sin), so a shape is sampled
at the same values.
"""
import math
from dataclasses import dataclass

from . import _api, errors
from ._lib import mu

KINDS = ("activation", "tension", "pulse", "recruit")
SHAPES = ("step", "ramp", "sine", "pulses")
#: N: the largest tension target accepted (as `sinew run`).
MAX_TENSION = 1e9
#: s: the latest time and longest duration accepted.
MAX_TIME = 1e6
_NO_PULSE = -1

_MUSCLE, _GROUP, _TORQUE_MUSCLE = 5, 6, 7


def c_round(x):
    """C's round() and lround(): halves away from zero."""
    r = math.floor(abs(x))
    if abs(x) - r >= 0.5:
        r += 1
    return math.copysign(r, x)


def c_nearbyint(x):
    """nearbyint() in the default rounding mode: halves to even (Python's round)."""
    return float(round(x))


def first_substep_at(time, substep):
    """The first substep starting at or after ``time`` s."""
    substeps = time / substep
    nearest = c_nearbyint(substeps)
    return int(nearest if abs(substeps - nearest) < 1e-6 else math.ceil(substeps))


@dataclass
class Shape:
    """A control's shape: kind (SHAPES), start (s), duration (s), first
    (step: value; ramp: FROM; sine: MEAN; pulses: LEVEL), second (ramp:
    TO; sine: AMPLITUDE), frequency (Hz), width (s)."""

    kind: str = "step"
    start: float = 0.0
    duration: float = 0.0
    first: float = 0.0
    second: float = 0.0
    frequency: float = 0.0
    width: float = 0.0

    def pulse_substeps(self, substep):
        return int(c_round(self.width / substep))

    def _in_pulse(self, time, substep):
        k = int(c_round(time / substep))
        width = self.pulse_substeps(substep)
        last = math.ceil(self.duration * self.frequency - 1e-9) - 1.0
        guess = math.floor((time - self.start) * self.frequency + 1e-9)
        n = max(guess - 1.0, 0.0)
        while n <= min(guess + 1.0, last):
            first = first_substep_at(self.start + n / self.frequency, substep)
            if first <= k < first + width:
                return True
            n += 1.0
        return False

    def value(self, time, substep):
        """The value at ``time`` s (a substep's start)."""
        elapsed = max(time - self.start, 0.0)
        if self.kind == "ramp":
            if elapsed >= self.duration:
                return self.second
            return self.first + (self.second - self.first) * (elapsed / self.duration)
        if self.kind == "sine":
            if elapsed >= self.duration:
                return self.first
            return self.first + self.second * math.sin(2.0 * math.pi * self.frequency * elapsed)
        if self.kind == "pulses":
            return self.first if self._in_pulse(time, substep) else 0.0
        return self.first


class _Channel:
    __slots__ = ("kind", "shape", "pulse_end", "pulse_value", "due", "value")

    def __init__(self, kind):
        self.kind = kind
        self.shape = Shape()
        self.pulse_end = _NO_PULSE
        self.pulse_value = 0.0
        self.due = False
        self.value = 0.0


class Schedule:
    """The controls of a run of ``model`` (a :class:`sinew.Model`), checked
    as they are added (names against the model's variant, values in range)."""

    def __init__(self, model):
        self._model = model
        d = model._d
        self._d = d
        self.substep = 1.0 / (d.frame_rate * d.substeps)
        self._events = []  # (substep, kind, channels, shape)
        self._next = 0
        self._channels = [_Channel("activation") for _ in range(d.muscle_count)] + [
            _Channel("recruit") for _ in range(d.torque_muscle_count)
        ]
        variant = d.variants[model.options.variant]
        in_variant = {variant.muscles[k] for k in range(variant.muscle_count)}
        bones = {variant.bones[k] for k in range(variant.bone_count)}
        self._in_variant = [m in in_variant for m in range(d.muscle_count)]
        for t in range(d.torque_muscle_count):
            torque = d.torque_muscles[t]
            reaction_ok = (
                not torque.has_reaction_body or torque.reaction_body.kind == 0 or torque.reaction_body.index in bones
            )
            self._in_variant.append(torque.body.index in bones and reaction_ok)
        self._names = [
            model._desc_name(_MUSCLE, m) for m in range(d.muscle_count)
        ] + [model._desc_name(_TORQUE_MUSCLE, t) for t in range(d.torque_muscle_count)]

    # --------------------------------------------------------------- adding

    def _resolve(self, kind, name):
        d = self._d
        ref = _api.ModelRef()
        found = bool(mu.mu_model_desc_find(self._model._desc, errors.text("name", name), ref))
        torque = found and ref.kind == _TORQUE_MUSCLE
        muscle = found and ref.kind in (_MUSCLE, _GROUP)
        if kind == "recruit" and not torque:
            raise errors.InvalidArgument(f"no torque muscle named {name!r} (torque muscles: {self._torque_list()})")
        if kind != "recruit" and not muscle:
            what = "is a torque muscle, driven by recruitment" if torque else "is no muscle or group"
            raise errors.InvalidArgument(f"{name!r} {what} (muscles and groups: {self._muscle_list()})")
        if ref.kind == _GROUP:
            group = d.groups[ref.index]
            channels = [group.muscles[k] for k in range(group.muscle_count)]
        elif ref.kind == _TORQUE_MUSCLE:
            channels = [d.muscle_count + ref.index]
        else:
            channels = [ref.index]
        if not any(self._in_variant[c] for c in channels):
            raise errors.InvalidArgument(f"{name!r} has nothing in variant {self._model.variant_name!r}")
        return ref, channels

    def _muscle_list(self):
        d = self._d
        names = self._names[: d.muscle_count] + [
            d.groups[g].name.decode() for g in range(d.group_count)
        ]
        return ", ".join(repr(n) for n in names) or "none"

    def _torque_list(self):
        return ", ".join(repr(n) for n in self._names[self._d.muscle_count :]) or "none"

    def _check_value(self, kind, ref, label, value, whole=True):
        if kind == "tension":
            top = MAX_TENSION
        elif kind == "recruit":
            top = self._d.torque_muscles[ref.index].neurons
        else:
            top = 1.0
        if not (0.0 <= value <= top) or (whole and kind == "recruit" and value != math.floor(value)):
            raise errors.InvalidArgument(f"{kind} {label} must be from 0 to {top:g}, got {value!r}")

    def add(self, time, kind, name, value=None, shape="step", **parameters):
        """Adds an event at ``time`` s (not before the last one added):
        ``kind`` "activation", "tension" (N), "pulse" or "recruit"
        (neurons) for the muscle, group or torque muscle ``name``. With
        ``shape`` "step" the value is ``value``; "ramp" takes ``start_value``,
        ``end_value``, ``duration``; "sine" ``mean``, ``amplitude``,
        ``frequency`` (Hz), ``duration``; "pulses" ``level``, ``frequency``,
        ``width`` (s), ``duration``."""
        if kind not in KINDS:
            raise errors.InvalidArgument(f"control kind must be one of {', '.join(KINDS)}, got {kind!r}")
        if shape not in SHAPES or (kind == "pulse" and shape != "step"):
            raise errors.InvalidArgument(
                f"control shape must be one of {', '.join(SHAPES)} (a pulse: step), got {shape!r}"
            )
        time = errors.real("time", time)
        if not 0.0 <= time <= MAX_TIME:
            raise errors.InvalidArgument(f"the time must be from 0 to {MAX_TIME:g} s, got {time!r}")
        if self._events and time < self._events[-1][3].start:
            raise errors.InvalidArgument(
                f"the time {time:g} s is before the previous control's {self._events[-1][3].start:g} s"
            )
        ref, channels = self._resolve(kind, name)
        s = Shape(kind=shape, start=time)
        p = {k: errors.real(k, v) for k, v in parameters.items()}
        expected = {
            "step": set(),
            "ramp": {"start_value", "end_value", "duration"},
            "sine": {"mean", "amplitude", "frequency", "duration"},
            "pulses": {"level", "frequency", "width", "duration"},
        }[shape]
        if set(p) != expected or (shape == "step") == (value is None):
            want = "value" if shape == "step" else ", ".join(sorted(expected))
            raise TypeError(f"a {shape} control takes {want}; got {', '.join(sorted(p)) or 'value'}")
        check_kind = "activation" if kind == "pulse" else kind
        if shape == "step":
            s.first = errors.real("value", value)
            self._check_value(check_kind, ref, "value", s.first)
        else:
            s.duration = p["duration"]
            if not 0.0 < s.duration <= MAX_TIME:
                raise errors.InvalidArgument(f"the {shape}'s duration must be more than 0 s, got {s.duration!r}")
            if shape == "ramp":
                s.first, s.second = p["start_value"], p["end_value"]
                self._check_value(check_kind, ref, "ramp start", s.first)
                self._check_value(check_kind, ref, "ramp end", s.second)
            elif shape == "sine":
                s.first, s.second, s.frequency = p["mean"], p["amplitude"], p["frequency"]
                rate = 1.0 / self.substep
                if not (s.second >= 0.0 and 0.0 < s.frequency <= rate / 2.0):
                    raise errors.InvalidArgument(
                        f"the sine's amplitude must be >= 0 and its frequency in (0, {rate / 2.0:g}] Hz"
                    )
                self._check_value(check_kind, ref, "sine minimum", s.first - s.second, False)
                self._check_value(check_kind, ref, "sine maximum", s.first + s.second, False)
            else:
                s.first, s.frequency, s.width = p["level"], p["frequency"], p["width"]
                period = 1.0 / s.frequency if s.frequency > 0.0 else 0.0
                if not (s.frequency > 0.0 and 0.0 < s.width < period and s.pulse_substeps(self.substep) >= 1):
                    raise errors.InvalidArgument(
                        "the pulses' frequency must be > 0 Hz and their width at least half a substep and "
                        "less than the period"
                    )
                if math.floor((1.0 / s.frequency) / self.substep + 1e-6) < s.pulse_substeps(self.substep) + 1:
                    raise errors.InvalidArgument("the pulses leave no substep between two pulses")
                self._check_value(check_kind, ref, "pulses level", s.first)
        self._events.append((first_substep_at(time, self.substep), kind, channels, s))

    # -------------------------------------------------------------- driving

    def _channel_value(self, channel, substep):
        if substep < channel.pulse_end:
            return channel.pulse_value
        value = channel.shape.value(float(substep) * self.substep, self.substep)
        return c_round(value) if channel.kind == "recruit" else value

    def _drive(self, c, substep):
        model = self._model
        channel = self._channels[c]
        channel.value = self._channel_value(channel, substep)
        name = self._names[c]
        if channel.kind == "recruit":
            for t, built in enumerate(model.torque_muscle_names):
                if built == name:
                    model.recruit(t, int(channel.value))
                    return
            return
        if channel.kind == "tension" and substep >= channel.pulse_end:
            model.set_tension(name, channel.value)
        else:
            model.set_activation(name, channel.value)

    def _act(self, event, substep):
        _, kind, channels, shape = event
        for c in channels:
            if not self._in_variant[c]:
                continue
            channel = self._channels[c]
            if kind == "pulse":
                channel.pulse_end = substep + self._d.substeps
                channel.pulse_value = shape.first
            else:
                channel.kind = kind
                channel.shape = shape
                channel.pulse_end = _NO_PULSE
            channel.due = True

    def apply(self, substep):
        """Acts the events due before ``substep`` and drives what changes there."""
        while self._next < len(self._events) and self._events[self._next][0] <= substep:
            self._act(self._events[self._next], substep)
            self._next += 1
        for c, channel in enumerate(self._channels):
            if channel.due or substep == channel.pulse_end or channel.shape.kind != "step":
                channel.due = False
                self._drive(c, substep)

    def _steady(self, first, count):
        end = first + count
        if self._next < len(self._events) and self._events[self._next][0] < end:
            return False
        for c, channel in enumerate(self._channels):
            if first < channel.pulse_end < end:
                return False
            if channel.shape.kind == "step" or not self._in_variant[c]:
                continue
            value = self._channel_value(channel, first)
            for k in range(first + 1, end):
                if self._channel_value(channel, k) != value:
                    return False
        return True

    def step_frame(self, frame):
        """Steps frame ``frame`` (0, 1, ...) with the controls applied."""
        substeps = self._d.substeps
        first = frame * substeps
        self.apply(first)
        if self._steady(first, substeps):
            self._model.step()
            return
        self._model.substep()
        for k in range(first + 1, first + substeps):
            self.apply(k)
            self._model.substep()

    @property
    def pending(self):
        """Events that have not acted yet."""
        return len(self._events) - self._next
