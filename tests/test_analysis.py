"""The subsystem declarations: every subsystem the audit loops over is declared once, and
what a declaration names exists (its spec section, Campbell diagram and figures)."""

from wtvib import audit, spec
from wtvib.judge import analysis
from wtvib.judge.analysis import Analysis, Context, section_damping
from wtvib.judge.excitation import operating_range
from wtvib.outputs.plots import FIGURES
from wtvib.spec import Spec


def test_every_subsystem_is_declared_once_with_a_unique_name():
    names = [sub.name for sub in audit.SUBSYSTEMS]
    assert len(set(names)) == len(names)
    for sub in audit.SUBSYSTEMS:
        assert isinstance(sub, analysis.Subsystem)
        for attr in ("default_damping", "build_modes", "analyse", "excitations"):
            assert callable(getattr(sub, attr)), (sub.name, attr)


def test_what_a_declaration_names_exists():
    """A subsystem's spec section is a field of the spec, its diagram one the figures draw,
    its figures entries of the registry; and every registered figure is some subsystem's
    (a figure nobody declares, or a declared one nobody draws, fails here by name)."""
    declared = [f for sub in audit.SUBSYSTEMS for f in sub.figures]
    assert len(set(declared)) == len(declared), declared
    assert set(declared) == set(FIGURES)
    for sub in audit.SUBSYSTEMS:
        assert sub.part is None or sub.part in Spec.model_fields, (sub.name, sub.part)
        assert sub.diagram is None or sub.diagram in analysis.DIAGRAMS, (sub.name, sub.diagram)
        assert (sub.diagram is None) == (not sub.title), sub.name  # a drawn one is named
    drawn = {sub.diagram for sub in audit.SUBSYSTEMS}
    assert set(analysis.DIAGRAMS) <= drawn


def test_a_subsystem_s_own_lines_reach_the_audit_and_act_on_it_alone(write_spec):
    """The drive train declares its gear mesh: the audit judges it, on the drive train."""
    from tests.conftest import spec_text

    extra = "drivetrain:\n  gear_stages: [{name: stage2, teeth: 19, shaft_speed_ratio: 27}]\n"
    s = spec.load(write_spec(spec_text() + extra, name="g.yaml"))
    lines = audit.all_lines(s)
    (mesh,) = [e for e in lines if e.id == "mesh.stage2"]
    assert mesh.acts_on("drivetrain") and not mesh.acts_on("tower")
    assert audit.run(s).lines == tuple(lines)


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
    ctx = Context(operating_range(s.rotor.speed), audit.all_lines(s), r.rule, s.audit, r.modes)
    assert [m.id for m in ctx.own("tower")] == ["tower.fa1"]
    for sub in audit.SUBSYSTEMS:
        assert isinstance(sub.analyse(s, ctx), Analysis)
    assert analysis.Damping(0.01, "x", True).ratio == 0.01
