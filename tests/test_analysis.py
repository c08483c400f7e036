"""The subsystem protocol: every subsystem module the audit loops over satisfies it."""

from wtvib import audit, spec
from wtvib.judge import analysis
from wtvib.judge.analysis import Analysis, Context, section_damping
from wtvib.judge.excitation import excitations, operating_range


def test_every_subsystem_has_the_protocol_and_a_unique_name():
    names = [sub.NAME for sub in audit.SUBSYSTEMS]
    assert len(set(names)) == len(names)
    for sub in audit.SUBSYSTEMS:
        for attr in ("default_damping", "build_modes", "analyse"):
            assert callable(getattr(sub, attr)), (sub.NAME, attr)


def test_section_damping_says_whether_it_was_given(write_spec):
    bare = spec.load(write_spec())
    d = section_damping(bare.tower, "tower")
    assert d.assumed and d.source == "assumed (no value given)"
    text = write_spec().read_text().replace("tower:\n", "tower:\n  damping_ratio: 0.03\n", 1)
    given = spec.load(write_spec(text, name="g.yaml"))
    d = section_damping(given.tower, "tower")
    assert not d.assumed and d.ratio == 0.03 and d.source == "tower.damping_ratio (given)"


def test_each_analysis_is_an_analysis_and_sees_the_whole_turbine(write_spec):
    s = spec.load(write_spec())
    r = audit.run(s)
    ctx = Context(operating_range(s.rotor.speed), excitations(s), r.rule, s.audit, r.modes)
    assert [m.id for m in ctx.own("tower")] == ["tower.fa1"]
    for sub in audit.SUBSYSTEMS:
        assert isinstance(sub.analyse(s, ctx), Analysis)
    assert analysis.Damping(0.01, "x", True).ratio == 0.01
