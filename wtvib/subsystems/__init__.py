"""The turbine's parts and their modes, one module per part: tower (with its soil,
platform and dampers), blade, drive train, yaw system, the one- and two-bladed rotor, the
coupled whole turbine (:mod:`.coupled`, in multi-blade coordinates :mod:`.multiblade`, the
two-bladed one's periodic equations :mod:`.periodic`), ElastoDyn's mode-shape polynomials,
and the modes a spec gives (:mod:`.given`) or another tool computed (:mod:`.imported`).
Each analysis judges its own modes with :mod:`wtvib.judge`.
"""
