"""Numerics and mechanics that know no turbine: the one eigen-solver and mode tracking
(:mod:`.modal`), beam finite elements (:mod:`.beam`), second-order kinematics
(:mod:`.kinematics`), the Floquet integrator (:mod:`.floquet`), the Coleman transformation
(:mod:`.coleman`), rigid bodies (:mod:`.rigid`), a floating hull's hydrostatics and
strip-theory added mass (:mod:`.hull`) and the shed wake's lift deficiency
(:mod:`.unsteady`). The lowest layer above the shared types: it imports none of the others.
"""
