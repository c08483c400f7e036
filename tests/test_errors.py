"""The project's exceptions: one readable line naming file, line and field."""

from wtvib.errors import OutputError, SpecError, WtvibError


def test_spec_error_names_file_line_and_field():
    e = SpecError(
        "Input should be greater than 0", path="tower.modes.fa1", line=12, source="t.yaml"
    )
    assert str(e) == "t.yaml:12: tower.modes.fa1: Input should be greater than 0"
    assert str(SpecError("bad", line=3)) == "line 3: bad"
    assert str(SpecError("bad")) == "bad"


def test_errors_subclass_the_builtins_and_the_project_base():
    assert issubclass(SpecError, ValueError) and issubclass(SpecError, WtvibError)
    assert issubclass(OutputError, OSError) and issubclass(OutputError, WtvibError)
