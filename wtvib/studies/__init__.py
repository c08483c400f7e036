"""Questions asked around an audit: tolerances propagated to frequencies and verdicts
(:mod:`.uncertainty`, on a Dask cluster with :mod:`.cluster`), a tower head's usual mass
(:mod:`.scaling`), and the design windows and tower sizing of a finished audit
(:mod:`.design`).
"""
