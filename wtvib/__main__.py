"""``python -m wtvib``: the same command as ``wtvib``."""

from .cli import program

program()
