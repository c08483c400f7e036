"""wtvib — vibration audit of wind turbines (Hau, *Wind Turbines*, ch. 7)."""

__version__ = "0.1.0"
