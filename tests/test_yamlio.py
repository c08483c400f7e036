"""Safe YAML with line numbers: duplicate keys and object tags refused, paths located."""

import pytest

from wtvib import yamlio
from wtvib.errors import SpecError


def test_lines_of_field_paths():
    doc = yamlio.parse("a: 1\nb:\n  c: [1, 2]\n", "t.yaml")
    assert doc.data == {"a": 1, "b": {"c": [1, 2]}}
    assert doc.line_of(("b", "c")) == 3
    assert doc.line_of(("b", "c", 5)) == 3  # nearest ancestor that has a line
    assert yamlio.format_path(("rotor", "speed", 0)) == "rotor.speed[0]"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("a: 1\na: 2\n", "duplicate"),
        ("a: !!python/object/apply:os.system [ls]\n", "tag"),
        ("", "empty"),
    ],
)
def test_unsafe_or_ambiguous_documents_are_refused(text, message):
    with pytest.raises(SpecError, match=message):
        yamlio.parse(text, "t.yaml")


def test_nesting_is_bounded_before_parsing():
    assert yamlio.nesting_depth("a: [[[1]]]\n") >= 3
    with pytest.raises(SpecError):
        yamlio.parse("a: " + "[" * 200 + "]" * 200 + "\n", "t.yaml")
