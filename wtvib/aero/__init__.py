"""Aerodynamics and aeroelasticity on top of the structural models: steady BEM operating
points (:mod:`.bem`), the aerodynamic damping of every mode (:mod:`.aerodamping`), blade
flutter and divergence (:mod:`.aeroelastic`), stall-induced vibration (:mod:`.stall`) and
the blade-tip tuned damper (:mod:`.tuned_damper`).
"""
