"""Safe YAML with line numbers: duplicate keys and object tags refused, paths located."""

import pytest

from wtvib.errors import SpecError
from wtvib.spec import yamlio


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


def test_plain_scalars_follow_the_yaml_1_2_core_schema():
    """PyYAML implements YAML 1.1: 1.6e7 was text, 1:30 was 90 (sexagesimal), 0_5 was 5,
    on was true. The spec reader resolves plain scalars by YAML 1.2's core schema."""
    doc = yamlio.parse(
        "a: 1.6e7\nb: 1:30\nc: 0_5\nd: on\ne: true\nf: 12\ng: -.inf\nh: '5'\ni: ~\n", "t.yaml"
    )
    assert doc.data == {
        "a": 1.6e7,
        "b": "1:30",
        "c": "0_5",
        "d": "on",
        "e": True,
        "f": 12,
        "g": float("-inf"),
        "h": "5",
        "i": None,
    }


def test_a_number_of_thousands_of_digits_is_refused():
    with pytest.raises(SpecError, match="digits is not a spec value"):
        yamlio.parse("a: " + "9" * 5000 + "\n", "t.yaml")


def test_legal_yaml_stays_legal_and_a_recursive_alias_is_one_line():
    """A merge key followed by an override was refused as a duplicate, indented
    comments counted as nesting, and a recursive alias ended in a RecursionError."""
    doc = yamlio.parse("base: &b {x: 1, y: 2}\nother:\n  <<: *b\n  y: 3\n", "t.yaml")
    assert doc.data["other"] == {"x": 1, "y": 3}  # the explicit key wins (YAML merge)
    comments = "a: 1\n" + "".join("  " * i + "# note\n" for i in range(80)) + "b: 2\n"
    assert yamlio.parse(comments, "t.yaml").data == {"a": 1, "b": 2}
    with pytest.raises(SpecError, match="recursive alias"):
        yamlio.parse("notes: &a [*a]\n", "t.yaml")
    with pytest.raises(SpecError, match="duplicate key 'x'"):
        yamlio.parse("a: {x: 1, x: 2}\n", "t.yaml")


@pytest.mark.parametrize(
    "text",
    [
        "x: 8e-05",
        "x: 1e5",
        "x: 1.6e7",
        "x: 1:30",
        "x: on",
        "x: 010",
        "x: 0_5",
        'x: "1e5"',
        "x: [a, 0x1f, .inf, ~, 2.5, -3]",
        "a: &b {c: 1}\nd:\n  <<: *b\n  e: 2",
    ],
)
def test_the_fast_windio_reader_reads_plain_scalars_as_the_spec_reader_does(text):
    """The fast reader of machine-written files (windIO) used PyYAML's YAML 1.1
    resolvers: 8e-05 and 1e5 stayed text (an airfoil coordinate of the IEA-22 example file
    failed the windIO schema), 1:30 was 90 and on was true. Both readers are YAML 1.2 now."""
    from wtvib.spec.yamlio import parse, parse_plain

    assert parse_plain(text).data == parse(text).data


def test_plain_number_lists_read_by_json_equal_the_yaml_readers():
    """Parse_plain reads a line's flow list of plain numbers with json (in C) —
    the IEA-22 windIO file's 46,000 numbers cost PyYAML 0.15 s — and must give what the
    YAML 1.2 core reading gives: ints stay ints, floats floats; a list with an entry json
    would read otherwise (.5, +1, 01, .inf, 1e5 as YAML 1.2 reads it: a float) stays with
    YAML; so does a list with an anchor or a comment, or a text that holds the token."""
    import yaml

    from wtvib.spec import yamlio

    text = """\
a: [0.0, 1, -2.5e-07, 3E+2]
b:
  - c: [1, 2, 3]
  - [4, 5]
d: [.5, 1.0]
e: [+1, 2]
f: [01, 2]
g: [.inf, 1.0]
h: &x [1.0, 2.0]
i: *x
j: [1.0, 2.0] # note
k: []
l: [1e5, 2]
m: "[1.0, 2.0]"
"""
    got = yamlio.parse_plain(text).data
    assert got == yaml.load(text, Loader=yamlio._fast_loader())
    assert type(got["a"][1]) is int and type(got["a"][0]) is float
    assert got["d"] == [0.5, 1.0] and got["l"] == [1e5, 2] and got["m"] == "[1.0, 2.0]"
    assert len(yamlio._number_lists(text)[1]) == 3  # a, c and l; the others stay with YAML
    # an integer of more digits than any value has is still refused, with its line
    with pytest.raises(SpecError, match=r"line 1: .*a number of 40 digits"):
        yamlio.parse_plain("a: [1, " + "1234567890" * 4 + "]\n")
