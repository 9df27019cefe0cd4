# SPDX-License-Identifier: EPL-2.0
"""Parsing a search spec from text in the spec tests: the parsed spec, or the message of its error."""

from __future__ import annotations

from pathlib import Path

import pytest

from rei.campaign.spec import SpecError
from rei.search.spec import SearchSpec, parse_search_spec


def parse(text: str, folder: Path) -> SearchSpec:
    return parse_search_spec(text, base=folder, file="s.yaml")


def error_of(text: str, folder: Path) -> str:
    with pytest.raises(SpecError) as raised:
        parse(text, folder)
    return str(raised.value)
