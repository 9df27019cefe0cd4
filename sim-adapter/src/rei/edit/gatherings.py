# SPDX-License-Identifier: EPL-2.0
"""Crowds and groups in a test case's text: where each line's count, rate and behaviour are, and the text with
other values.

Text-level edits beside the room editor's engine: `rei search` sets a crowd's or group's numbers and behaviour, and
a campaign variant every person's behaviour, in a case's text, before the engine's ``reset`` validates it with the
language's own checks (a crowd larger than its floors hold is the language's error, as in a case written by hand).
The statements are read token by token with the grammar's
shape (``crowd NAME N [: Type] from [...] to [...] options``, ``group NAME N [: Type] route [...] options``, the
options in any order), comments masked, so a change touches the value's own token and nothing else.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

from rei.artifacts.animation import Behaviour

#: A group's and a crowd's behaviours towards the robot (the language's Behaviour); avoids when none is written.
BEHAVIOURS = tuple(b.value for b in Behaviour)
DEFAULT_BEHAVIOUR = Behaviour.AVOIDS.value

_COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.DOTALL)
_STRING = re.compile(r'"(?:[^"\\\n]|\\.)*"')
_TOKEN = re.compile(r"\d+(?:\.\d+)?|\^?[A-Za-z_][A-Za-z0-9_]*|\S")
_INT = re.compile(r"\d+")
_NUMBER = re.compile(r"\d+(?:\.\d+)?")
_ID = re.compile(r"\^?[A-Za-z_][A-Za-z0-9_]*")


@dataclass(frozen=True, slots=True)
class Gathering:
    """One crowd or group statement: ``kind`` crowd or group; each ``*_at`` a (start, end) offset of the value's
    token in the text, None when the line does not write it; ``end``: the offset after the statement's last token,
    where a missing option is appended."""

    kind: str
    name: str
    count: int
    count_at: tuple[int, int]
    rate: float | None
    rate_at: tuple[int, int] | None
    behaviour: str
    behaviour_at: tuple[int, int] | None
    end: int

    def people(self) -> list[str]:
        """The names the generator gives its people: NAME_1 ... NAME_N."""
        return [f"{self.name}_{i}" for i in range(1, self.count + 1)]


def gatherings(text: str, *, routes: bool = False) -> dict[str, Gathering]:
    """Every crowd and group of ``text``, by name, in the order written (none when it has none); with ``routes``,
    every person on a route too (``human NAME route [...]``, kind human, count 1), so that every behaviour towards
    the robot in the text is among them."""
    masked = _STRING.sub(lambda m: " " * len(m[0]), _COMMENT.sub(lambda m: re.sub(r"[^\n]", " ", m[0]), text))
    tokens = [(m[0], m.start(), m.end()) for m in _TOKEN.finditer(masked)]
    found: dict[str, Gathering] = {}
    for i, (word, _, _) in enumerate(tokens):
        if routes and word == "human" and i + 2 < len(tokens) and _ID.fullmatch(tokens[i + 1][0]):
            person = _read("human", tokens, i)
            if person is not None:
                found.setdefault(person.name, person)
            continue
        if word not in ("crowd", "group") or i + 2 >= len(tokens):
            continue
        # a statement: the keyword, a name and a whole number (crowd and group are names too: 'object crowd : Box',
        # 'on crowd' never read so)
        if i > 0 and tokens[i - 1][0] in ("on", "[", ",", "@", ":", "object", "human", "robot", "dynamic"):
            continue
        if not _ID.fullmatch(tokens[i + 1][0]) or not _INT.fullmatch(tokens[i + 2][0]):
            continue
        gathering = _read(word, tokens, i)
        if gathering is not None:
            found.setdefault(gathering.name, gathering)
    return found


def _read(kind: str, tokens: list[tuple[str, int, int]], i: int) -> Gathering | None:
    name = tokens[i + 1][0].lstrip("^")
    # a person on a route is one person: its count stands nowhere in the text
    count_token = tokens[i + 2] if kind != "human" else ("1", tokens[i + 1][2], tokens[i + 1][2])
    j = i + 3 if kind != "human" else i + 2

    def word(k: int) -> str:
        return tokens[k][0] if k < len(tokens) else ""

    if word(j) == ":":
        j += 2
    lists = ("from", "to") if kind == "crowd" else ("route",)  # a group's route, or a person's
    for keyword in lists:
        if word(j) != keyword or word(j + 1) != "[":
            return None
        j += 2
        while j < len(tokens) and word(j) != "]":
            j += 1
        if j >= len(tokens):
            return None
        j += 1
    end = tokens[j - 1][2]
    rate: float | None = None
    rate_at: tuple[int, int] | None = None
    behaviour, behaviour_at = DEFAULT_BEHAVIOUR, None
    while j < len(tokens):
        w = word(j)
        if w == "rate" and kind == "crowd" and _NUMBER.fullmatch(word(j + 1)):
            rate, rate_at = float(word(j + 1)), (tokens[j + 1][1], tokens[j + 1][2])
            j += 2
        elif w == "speed" and _NUMBER.fullmatch(word(j + 1)):
            j += 4 if word(j + 2) == "to" and _NUMBER.fullmatch(word(j + 3)) else 2
        elif w == "start" and _NUMBER.fullmatch(word(j + 1)):
            j += 3 if word(j + 2) == "s" else 2
        elif w in ("loop", "once"):
            j += 1
        elif w in BEHAVIOURS:
            behaviour, behaviour_at = w, (tokens[j][1], tokens[j][2])
            j += 1
        else:
            break
        end = tokens[j - 1][2]
    return Gathering(kind, name, int(count_token[0]), (count_token[1], count_token[2]), rate, rate_at, behaviour,
                     behaviour_at, end)


def number(value: float) -> str:
    """A number as the language writes one: digits, a point and at most three decimals (no exponent)."""
    text = f"{round(float(value), 3):.3f}".rstrip("0").rstrip(".")
    return text if text not in ("", "-0") else "0"


def with_behaviour(text: str, behaviour: str) -> str:
    """``text`` with every person on a route, crowd and group behaving ``behaviour`` towards the robot (a campaign's
    behaviour variant, rei.campaign.plan)."""
    found = gatherings(text, routes=True)
    return with_values(text, [{"name": name, "behaviour": behaviour} for name in found], routes=True)


def with_values(text: str, settings: Iterable[Mapping[str, Any]], *, routes: bool = False) -> str:
    """``text`` with each setting's crowd or group changed: ``{"name": N, "count": 5, "rate": 0.5,
    "behaviour": "blocks"}``, any of the three left out to keep it as written. An unwritten rate or behaviour is
    appended to the statement; ``avoids`` is not written where none is (it is the default)."""
    found = gatherings(text, routes=routes)
    changes: list[tuple[int, int, str]] = []
    for setting in settings:
        g = found[setting["name"]]
        if setting.get("count") is not None:
            changes.append((*g.count_at, str(int(setting["count"]))))
        appended = ""
        if setting.get("rate") is not None:
            if g.rate_at is not None:
                changes.append((*g.rate_at, number(setting["rate"])))
            else:
                appended += f" rate {number(setting['rate'])}"
        behaviour = setting.get("behaviour")
        if behaviour is not None:
            if g.behaviour_at is not None:
                changes.append((*g.behaviour_at, str(behaviour)))
            elif behaviour != DEFAULT_BEHAVIOUR:
                appended += f" {behaviour}"
        if appended:
            changes.append((g.end, g.end, appended))
    for start, end, new in sorted(changes, reverse=True):  # from the end, so earlier offsets stay right
        text = text[:start] + new + text[end:]
    return text
