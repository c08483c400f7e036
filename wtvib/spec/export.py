"""The JSON Schema of the spec, for editors and validators (`wtvib schema`)."""

from typing import Any

from .base import Quantity
from .turbine import Spec


def json_schema() -> dict[str, Any]:
    """JSON Schema of the spec, with every number also accepting a quantity mapping."""
    schema = Spec.model_json_schema()
    defs = schema.setdefault("$defs", {})
    quantity = Quantity.model_json_schema()
    defs["Quantity"] = quantity
    ref = {"$ref": "#/$defs/Quantity"}

    def widen(node: Any) -> Any:
        if isinstance(node, dict):
            if node.get("type") in ("number", "integer") and "const" not in node:
                return {"anyOf": [node, ref]}
            return {k: widen(v) if k != "Quantity" else v for k, v in node.items()}
        if isinstance(node, list):
            return [widen(v) for v in node]
        return node

    out = widen(schema)
    out["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    out["title"] = "wtvib turbine spec, format version 1"
    return out  # type: ignore[no-any-return]
