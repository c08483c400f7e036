"""Judging, the same for every subsystem: the excitations and operating speeds
(:mod:`.excitation`), the one resonance routine (:mod:`.resonance`), frequencies of
different subsystems close to each other (:mod:`.closeness`), the Campbell data
(:mod:`.campbell`) and the subsystem protocol every analysis follows (:mod:`.analysis`).
Below the subsystems, which judge their modes with it; above the spec and the importers.
"""
