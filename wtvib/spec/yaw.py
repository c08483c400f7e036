"""The yaw system: drives, play, friction and brakes."""

from typing import Annotated, Literal

from pydantic import Field

from .base import ModeEntry, Positive, Ratio, YawModeName, _Strict


class YawPlay(_Strict):
    """Backlash in the yaw drive (worm gear, pinion and ring)."""

    half_gap_deg: Positive = Field(description="Half the gear play δ. [deg]")
    amplitude_deg: Positive | None = Field(
        None,
        description="Vibration amplitude A (through the gap) the yaw moments drive; default "
        "δ + M_yaw/k from the cyclic yaw moment. [deg]",
    )


class Yaw(_Strict):
    """The yaw system: given frequencies, or the drive, inertia, play and friction."""

    drive: Literal["active", "fantail", "free"] | None = Field(None, description="Yaw drive.")
    damping_ratio: Ratio = Field(0.02, description="Default modal damping ratio. [-]")
    modes: dict[YawModeName, ModeEntry] = Field(
        default_factory=dict,
        description="Yaw natural frequencies [Hz], keyed 1, 2, … (ignored with a drive model)",
    )
    drive_stiffness_nm_rad: Positive | None = Field(
        None, description="Torsional stiffness of one yaw drive at the yaw axis. [N·m/rad]"
    )
    drives: int = Field(1, ge=1, le=64, description="Yaw drives acting in parallel.")
    drive_damping_nms_rad: Annotated[float, Field(ge=0, le=1e15)] | None = Field(
        None,
        description="Viscous damping of the yaw drives together at the yaw axis (OpenFAST "
        "ServoDyn's YawDamp): ζ = c/(2·J·ω) of the yaw mode. [N·m·s/rad]",
    )
    inertia_kgm2: Positive | None = Field(
        None,
        description="Tower-head inertia about the yaw axis; default tower_head inertia_yaw + "
        "M·x_cm² (and the rotor's mean for two blades). [kg·m²]",
    )
    rotor_polar_inertia_kgm2: Positive | None = Field(
        None, description="Rotor inertia about its shaft (gyroscopics, two-blade 2P). [kg·m²]"
    )
    tower_torsion_nm_rad: Positive | None = Field(
        None, description="Tower torsional stiffness G·J/L, in series with the drive. [N·m/rad]"
    )
    tower_inertia_kgm2: Positive | None = Field(
        None,
        description="Tower inertia taking part in torsion (two-mass model; default: none, the "
        "tower acts as a spring in series). [kg·m²]",
    )
    play: YawPlay | None = None
    friction_moment_nm: float = Field(
        0.0, ge=0, description="Friction in the yaw bearing / sliding blocks while yawing. [N·m]"
    )
    brake_moment_nm: float = Field(
        0.0, ge=0, description="Holding moment of the yaw brakes when parked. [N·m]"
    )
    yaw_rate_deg_s: Positive | None = Field(None, description="Yawing rate. [deg/s]")
    yaw_moment_amplitude_nm: Positive | None = Field(
        None, description="Amplitude of the cyclic aerodynamic yaw moment at N_b·P. [N·m]"
    )
    rated_torque_nm: Positive | None = Field(
        None, description="Rotor torque at rated power, for the tilted-shaft term. [N·m]"
    )
    shaft_tilt_deg: float = Field(0.0, ge=-20, le=20, description="Shaft tilt angle. [deg]")

    @property
    def has_model(self) -> bool:
        return self.drive_stiffness_nm_rad is not None

    @property
    def free(self) -> bool:
        """The nacelle turns freely on the tower top: a free yaw drive with no stiffness (an
        OpenFAST deck's yaw DOF without a yaw spring, read as OpenFAST models it)."""
        return self.drive == "free" and not self.has_model
