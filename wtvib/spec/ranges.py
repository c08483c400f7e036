"""The valid range of the number at a spec path, read from the schema's own constraints —
for code that makes new values of a validated spec (the Monte Carlo sampling) and must keep
them inside what the spec accepts."""

import math
import types
import typing
from typing import Any

import annotated_types
from pydantic import BaseModel
from pydantic.fields import FieldInfo

from .messages import _split
from .turbine import Spec


def _arms(annotation: Any) -> list[Any]:
    """The alternatives of a union (``X | None``), else the annotation itself."""
    if typing.get_origin(annotation) in (typing.Union, types.UnionType):
        return [a for a in typing.get_args(annotation) if a is not type(None)]
    return [annotation]


def _strip(annotation: Any, metadata: list[Any]) -> Any:
    """The type under ``Annotated[...]`` wrappers, their constraints added to ``metadata``."""
    while typing.get_origin(annotation) is typing.Annotated:
        base, *extra = typing.get_args(annotation)
        for x in extra:
            metadata.extend(x.metadata if isinstance(x, FieldInfo) else [x])
        annotation = base
    return annotation


def valid_range(path: str) -> tuple[float, float, bool, bool]:
    """``(low, high, low_open, high_open)`` of the number at a dotted path such as
    ``tower.foundation.soil[0].friction_angle_deg`` (±inf where the schema sets no bound)."""
    tokens = _split(path)
    model: type[BaseModel] | None = Spec
    metadata: list[Any] = []
    annotation: Any = None
    for token in tokens:
        if model is not None and isinstance(token, str) and token in model.model_fields:
            info = model.model_fields[token]
            metadata = list(info.metadata)
            annotation = [_strip(a, metadata) for a in _arms(info.annotation)]
        else:  # a list item or a mapping's value: the container's element type
            element = next(
                (
                    typing.get_args(a)[-1]
                    for a in annotation or ()
                    if typing.get_origin(a) in (list, dict) and typing.get_args(a)
                ),
                None,
            )
            if element is None:
                return -math.inf, math.inf, False, False
            metadata = []
            annotation = [_strip(a, metadata) for a in _arms(_strip(element, metadata))]
        model = next(
            (a for a in annotation if isinstance(a, type) and issubclass(a, BaseModel)), None
        )
    low, high, low_open, high_open = -math.inf, math.inf, False, False
    for c in metadata:
        if isinstance(c, annotated_types.Ge):
            low, low_open = float(c.ge), False  # type: ignore[arg-type]
        elif isinstance(c, annotated_types.Gt):
            low, low_open = float(c.gt), True  # type: ignore[arg-type]
        elif isinstance(c, annotated_types.Le):
            high, high_open = float(c.le), False  # type: ignore[arg-type]
        elif isinstance(c, annotated_types.Lt):
            high, high_open = float(c.lt), True  # type: ignore[arg-type]
    return low, high, low_open, high_open
