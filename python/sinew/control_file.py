# SPDX-License-Identifier: MIT
"""Control files, the text form of a schedule that ``sinew run --control
FILE`` reads (docs/cli.md, "Control files"), read into a
:class:`~sinew.Schedule`. One control per line:

    # a comment; blank lines are skipped
    TIME [QUANTITY] SHAPE NAME ARGUMENTS...
    TIME QUANTITY NAME VALUE             a step
    TIME pulse NAME [VALUE]              activation VALUE (default 1) for one frame

QUANTITY is activation (when left out), tension or recruit; SHAPE is step
VALUE, ramp FROM TO DURATION, sine MEAN AMPLITUDE FREQUENCY DURATION or
pulses LEVEL FREQUENCY WIDTH DURATION. A name with spaces goes in double
quotes (no escapes); '#' outside quotes starts a comment.

A bad line raises :class:`sinew.InvalidArgument` naming the file and the
line: one that does not parse before anything of the file is scheduled,
one whose name or values the model refuses when it is added.
"""
import math
import re

from . import errors

_ARGUMENTS = {
    "step": ("value",),
    "ramp": ("start_value", "end_value", "duration"),
    "sine": ("mean", "amplitude", "frequency", "duration"),
    "pulses": ("level", "frequency", "width", "duration"),
}
_QUANTITIES = ("activation", "tension", "recruit", "pulse")
# What strtod reads as a whole field, finite: decimal or hexadecimal.
_NUMBER = re.compile(r"^[+-]?((\d+\.?\d*|\.\d+)([eE][+-]?\d+)?|0[xX][0-9a-fA-F.]+([pP][+-]?\d+)?)$")


def split_words(line):
    """The words of a line, quotes removed; raises ValueError for a quote
    left open or followed by text."""
    words, k, n = [], 0, len(line)
    while k < n:
        c = line[k]
        if c in " \t\r\n":
            k += 1
        elif c == "#":
            break
        elif c == '"':
            end = line.find('"', k + 1)
            if end < 0:
                raise ValueError("a quote is left open")
            if end + 1 < n and line[end + 1] not in " \t\r\n#":
                raise ValueError("a closing quote is followed by text")
            words.append(line[k + 1 : end])
            k = end + 1
        else:
            end = k
            while end < n and line[end] not in " \t\r\n#":
                end += 1
            words.append(line[k:end])
            k = end
    return words


def _number(text):
    if not _NUMBER.match(text):
        return None
    value = float.fromhex(text) if "x" in text.lower() else float(text)
    return value if math.isfinite(value) else None


def parse_line(words):
    """The Schedule.add arguments of one line's words (None for an empty line)."""
    if not words:
        return None
    time = _number(words[0])
    if time is None:
        raise ValueError(f'expected a time in seconds, got "{words[0]}"')
    kind, shape, name_field = "activation", None, 2
    if len(words) >= 2 and words[1] in _QUANTITIES:
        kind = words[1]
        if kind != "pulse" and len(words) >= 3 and words[2] in _ARGUMENTS:
            shape, name_field = words[2], 3
        else:
            shape = "step"
    elif len(words) >= 2 and words[1] in _ARGUMENTS:
        shape = words[1]
    if shape is None:
        got = f'"{words[1]}"' if len(words) >= 2 else "the end of the line"
        raise ValueError(
            f"expected activation, tension, recruit, pulse, step, ramp, sine or pulses after the time, got {got}"
        )
    if len(words) <= name_field or words[name_field] == "":
        raise ValueError(f'expected a name after "{words[name_field - 1]}"')
    name = words[name_field]
    given = words[name_field + 1 :]
    names = _ARGUMENTS[shape]
    if kind == "pulse":
        if len(given) > 1:
            raise ValueError(f'a pulse takes at most one value after the name, got "{given[1]}"')
        values = [1.0] if not given else [_number(given[0])]
    else:
        if len(given) != len(names):
            raise ValueError(
                f"a {shape} line takes {len(names)} number{'s' if len(names) > 1 else ''} after the name "
                f"({' '.join(n.upper() for n in names)}), got {len(given)}"
            )
        values = [_number(g) for g in given]
    for text, value in zip(given, values):
        if value is None:
            hint = " (a name with spaces goes in double quotes)" if " " not in name else ""
            raise ValueError(f'expected a number, got "{text}"{hint}')
    if shape == "step":
        return dict(time=time, kind=kind, name=name, value=values[0])
    return dict(time=time, kind=kind, name=name, shape=shape, **dict(zip(names, values)))


def read(path, schedule):
    """Adds the controls of the file at ``path`` to ``schedule``."""
    with open(path, encoding="utf-8") as stream:
        lines = stream.read().splitlines()
    parsed = []
    for number, line in enumerate(lines, 1):
        try:
            arguments = parse_line(split_words(line))
        except ValueError as problem:
            raise errors.InvalidArgument(f"{path}:{number}: {problem}") from None
        if arguments is not None:
            parsed.append((number, arguments))
    for number, arguments in parsed:
        try:
            schedule.add(**arguments)
        except (errors.Error, TypeError) as problem:
            raise errors.InvalidArgument(f"{path}:{number}: {problem}") from None
