# SPDX-License-Identifier: EPL-2.0
"""rei.located_yaml: positions of nodes and of the mistakes found reading them (the callers' own tests pin their
messages: tests/search/test_search_spec.py, tests/compare/test_compare_thresholds.py, tests/maps)."""

from __future__ import annotations

import pytest

from rei import located_yaml


def test_a_mapping_with_its_key_and_value_positions() -> None:
    root = located_yaml.compose("a: 1\nb:\n  c: [x, y]\n")
    assert root is not None
    entries = located_yaml.mapping(root, "the file")
    assert list(entries) == ["a", "b"]
    key, value = entries["b"]
    assert located_yaml.position(key) == (2, 1) and located_yaml.position(value) == (3, 3)
    assert located_yaml.value(value) == {"c": ["x", "y"]}
    assert located_yaml.compose("") is None


@pytest.mark.parametrize(("text", "expected"), [
    ("a: 1\na: 2\n", "f.yaml:2:1: 'a' is given twice"),
    ("- 1\n", "f.yaml:1:1: the file must be a mapping"),
    ("a: [1\n", "f.yaml:2:1: not YAML: expected ',' or ']', but got '<stream end>'"),
])
def test_mistakes_are_placed(text: str, expected: str) -> None:
    with pytest.raises(located_yaml.LocatedError) as raised:
        root = located_yaml.compose(text)
        assert root is not None
        located_yaml.mapping(root, "the file")
    assert raised.value.at("f.yaml") == expected


@pytest.mark.parametrize(("text", "expected"), [("1e-2", 0.01), ("3", 3.0), ("true", None), (".inf", None),
                                                ("fast", None), ("[1]", None)])
def test_numbers(text: str, expected: float | None) -> None:
    root = located_yaml.compose(f"n: {text}\n")
    assert root is not None
    assert located_yaml.number(located_yaml.mapping(root, "f")["n"][1]) == expected
