"""``python -m wtvib``: the same command as ``wtvib``."""

from .cli import main

main()
